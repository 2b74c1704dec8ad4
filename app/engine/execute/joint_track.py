"""One joint's value over time under its controls (SPEC §3).

The joint's timeline is cut at every control's ``t0`` and ``t1``. On each piece the
winning control (the last active one in timeline order) moves the joint from its
value at the piece's start; with no active control the joint keeps its value.
Velocity and spring controls are integrated on sub-steps of at most 1 ms.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from app.engine.execute.ease import CURVES
from app.engine.execute.events import ExecutionEvent
from app.engine.plan.schema import HoldPosition, JointPosition, JointVelocity, SpringReturn
from app.engine.types import FloatArray

TIME_EPS = 1e-9
"""Times closer than this (seconds) are equal."""
MAX_SUBSTEP_S = 1e-3
"""Largest integration sub-step (>= 1 kHz, SPEC §3)."""
CRITICAL_RATE = 8.0
"""Rate (per normalised phase time) of the critically damped return when no spring_k is given."""
LIMIT_EPS = 1e-12

JointControl = JointPosition | JointVelocity | HoldPosition | SpringReturn


@dataclass(frozen=True)
class TimedControl:
    """A joint control with its phase times; ``where`` locates it in the plan."""

    t0: float
    t1: float
    control: JointControl
    where: str
    target: float | None = None
    """Resolved numeric target of a ``joint_position`` (already clamped)."""


@dataclass(frozen=True)
class JointContext:
    name: str
    lower: float | None
    upper: float | None
    rest: float
    spring_k: float | None = None
    damping_c: float | None = None
    spring_rest: float | None = None

    def clamp(self, values: FloatArray) -> FloatArray:
        if self.lower is None or self.upper is None:
            return values
        return np.clip(values, self.lower, self.upper)


@dataclass
class _Piece:
    """One interval [a, b) and the frames that fall in it."""

    a: float
    b: float
    times: FloatArray
    q_a: float


def _fine_grid(a: float, b: float, times: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Sub-steps covering [a, b] with every frame time as a knot.

    Returns (mids (p,), widths (p,), knot_index (len(times) + 1,)): the number of
    sub-steps completed at each frame time and at ``b``.
    """
    knots = np.unique(np.concatenate([[a], times, [b]]))
    gaps = np.diff(knots)
    counts = np.maximum(1, np.ceil(gaps / MAX_SUBSTEP_S - 1e-9)).astype(np.int64)
    widths = np.repeat(gaps / counts, counts)
    offsets = np.concatenate([[0], np.cumsum(counts)])
    local = np.arange(int(offsets[-1])) - np.repeat(offsets[:-1], counts)
    mids = np.repeat(knots[:-1], counts) + (local + 0.5) * widths
    wanted = np.searchsorted(knots, np.concatenate([times, [b]]))
    return mids, widths, offsets[wanted]


def _limit_note(ctx: JointContext, timed: TimedControl, value: float, when: float) -> ExecutionEvent:
    side = "upper" if ctx.upper is not None and value >= ctx.upper - LIMIT_EPS else "lower"
    message = f"{ctx.name}: {timed.control.mode} at {timed.where} reached the {side} limit {value:.6g} at t={when:.3f} s and stopped there"
    return ExecutionEvent(kind="limit_reached", message=message, joint=ctx.name, mode=timed.control.mode, where=timed.where,
                          time_s=round(when, 6), value=value)


def _clipped_path(start: float, increments: FloatArray, ctx: JointContext) -> tuple[FloatArray, int | None]:
    """Cumulative path (p+1,) from ``start`` with per-step clamping; index of first limit hit."""
    path = start + np.concatenate([[0.0], np.cumsum(increments)])
    if ctx.lower is None or ctx.upper is None:
        return path, None
    if path.min() >= ctx.lower - LIMIT_EPS and path.max() <= ctx.upper + LIMIT_EPS:
        return np.clip(path, ctx.lower, ctx.upper), None
    out = np.zeros_like(path)
    value = out[0] = min(max(start, ctx.lower), ctx.upper)
    first_hit = None
    for i, step in enumerate(increments.tolist(), start=1):
        moved = value + step
        value = min(max(moved, ctx.lower), ctx.upper)
        if first_hit is None and value != moved:
            first_hit = i
        out[i] = value
    return out, first_hit


