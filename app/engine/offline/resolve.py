"""Goals -> joint values, decided from geometry (never from the sign of a limit).

A :class:`~app.engine.contracts.steps.Goal` names an end state and, optionally, an amount and
what it is measured from; this module turns it into a joint value for one joint, given where
the joint is now and where it was before its last move.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.steps import Goal
from app.engine.lexicon.kinds import PartKind, info
from app.engine.offline.base_motion import HORIZONTAL_AXIS_MAX_UP, wheel_rates
from app.engine.offline.geometry import JointGeometry, ObjectGeometry
from app.engine.offline.orientation import directional_sign, orientation_value

DEFAULT_TURN_RAD = math.pi / 2
"""A continuous joint turned without an amount turns a quarter turn."""
DEFAULT_SPIN_RADPS = math.pi
DEFAULT_SPIN_S = 2.0
LIMIT_EPS = 1e-9
VERTICAL_AXIS = 0.7
"""|axis . up| above this: the part turns about a vertical axis and is seen from above."""


@dataclass(frozen=True)
class Resolved:
    value: float | None = None
    omega: float | None = None
    duration_s: float | None = None


def clamp(geometry: JointGeometry, value: float) -> float:
    if geometry.lower is None or geometry.upper is None:
        return value
    return float(min(max(value, geometry.lower), geometry.upper))


def other_limit(geometry: JointGeometry) -> float | None:
    """The limit farther from rest (something must move)."""
    if geometry.lower is None or geometry.upper is None:
        return None
    return geometry.upper if abs(geometry.upper - geometry.rest) >= abs(geometry.lower - geometry.rest) else geometry.lower


def closed_of(geometry: JointGeometry) -> float:
    return geometry.closed_value if geometry.closed_value is not None else geometry.rest


def open_of(geometry: JointGeometry) -> float | None:
    return geometry.open_value if geometry.open_value is not None else other_limit(geometry)


def pressed_of(geometry: JointGeometry) -> float | None:
    """Where "pressing" takes the part: down for pedals and levers, into its face for buttons."""
    kind = geometry.category
    if kind is not None and info(PartKind(kind)).press == "down" and geometry.down_value is not None and abs(geometry.down_value - geometry.rest) > LIMIT_EPS:
        return geometry.down_value
    value = geometry.press_value
    if value is None or abs(value - geometry.rest) <= LIMIT_EPS:
        value = other_limit(geometry)
    return value


def rotation_sign(geometry: JointGeometry, sense: str | None, obj: ObjectGeometry) -> float:
    """+1 or -1: the joint direction that turns the part clockwise (default) or counter-clockwise
    as seen by a viewer facing the face the part sits on. A wheel turned without a sense turns the
    way it rolls when the object moves forward, so wheels on opposite sides agree."""
    lean = float(geometry.axis_world @ obj.up)
    kind = PartKind(geometry.category) if geometry.category is not None else None
    if sense is None and kind is not None and info(kind).rolls and abs(lean) <= HORIZONTAL_AXIS_MAX_UP:
        rolling = float(obj.front @ np.cross(geometry.axis_world, obj.up))
        if abs(rolling) > 1e-6:
            return 1.0 if rolling > 0 else -1.0
    if abs(lean) > VERTICAL_AXIS:
        facing = obj.up  # turntables, caps, faucet handles: seen from above
    elif kind is not None and info(kind).control and 0.2 < abs(lean) <= VERTICAL_AXIS:
        facing = geometry.axis_world if lean > 0 else -geometry.axis_world  # a knob on a tilted panel faces up and out
    elif np.linalg.norm(geometry.face_normal) > 0 and abs(float(geometry.face_normal @ obj.up)) < VERTICAL_AXIS:
        facing = geometry.face_normal
    else:
        facing = obj.front
    toward_viewer = float(geometry.axis_world @ facing)
    if abs(toward_viewer) < 1e-6:
        toward_viewer = float(geometry.axis_world @ obj.front) or 1.0
    clockwise = -1.0 if toward_viewer > 0 else 1.0
    return clockwise if sense != "ccw" else -clockwise


_DIRECTIONS = ("left", "right", "forward", "backward")


def direction_vector(state: str, obj: ObjectGeometry) -> np.ndarray:
    return {"left": -obj.right, "right": obj.right, "forward": obj.front, "backward": -obj.front}[state]


def _moving_sign(geometry: JointGeometry, vector: np.ndarray, obj: ObjectGeometry) -> float:
    """+1 or -1: the joint direction that moves the part along ``vector`` (a wheel: the way it rolls)."""
    kind = PartKind(geometry.category) if geometry.category is not None else None
    if kind is not None and info(kind).rolls:
        rates = wheel_rates([geometry], vector, obj)
        if rates:
            return 1.0 if rates[0][1] >= 0 else -1.0
    return directional_sign(geometry, vector)


def _toward(geometry: JointGeometry, start: float, end: float, goal: Goal) -> float:
    """From ``start`` toward ``end``: a fraction of the way, or an angle / distance."""
    if goal.amount is None or goal.unit is None:
        return end
    if goal.unit == "fraction":
        return start + goal.amount * (end - start)
    if abs(end - start) <= LIMIT_EPS:
        if goal.measured_from != "closed" or geometry.lower is None or geometry.upper is None:
            return end  # already there: no way to go (an explicit amount is then refused, never sent the URDF's + way)
        # "lower it until it is open 45 degrees": the state named is the closed end itself; measured from there,
        # the amount goes into the range (not toward whichever limit happens to be written as the larger number)
        end = geometry.upper if abs(geometry.upper - start) >= abs(geometry.lower - start) else geometry.lower
    direction = 1.0 if end > start else -1.0
    return clamp(geometry, start + direction * goal.amount)


def _far_end(geometry: JointGeometry, sign: float, goal: Goal, now: float | None = None) -> float:
    """The limit in direction ``sign`` (or, unbounded, an amount / a quarter turn that way from where it is: a wheel the
    object rolled on has turned)."""
    if geometry.lower is None or geometry.upper is None:
        return (geometry.rest if now is None else now) + sign * (goal.amount if goal.unit == "rad" and goal.amount is not None else DEFAULT_TURN_RAD)
    return geometry.upper if sign > 0 else geometry.lower


def end_value(goal: Goal, geometry: JointGeometry, obj: ObjectGeometry, asset: ArticulatedAsset, previous: float | None,
              now: float | None = None) -> float | None:
    """The joint value ``goal.state`` names, before any amount."""
    state = goal.state
    top_lid = geometry.category is not None and info(geometry.category).lid_like and float(geometry.home_face[2]) > 0.5 and (
        geometry.open_value is not None and geometry.closed_value is not None)  # a bin's lid that swings over the top is up when open
    table: dict[str, float | None] = {
        "open": open_of(geometry), "closed": closed_of(geometry), "pressed": pressed_of(geometry),
        "up": open_of(geometry) if top_lid else geometry.up_value, "down": closed_of(geometry) if top_lid else geometry.down_value,
        "rest": geometry.rest, "upper": geometry.upper, "lower": geometry.lower,
        "previous": previous if previous is not None else geometry.rest, "value": goal.value,
    }
    if state in table:
        return table[state]
    if state in ("cw", "ccw"):
        return _far_end(geometry, rotation_sign(geometry, state, obj), goal, now)
    if state in _DIRECTIONS or state == "toward":
        vector = np.asarray(goal.direction_world, dtype=np.float64) if state == "toward" and goal.direction_world else direction_vector(state, obj)
        return _far_end(geometry, _moving_sign(geometry, vector, obj), goal, now)
    if state in ("vertical", "flat"):
        way = _moving_sign(geometry, np.asarray(goal.direction_world, dtype=np.float64), obj) if goal.direction_world else None
        return orientation_value(asset, geometry, state, opening=True, way=way, start=now)
    return None


def start_value(goal: Goal, geometry: JointGeometry, now: float) -> float:
    if goal.measured_from == "current":
        return now
    if goal.measured_from == "rest":
        return geometry.rest
    return closed_of(geometry)


def resolve(goal: Goal, geometry: JointGeometry, obj: ObjectGeometry, asset: ArticulatedAsset, now: float, previous: float | None = None) -> Resolved:
    """The joint value (or spin) ``goal`` asks of ``geometry``'s joint, which is at ``now``."""
    if goal.state == "velocity":
        return Resolved(omega=goal.omega_radps, duration_s=goal.duration_s)
    if goal.state in ("cw", "ccw") and geometry.type == "continuous":
        sign = rotation_sign(geometry, goal.state, obj)
        angle = goal.amount if goal.unit == "rad" and goal.amount is not None else DEFAULT_TURN_RAD
        return Resolved(value=now + sign * angle)
    end = end_value(goal, geometry, obj, asset, previous, now)
    if end is None:
        return Resolved()
    return Resolved(value=clamp(geometry, _toward(geometry, start_value(goal, geometry, now), end, goal)))


