"""Engine tunables (no environment reads: the service builds this from its settings)."""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator

from app.engine.errors import ExportError

PROMPTS_DIR = Path(__file__).resolve().parents[2] / "prompts"
Fallback = Literal["offline", "fail"]


class FallbackPolicy(BaseModel):
    """What happens when a model role gives no usable answer (after its retries).

    ``offline``: the offline role stands in (rule-based perceiver/planner, geometric critic)
    and the report says so. ``fail``: the perceiver/planner failure ends the run; a critic
    failure ends the critic-actor loop, keeping the best plan so far (every output is still
    written, with the failure in the report).
    """

    model_config = ConfigDict(frozen=True)

    perceiver: Fallback = "fail"
    planner: Fallback = "fail"
    critic: Fallback = "offline"

    @classmethod
    def parse(cls, text: str) -> FallbackPolicy:
        """``"offline"``, ``"fail"`` or ``"critic=offline,planner=fail"`` (unnamed roles keep their default).

        Raises
        ------
        ValueError
            An unknown role or policy.
        """
        values: dict[str, str] = {}
        for item in (part.strip() for part in text.split(",") if part.strip()):
            role, sep, value = item.rpartition("=")
            roles = [role.strip()] if sep else ["perceiver", "planner", "critic"]
            if value.strip() not in ("offline", "fail") or any(r not in ("perceiver", "planner", "critic") for r in roles):
                raise ValueError(f"fallback policy expects offline, fail or ROLE=offline|fail (ROLE: perceiver, planner, critic), got {item!r}")
            values.update(dict.fromkeys(roles, value.strip()))
        return cls(**values)  # type: ignore[arg-type]


class EngineConfig(BaseModel):
    """Everything the pipeline may be tuned with; defaults are the documented behaviour."""

    model_config = ConfigDict(frozen=True)

    max_critic_rounds: int = Field(default=3, ge=0, le=10)
    """Critic-actor repair rounds after the first execution (paper: 3)."""
    role_attempts: int = Field(default=3, ge=1, le=10)
    """Tries per model role; a schema error goes back to the model as feedback."""
    check_collisions: bool = True
    render_images: bool | None = None
    """Render reference/overlay views and critic keyframes. None (default): on whenever a role is a
    model that looks at images (perceiver, critic), off for the offline agent."""
    image_size: tuple[int, int] = (800, 600)
    preview: bool = False
    """Also write ``preview.gif``: the final animation rendered from a fixed three-quarter view (EGL)."""
    prompts_dir: Path = PROMPTS_DIR
    request_timeout_s: float = Field(default=60.0, gt=0)
    """Read timeout of a model call: the longest silence while waiting for the answer."""
    connect_timeout_s: float = Field(default=10.0, gt=0)
    call_timeout_s: float = Field(default=240.0, gt=0)
    """Limit for one model call with all its retries and waits."""
    max_concurrent_calls: int = Field(default=4, ge=1, le=32)
    exports: tuple[str, ...] = ()
    """Extra export formats to write: ``usd``, ``mjcf``, ``ros``, ``csv``, ``npz`` (see ``app.engine.export.outputs``)."""
    fallback: FallbackPolicy = Field(default_factory=FallbackPolicy)
    asset_cache_dir: Path | None = None
    """Disk cache of loaded assets (see ``app.engine.asset.cache``); ``None`` disables it."""

    @field_validator("exports", mode="before")
    @classmethod
    def _known_exports(cls, value: object) -> tuple[str, ...]:
        from app.engine.export.outputs import parse_exports

        if not isinstance(value, str | list | tuple):
            raise ValueError("exports must be a comma-separated string or a list of names")
        try:
            return parse_exports(value)
        except ExportError as exc:  # a ValueError lets pydantic name the field
            raise ValueError(str(exc)) from exc