def _omega(control: JointVelocity, t0: float, t1: float, t: FloatArray) -> FloatArray:
    """Commanded angular (or linear) velocity at times ``t`` (SPEC §3)."""
    s = np.clip((t - t0) / (t1 - t0), 0.0, 1.0)
    ramp = control.omega_radps if control.ramp_to_omega_radps is None else control.ramp_to_omega_radps
    omega = control.omega_radps + (ramp - control.omega_radps) * s
    if control.decay is None:
        return omega
    decayed = omega * np.exp(-(t - t0) / control.decay.tau_s)
    floor = control.decay.min_omega_radps  # |w| >= min_omega with the sign of the undecayed w (SPEC §3)
    return np.where(np.abs(decayed) < floor, np.sign(omega) * floor, decayed)


def _position(piece: _Piece, timed: TimedControl, ctx: JointContext, events: list[ExecutionEvent]) -> tuple[FloatArray, float]:
    control = timed.control
    assert isinstance(control, JointPosition) and timed.target is not None
    ease = CURVES[control.curve]
    span = timed.t1 - timed.t0
    start = piece.q_a
    if abs(piece.a - timed.t0) <= TIME_EPS and control.q_start_rad is not None:
        start = float(ctx.clamp(np.array(control.q_start_rad)))
        if abs(start - piece.q_a) > 1e-6:
            message = f"{ctx.name}: q_start_rad {start:.6g} at {timed.where} differs from the current value {piece.q_a:.6g}; the joint jumps at t={timed.t0:.3f} s"
            events.append(ExecutionEvent(kind="start_jump", message=message, joint=ctx.name, mode=control.mode, where=timed.where, time_s=timed.t0, value=start))
    e_a = float(ease(np.array((piece.a - timed.t0) / span)))
    scale = 1.0 / (1.0 - e_a)

    def at(t: FloatArray) -> FloatArray:
        progress = (ease(np.clip((t - timed.t0) / span, 0.0, 1.0)) - e_a) * scale
        return start + (timed.target - start) * progress  # type: ignore[operator]

    return ctx.clamp(at(piece.times)), float(ctx.clamp(at(np.array(piece.b))))


def _velocity(piece: _Piece, timed: TimedControl, ctx: JointContext, events: list[ExecutionEvent]) -> tuple[FloatArray, float]:
    control = timed.control
    assert isinstance(control, JointVelocity)
    mids, widths, knots = _fine_grid(piece.a, piece.b, piece.times)
    path, hit = _clipped_path(piece.q_a, _omega(control, timed.t0, timed.t1, mids) * widths, ctx)
    if hit is not None:
        events.append(_limit_note(ctx, timed, float(path[hit]), float(mids[hit - 1] + widths[hit - 1] / 2)))
    values = path[knots]
    return values[:-1], float(values[-1])


def _spring_parameters(control: SpringReturn, ctx: JointContext) -> tuple[float, float, float]:
    k = control.spring_k if control.spring_k is not None else (ctx.spring_k or 0.0)
    c = control.damping_c if control.damping_c is not None else (ctx.damping_c or 0.0)
    rest = control.rest_position if control.rest_position is not None else (ctx.spring_rest if ctx.spring_rest is not None else ctx.rest)
    return float(k), float(c), float(ctx.clamp(np.array(rest)))


