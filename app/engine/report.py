"""``report.json`` (SPEC §4): what ran, with which models and prompts, how long, what it found."""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from pydantic import BaseModel, Field

from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import scale_context

REPORT_VERSION = 1


class AssetSummary(BaseModel):
    name: str
    urdf_file: str
    content_hash: str
    links: list[str]
    visual_links: list[str]
    movable_joints: list[str]
    object_bbox_extents_m: tuple[float, float, float]
    object_diag_m: float
    warnings: list[str] = Field(default_factory=list)

    @classmethod
    def of(cls, asset: ArticulatedAsset) -> AssetSummary:
        scale = scale_context(asset)
        return cls(
            name=asset.name,
            urdf_file=asset.urdf_file,
            content_hash=asset.content_hash,
            links=list(asset.link_order),
            visual_links=list(asset.visual_links),
            movable_joints=list(asset.movable_joints),
            object_bbox_extents_m=scale.object_bbox_extents_m,
            object_diag_m=scale.object_diag_m,
            warnings=list(asset.warnings),
        )


class TokenUsage(BaseModel):
    input_tokens: int = 0
    output_tokens: int = 0


class RoleCall(BaseModel):
    """One call of a role (perceiver, planner, critic) to its model."""

    role: str
    provider: str
    model: str
    prompt_version: str | None = None
    input_sha256: str | None = None
    attempts: int = 1
    seconds: float = 0.0
    usage: TokenUsage = Field(default_factory=TokenUsage)
    error: str | None = None


class CriticRound(BaseModel):
    """One critic-actor round: what the critic found and what the actor changed."""

    index: int
    issues: list[dict[str, Any]] = Field(default_factory=list)
    patches: list[dict[str, Any]] = Field(default_factory=list)
    score: float | None = None
    accepted: bool = False


class StageTiming(BaseModel):
    stage: str
    seconds: float


class RunReport(BaseModel):
    report_version: int = REPORT_VERSION
    asset: AssetSummary
    prompt: str | None = None
    provider: str | None = None
    models: dict[str, str] = Field(default_factory=dict)
    prompt_versions: dict[str, str] = Field(default_factory=dict)
    role_calls: list[RoleCall] = Field(default_factory=list)
    critic_rounds: list[CriticRound] = Field(default_factory=list)
    final_state: str | None = None
    warnings: list[str] = Field(default_factory=list)
    understanding: list[dict[str, Any]] = Field(default_factory=list)
    """Per prompt clause, what the agent understood: words -> link/joint, goal, what it is measured from, order, why."""
    events: list[str] = Field(default_factory=list)
    stages: list[StageTiming] = Field(default_factory=list)
    total_s: float = 0.0
    outputs: dict[str, str] = Field(default_factory=dict)


class StageClock:
    """Collects wall time per named stage."""

    def __init__(self) -> None:
        self.stages: list[StageTiming] = []
        self._start = time.perf_counter()

    @contextmanager
    def stage(self, name: str) -> Iterator[None]:
        began = time.perf_counter()
        try:
            yield
        finally:
            self.stages.append(StageTiming(stage=name, seconds=round(time.perf_counter() - began, 6)))

    @property
    def total(self) -> float:
        return round(time.perf_counter() - self._start, 6)
