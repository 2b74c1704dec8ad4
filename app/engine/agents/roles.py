"""Role interfaces shared by every provider (offline rules, OpenAI-compatible, Gemini).

Each role is an object with one async method; the pipeline does not know which
provider is behind it. A role returns its result plus the :class:`RoleCall` records of
the model calls it made (none for the offline agent's rules).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

from app.engine.agents.critique import Critique
from app.engine.agents.expectations import Expectations
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import JointSummary, ScaleContext
from app.engine.config import EngineConfig
from app.engine.contracts.causal import CausalDocument
from app.engine.execute.trajectory import Trajectory
from app.engine.offline.intent import Intent
from app.engine.plan.schema import Plan
from app.engine.report import CoverageChoice, RoleCall


@dataclass(frozen=True, eq=False)
class Context:
    """What every role may look at."""

    asset: ArticulatedAsset
    prompt: str
    joint_summary: list[JointSummary]
    scale: ScaleContext
    config: EngineConfig
    images: dict[str, bytes] = field(default_factory=dict)
    """PNG images by name (reference/overlay views) when rendering is on."""
    render: bool = False
    """Whether to render images for the model roles (critic keyframes, coverage views)."""
    keyframe_dir: Path | None = None
    """Where the critic's keyframes are saved (``round_NN_<name>.png``); None keeps them in memory only."""


@dataclass(frozen=True)
class Perception:
    causal: CausalDocument
    intent: Intent
    """The resolved steps of ``causal``'s contract (what the planner schedules and the critic checks)."""
    calls: tuple[RoleCall, ...] = ()
    understanding: tuple[dict[str, Any], ...] = ()
    """Per clause, what was understood (the offline perceiver's explanation)."""
    notes: tuple[str, ...] = ()
    """Warnings for the report (e.g. a fallback to the offline perceiver)."""


@dataclass(frozen=True)
class Planned:
    plan: Plan
    calls: tuple[RoleCall, ...] = ()
    notes: tuple[str, ...] = ()


@dataclass(frozen=True)
class Diagnosed:
    critique: Critique
    calls: tuple[RoleCall, ...] = ()
    notes: tuple[str, ...] = ()
    critic: str | None = None
    """Which critic answered (``provider:model``), when it is not the role's own (a fallback)."""
    coverage: tuple[CoverageChoice, ...] = ()
    """The view chosen for each link the critic looked at (empty without images)."""


class Perceiver(Protocol):
    name: str
    model: str

    async def perceive(self, context: Context) -> Perception: ...


class Planner(Protocol):
    name: str
    model: str

    async def plan(self, context: Context, perception: Perception) -> Planned: ...


class Critic(Protocol):
    name: str
    model: str

    async def critique(self, context: Context, expected: Expectations, plan: Plan, trajectory: Trajectory) -> Diagnosed: ...


@dataclass(frozen=True)
class Roles:
    provider: str
    perceiver: Perceiver
    planner: Planner
    critic: Critic
    closers: tuple[Any, ...] = ()
    """Model clients to close (``aclose()``) when the run ends."""
    vision: tuple[str, ...] = ()
    """Roles that look at images (a model perceiver or critic): rendering is on by default for them."""

    async def aclose(self) -> None:
        for closer in self.closers:
            await closer.aclose()
