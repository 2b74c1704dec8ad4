"""Offline planner: :class:`Intent` -> Plan.json, following the paper's timeline rules.

control_actuation -> causal_latency (>= 0.05 s for buttons/latches/switches, >= 0.10 s for
spring lids/doors) -> effect_motion; sustaining controls are held while their effect runs,
transient ones return (control_release) while it runs; durations scale with the size of
the motion; fps 30; whole-object motion drives the base and rolls the wheels.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from app.engine.asset.model import ArticulatedAsset
from app.engine.lexicon.kinds import HINGED_KINDS, info
from app.engine.offline.intent import BaseGoal, Intent, JointGoal, Step
from app.engine.plan.schema import MAX_DURATION_S, MIN_DURATION_S, Plan

FPS = 30
FINAL_HOLD_S = 0.3
STEP_GAP_S = 0.05
LATENCY_CONTROL_S = 0.05
LATENCY_SPRING_S = 0.10
BASE_SPEED_MPS = 0.4
QUARTER = math.pi / 2
MAX_PLAN_S = MAX_DURATION_S - FINAL_HOLD_S
YAW_SPEED_RADPS = math.pi / 2 / 1.2
"""A quarter turn of the whole object takes 1.2 s."""
MAX_WHEEL_OMEGA = 19.5
"""Wheel speed cap (rad/s), just under the contract's 20."""
DIGITS = 4
TARGET_DIGITS = 9


def _r(value: float) -> float:
    return round(float(value), DIGITS) + 0.0


def _q(value: float) -> float:
    return round(float(value), TARGET_DIGITS) + 0.0


def motion_duration(goal: JointGoal, asset: ArticulatedAsset) -> float:
    """Seconds for one joint motion, before the speed factor."""
    joint = asset.joints[goal.joint]
    entry = info(goal.category) if goal.category is not None else None
    if entry is not None and entry.actuation_s is not None and goal.role == "control":
        return entry.actuation_s
    if goal.value is None:
        return 2.0
    delta = abs(goal.value - joint.rest)
    if joint.type == "prismatic":
        size = max(_link_size(asset, goal.link), 0.05)
        return min(max(0.5 + delta / size, 0.3), 2.5)
    if entry is not None and entry.press == "turn":
        return min(max(0.3 + 0.3 * delta / QUARTER, 0.3), 1.5)
    return min(max(0.5 + 0.5 * delta / QUARTER, 0.4), 2.5)


def _link_size(asset: ArticulatedAsset, link: str) -> float:
    vertices = asset.links[link].vertices()
    return float((vertices.max(axis=0) - vertices.min(axis=0)).max()) if vertices.shape[0] else 0.0


def _position(goal: JointGoal, target: float | None = None, expr: str | None = None) -> dict[str, Any]:
    control: dict[str, Any] = {"mode": "joint_position", "joint": goal.joint, "curve": "ease_in_out"}
    if expr is not None:
        control["q_target_expr"] = expr
    value = goal.value if target is None else target
    assert value is not None, "position controls need a target"
    control["q_target_rad"] = _q(value)
    return control


def _hold(joint: str) -> dict[str, Any]:
    return {"mode": "hold_position", "joint": joint}


@dataclass
class _Timeline:
    asset: ArticulatedAsset
    segments: list[dict[str, Any]] = field(default_factory=list)
    cursor: float = 0.0
    last_start: float = 0.0
    onset: float | None = None
    effect_start: float | None = None
    delay: float | None = None

    def add(self, name: str, phase: str, t0: float, t1: float, controls: list[dict[str, Any]]) -> None:
        self.segments.append({"name": name, "phase_type": phase, "t0": _r(t0), "t1": _r(t1), "controls": controls})

    def rest(self, joint: str) -> float:
        return self.asset.joints[joint].rest


def _label(goal: JointGoal) -> str:
    return goal.category or goal.link


def _joint_step(timeline: _Timeline, step: Step, start: float) -> float:
    """Schedule one step of joint motions; returns its end time."""
    factor = step.speed_factor
    asset = timeline.asset
    t = start
    held: list[str] = []
    if step.controls:
        duration = max(motion_duration(g, asset) for g in step.controls) * factor
        if step.duration_s is not None and not step.effects:
            duration = step.duration_s
        timeline.add("actuate_" + "_".join(_label(g) for g in step.controls), "control_actuation", t, t + duration,
                     [_position(g, expr=g.expr) for g in step.controls if g.value is not None] + _velocities(step.controls))
        timeline.onset = start if timeline.onset is None else timeline.onset
        t += duration
        held = [g.joint for g in step.controls if g.value is not None]
    if not step.effects:
        t += _hold_all(timeline, step, t)
        return t + _release(timeline, step, t, 0.0) if step.controls else t
    if step.controls:
        delay = LATENCY_SPRING_S if any(e.category in HINGED_KINDS for e in step.effects) else LATENCY_CONTROL_S
        timeline.add("causal_latency", "causal_latency", t, t + delay, [_hold(j) for j in held])
        timeline.delay = delay if timeline.delay is None else timeline.delay
        t += delay
    duration = step.duration_s or max(motion_duration(g, asset) for g in step.effects) * factor
    sustained = [g.joint for g in step.controls if g.sustains or g.returns == "stays"]
    controls = [_position(g, expr=g.expr) for g in step.effects if g.value is not None] + _velocities(step.effects)
    controls += [_hold(j) for j in sustained if j in held]
    timeline.add("move_" + "_".join(_label(g) for g in step.effects), "effect_motion", t, t + duration, controls)
    timeline.effect_start = t if timeline.effect_start is None else timeline.effect_start
    if step.hold_s > 0:
        t += duration
        t += _hold_all(timeline, step, t)
        return t + _release(timeline, step, t, 0.0)
    _release(timeline, step, t, duration)
    return t + duration


