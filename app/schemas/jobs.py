"""Animation job requests and responses."""

from __future__ import annotations

import uuid
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from app.db.models import JobStatus
from app.engine.providers.names import MODEL_NAME_PATTERN
from app.schemas.common import Name, Text, UtcDatetime

MAX_PROMPT_CHARS = 2000
MAX_MODEL_NAME_CHARS = 200
MAX_PLAN_CHARS = 1_000_000


class JobOptions(BaseModel):
    """How to run a job (all optional; the server's defaults apply)."""

    model_config = ConfigDict(extra="forbid")

    provider: Name | None = Field(default=None, max_length=40, description="offline (default), openai or gemini")
    perceiver_model: Name | None = Field(default=None, min_length=1, max_length=MAX_MODEL_NAME_CHARS, pattern=MODEL_NAME_PATTERN)
    planner_model: Name | None = Field(default=None, min_length=1, max_length=MAX_MODEL_NAME_CHARS, pattern=MODEL_NAME_PATTERN)
    critic_model: Name | None = Field(default=None, min_length=1, max_length=MAX_MODEL_NAME_CHARS, pattern=MODEL_NAME_PATTERN)
    fps: Literal[24, 30] | None = None
    max_critic_rounds: int | None = Field(default=None, ge=0, le=3)
    preview: bool | None = Field(default=None, description="also render preview.gif of the final animation")
    exports: list[str] | None = Field(default=None, description="also write: usd, mjcf, ros, csv, npz (a list, or comma-separated in a form)")

    @field_validator("provider")
    @classmethod
    def _known_provider(cls, value: str | None) -> str | None:
        from app.engine.providers.registry import available_providers

        if value is not None and value not in available_providers():
            raise ValueError(f"unknown provider {value!r} (available: {', '.join(available_providers())})")
        return value

    @field_validator("exports", mode="before")
    @classmethod
    def _known_exports(cls, value: object) -> list[str] | None:
        from app.engine.errors import ExportError
        from app.engine.export.outputs import parse_exports

        if value is None:
            return None
        if not isinstance(value, str | list | tuple) or not all(isinstance(item, str) for item in value):
            raise ValueError("exports must be a list of names or a comma-separated string")
        try:
            return list(parse_exports(value)) or None
        except ExportError as exc:
            raise ValueError(str(exc)) from exc

    def stored(self) -> dict[str, Any]:
        """The options saved with the job (unset ones left out)."""
        return self.model_dump(exclude_none=True)


class JobCreate(JobOptions):
    """The text fields of ``POST /v1/animations`` (the asset comes as file(s) or ``asset_ref``).

    ``prompt`` runs the whole pipeline; ``plan`` (a Plan.json document as JSON text) instead
    runs only the executor and the exporters, and ``prompt`` is then an optional label.
    """

    prompt: Text | None = Field(default=None, min_length=1, max_length=MAX_PROMPT_CHARS)
    plan: Text | None = Field(default=None, min_length=1, max_length=MAX_PLAN_CHARS,
                              description="Plan.json (JSON text) to execute instead of a prompt")

    @field_validator("prompt")
    @classmethod
    def _not_blank(cls, value: str | None) -> str | None:
        if value is not None and not value.strip():
            raise ValueError("the prompt is blank")
        return None if value is None else value.strip()

    @model_validator(mode="after")
    def _prompt_or_plan(self) -> JobCreate:
        if self.prompt is None and self.plan is None:
            raise ValueError("send a 'prompt' (or a 'plan' to execute)")
        return self

    def stored(self) -> dict[str, Any]:
        return self.model_dump(exclude_none=True, exclude={"prompt", "plan"})


class JobAccepted(BaseModel):
    """Answer of ``POST /v1/animations`` (202): poll ``url``."""

    id: uuid.UUID
    url: str
    status: JobStatus


class ArtifactPublic(BaseModel):
    name: str
    url: str
    content_type: str
    size_bytes: int
    sha256: str


class JobPublic(BaseModel):
    id: uuid.UUID
    url: str
    status: JobStatus
    stage: str | None
    progress: int = Field(ge=0, le=100)
    cancel_requested: bool
    prompt: str
    options: dict[str, Any]
    asset_id: uuid.UUID
    batch_id: uuid.UUID | None
    case_id: str | None
    error: str | None
    """The engine's message when the job failed (e.g. the grounding error listing movable parts)."""
    error_kind: str | None
    """The error class (``AssetError``, ``GroundingError``, ``TimeLimitExceeded``, ...)."""
    timings: dict[str, float]
    """Seconds per pipeline stage, plus ``total``."""
    attempts: int
    created_at: UtcDatetime
    started_at: UtcDatetime | None
    finished_at: UtcDatetime | None
    artifacts: list[ArtifactPublic]


class JobsPublic(BaseModel):
    data: list[JobPublic]
    count: int
    """Jobs matching the filter in total (not only on this page)."""
    limit: int
    offset: int