def spin_velocity(geometry: JointGeometry, sense: str | None, obj: ObjectGeometry, angle: float | None, omega: float | None,
                  duration: float | None, speed_factor: float = 1.0, direction: str | None = None) -> tuple[float, float]:
    """(omega rad/s, duration s) of a spin request."""
    sign = rotation_sign(geometry, sense, obj)
    kind = PartKind(geometry.category) if geometry.category is not None else None
    if sense is None and kind is not None and info(kind).rolls and direction in ("forward", "backward"):
        rates = wheel_rates([geometry], obj.front if direction == "forward" else -obj.front, obj)
        if rates and abs(rates[0][1]) > 0:
            sign = 1.0 if rates[0][1] > 0 else -1.0
    if omega is not None:
        length = duration or (abs(angle / omega) if angle else DEFAULT_SPIN_S)
        return sign * abs(omega), length
    if angle is not None:
        length = duration or DEFAULT_SPIN_S
        return sign * abs(angle / length), length
    length = duration or DEFAULT_SPIN_S
    return sign * DEFAULT_SPIN_RADPS / speed_factor, length


def target_expression(geometry: JointGeometry, value: float) -> str:
    """The paper's contract form of a target: ``upper_limit``, ``lower_limit``, ``a*upper_limit``,
    a mid-range form, or a plain number for unbounded joints."""
    if geometry.lower is None or geometry.upper is None:
        return f"{value:.9g}"
    if abs(value - geometry.upper) <= LIMIT_EPS:
        return "upper_limit"
    if abs(value - geometry.lower) <= LIMIT_EPS:
        return "lower_limit"
    for name, limit in (("upper_limit", geometry.upper), ("lower_limit", geometry.lower)):
        if abs(limit) > LIMIT_EPS and abs(geometry.rest) <= LIMIT_EPS:
            alpha = value / limit
            if 0.0 < alpha < 1.0:
                return f"{alpha:.9g}*{name}"
    span = geometry.upper - geometry.lower
    alpha = (value - geometry.lower) / span
    return f"lower_limit + {alpha:.9g}*(upper_limit - lower_limit)"
