"""Inject one known failure into a correct plan (the paper's critic test, supplementary §4.2).

The correct plan is the case's ground-truth plan (the annotation compiled, SPEC §5); the
critic gets the correct expectations (from the same annotation) and the corrupted
execution, never the ground-truth animation. One injection per class and case, on the
first motion where the class can be made visible:

- ``WRONG_DIRECTION``: a motion mirrored about its start (needs room on the other side
  within the limits), or a spin reversed;
- ``MOTION_TOO_SMALL``: 40 % of a motion (or of a spin speed);
- ``EXCESSIVE_MOTION``: 160 % of a motion (needs room past the target within the limits),
  or of a spin speed;
- ``UNEXPECTED_EXTRA_MOTION``: a joint nobody asked to move turned by 30 % of its range;
- ``NO_RELEASE_RETURN``: a control that should spring back comes back only 30 % of the way.

A class that cannot be made on a case (a door at its lower limit cannot open the wrong
way; a case without a returning control) is recorded as not applicable.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from app.engine.agents.expectations import Expectations, ExpectedMotion
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.metrics.annotation import Case
from app.engine.metrics.compiler import GroundTruth
from app.engine.metrics.subjects import resolve_subject
from app.engine.plan.checks import resolve_target
from app.engine.plan.schema import HoldPosition, JointPosition, JointVelocity, Plan

CLASSES = ("WRONG_DIRECTION", "MOTION_TOO_SMALL", "EXCESSIVE_MOTION", "UNEXPECTED_EXTRA_MOTION", "NO_RELEASE_RETURN")
SMALL_FACTOR = 0.4
LARGE_FACTOR = 1.6
EXTRA_FRACTION = 0.3
RETURN_FRACTION = 0.3
MIN_VISIBLE = {"revolute": 0.08, "continuous": 0.08, "prismatic": 0.01}
"""Smallest change (rad / m) an injection must make to count as visible."""


@dataclass(frozen=True)
class Injection:
    code: str
    joint: str
    segment_index: int
    description: str
    plan: Plan


def expectations_from_case(case: Case, asset: ArticulatedAsset) -> Expectations:
    """The correct expectations of ``case``: each constrained joint's target / speed, in phase order."""
    order = {phase.id: index for index, phase in enumerate(case.ordered_phases())}
    motions: list[ExpectedMotion] = []
    base = False
    for constraint in sorted(case.constraints, key=lambda c: order[c.phase]):
        subject = resolve_subject(asset, constraint.subject, f"case {case.case_id}")
        fields = constraint.constraints
        if subject.joint is None:
            base = base or fields.displacement_m is not None
            continue
        joint = asset.joints[subject.joint]
        step = order[constraint.phase]
        if fields.return_mode == "self_return":
            earlier = [i for i, m in enumerate(motions) if m.joint == joint.name]
            if earlier:
                motions[earlier[-1]] = replace(motions[earlier[-1]], returns_to_rest=True, role="control")
                continue
            rest = joint.rest if fields.rest_position_q is None else fields.rest_position_q
            motions.append(ExpectedMotion(joint=joint.name, link=joint.child, step=step, role="direct", target=joint.clamp(rest)))
        elif fields.target_q is not None:
            motions.append(ExpectedMotion(joint=joint.name, link=joint.child, step=step, role="direct", target=joint.clamp(fields.target_q)))
        elif fields.omega_radps is not None:
            motions.append(ExpectedMotion(joint=joint.name, link=joint.child, step=step, role="direct", omega=fields.omega_radps))
    return Expectations(motions=tuple(motions), base_motion=base)


def _start(trajectory: Trajectory, joint: str, time: float) -> float:
    return float(trajectory.joint(joint)[min(round(time * trajectory.fps), trajectory.frame_count - 1)])


def _with_control(plan: Plan, s_index: int, c_index: int, control: JointPosition | JointVelocity | HoldPosition) -> Plan:
    timeline = list(plan.timeline)
    controls = list(timeline[s_index].controls)
    controls[c_index] = control
    timeline[s_index] = timeline[s_index].model_copy(update={"controls": controls})
    return plan.model_copy(update={"timeline": timeline})


def _motions(plan: Plan, asset: ArticulatedAsset, trajectory: Trajectory, expected: Expectations) -> list[tuple[int, int, str, float, float]]:
    """(segment, control, joint, start, target) of each position control that makes an expected first motion."""
    firsts: dict[str, bool] = {}
    found = []
    expected_joints = {m.joint for m in expected.motions}
    for s_index, segment in enumerate(plan.timeline):
        for c_index, control in enumerate(segment.controls):
            if isinstance(control, JointPosition) and control.joint in expected_joints and control.joint not in firsts:
                firsts[control.joint] = True
                start = _start(trajectory, control.joint, segment.t0)
                found.append((s_index, c_index, control.joint, start, asset.joints[control.joint].clamp(resolve_target(control, asset))))
    return found


