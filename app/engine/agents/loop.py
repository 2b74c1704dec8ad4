"""The critic-actor refinement loop: bounded, recorded, keeps the best iteration.

Ends in one explicit state: ``accepted`` (no issue left), ``max_iterations``, ``no_patch``
(the actor could not change anything), ``oscillation`` (a patch would undo an earlier one:
the loop would go round in circles), ``critic_failed`` (the critic gave no usable answer:
the best plan so far is kept and every output is still written) or ``no_critic``.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Literal

from app.engine.agents.actor import repair
from app.engine.agents.critique import Critique, Patch
from app.engine.agents.expectations import Expectations
from app.engine.agents.roles import Context, Critic
from app.engine.errors import CancelledError, ProviderError, RenderError, RoleOutputError
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.schema import Plan
from app.engine.report import CoverageChoice, CriticRound, RoleCall

logger = logging.getLogger(__name__)

FinalState = Literal["accepted", "max_iterations", "no_patch", "oscillation", "critic_failed", "no_critic"]


@dataclass
class Refined:
    plan: Plan
    trajectory: Trajectory
    critique: Critique | None
    best_round: int
    state: FinalState
    rounds: list[CriticRound] = field(default_factory=list)
    calls: list[RoleCall] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    """Warnings for the report (critic failures, fallbacks, oscillation)."""
    coverage: list[CoverageChoice] = field(default_factory=list)


def _undoing(patches: list[Patch], history: list[Patch]) -> Patch | None:
    return next((p for p in patches for earlier in history if p.undoes(earlier)), None)


async def refine(
    context: Context,
    expected: Expectations,
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
    best = Refined(plan=current, trajectory=trajectory, critique=None, best_round=0, state="no_critic")
    if critic is None:
        return best
    rounds: list[CriticRound] = []
    calls: list[RoleCall] = []
    notes: list[str] = []
    history: list[Patch] = []
    coverage: dict[str, CoverageChoice] = {}
    state: FinalState = "max_iterations"
    for index in range(max_rounds + 1):
        if should_stop is not None and should_stop():
            raise CancelledError("cancelled during the critic-actor loop")
        try:
            diagnosed = await critic.critique(context, expected, current, trajectory)
        except (RoleOutputError, ProviderError, RenderError) as exc:
            calls.extend(getattr(exc, "calls", ()))
            rounds.append(CriticRound(index=index, critic=f"{critic.name}:{critic.model}", error=str(exc)))
            notes.append(f"critic failed in round {index} ({type(exc).__name__}: {exc}); kept the best plan so far (round {best.best_round})")
            state = "critic_failed"
            break
        calls.extend(diagnosed.calls)
        notes.extend(diagnosed.notes)
        coverage.update((choice.link, choice) for choice in diagnosed.coverage)
        verdict = diagnosed.critique
        score = verdict.score()
        record = CriticRound(index=index, critic=diagnosed.critic or f"{critic.name}:{critic.model}", issues=list(verdict.issues),
                             score=round(score, 6), accepted=verdict.ok)
        rounds.append(record)
        if on_round is not None:
            on_round(index, verdict)
        if best.critique is None or score < best.critique.score():
            best = Refined(plan=current, trajectory=trajectory, critique=verdict, best_round=index, state=state)
        if verdict.ok:
            state = "accepted"
            break
        if index == max_rounds:
            break
        repaired, patches = repair(current, verdict, context.asset, trajectory)
        if not patches:
            state = "no_patch"
            break
        undoing = _undoing(patches, history)
        if undoing is not None:
            record.rejected_patches = patches
            notes.append(f"critic round {index}: the repair of segment {undoing.segment_index} ({undoing.joint or 'timing'}) would undo an "
                         f"earlier patch; stopped with the best plan (round {best.best_round})")
            state = "oscillation"
            break
        record.patches = patches
        history.extend(patches)
        logger.info("critic round %d: %d issues, %d patches", index, len(verdict.issues), len(patches))
        current = repaired
        trajectory = execute(current, context.asset)
    best.state = state
    best.rounds = rounds
    best.calls = calls
    best.notes = notes
    best.coverage = list(coverage.values())
    return best
