"""Target joint values for a verb applied to a part, decided from geometry (never from signs)."""

from __future__ import annotations

import math

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.offline.base_motion import HORIZONTAL_AXIS_MAX_UP, wheel_rates
from app.engine.offline.geometry import JointGeometry, ObjectGeometry
from app.engine.offline.grounding import Part
from app.engine.offline.orientation import directional_sign, orientation_value
from app.engine.offline.quantities import Quantity
from app.engine.offline.vocabulary import CONTROL_CATEGORIES

DEFAULT_TURN_RAD = math.pi / 2
"""A knob turned without an amount turns a quarter turn."""
DEFAULT_SPIN_RADPS = math.pi
DEFAULT_SPIN_S = 2.0
PUSH_CATEGORIES = ("button", "switch", "key")
DOWN_CATEGORIES = ("pedal", "lever", "handle")
LIMIT_EPS = 1e-9
VERTICAL_AXIS = 0.7
"""|axis . up| above this: the part turns about a vertical axis and is seen from above."""


def _clamp(geometry: JointGeometry, value: float) -> float:
    if geometry.lower is None or geometry.upper is None:
        return value
    return float(min(max(value, geometry.lower), geometry.upper))


def _toward(geometry: JointGeometry, start: float, end: float, quantity: Quantity, current: float | None = None) -> float:
    """Value toward ``end``: a fraction of the way from ``start``, or an angle or distance from the
    current value (an amount is an increment: "open it another 10 degrees")."""
    direction = 1.0 if end >= start else -1.0
    base = start if current is None else current
    if quantity.fraction is not None:
        return start + quantity.fraction * (end - start)
    if geometry.type in ("revolute", "continuous") and quantity.angle_rad is not None:
        return _clamp(geometry, base + direction * quantity.angle_rad)
    if geometry.type == "prismatic" and quantity.distance_m is not None:
        return _clamp(geometry, base + direction * quantity.distance_m)
    return end


def _other_limit(geometry: JointGeometry) -> float | None:
    """The limit farther from rest (something must move)."""
    if geometry.lower is None or geometry.upper is None:
        return None
    return geometry.upper if abs(geometry.upper - geometry.rest) >= abs(geometry.lower - geometry.rest) else geometry.lower


def _pressed(geometry: JointGeometry, category: str | None, particle: str | None) -> float | None:
    if particle == "up" and geometry.up_value is not None:
        return geometry.up_value
    if particle == "down" or category in DOWN_CATEGORIES:
        if geometry.down_value is not None and abs(geometry.down_value - geometry.rest) > LIMIT_EPS:
            return geometry.down_value
    value = geometry.press_value
    if value is None or abs(value - geometry.rest) <= LIMIT_EPS:
        value = _other_limit(geometry)
    return value


def rotation_sign(geometry: JointGeometry, sense: str | None, obj: ObjectGeometry) -> float:
    """+1 or -1: the joint direction that turns the part clockwise (default) or counter-clockwise
    as seen by a viewer facing the face the part sits on. A wheel turned without a sense turns the
    way it rolls when the object moves forward, so wheels on opposite sides (opposite axes) agree."""
    lean = float(geometry.axis_world @ obj.up)
    if sense is None and geometry.category == "wheel" and abs(lean) <= HORIZONTAL_AXIS_MAX_UP:
        rolling = float(obj.front @ np.cross(geometry.axis_world, obj.up))
        if abs(rolling) > 1e-6:
            return 1.0 if rolling > 0 else -1.0
    if abs(lean) > VERTICAL_AXIS:
        facing = obj.up  # turntables, caps, faucet handles: seen from above
    elif geometry.category in ("knob", "handle", "latch") and 0.2 < abs(lean) <= VERTICAL_AXIS:
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


def _turn(part: Part, quantity: Quantity, obj: ObjectGeometry) -> float:
    geometry = part.geometry
    sign = rotation_sign(geometry, quantity.sense, obj)
    if geometry.type == "continuous":
        angle = quantity.angle_rad if quantity.angle_rad is not None else DEFAULT_TURN_RAD
        return geometry.rest + sign * angle
    if geometry.lower is None or geometry.upper is None:
        return geometry.rest
    wanted = geometry.upper if sign > 0 else geometry.lower
    if abs(wanted - geometry.rest) <= LIMIT_EPS and quantity.sense is None:
        wanted = _other_limit(geometry) or wanted
    return _toward(geometry, geometry.rest, wanted, quantity)


