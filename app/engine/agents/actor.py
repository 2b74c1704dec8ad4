"""The actor: apply a critic's bounded hints to a plan, deterministically, parameters only.

One explicit decision per (segment, joint): the hint's type and direction map to one
numeric change (strength factors 1.10 / 1.20 / 1.35 / 2.00). Targets are resolved to
numbers (the expression is kept only when the number still equals it), so every target
can be increased, decreased, flipped or zeroed; results are clamped to the URDF limits.
Joint identity, control mode and the phase graph never change.
"""

from __future__ import annotations

from typing import Any

from app.engine.agents.critique import STRENGTH_FACTOR, Critique, FixHint
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.checks import resolve_target
from app.engine.plan.schema import JointPosition, Plan

MIN_SEGMENT_S = 0.05


def _value_at(trajectory: Trajectory | None, joint: str, time: float, rest: float) -> float:
    if trajectory is None:
        return rest
    index = min(round(time * trajectory.fps), trajectory.frame_count - 1)
    return float(trajectory.joint(joint)[index])


def _patch_position(control: dict[str, Any], hint: FixHint, asset: ArticulatedAsset, start: float) -> dict[str, Any] | None:
    joint = asset.joints[hint.joint]
    target = resolve_target(JointPosition.model_validate(control), asset)
    factor = STRENGTH_FACTOR[hint.strength or "medium"]
    delta = target - start
    if hint.direction == "flip":
        new = start - delta
        if abs(joint.clamp(new) - start) < 1e-9 and joint.bounded and joint.lower is not None and joint.upper is not None:
            new = joint.lower if abs(target - joint.upper) < abs(target - joint.lower) else joint.upper
    elif hint.direction == "zero":
        new = start
    elif hint.direction == "increase":
        new = start + delta * factor if abs(delta) > 1e-9 else target
    else:
        new = start + delta / factor
    new = joint.clamp(new)
    if abs(new - target) < 1e-12:
        return None
    patched = {k: v for k, v in control.items() if k != "q_target_expr"}
    patched["q_target_rad"] = round(new, 9) + 0.0
    return patched


def _patch_velocity(control: dict[str, Any], hint: FixHint) -> dict[str, Any] | None:
    factor = STRENGTH_FACTOR[hint.strength or "medium"]
    patched = dict(control)
    for key in ("omega_radps", "ramp_to_omega_radps"):
        if patched.get(key) is None:
            continue
        value = float(patched[key])
        if hint.direction == "flip":
            value = -value
        elif hint.direction == "zero":
            value = 0.0
        elif hint.direction == "increase":
            value *= factor
        else:
            value /= factor
        patched[key] = max(-20.0, min(20.0, round(value, 9))) + 0.0
    return patched if patched != control else None


def _retime(timeline: list[dict[str, Any]], index: int, hint: FixHint) -> bool:
    """Stretch (or shrink) segment ``index`` and shift every segment that starts at or after its end."""
    segment = timeline[index]
    factor = STRENGTH_FACTOR[hint.strength or "medium"]
    t0, t1 = float(segment["t0"]), float(segment["t1"])
    span = t1 - t0
    new_span = max(MIN_SEGMENT_S, span * factor if hint.direction == "increase" else span / factor)
    shift = new_span - span
    if abs(shift) < 1e-9:
        return False
    segment["t1"] = round(t0 + new_span, 6)
    for other_index, other in enumerate(timeline):
        if other_index != index and float(other["t0"]) >= t1 - 1e-9:
            other["t0"] = round(float(other["t0"]) + shift, 6)
            other["t1"] = round(float(other["t1"]) + shift, 6)
    return True


def repair(plan: Plan, critique: Critique, asset: ArticulatedAsset, trajectory: Trajectory | None = None) -> tuple[Plan, list[dict[str, Any]]]:
    """The patched plan and a record of each change (empty when nothing applied)."""
    document = plan.model_dump(exclude_none=True)
    timeline: list[dict[str, Any]] = document["timeline"]
    patches: list[dict[str, Any]] = []
    done: set[tuple[int, str, str]] = set()
    for hint in critique.param_fix_hints:
        key = (hint.segment_index, hint.joint, hint.type)
        if key in done or hint.segment_index >= len(timeline):
            continue
        done.add(key)
        segment = timeline[hint.segment_index]
        if hint.type == "adjust_timing":
            if _retime(timeline, hint.segment_index, hint):
                patches.append({"segment_index": hint.segment_index, "change": "timing", "direction": hint.direction, "strength": hint.strength, "why": hint.why})
            continue
        for c_index, control in enumerate(segment["controls"]):
            if control.get("joint") != hint.joint:
                continue
            before = dict(control)
            if control["mode"] == "joint_position" and hint.type in ("adjust_joint_target", "adjust_direction"):
                start = _value_at(trajectory, hint.joint, float(segment["t0"]), asset.joints[hint.joint].rest)
                patched = _patch_position(control, hint, asset, start)
            elif control["mode"] == "joint_velocity" and hint.type in ("adjust_joint_velocity", "adjust_direction", "adjust_joint_target"):
                patched = _patch_velocity(control, hint)
            else:
                continue
            if patched is not None:
                segment["controls"][c_index] = patched
                patches.append({"segment_index": hint.segment_index, "joint": hint.joint, "before": before, "after": patched, "hint": hint.model_dump()})
    document["meta"]["duration_s"] = min(max(document["meta"]["duration_s"], max(float(s["t1"]) for s in timeline)), 8.0)
    return Plan.model_validate(document), patches