def _spring(piece: _Piece, timed: TimedControl, ctx: JointContext, events: list[ExecutionEvent]) -> tuple[FloatArray, float]:  # noqa: ARG001 - handler signature
    control = timed.control
    assert isinstance(control, SpringReturn)
    k, c, rest = _spring_parameters(control, ctx)
    if k <= 0.0:
        return _critically_damped(piece, timed, ctx, rest)
    _, widths, knots = _fine_grid(piece.a, piece.b, piece.times)
    path = np.zeros(widths.shape[0] + 1)
    q = path[0] = piece.q_a
    v = 0.0
    lower = -math.inf if ctx.lower is None else ctx.lower
    upper = math.inf if ctx.upper is None else ctx.upper
    for i, h in enumerate(widths.tolist(), start=1):
        v += h * (-k * (q - rest) - c * v)
        q += h * v
        if q < lower or q > upper:
            q = min(max(q, lower), upper)
            v = 0.0
        path[i] = q
    values = path[knots]
    return values[:-1], float(values[-1])


def _critically_damped(piece: _Piece, timed: TimedControl, ctx: JointContext, rest: float) -> tuple[FloatArray, float]:
    """Critically damped return from the piece start that reaches ``rest`` exactly at ``t1``."""
    span = max(timed.t1 - piece.a, TIME_EPS)
    end = (1.0 + CRITICAL_RATE) * math.exp(-CRITICAL_RATE)

    def at(t: FloatArray) -> FloatArray:
        s = np.clip((t - piece.a) / span, 0.0, 1.0)
        g = (1.0 + CRITICAL_RATE * s) * np.exp(-CRITICAL_RATE * s)
        return rest + (piece.q_a - rest) * (g - end) / (1.0 - end)

    return ctx.clamp(at(piece.times)), float(ctx.clamp(at(np.array(piece.b))))


def _hold(piece: _Piece, timed: TimedControl | None, ctx: JointContext, events: list[ExecutionEvent]) -> tuple[FloatArray, float]:  # noqa: ARG001 - handler signature
    return np.full(piece.times.shape[0], piece.q_a), piece.q_a


_HANDLERS: dict[str, Callable[[_Piece, TimedControl, JointContext, list[ExecutionEvent]], tuple[FloatArray, float]]] = {
    "joint_position": _position,
    "joint_velocity": _velocity,
    "spring_return": _spring,
    "hold_position": _hold,
}


def overlap_notes(ctx: JointContext, controls: list[TimedControl]) -> list[ExecutionEvent]:
    notes = []
    for i, first in enumerate(controls):
        for second in controls[i + 1 :]:
            start, end = max(first.t0, second.t0), min(first.t1, second.t1)
            if end - start > TIME_EPS:
                message = f"{ctx.name}: {first.where} and {second.where} overlap on [{start:.3f}, {end:.3f}] s; {second.where} wins"
                notes.append(ExecutionEvent(kind="overlap", message=message, joint=ctx.name, mode=second.control.mode, where=second.where, time_s=start))
    return notes


def track_joint(ctx: JointContext, controls: list[TimedControl], times: FloatArray, events: list[ExecutionEvent]) -> FloatArray:
    """(f,) values of one joint at ``times`` under ``controls`` (given in timeline order)."""
    values = np.full(times.shape[0], ctx.rest)
    if not controls:
        return values
    events.extend(overlap_notes(ctx, controls))
    cuts = sorted({0.0, *(c.t0 for c in controls), *(c.t1 for c in controls)})
    current = ctx.rest
    for a, b in itertools.pairwise(cuts):
        if b - a <= TIME_EPS:
            continue
        mask = (times >= a - TIME_EPS) & (times < b - TIME_EPS)
        active = [c for c in controls if c.t0 <= a + TIME_EPS and c.t1 >= b - TIME_EPS]
        winner = active[-1] if active else None
        piece = _Piece(a=a, b=b, times=times[mask], q_a=current)
        if winner is None:
            values[mask], current = _hold(piece, None, ctx, events)
        else:
            values[mask], current = _HANDLERS[winner.control.mode](piece, winner, ctx, events)
    values[times >= cuts[-1] - TIME_EPS] = current
    return values
