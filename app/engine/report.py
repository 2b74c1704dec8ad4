"""``report.json`` (SPEC §4): what ran, with which models and prompts, how long, what it found."""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from app.engine.agents.critique import Issue, Patch
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import scale_context
from app.engine.execute.events import ExecutionEvent

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

    def __add__(self, other: TokenUsage) -> TokenUsage:
        return TokenUsage(input_tokens=self.input_tokens + other.input_tokens, output_tokens=self.output_tokens + other.output_tokens)


TransportOutcome = Literal["ok", "rate_limited", "quota", "server_error", "client_error", "timeout", "network", "unreadable"]


class TransportAttempt(BaseModel):
    """One HTTP request of a model call (a call retries these on 429 / 5xx / timeouts)."""

    attempt: int
    outcome: TransportOutcome
    status: int | None = None
    """HTTP status; None when no answer came (timeout, network error)."""
    seconds: float = 0.0
    error: str | None = None
    """What went wrong, with any key masked."""
    retry_after_s: float | None = None


class RoleCall(BaseModel):
    """One call of a role (perceiver, planner, critic, coverage) to its model: one reply, valid or not.

    ``attempts`` is the role-level attempt number (a reply that fails validation is sent
    back and counts as one attempt); ``transport`` lists the HTTP requests behind this one
    reply, retries included.
    """

    role: str
    provider: str
    model: str
    prompt_version: str | None = None
    input_sha256: str | None = None
    attempts: int = 1
    seconds: float = 0.0
    usage: TokenUsage = Field(default_factory=TokenUsage)
    error: str | None = None
    finish_reason: str | None = None
    output_mode: str | None = None
    """How structured output was asked for: ``json_schema``, ``json_object`` or ``text``."""
    transport: list[TransportAttempt] = Field(default_factory=list)
    est_cost_usd: float | None = None
    """Estimated from the model's list price per token (None when the price is unknown)."""


class RoleUsage(BaseModel):
    """Sum over one role's calls."""

    calls: int = 0
    failed_calls: int = 0
    transport_retries: int = 0
    input_tokens: int = 0
    output_tokens: int = 0
    seconds: float = 0.0
    est_cost_usd: float | None = None


def usage_by_role(calls: list[RoleCall]) -> dict[str, RoleUsage]:
    """Per role: calls, failures, retries, tokens, time and estimated cost (None if any call's price is unknown)."""
    out: dict[str, RoleUsage] = {}
    for role in dict.fromkeys(call.role for call in calls):
        mine = [call for call in calls if call.role == role]
        costs = [call.est_cost_usd for call in mine]
        out[role] = RoleUsage(
            calls=len(mine),
            failed_calls=sum(call.error is not None for call in mine),
            transport_retries=sum(max(0, len(call.transport) - 1) for call in mine),
            input_tokens=sum(call.usage.input_tokens for call in mine),
            output_tokens=sum(call.usage.output_tokens for call in mine),
            seconds=round(sum(call.seconds for call in mine), 6),
            est_cost_usd=None if any(c is None for c in costs) else round(sum(c for c in costs if c is not None), 6),
        )
    return out


class CriticRound(BaseModel):
    """One critic-actor round: what the critic found and what the actor changed."""

    index: int
    critic: str | None = None
    """``provider:model`` of the critic that answered."""
    issues: list[Issue] = Field(default_factory=list)
    patches: list[Patch] = Field(default_factory=list)
    rejected_patches: list[Patch] = Field(default_factory=list)
    """Patches not applied because they would undo an earlier one (the loop stopped)."""
    score: float | None = None
    accepted: bool = False
    error: str | None = None
    """Why the critic gave no verdict this round."""


class CoverageChoice(BaseModel):
    """The view chosen for one moving link (supplementary §2.3)."""

    model_config = ConfigDict(frozen=True)

    link: str
    azimuth_deg: float
    elevation_deg: float
    distance_scale: float
    fov_deg: float
    visible_px: int = 0
    source: str = "geometric"
    """``geometric`` (visible pixels over the motion) or ``model``."""


class StageTiming(BaseModel):
    stage: str
    seconds: float


class RunReport(BaseModel):
    report_version: int = REPORT_VERSION
    asset: AssetSummary | None = None
    """None only when the asset itself could not be loaded (see ``error``)."""
    prompt: str | None = None
    provider: str | None = None
    models: dict[str, str] = Field(default_factory=dict)
    prompt_versions: dict[str, str] = Field(default_factory=dict)
    role_calls: list[RoleCall] = Field(default_factory=list)
    usage_by_role: dict[str, RoleUsage] = Field(default_factory=dict)
    fallbacks: dict[str, str] = Field(default_factory=dict)
    """Role -> why the offline role stood in for the model."""
    images: bool = False
    """Whether the model roles were shown rendered images."""
    coverage: list[CoverageChoice] = Field(default_factory=list)
    critic_rounds: list[CriticRound] = Field(default_factory=list)
    final_state: str | None = None
    error: str | None = None
    error_kind: str | None = None
    warnings: list[str] = Field(default_factory=list)
    understanding: list[dict[str, Any]] = Field(default_factory=list)
    """Per prompt clause, what the agent understood: words -> link/joint, goal, what it is measured from, order, why."""
    events: list[str] = Field(default_factory=list)
    """Readable execution notes (the messages of ``execution_events``)."""
    execution_events: list[ExecutionEvent] = Field(default_factory=list)
    stages: list[StageTiming] = Field(default_factory=list)
    total_s: float = 0.0
    outputs: dict[str, str] = Field(default_factory=dict)

    def add_calls(self, calls: list[RoleCall] | tuple[RoleCall, ...]) -> None:
        """Record model calls: the list, the prompt version per role and the per-role sums."""
        self.role_calls.extend(calls)
        for call in calls:
            if call.prompt_version:
                self.prompt_versions.setdefault(call.role, call.prompt_version)
        self.usage_by_role = usage_by_role(self.role_calls)


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
