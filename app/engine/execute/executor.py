"""``execute``: Plan.json -> :class:`Trajectory` under the asset's URDF limits (SPEC §3)."""

from __future__ import annotations

import logging

import numpy as np

from app.engine.asset.kinematics import resolve_joint_values
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.events import ExecutionEvent
from app.engine.execute.joint_track import JointContext, TimedControl, track_joint
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.checks import resolve_target, validate_plan
from app.engine.plan.schema import (
    JOINT_CONTROLS,
    BaseVelocity,
    BaseVelocityDecay,
    BaseYawRate,
    JointPosition,
    ModeSet,
    Plan,
)
from app.engine.types import FloatArray

logger = logging.getLogger(__name__)

TIME_EPS = 1e-9


def frame_times(plan: Plan) -> FloatArray:
    """(N + 1,) times ``i / fps`` with ``N = round(duration_s * fps)``."""
    fps = plan.meta.fps
    count = round(plan.duration_s * fps)
    return np.arange(count + 1, dtype=np.float64) / fps


def _contexts(plan: Plan, asset: ArticulatedAsset) -> dict[str, JointContext]:
    dynamics = {d.joint: d for d in plan.physics.joint_dynamics}
    contexts = {}
    for name in asset.controllable_joints:
        joint = asset.joints[name]
        extra = dynamics.get(name)
        contexts[name] = JointContext(
            name=name,
            lower=joint.lower if joint.bounded else None,
            upper=joint.upper if joint.bounded else None,
            rest=joint.rest,
            spring_k=None if extra is None else extra.spring_k,
            damping_c=None if extra is None else extra.damping_c,
            spring_rest=None if extra is None else extra.rest_position,
        )
    return contexts


def _joint_controls(plan: Plan, asset: ArticulatedAsset, events: list[ExecutionEvent]) -> dict[str, list[TimedControl]]:
    per_joint: dict[str, list[TimedControl]] = {}
    for s_index, segment in enumerate(plan.timeline):
        for c_index, control in enumerate(segment.controls):
            if not isinstance(control, JOINT_CONTROLS):
                continue
            where = f"timeline[{s_index}].controls[{c_index}]"
            target = None
            if isinstance(control, JointPosition):
                raw = resolve_target(control, asset)
                target = asset.joints[control.joint].clamp(raw)
                if abs(target - raw) > 1e-12:
                    message = f"{control.joint}: target {raw:.6g} at {where} clamped to the limit {target:.6g}"
                    events.append(ExecutionEvent(kind="target_clamped", message=message, joint=control.joint, mode=control.mode, where=where,
                                                 time_s=segment.t0, value=target))
            timed = TimedControl(t0=segment.t0, t1=segment.t1, control=control, where=where, target=target)
            per_joint.setdefault(control.joint, []).append(timed)
    return per_joint


def _unit(axis: tuple[float, float, float]) -> FloatArray:
    vector = np.asarray(axis, dtype=np.float64)
    return vector / np.linalg.norm(vector)


def base_translation(plan: Plan, times: FloatArray) -> FloatArray:
    """(f, 3) base translation: exact integral of every base control's velocity."""
    out = np.zeros((times.shape[0], 3))
    for segment in plan.timeline:
        elapsed = np.clip(times, segment.t0, segment.t1) - segment.t0
        for control in segment.controls:
            if isinstance(control, BaseVelocity):
                out += (control.v_mps * elapsed)[:, None] * _unit(control.axis_world)[None]
            elif isinstance(control, BaseVelocityDecay):
                distance = control.v0_mps * control.tau_s * (1.0 - np.exp(-elapsed / control.tau_s))
                out += distance[:, None] * _unit(control.axis_world)[None]
    return out


def base_yaw(plan: Plan, times: FloatArray, events: list[ExecutionEvent]) -> tuple[FloatArray, FloatArray]:
    """((f, 4) rotation quaternions xyzw, (f, 3) translation that keeps the pivot in place) of every
    ``base_yaw_rate`` control: the yaw is the exact integral of the rates."""
    angle = np.zeros(times.shape[0])
    pivot: FloatArray | None = None
    for segment in plan.timeline:
        elapsed = np.clip(times, segment.t0, segment.t1) - segment.t0
        for control in segment.controls:
            if isinstance(control, BaseYawRate):
                angle += control.omega_radps * elapsed
                here = np.asarray(control.pivot_world, dtype=np.float64)
                if pivot is None:
                    pivot = here
                elif np.linalg.norm(here - pivot) > 1e-9:
                    events.append(ExecutionEvent(kind="plan_warning", message=f"base_yaw_rate pivots differ; turning about the first one {pivot.tolist()}"))
    rotation = np.zeros((times.shape[0], 4))
    rotation[:, 2] = np.sin(angle / 2.0)
    rotation[:, 3] = np.cos(angle / 2.0)
    shift = np.zeros((times.shape[0], 3))
    if pivot is not None:
        cos, sin = np.cos(angle), np.sin(angle)
        shift[:, 0] = pivot[0] - (cos * pivot[0] - sin * pivot[1])
        shift[:, 1] = pivot[1] - (sin * pivot[0] + cos * pivot[1])
    return rotation, shift


def _modes(plan: Plan, times: FloatArray) -> tuple[dict[str, bool], ...]:
    """Per-frame mode flags; a ``mode_set`` takes effect at its phase's ``t0`` and persists."""
    changes = [
        (segment.t0, order, control)
        for order, (segment, control) in enumerate((s, c) for s in plan.timeline for c in s.controls)
        if isinstance(control, ModeSet)
    ]
    changes.sort(key=lambda item: (item[0], item[1]))
    frames = []
    state: dict[str, bool] = {}
    pointer = 0
    for t in times.tolist():
        while pointer < len(changes) and changes[pointer][0] <= t + TIME_EPS:
            control = changes[pointer][2]
            state[control.name] = control.set
            pointer += 1
        frames.append(dict(state))
    return tuple(frames)


def execute(plan: Plan, asset: ArticulatedAsset) -> Trajectory:
    """Turn ``plan`` into a trajectory of every movable joint of ``asset``.

    Deterministic: the same plan and asset give identical arrays.

    Raises
    ------
    PlanValidationError
        If the plan names unknown or fixed joints or has unusable targets.
    """
    warnings = validate_plan(plan, asset).warnings
    events = [ExecutionEvent(kind="plan_warning", message=warning) for warning in warnings]
    times = frame_times(plan)
    contexts = _contexts(plan, asset)
    per_joint = _joint_controls(plan, asset, events)
    tracks = {name: track_joint(contexts[name], per_joint.get(name, []), times, events) for name in asset.controllable_joints}
    values = resolve_joint_values(asset, tracks, times.shape[0])
    q = np.stack([values[name] for name in asset.movable_joints], axis=1) if asset.movable_joints else np.zeros((times.shape[0], 0))
    rotation, pivot_shift = base_yaw(plan, times, events)
    for note in events:
        logger.debug("execute %s: %s", asset.name, note.message)
    return Trajectory(
        fps=plan.meta.fps,
        times=times,
        joint_names=asset.movable_joints,
        q=q,
        base_translation=base_translation(plan, times) + pivot_shift,
        base_rotation_xyzw=rotation,
        modes=_modes(plan, times),
        events=tuple(events),
    )
