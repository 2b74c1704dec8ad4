"""Benchmark annotation -> ground-truth plan -> GT trajectory -> K key states (SPEC §5).

Schedule: phases run in ``order`` (ties keep file order), each for its ``duration_s``.
A phase starts when its predecessor ends, except where a relation from the predecessor
says ``overlap_allowed: true``: then it starts when the predecessor reaches
``start_rule.progress`` (default 0.2) of its duration. A non-overlapping relation from an
earlier, non-adjacent phase additionally keeps the phase from starting before that
phase ends.

Times are counted in frames of the GT grid (``GT_FPS``): every duration and start offset
is rounded half-up to a whole frame (at most half a frame, 16.7 ms, of error), so every
phase end is a frame of the GT trajectory and a prediction that reproduces the GT
animation contains every key state exactly.

Constraints become controls: ``target_q`` -> ``joint_position`` (ease_in_out);
``omega_radps`` -> ``joint_velocity`` (constant); ``displacement_m`` on ``base`` ->
``base_velocity`` of that length over the phase; ``return_mode: self_return`` ->
``joint_position`` back to ``rest_position_q`` (default: the joint's rest value). When a
constraint gives several of these, ``self_return`` wins over ``target_q`` over
``omega_radps`` (the ignored fields are listed in ``GroundTruth.notes``).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Any

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import ExecutionError, MetricError, PlanValidationError
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.metrics.annotation import DEFAULT_START_PROGRESS, Case, Constraint, Phase
from app.engine.metrics.subjects import Subject, moved_links, resolve_subject
from app.engine.plan.checks import parse_document
from app.engine.plan.schema import (
    MAX_BASE_SPEED_MPS,
    MAX_DURATION_S,
    MAX_OMEGA_RADPS,
    MAX_TIMELINE_S,
    MIN_DURATION_S,
    Plan,
)

GT_FPS = 30
"""Frame rate of the ground-truth plan and trajectory."""
ROUND_EPS = 1e-9
"""Added before rounding seconds to frames so 0.15 s x 30 (4.4999...) rounds like 4.5."""
GT_CURVE = "ease_in_out"
MAX_GT_FRAMES = round(MAX_TIMELINE_S * GT_FPS)


@dataclass(frozen=True)
class PhaseTiming:
    """Where one phase sits on the GT frame grid (``end_frame`` is its key frame)."""

    phase: str
    order_index: int
    start_frame: int
    end_frame: int


@dataclass(frozen=True)
class KeyState:
    """One GT key state: the GT trajectory's state at a phase's end frame."""

    index: int
    phase: str
    phase_index: int
    frame: int
    time_s: float
    constrained_joints: tuple[str, ...]
    base_constrained: bool
    dynamic_links: tuple[str, ...]
    """Visual links moved by the phase's subjects (all visual links when ``base`` is one)."""


@dataclass(frozen=True, eq=False)
class GroundTruth:
    """A compiled case.

    ``allow_equal[k]`` says whether key states ``k`` and ``k + 1`` may be matched to the
    same predicted frame (their phases end on the same frame, or a relation between them
    has ``overlap_allowed``).
    """

    case_id: str
    asset_name: str
    plan: Plan
    trajectory: Trajectory
    timings: tuple[PhaseTiming, ...]
    key_states: tuple[KeyState, ...]
    allow_equal: tuple[bool, ...]
    notes: tuple[str, ...]


def seconds_to_frames(seconds: float) -> int:
    """Whole GT frames in ``seconds`` (rounded half up)."""
    return math.floor(seconds * GT_FPS + 0.5 + ROUND_EPS)


def _positions(case: Case, ordered: list[Phase]) -> dict[str, int]:
    index = {phase.id: i for i, phase in enumerate(ordered)}
    for number, relation in enumerate(case.relations):
        if index[relation.from_phase] >= index[relation.to_phase]:
            raise MetricError(
                f"case {case.case_id}: relations[{number}]: from_phase '{relation.from_phase}' must come before "
                f"to_phase '{relation.to_phase}' in phase order"
            )
    return index


def _start_frame(case: Case, previous: Phase, previous_timing: PhaseTiming, phase: Phase) -> int:
    """Predecessor's end, or its start + progress x duration under an overlapping relation."""
    for relation in case.relations:
        if relation.overlap_allowed and relation.from_phase == previous.id and relation.to_phase == phase.id:
            progress = DEFAULT_START_PROGRESS if relation.start_rule is None else relation.start_rule.progress
            return previous_timing.start_frame + seconds_to_frames(progress * previous.duration_s)
    return previous_timing.end_frame


