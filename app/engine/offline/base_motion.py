"""Whole-object motion: direction, distance, and wheels that roll without slipping."""

from __future__ import annotations

import re

import numpy as np

from app.engine.offline.geometry import ObjectGeometry
from app.engine.offline.grounding import Part
from app.engine.offline.intent import BaseGoal
from app.engine.offline.quantities import Quantity

DEFAULT_HORIZONTAL_FRACTION = 0.5
"""Distance of an unquantified push, as a fraction of the object's diagonal."""
DEFAULT_LIFT_FRACTION = 0.2
MIN_DEFAULT_DISTANCE_M = 0.1
DEFAULT_SPEED_MPS = 0.4
"""Speed of a timed motion with no distance or speed given: "push the cart forward for 2 seconds" moves it 0.8 m."""
COAST = re.compile(r"\b(?:let (?:it|them)\s+(?:roll|coast|glide|slide)|coast(?:s|ing)?|glide(?:s)?|roll(?:s|ing)? to a stop|give (?:it|the \w+) a (?:push|shove|nudge)|comes? to a stop|slows? down)\b")
MIN_WHEEL_RADIUS_M = 1e-4
LOWERING = frozenset({"lower", "drop", "lay"})
HORIZONTAL_AXIS_MAX_UP = 0.5


def direction(verb: str | None, particle: str | None, quantity: Quantity, obj: ObjectGeometry) -> np.ndarray:
    """Unit world direction of a whole-object motion."""
    if quantity.axis is not None:
        return np.asarray(quantity.axis, dtype=np.float64)
    if verb in LOWERING and quantity.axis is None and quantity.direction in (None, "backward", "down"):
        return -obj.up  # "lower it", "set it back down"
    word = quantity.direction or {"up": "up", "down": "down", "forward": "forward", "backward": "backward", "away": "away"}.get(particle or "")
    table = {
        "forward": obj.front, "backward": -obj.front, "left": -obj.right, "right": obj.right,
        "up": obj.up, "down": -obj.up, "away": -obj.front, "toward": obj.front,
    }
    if word in table:
        return np.asarray(table[word], dtype=np.float64)
    if verb in ("lift", "raise", "pick", "elevate", "hoist"):
        return obj.up.copy()
    if verb in ("pull", "drag", "draw"):
        return obj.front.copy()
    if verb in ("push", "shove", "press", "nudge"):
        return -obj.front
    return obj.front.copy()


def wheel_rates(parts: list[Part], axis: np.ndarray, obj: ObjectGeometry) -> tuple[tuple[str, float], ...]:
    """(joint, rad per metre) of every wheel so that its contact point does not slip.

    A wheel of radius r about world axis a rolling with base velocity v needs
    omega = v . (a x up) / (r |a x up|^2).
    """
    rates = []
    for part in parts:
        if part.category != "wheel" or part.geometry.type not in ("continuous", "revolute"):
            continue
        spin = part.geometry.axis_world
        if abs(float(spin @ obj.up)) > HORIZONTAL_AXIS_MAX_UP or part.geometry.radius < MIN_WHEEL_RADIUS_M:
            continue
        rolling = np.cross(spin, obj.up)
        rate = float(axis @ rolling) / (part.geometry.radius * float(rolling @ rolling))
        if abs(rate) > 1e-9:
            rates.append((part.joint, rate))
    return tuple(rates)


def base_goal(verb: str | None, particle: str | None, quantity: Quantity, text: str, parts: list[Part], obj: ObjectGeometry) -> BaseGoal:
    axis = direction(verb, particle, quantity, obj)
    axis = axis / np.linalg.norm(axis)
    vertical = abs(float(axis @ obj.up)) > 0.9
    if quantity.distance_m is not None:
        distance = quantity.distance_m
    elif quantity.duration_s is not None:
        distance = (quantity.speed_mps or DEFAULT_SPEED_MPS) * quantity.duration_s
    else:
        fraction = DEFAULT_LIFT_FRACTION if vertical else DEFAULT_HORIZONTAL_FRACTION
        distance = max(MIN_DEFAULT_DISTANCE_M, round(fraction * obj.diag, 2))
    rolls = [] if vertical else list(wheel_rates(parts, axis, obj))
    return BaseGoal(axis=axis, distance_m=abs(distance), speed_mps=quantity.speed_mps, coast=bool(COAST.search(text)), wheels=tuple(rolls))