def _position(truth: GroundTruth, asset: ArticulatedAsset, expected: Expectations, code: str) -> Injection | None:
    for s_index, c_index, joint_name, start, target in _motions(truth.plan, asset, truth.trajectory, expected):
        joint = asset.joints[joint_name]
        delta = target - start
        floor = MIN_VISIBLE[joint.type]
        if abs(delta) < floor:
            continue
        new = {"WRONG_DIRECTION": start - delta, "MOTION_TOO_SMALL": start + SMALL_FACTOR * delta, "EXCESSIVE_MOTION": start + LARGE_FACTOR * delta}[code]
        clamped = joint.clamp(new)
        if code == "WRONG_DIRECTION" and (start - clamped) * delta < 0.5 * delta * delta:
            continue  # no room on the other side: it would only look like a smaller motion
        if code == "EXCESSIVE_MOTION" and abs(clamped - target) < max(floor, 0.25 * abs(delta)):
            continue  # the limit stops it at the target
        control = truth.plan.timeline[s_index].controls[c_index]
        assert isinstance(control, JointPosition)
        patched = control.model_copy(update={"q_target_expr": None, "q_target_rad": round(clamped, 9)})
        text = f"{joint_name} in segment {s_index}: target {target:.4g} -> {clamped:.4g} (start {start:.4g})"
        return Injection(code, joint_name, s_index, text, _with_control(truth.plan, s_index, c_index, patched))
    return _velocity(truth.plan, expected, code)


def _velocity(plan: Plan, expected: Expectations, code: str) -> Injection | None:
    spinning = {m.joint for m in expected.motions if m.omega is not None}
    factor = {"WRONG_DIRECTION": -1.0, "MOTION_TOO_SMALL": SMALL_FACTOR, "EXCESSIVE_MOTION": LARGE_FACTOR}[code]
    for s_index, segment in enumerate(plan.timeline):
        for c_index, control in enumerate(segment.controls):
            if isinstance(control, JointVelocity) and control.joint in spinning and abs(control.omega_radps) > 1e-6:
                omega = max(-20.0, min(20.0, control.omega_radps * factor))
                patched = control.model_copy(update={"omega_radps": omega, "ramp_to_omega_radps": None})
                text = f"{control.joint} in segment {s_index}: omega {control.omega_radps:.4g} -> {omega:.4g} rad/s"
                return Injection(code, control.joint, s_index, text, _with_control(plan, s_index, c_index, patched))
    return None


def _extra(truth: GroundTruth, asset: ArticulatedAsset, expected: Expectations) -> Injection | None:
    busy = expected.joints | {getattr(c, "joint", "") for s in truth.plan.timeline for c in s.controls}
    for name in asset.controllable_joints:
        joint = asset.joints[name]
        if name in busy or joint.mimic is not None or not asset.links[joint.child].has_geometry:
            continue
        if joint.type == "continuous" or joint.lower is None or joint.upper is None:
            value = joint.rest + 0.5
        else:
            span = joint.upper - joint.lower
            up, down = joint.upper - joint.rest, joint.rest - joint.lower
            value = joint.rest + EXTRA_FRACTION * span if up >= down else joint.rest - EXTRA_FRACTION * span
        if abs(value - joint.rest) < MIN_VISIBLE[joint.type]:
            continue
        timeline = list(truth.plan.timeline)
        segment = timeline[0]
        timeline[0] = segment.model_copy(update={"controls": [*segment.controls, JointPosition(mode="joint_position", joint=name, q_target_rad=round(value, 9), curve="ease_in_out")]})
        text = f"{name} (not asked to move) driven to {value:.4g} in segment 0"
        return Injection("UNEXPECTED_EXTRA_MOTION", name, 0, text, truth.plan.model_copy(update={"timeline": timeline}))
    return None


def _no_return(truth: GroundTruth, asset: ArticulatedAsset, expected: Expectations) -> Injection | None:
    returning = [m.joint for m in expected.motions if m.returns_to_rest]
    for joint_name in returning:
        rest = asset.joints[joint_name].rest
        drivers = [(s, c) for s, segment in enumerate(truth.plan.timeline) for c, control in enumerate(segment.controls)
                   if isinstance(control, JointPosition) and control.joint == joint_name]
        if len(drivers) < 2:
            continue
        s_index, c_index = drivers[-1]
        start = _start(truth.trajectory, joint_name, truth.plan.timeline[s_index].t0)
        if abs(start - rest) < MIN_VISIBLE[asset.joints[joint_name].type] / 2:
            continue
        value = start + RETURN_FRACTION * (rest - start)
        control = truth.plan.timeline[s_index].controls[c_index]
        assert isinstance(control, JointPosition)
        patched = control.model_copy(update={"q_target_expr": None, "q_target_rad": round(value, 9)})
        text = f"{joint_name} in segment {s_index}: returns to {value:.4g} instead of rest {rest:.4g}"
        return Injection("NO_RELEASE_RETURN", joint_name, s_index, text, _with_control(truth.plan, s_index, c_index, patched))
    return None


def inject(code: str, truth: GroundTruth, asset: ArticulatedAsset, expected: Expectations) -> Injection | None:
    """The ground-truth plan with one ``code`` failure, or None when the case cannot show it."""
    if code in ("WRONG_DIRECTION", "MOTION_TOO_SMALL", "EXCESSIVE_MOTION"):
        return _position(truth, asset, expected, code)
    if code == "UNEXPECTED_EXTRA_MOTION":
        return _extra(truth, asset, expected)
    return _no_return(truth, asset, expected)
