"""The critic-actor refinement loop: bounded, recorded, keeps the best iteration."""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Literal

from app.engine.agents.actor import repair
from app.engine.agents.critique import Critique
from app.engine.agents.roles import Context, Critic, Perception
from app.engine.errors import CancelledError
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.schema import Plan
from app.engine.report import CriticRound, RoleCall

logger = logging.getLogger(__name__)

FinalState = Literal["accepted", "max_iterations", "no_patch", "no_critic"]


@dataclass
class Refined:
    plan: Plan
    trajectory: Trajectory
    critique: Critique | None
    best_round: int
    state: FinalState
    rounds: list[CriticRound] = field(default_factory=list)
    calls: list[RoleCall] = field(default_factory=list)


async def refine(
    context: Context,
    perception: Perception,
    plan: Plan,
    critic: Critic | None,
    *,
    max_rounds: int,
    on_round: Callable[[int, Critique], None] | None = None,
    should_stop: Callable[[], bool] | None = None,
) -> Refined:
    """Execute, critique, repair, up to ``max_rounds`` repairs; return the best iteration.

    Raises
    ------
    CancelledError
        When ``should_stop`` says so between rounds.
    """
    current = plan
    trajectory = execute(current, context.asset)
    if critic is None:
        return Refined(plan=current, trajectory=trajectory, critique=None, best_round=0, state="no_critic")
    best: Refined | None = None
    rounds: list[CriticRound] = []
    calls: list[RoleCall] = []
    state: FinalState = "max_iterations"
    for index in range(max_rounds + 1):
        if should_stop is not None and should_stop():
            raise CancelledError("cancelled during the critic-actor loop")
        diagnosed = await critic.critique(context, perception, current, trajectory)
        calls.extend(diagnosed.calls)
        verdict = diagnosed.critique
        score = verdict.score()
        record = CriticRound(index=index, issues=[i.model_dump() for i in verdict.issues], score=round(score, 6), accepted=verdict.ok)
        rounds.append(record)
        if on_round is not None:
            on_round(index, verdict)
        if best is None or score < (best.critique.score() if best.critique else float("inf")):
            best = Refined(plan=current, trajectory=trajectory, critique=verdict, best_round=index, state=state)
        if verdict.ok:
            state = "accepted"
            break
        if index == max_rounds:
            break
        repaired, patches = repair(current, verdict, context.asset, trajectory)
        record.patches = patches
        if not patches:
            state = "no_patch"
            break
        logger.info("critic round %d: %d issues, %d patches", index, len(verdict.issues), len(patches))
        current = repaired
        trajectory = execute(current, context.asset)
    assert best is not None
    best.state = state
    best.rounds = rounds
    best.calls = calls
    return best
