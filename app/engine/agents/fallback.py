"""Per-role fallback: when a model role gives no usable answer, the offline role stands in.

A model role fails when its replies never validate (:class:`RoleOutputError`) or the
provider fails after its retries (quota, blocks, timeouts: :class:`ProviderError`). With
the role's policy ``offline`` the wrapper answers with the offline role instead, keeps the
failed calls for the report and adds a note; after a critic failure the geometric critic
serves the remaining rounds (the model would most likely fail again). With ``fail`` the
error goes on (the loop keeps the best plan for a critic failure; see :mod:`loop`).
"""

from __future__ import annotations

import logging

from app.engine.agents.expectations import Expectations
from app.engine.agents.roles import Context, Critic, Diagnosed, Perceiver, Perception, Planned, Planner
from app.engine.errors import ProviderError, RenderError, RoleOutputError
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.schema import Plan
from app.engine.report import RoleCall

logger = logging.getLogger(__name__)
RoleFailure = (RoleOutputError, ProviderError, RenderError)
"""What makes a model role give no usable answer (a critic's keyframes that cannot be rendered included)."""


def _failure(role: str, exc: Exception) -> tuple[tuple[RoleCall, ...], str]:
    calls = tuple(c for c in getattr(exc, "calls", ()) if isinstance(c, RoleCall))
    note = f"{role}: the model gave no usable answer ({type(exc).__name__}: {exc}); the offline {role} was used instead"
    logger.warning("%s", note)
    return calls, note


class FallbackPerceiver:
    def __init__(self, primary: Perceiver, backup: Perceiver) -> None:
        self.primary, self.backup = primary, backup
        self.name, self.model = primary.name, primary.model
        self.used: str | None = None

    async def perceive(self, context: Context) -> Perception:
        try:
            return await self.primary.perceive(context)
        except RoleFailure as exc:
            calls, note = _failure("perceiver", exc)
            self.used = note
            result = await self.backup.perceive(context)
            return Perception(causal=result.causal, intent=result.intent, calls=calls + result.calls, notes=(*result.notes, note))


class FallbackPlanner:
    def __init__(self, primary: Planner, backup: Planner) -> None:
        self.primary, self.backup = primary, backup
        self.name, self.model = primary.name, primary.model
        self.used: str | None = None

    async def plan(self, context: Context, perception: Perception) -> Planned:
        try:
            return await self.primary.plan(context, perception)
        except RoleFailure as exc:
            calls, note = _failure("planner", exc)
            self.used = note
            result = await self.backup.plan(context, perception)
            return Planned(plan=result.plan, calls=calls + result.calls, notes=(*result.notes, note))


class FallbackCritic:
    def __init__(self, primary: Critic, backup: Critic) -> None:
        self.primary, self.backup = primary, backup
        self.name, self.model = primary.name, primary.model
        self.used: str | None = None

    async def critique(self, context: Context, expected: Expectations, plan: Plan, trajectory: Trajectory) -> Diagnosed:
        if self.used is None:
            try:
                return await self.primary.critique(context, expected, plan, trajectory)
            except RoleFailure as exc:
                calls, note = _failure("critic", exc)
                self.used = note
                result = await self.backup.critique(context, expected, plan, trajectory)
                return Diagnosed(critique=result.critique, calls=calls + result.calls, notes=(*result.notes, note),
                                 critic=f"{self.backup.name}:{self.backup.model} (fallback)")
        result = await self.backup.critique(context, expected, plan, trajectory)
        return Diagnosed(critique=result.critique, calls=result.calls, notes=result.notes, critic=f"{self.backup.name}:{self.backup.model} (fallback)")


def fallbacks_used(*roles: object) -> dict[str, str]:
    """{role: note} for each wrapper that fell back during the run."""
    names = ("perceiver", "planner", "critic")
    return {name: role.used for name, role in zip(names, roles, strict=False) if isinstance(getattr(role, "used", None), str)}  # type: ignore[attr-defined]
