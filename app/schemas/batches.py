"""Batches: many (asset, prompt) cases submitted at once."""

from __future__ import annotations

import uuid

from pydantic import BaseModel, ConfigDict, Field

from app.db.models import JobStatus
from app.schemas.common import Name, Text, UtcDatetime
from app.schemas.jobs import MAX_PROMPT_CHARS, ArtifactPublic, JobOptions


class BatchCaseCreate(BaseModel):
    model_config = ConfigDict(extra="forbid")

    asset: Name = Field(min_length=1, max_length=100, description="an asset id or sha256 from POST /v1/assets")
    prompt: Text = Field(min_length=1, max_length=MAX_PROMPT_CHARS, pattern=r"\S")
    case_id: Name | None = Field(default=None, min_length=1, max_length=200)
    options: JobOptions | None = None
    """Overrides the batch's options for this case."""


class BatchCreate(BaseModel):
    model_config = ConfigDict(extra="forbid")

    name: Name | None = Field(default=None, max_length=200)
    options: JobOptions = Field(default_factory=JobOptions)
    cases: list[BatchCaseCreate] = Field(min_length=1)


class BatchCasePublic(BaseModel):
    case_id: str | None
    job_id: uuid.UUID
    url: str
    status: JobStatus
    stage: str | None
    progress: int
    error: str | None
    error_kind: str | None
    artifacts: list[ArtifactPublic]


class BatchPublic(BaseModel):
    id: uuid.UUID
    url: str
    name: str | None
    created_at: UtcDatetime
    count: int
    status_counts: dict[str, int]
    """Cases per job status."""
    done: bool
    """Every case has finished (succeeded, failed or cancelled)."""
    cases: list[BatchCasePublic]