def _directional(part: Part, quantity: Quantity, obj: ObjectGeometry) -> float | None:
    """ "Swing the lever 90 degrees to the left": the way that moves the part's centre that way."""
    vectors = {"left": -obj.right, "right": obj.right, "forward": obj.front, "backward": -obj.front}
    geometry = part.geometry
    if quantity.axis is not None:
        wanted = np.asarray(quantity.axis, dtype=np.float64)
    elif quantity.direction in vectors:
        wanted = vectors[quantity.direction]
    else:
        return None
    if geometry.type not in ("revolute", "continuous", "prismatic"):
        return None
    if part.category == "wheel" and quantity.direction in ("forward", "backward"):
        rates = wheel_rates([part], wanted, obj)  # "the forward-rolling direction"
        sign = 1.0 if not rates or rates[0][1] >= 0 else -1.0
    else:
        sign = directional_sign(geometry, wanted)
    if geometry.lower is None or geometry.upper is None:
        angle = quantity.angle_rad if quantity.angle_rad is not None else DEFAULT_TURN_RAD
        return geometry.rest + sign * angle
    limit = geometry.upper if sign > 0 else geometry.lower
    return _toward(geometry, geometry.rest, limit, quantity)


def effective_kind(kind: str | None, particle: str | None) -> str | None:
    """The verb's kind after its particle: "push ... in" = push_in, "swing ... shut" = close."""
    if particle == "out" and kind in ("pull_out", "press", "move", "open"):
        return "pull_out"
    if particle == "in" and kind in ("press", "move", "push_in", "pull_out"):
        return "push_in"
    if particle == "open" and kind not in ("unlatch",):
        return "open"
    if particle == "shut":
        return "close"
    return kind


