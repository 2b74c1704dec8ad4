"""Engine tunables (no environment reads: the service builds this from its settings)."""

from __future__ import annotations

from pathlib import Path

from pydantic import BaseModel, ConfigDict, Field, field_validator

from app.engine.errors import ExportError

PROMPTS_DIR = Path(__file__).resolve().parents[2] / "prompts"


class EngineConfig(BaseModel):
    """Everything the pipeline may be tuned with; defaults are the documented behaviour."""

    model_config = ConfigDict(frozen=True)

    max_critic_rounds: int = Field(default=3, ge=0, le=10)
    """Critic-actor repair rounds after the first execution (paper: 3)."""
    role_attempts: int = Field(default=3, ge=1, le=10)
    """Tries per model role; a schema error goes back to the model as feedback."""
    check_collisions: bool = True
    render_images: bool = False
    """Render reference/overlay views and critic keyframes (needed by VLM roles, optional offline)."""
    image_size: tuple[int, int] = (800, 600)
    preview: bool = False
    """Also write ``preview.gif``: the final animation rendered from a fixed three-quarter view (EGL)."""
    prompts_dir: Path = PROMPTS_DIR
    request_timeout_s: float = Field(default=120.0, gt=0)
    max_concurrent_calls: int = Field(default=4, ge=1, le=32)
    exports: tuple[str, ...] = ()
    """Extra export formats to write: ``usd``, ``mjcf``, ``ros``, ``csv``, ``npz`` (see ``app.engine.export.outputs``)."""
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