def schedule(case: Case) -> tuple[PhaseTiming, ...]:
    """Start and end frame of every phase, in phase order.

    Raises
    ------
    MetricError
        A relation runs against the phase order, or the schedule is longer than
        ``MAX_TIMELINE_S``.
    """
    ordered = case.ordered_phases()
    index = _positions(case, ordered)
    timings: list[PhaseTiming] = []
    for i, phase in enumerate(ordered):
        length = max(1, seconds_to_frames(phase.duration_s))
        start = 0 if i == 0 else _start_frame(case, ordered[i - 1], timings[i - 1], phase)
        for relation in case.relations:
            if relation.to_phase == phase.id and not relation.overlap_allowed:
                start = max(start, timings[index[relation.from_phase]].end_frame)
        timings.append(PhaseTiming(phase=phase.id, order_index=i, start_frame=start, end_frame=start + length))
    total = max(t.end_frame for t in timings)
    if total > MAX_GT_FRAMES:
        raise MetricError(f"case {case.case_id}: phases run for {total / GT_FPS:.2f} s, more than {MAX_TIMELINE_S:g} s")
    return tuple(timings)


def _base_control(case: Case, number: int, constraint: Constraint, seconds: float) -> dict[str, Any] | None:
    fields = constraint.constraints
    where = f"case {case.case_id}: constraints[{number}].constraints"
    for name in ("target_q", "omega_radps", "return_mode"):
        if getattr(fields, name) is not None:
            raise MetricError(
                f"{where}.{name}: the base has no joint value (use displacement_m with direction_axis_world)"
            )
    if fields.displacement_m is None:
        return None
    axis = fields.direction_axis_world
    if axis is None or math.sqrt(sum(a * a for a in axis)) < 1e-9:
        raise MetricError(f"{where}.direction_axis_world: a non-zero axis is required with displacement_m")
    speed = fields.displacement_m / seconds
    if abs(speed) > MAX_BASE_SPEED_MPS:
        raise MetricError(
            f"{where}.displacement_m: {fields.displacement_m} m in {seconds:.3f} s exceeds {MAX_BASE_SPEED_MPS} m/s"
        )
    return {"mode": "base_velocity", "axis_world": list(axis), "v_mps": speed}


def _joint_control(
    case: Case, asset: ArticulatedAsset, number: int, constraint: Constraint, joint: str, notes: list[str]
) -> dict[str, Any] | None:
    fields = constraint.constraints
    where = f"case {case.case_id}: constraints[{number}].constraints"
    if fields.displacement_m is not None:
        raise MetricError(f"{where}.displacement_m: applies to 'base' only; use target_q for joint '{joint}'")
    drives = [n for n in ("return_mode", "target_q", "omega_radps") if getattr(fields, n) is not None]
    if not drives:
        return None
    spec = asset.joints[joint]
    if not spec.movable:
        raise MetricError(f"{where}.{drives[0]}: joint '{joint}' (subject '{constraint.subject}') is fixed")
    if spec.mimic is not None:
        raise MetricError(
            f"{where}.{drives[0]}: joint '{joint}' mimics '{spec.mimic.joint}'; constrain '{spec.mimic.joint}' instead"
        )
    if len(drives) > 1:
        notes.append(f"constraints[{number}]: {', '.join(drives[1:])} ignored because {drives[0]} is given")
    if drives[0] == "return_mode":
        rest = spec.rest if fields.rest_position_q is None else fields.rest_position_q
        return {"mode": "joint_position", "joint": joint, "q_target_rad": rest, "curve": GT_CURVE}
    if drives[0] == "target_q":
        return {"mode": "joint_position", "joint": joint, "q_target_rad": fields.target_q, "curve": GT_CURVE}
    omega = float(fields.omega_radps)  # type: ignore[arg-type]
    if abs(omega) > MAX_OMEGA_RADPS:
        raise MetricError(f"{where}.omega_radps: {omega} exceeds the {MAX_OMEGA_RADPS} rad/s limit")
    return {"mode": "joint_velocity", "joint": joint, "omega_radps": omega}


@dataclass
class _PhaseWork:
    controls: list[dict[str, Any]]
    joints: set[str]
    base: bool


