"""The actor: apply a critic's bounded hints to a plan, deterministically, parameters only.

One explicit decision per (segment, joint): the hint's type and direction map to one
numeric change (strength factors 1.10 / 1.20 / 1.35 / 2.00, or the hint's measured
``factor`` when the critic gives one, at most 2). Targets are resolved to
numbers (the expression is dropped once the number changes), so every target can be
increased, decreased, flipped or zeroed; results are clamped to the URDF limits. Joint
identity, control mode and the phase graph never change. The plan stays a typed
:class:`Plan` throughout (segments and controls are copied, never dumped to dicts).
"""

from __future__ import annotations

from app.engine.agents.critique import STRENGTH_FACTOR, ChangeKind, Critique, FixHint, Patch
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.checks import resolve_target
from app.engine.plan.schema import MAX_DURATION_S, MAX_OMEGA_RADPS, JointPosition, JointVelocity, Plan, Segment

MIN_SEGMENT_S = 0.05
SAME = 1e-12


def _value_at(trajectory: Trajectory | None, joint: str, time: float, rest: float) -> float:
    if trajectory is None:
        return rest
    index = min(round(time * trajectory.fps), trajectory.frame_count - 1)
    return float(trajectory.joint(joint)[index])


def _factor(hint: FixHint) -> float:
    return hint.factor if hint.factor is not None else STRENGTH_FACTOR[hint.strength or "medium"]


def _new_target(control: JointPosition, hint: FixHint, asset: ArticulatedAsset, start: float) -> tuple[float, float]:
    """(old target, new target) of a position control under ``hint``."""
    joint = asset.joints[hint.joint]
    target = resolve_target(control, asset)
    delta = target - start
    if hint.direction == "flip":
        new = start - delta
        if abs(joint.clamp(new) - start) < 1e-9 and joint.bounded and joint.lower is not None and joint.upper is not None:
            new = joint.lower if abs(target - joint.upper) < abs(target - joint.lower) else joint.upper
    elif hint.direction == "zero":
        new = start
    elif hint.direction == "increase":
        new = start + delta * _factor(hint) if abs(delta) > 1e-9 else target
    else:
        new = start + delta / _factor(hint)
    return target, joint.clamp(new)


def _scaled_omega(value: float, hint: FixHint) -> float:
    if hint.direction == "flip":
        value = -value
    elif hint.direction == "zero":
        value = 0.0
    elif hint.direction == "increase":
        value *= _factor(hint)
    else:
        value /= _factor(hint)
    return max(-MAX_OMEGA_RADPS, min(MAX_OMEGA_RADPS, round(value, 9))) + 0.0


def _patch_control(
    segment: Segment, where: tuple[int, int], hint: FixHint, asset: ArticulatedAsset, trajectory: Trajectory | None,
) -> tuple[Segment, Patch] | None:
    """The segment with control ``where = (segment index, control index)`` changed by ``hint``, and the record; or None."""
    s_index, index = where
    control = segment.controls[index]
    if isinstance(control, JointPosition) and hint.type in ("adjust_joint_target", "adjust_direction"):
        start = _value_at(trajectory, hint.joint, segment.t0, asset.joints[hint.joint].rest)
        old, new = _new_target(control, hint, asset, start)
        if abs(new - old) < SAME:
            return None
        patched: JointPosition | JointVelocity = control.model_copy(update={"q_target_expr": None, "q_target_rad": round(new, 9) + 0.0})
        change: ChangeKind = "target"
        value_before, value_after = old, round(new, 9) + 0.0
    elif isinstance(control, JointVelocity) and hint.type in ("adjust_joint_velocity", "adjust_direction", "adjust_joint_target"):
        omega = _scaled_omega(control.omega_radps, hint)
        ramp = None if control.ramp_to_omega_radps is None else _scaled_omega(control.ramp_to_omega_radps, hint)
        if omega == control.omega_radps and ramp == control.ramp_to_omega_radps:
            return None
        patched = control.model_copy(update={"omega_radps": omega, "ramp_to_omega_radps": ramp})
        change = "velocity"
        value_before, value_after = control.omega_radps, omega
    else:
        return None
    controls = list(segment.controls)
    controls[index] = patched
    record = Patch(segment_index=s_index, change=change, hint=hint, joint=hint.joint, value_before=value_before,
                   value_after=value_after, before=control, after=patched)
    return segment.model_copy(update={"controls": controls}), record


def _retime(timeline: list[Segment], index: int, hint: FixHint) -> Patch | None:
    """Stretch (or shrink) segment ``index`` in place and shift every segment that starts at or after its end."""
    segment = timeline[index]
    span = segment.t1 - segment.t0
    new_span = max(MIN_SEGMENT_S, span * _factor(hint) if hint.direction == "increase" else span / _factor(hint))
    shift = new_span - span
    if abs(shift) < 1e-9:
        return None
    old_end = segment.t1
    timeline[index] = segment.model_copy(update={"t1": round(segment.t0 + new_span, 6)})
    for other_index, other in enumerate(timeline):
        if other_index != index and other.t0 >= old_end - 1e-9:
            timeline[other_index] = other.model_copy(update={"t0": round(other.t0 + shift, 6), "t1": round(other.t1 + shift, 6)})
    return Patch(segment_index=index, change="timing", hint=hint, value_before=round(span, 6), value_after=round(new_span, 6),
                 span_before=(segment.t0, segment.t1), span_after=(timeline[index].t0, timeline[index].t1))


def repair(plan: Plan, critique: Critique, asset: ArticulatedAsset, trajectory: Trajectory | None = None) -> tuple[Plan, list[Patch]]:
    """The patched plan and a record of each change (empty when nothing applied)."""
    timeline = list(plan.timeline)
    patches: list[Patch] = []
    done: set[tuple[int, str, str]] = set()
    for hint in critique.param_fix_hints:
        key = (hint.segment_index, hint.joint, hint.type)
        if key in done or hint.segment_index >= len(timeline):
            continue
        done.add(key)
        if hint.type == "adjust_timing":
            timed = _retime(timeline, hint.segment_index, hint)
            if timed is not None:
                patches.append(timed)
            continue
        for c_index, control in enumerate(timeline[hint.segment_index].controls):
            if getattr(control, "joint", None) != hint.joint:
                continue
            changed = _patch_control(timeline[hint.segment_index], (hint.segment_index, c_index), hint, asset, trajectory)
            if changed is not None:
                timeline[hint.segment_index], record = changed
                patches.append(record)
    if not patches:
        return plan, []
    duration = min(max(plan.meta.duration_s, max(s.t1 for s in timeline)), MAX_DURATION_S)
    return plan.model_copy(update={"timeline": timeline, "meta": plan.meta.model_copy(update={"duration_s": duration})}), patches