def _hold_all(timeline: _Timeline, step: Step, start: float) -> float:
    """Hold every joint of the step where it is for ``step.hold_s`` seconds; returns the time used."""
    if step.hold_s <= 0:
        return 0.0
    joints = list(dict.fromkeys(g.joint for g in step.goals if g.value is not None))
    if not joints and step.base is None:
        return 0.0
    timeline.add("hold", "hold", start, start + step.hold_s, [_hold(j) for j in joints])
    return step.hold_s


def _release(timeline: _Timeline, step: Step, start: float, limit: float) -> float:
    """Return self-returning controls to rest from ``start`` (within ``limit`` s when > 0); returns the time used."""
    releasing = [g for g in step.controls if not g.sustains and g.returns == "self_return" and g.value is not None]
    if not releasing:
        return 0.0
    back = max(motion_duration(g, timeline.asset) for g in releasing) * step.speed_factor
    back = min(back, limit) if limit > 0 else back
    timeline.add("release_" + "_".join(_label(g) for g in releasing), "control_release", start, start + back,
                 [_position(g, target=timeline.rest(g.joint), expr="rest") for g in releasing])
    return back


def _velocities(goals: tuple[JointGoal, ...]) -> list[dict[str, Any]]:
    return [{"mode": "joint_velocity", "joint": g.joint, "omega_radps": _r(g.omega)} for g in goals if g.omega is not None]


def _base_step(timeline: _Timeline, step: Step, base: BaseGoal, start: float) -> float:
    if step.duration_s is not None:
        duration = step.duration_s
    elif base.speed_mps and base.distance_m:
        duration = base.distance_m / base.speed_mps
    elif base.distance_m:
        duration = min(max(base.distance_m / BASE_SPEED_MPS, 1.0), 4.0) * step.speed_factor
    else:
        duration = min(max(abs(base.yaw_rad) / YAW_SPEED_RADPS, 1.0), 4.0) * step.speed_factor
    fastest = max((abs(rate) for _, rate in base.wheels), default=0.0)
    if fastest > 0:  # keep every wheel within the contract's |omega| <= 20 rad/s
        peak_factor = 3.0 / (1.0 - math.exp(-3.0)) if base.coast else 1.0
        duration = max(duration, peak_factor * base.distance_m * fastest / MAX_WHEEL_OMEGA)
    if base.yaw_rad:
        duration = max(duration, abs(base.yaw_rad) / MAX_WHEEL_OMEGA)
    controls: list[dict[str, Any]] = []
    if base.distance_m:
        axis = list(base.axis_tuple())
        if base.coast:
            tau = duration / 3.0
            v0 = base.distance_m / (tau * (1.0 - math.exp(-duration / tau)))
            controls += [{"mode": "base_velocity_decay", "axis_world": axis, "v0_mps": _r(v0), "tau_s": _r(tau)}]
            controls += [{"mode": "joint_velocity", "joint": j, "omega_radps": _r(rate * v0), "decay": {"tau_s": _r(tau), "min_omega_radps": 0.0}} for j, rate in base.wheels]
        else:
            speed = base.distance_m / duration
            controls += [{"mode": "base_velocity", "axis_world": axis, "v_mps": _r(speed)}]
            controls += [{"mode": "joint_velocity", "joint": j, "omega_radps": _r(rate * speed)} for j, rate in base.wheels]
    if base.yaw_rad:
        controls.append({"mode": "base_yaw_rate", "omega_radps": base.yaw_rad / duration, "pivot_world": list(base.pivot or (0.0, 0.0, 0.0))})
    timeline.add("move_object" if base.distance_m else "turn_object", "effect_motion", start, start + duration, controls)
    timeline.onset = start if timeline.onset is None else timeline.onset
    timeline.effect_start = start if timeline.effect_start is None else timeline.effect_start
    return start + duration + _hold_all(timeline, step, start + duration)


def _compress(segments: list[dict[str, Any]], end: float) -> float:
    if end <= MAX_PLAN_S:
        return end
    scale = MAX_PLAN_S / end
    for segment in segments:
        segment["t0"], segment["t1"] = _r(segment["t0"] * scale), _r(segment["t1"] * scale)
    return MAX_PLAN_S


def plan_intent(intent: Intent, asset: ArticulatedAsset) -> Plan:
    """A Plan.json realising ``intent`` on ``asset`` (deterministic)."""
    timeline = _Timeline(asset=asset)
    end = 0.0
    for index, step in enumerate(intent.steps):
        start = timeline.last_start if step.parallel and index > 0 else (end + STEP_GAP_S if index > 0 else 0.0)
        start += step.pause_before_s  # with a parallel step: how long after the step it runs with ("while it's still rising")
        timeline.last_start = start
        step_end = _base_step(timeline, step, step.base, start) if step.base is not None else _joint_step(timeline, step, start)
        end = max(end, step_end)
    end = _compress(timeline.segments, end)
    duration = min(max(end + FINAL_HOLD_S, MIN_DURATION_S), MAX_DURATION_S)
    checks: dict[str, float] = {}
    if timeline.onset is not None:
        checks["control_onset_time"] = _r(timeline.onset)
    if timeline.effect_start is not None:
        checks["effect_start_time"] = _r(timeline.effect_start)
    if timeline.delay is not None:
        checks["enforced_delay_s"] = _r(timeline.delay)
    document: dict[str, Any] = {"meta": {"fps": FPS, "duration_s": _r(duration)}, "physics": {}, "timeline": timeline.segments}
    if checks:
        document["timing_checks"] = checks
    return Plan.model_validate(document)