def _phase_work(
    case: Case, asset: ArticulatedAsset, timings: dict[str, PhaseTiming], notes: list[str]
) -> dict[str, _PhaseWork]:
    work = {t.phase: _PhaseWork(controls=[], joints=set(), base=False) for t in timings.values()}
    for number, constraint in enumerate(case.constraints):
        subject: Subject = resolve_subject(
            asset, constraint.subject, f"case {case.case_id}: constraints[{number}].subject"
        )
        timing = timings[constraint.phase]
        entry = work[constraint.phase]
        seconds = (timing.end_frame - timing.start_frame) / GT_FPS
        if subject.joint is None:
            entry.base = True
            control = _base_control(case, number, constraint, seconds)
        else:
            entry.joints.add(subject.joint)
            control = _joint_control(case, asset, number, constraint, subject.joint, notes)
        if control is not None:
            entry.controls.append(control)
    return work


def _plan(case: Case, timings: tuple[PhaseTiming, ...], work: dict[str, _PhaseWork]) -> Plan:
    total = max(t.end_frame for t in timings) / GT_FPS
    segments = [
        {
            "name": t.phase,
            "phase_type": "effect_motion" if work[t.phase].controls else "hold",
            "t0": t.start_frame / GT_FPS,
            "t1": t.end_frame / GT_FPS,
            "controls": work[t.phase].controls,
        }
        for t in timings
    ]
    document = {
        "meta": {"fps": GT_FPS, "duration_s": min(max(total, MIN_DURATION_S), MAX_DURATION_S), "case_id": case.case_id},
        "timeline": segments,
    }
    try:
        return parse_document(Plan, document, f"ground-truth plan of case {case.case_id}")
    except PlanValidationError as exc:
        raise MetricError(exc.message) from exc


def _key_states(
    asset: ArticulatedAsset, timings: tuple[PhaseTiming, ...], work: dict[str, _PhaseWork]
) -> tuple[KeyState, ...]:
    visual = asset.visual_links
    ordered = sorted(timings, key=lambda t: (t.end_frame, t.order_index))
    states = []
    for index, timing in enumerate(ordered):
        entry = work[timing.phase]
        moved = set(visual) if entry.base else moved_links(asset, entry.joints)
        states.append(
            KeyState(
                index=index,
                phase=timing.phase,
                phase_index=timing.order_index,
                frame=timing.end_frame,
                time_s=timing.end_frame / GT_FPS,
                constrained_joints=tuple(j for j in asset.joint_order if j in entry.joints),
                base_constrained=entry.base,
                dynamic_links=tuple(n for n in visual if n in moved),
            )
        )
    return tuple(states)


def _allow_equal(case: Case, states: tuple[KeyState, ...]) -> tuple[bool, ...]:
    overlapping = {frozenset((r.from_phase, r.to_phase)) for r in case.relations if r.overlap_allowed}
    return tuple(
        a.frame == b.frame or frozenset((a.phase, b.phase)) in overlapping for a, b in itertools.pairwise(states)
    )


def compile_case(case: Case, asset: ArticulatedAsset) -> GroundTruth:
    """Compile ``case`` against ``asset`` and execute it with the engine's executor.

    Raises
    ------
    MetricError
        The annotation does not fit the asset (unknown subject, fixed or mimic joint
        driven, base given a joint value, speeds over the plan limits, relation against
        the phase order, ...); the message names the case and the field.
    """
    if not asset.visual_links:
        raise MetricError(f"case {case.case_id}: asset {asset.name} has no link with visual geometry")
    notes: list[str] = []
    timings = schedule(case)
    by_phase = {t.phase: t for t in timings}
    work = _phase_work(case, asset, by_phase, notes)
    plan = _plan(case, timings, work)
    try:
        trajectory = execute(plan, asset)
    except (PlanValidationError, ExecutionError) as exc:
        raise MetricError(f"case {case.case_id}: the ground-truth plan does not execute: {exc.message}") from exc
    notes.extend(trajectory.event_messages)
    states = _key_states(asset, timings, work)
    return GroundTruth(
        case_id=case.case_id,
        asset_name=asset.name,
        plan=plan,
        trajectory=trajectory,
        timings=timings,
        key_states=states,
        allow_equal=_allow_equal(case, states),
        notes=tuple(notes),
    )
