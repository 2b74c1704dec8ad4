"""Role interfaces shared by every provider (offline rules, OpenAI-compatible, Gemini).

Each role is an object with one async method; the pipeline does not know which
provider is behind it. A role returns its result plus the :class:`RoleCall` records of
the model calls it made (none for the offline agent's rules).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Protocol

from app.engine.agents.critique import Critique
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import JointSummary, ScaleContext
from app.engine.config import EngineConfig
from app.engine.contracts.causal import CausalDocument
from app.engine.execute.trajectory import Trajectory
from app.engine.offline.intent import Intent
from app.engine.plan.schema import Plan
from app.engine.report import RoleCall


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


@dataclass(frozen=True)
class Perception:
    causal: CausalDocument
    intent: Intent
    """The resolved steps of ``causal``'s contract (what the planner schedules and the critic checks)."""
    calls: tuple[RoleCall, ...] = ()
    understanding: tuple[dict[str, Any], ...] = ()
    """Per clause, what was understood (the offline perceiver's explanation)."""


@dataclass(frozen=True)
class Planned:
    plan: Plan
    calls: tuple[RoleCall, ...] = ()


@dataclass(frozen=True)
class Diagnosed:
    critique: Critique
    calls: tuple[RoleCall, ...] = ()


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

    async def critique(self, context: Context, perception: Perception, plan: Plan, trajectory: Trajectory) -> Diagnosed: ...


@dataclass(frozen=True)
class Roles:
    provider: str
    perceiver: Perceiver
    planner: Planner
    critic: Critic
    closers: tuple[Any, ...] = ()
    """Model clients to close (``aclose()``) when the run ends."""

    async def aclose(self) -> None:
        for closer in self.closers:
            await closer.aclose()