def goal_value(
    kind: str, particle: str | None, part: Part, quantity: Quantity, obj: ObjectGeometry, asset: ArticulatedAsset | None = None, current: float | None = None
) -> float | None:
    """Target joint value of ``kind`` (open, close, press, ...) on ``part``; ``None`` = spin at a velocity.

    ``current`` is the joint's value when the motion starts (rest by default).
    """
    geometry = part.geometry
    now = geometry.rest if current is None else current
    category = part.category
    if quantity.orientation is not None and asset is not None and kind != "spin":
        value = orientation_value(asset, geometry, quantity.orientation, opening=kind not in ("close", "push_in", "lower", "release"))
        if value is not None and quantity.fraction is not None and quantity.fraction < 1.0:
            return now + quantity.fraction * (value - now)  # "halfway to upright": a fraction of the way there
        if value is not None:
            return value
    closed = geometry.closed_value if geometry.closed_value is not None else geometry.rest
    opened = geometry.open_value
    if quantity.absolute and quantity.angle_rad is not None and opened is not None and geometry.type == "revolute" and kind != "spin":
        # "to 30 degrees", "45 degrees from closed": an opening measured from closed, whichever way the verb moves.
        # A part resting nearer its closed limit than its open one is closed at rest (the range past it is overtravel).
        shut = geometry.rest if abs(geometry.rest - closed) < abs(opened - geometry.rest) else closed
        return _clamp(geometry, shut + (1.0 if opened >= closed else -1.0) * quantity.angle_rad)
    if (kind in ("press", "move", "push_in") and quantity.direction == "backward" and quantity.axis is None and opened is not None
            and category not in PUSH_CATEGORIES and category not in CONTROL_CATEGORIES and abs(now - closed) > LIMIT_EPS):
        # "pull the drawer out 30 cm, then push it back 10 cm": back toward closed, by the amount, from where it is now
        return _toward(geometry, now, closed, quantity, now)
    if kind in ("turn", "move", "open", "toggle", "operate", "press", "lower", "raise") and quantity.sense is None and not (category in PUSH_CATEGORIES and geometry.type == "prismatic"):
        value = _directional(part, quantity, obj)
        # a world side ("onto the rim on the +X side") picks the way even when the part has an open side
        if value is not None and (kind != "open" or geometry.open_value is None or quantity.axis is not None):
            return value
    kind = effective_kind(kind, particle) or "operate"
    if kind in ("operate", "unlatch"):
        kind = "turn" if category in ("knob", "handle", "latch") and geometry.type != "prismatic" else "press"
    if kind == "move":
        kind = {"up": "raise", "down": "lower"}.get(particle or "", "open")
    if kind == "spin" or (kind == "turn" and geometry.type == "continuous" and (quantity.omega_radps is not None or quantity.duration_s is not None)):
        return None
    closed = geometry.closed_value if geometry.closed_value is not None else geometry.rest
    opened = geometry.open_value
    if kind in ("open", "pull_out") and opened is not None and category not in PUSH_CATEGORIES:
        return _toward(geometry, closed, opened, quantity, now)
    if kind in ("close", "push_in") and category not in PUSH_CATEGORIES and (opened is not None or kind == "close"):
        # "close the door halfway / 45 degrees": an amount is measured from where the part is now
        partial = (quantity.fraction is not None and quantity.fraction < 1.0) or quantity.angle_rad is not None or quantity.distance_m is not None
        if partial and abs(now - closed) > LIMIT_EPS:
            return _toward(geometry, now, closed, quantity, now)
        return closed
    against_opening = opened is not None and (geometry.up_value - geometry.rest) * (opened - closed) < 0 if geometry.up_value is not None else False
    if kind == "raise" and geometry.up_value is not None and not (opened is not None and abs(geometry.up_value - now) <= LIMIT_EPS) and not (
            against_opening and category not in PUSH_CATEGORIES):  # "raise the chest lid 50 degrees" opens it, even if its overtravel sits higher
        return _toward(geometry, geometry.rest, geometry.up_value, quantity, now)
    if kind == "raise" and opened is not None and category not in PUSH_CATEGORIES:
        # a lid that flips all the way back ends lower than it starts: "lift the lid" still opens it
        return _toward(geometry, closed, opened, quantity, now)
    if kind == "lower" and geometry.up_value is not None and abs(now - geometry.rest) > LIMIT_EPS and (now - geometry.rest) * (geometry.up_value - geometry.rest) > 0:
        # "raise the lid 30 cm, then lower it 20 cm": back toward where it rested, from where it is now
        return _toward(geometry, now, geometry.rest, quantity, now)
    if kind == "lower" and geometry.down_value is not None:
        return _toward(geometry, geometry.rest, geometry.down_value, quantity, now)
    if kind == "release":
        return geometry.rest
    if kind == "turn" or (geometry.type == "continuous" and kind in ("open", "close", "toggle", "press")):
        return _turn(part, quantity, obj)
    if kind in ("press", "push_in", "toggle", "pull_out", "raise", "lower", "open", "close"):
        pressed = _pressed(geometry, category, particle)
        if pressed is None:
            return None
        return _toward(geometry, geometry.rest, pressed, quantity, now)
    return _other_limit(geometry)


def spin_omega(part: Part, quantity: Quantity, obj: ObjectGeometry) -> tuple[float, float]:
    """(omega rad/s, duration s) of a spin request."""
    sign = rotation_sign(part.geometry, quantity.sense, obj)
    if quantity.sense is None and part.category == "wheel" and quantity.direction in ("forward", "backward"):
        rates = wheel_rates([part], obj.front if quantity.direction == "forward" else -obj.front, obj)  # the way it rolls
        if rates and abs(rates[0][1]) > 0:
            sign = 1.0 if rates[0][1] > 0 else -1.0
    if quantity.omega_radps is not None:
        omega = quantity.omega_radps
        duration = quantity.duration_s or (abs(quantity.angle_rad / omega) if quantity.angle_rad else DEFAULT_SPIN_S)
    elif quantity.angle_rad is not None:
        duration = quantity.duration_s or DEFAULT_SPIN_S
        omega = quantity.angle_rad / duration
    else:
        duration = quantity.duration_s or DEFAULT_SPIN_S
        omega = DEFAULT_SPIN_RADPS / quantity.speed_factor
    return sign * abs(omega), duration


def target_expression(geometry: JointGeometry, value: float) -> str:
    """The contract form of a target: ``upper_limit``, ``lower_limit``, ``a*upper_limit``,
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
