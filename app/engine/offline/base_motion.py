"""Whole-object motion: direction, distance, yaw, and wheels that roll without slipping.

"Forward" is the object's front (where its doors, drawers and controls face; for a
vehicle, where its front wheels are; for a tap, where its spout reaches), as :mod:`app.engine.offline.front`
decides. A push with no direction moves a vehicle forward and anything else away from the
user standing at its front; a guessed direction or distance is reported by the caller.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from app.engine.lexicon.kinds import PartKind, info
from app.engine.offline.geometry import JointGeometry, ObjectGeometry

DEFAULT_HORIZONTAL_FRACTION = 0.5
"""Distance of an unquantified push, as a fraction of the object's diagonal."""
DEFAULT_LIFT_FRACTION = 0.2
MIN_DEFAULT_DISTANCE_M = 0.1
DEFAULT_SPEED_MPS = 0.4
"""Speed of a timed motion with no distance or speed given: "push the cart forward for 2 seconds" moves it 0.8 m."""
MIN_WHEEL_RADIUS_M = 1e-4
HORIZONTAL_AXIS_MAX_UP = 0.5


@dataclass(frozen=True)
class Heading:
    axis: tuple[float, float, float]
    guessed: bool
    """No direction was given: the axis is this module's default."""


def _tuple(vector: np.ndarray) -> tuple[float, float, float]:
    rounded = np.round(np.asarray(vector, dtype=np.float64), 6) + 0.0
    return (float(rounded[0]), float(rounded[1]), float(rounded[2]))


def heading(direction: str | None, axis: tuple[float, float, float] | None, vertical: str | None, obj: ObjectGeometry,
            *, vehicle: bool, pulling: bool) -> Heading:
    """World axis of a whole-object motion from the words that name it."""
    if axis is not None:
        vector = np.asarray(axis, dtype=np.float64)
        return Heading(_tuple(vector / np.linalg.norm(vector)), guessed=False)
    table = {"forward": obj.front, "backward": -obj.front, "left": -obj.right, "right": obj.right, "up": obj.up, "down": -obj.up}
    if direction in table:
        return Heading(_tuple(table[direction]), guessed=False)
    if vertical in ("up", "down"):
        return Heading(_tuple(table[vertical]), guessed=False)
    if pulling:
        return Heading(_tuple(obj.front), guessed=not vehicle)  # pulled toward the user standing at its front
    return Heading(_tuple(obj.front if vehicle else -obj.front), guessed=True)


def default_distance(obj: ObjectGeometry, vertical: bool) -> float:
    fraction = DEFAULT_LIFT_FRACTION if vertical else DEFAULT_HORIZONTAL_FRACTION
    return max(MIN_DEFAULT_DISTANCE_M, round(fraction * obj.diag, 2))


def wheel_rates(wheels: Iterable[JointGeometry], axis: np.ndarray | tuple[float, float, float], obj: ObjectGeometry) -> tuple[tuple[str, float], ...]:
    """(joint, rad per metre) of every wheel so that its contact point does not slip.

    A wheel of radius r about world axis a rolling with base velocity v needs
    omega = v . (a x up) / (r |a x up|^2).
    """
    direction = np.asarray(axis, dtype=np.float64)
    rates = []
    for geometry in wheels:
        kind = PartKind(geometry.category) if geometry.category is not None else None
        if kind is None or not info(kind).rolls or geometry.type not in ("continuous", "revolute"):
            continue
        spin = geometry.axis_world
        if abs(float(spin @ obj.up)) > HORIZONTAL_AXIS_MAX_UP or geometry.radius < MIN_WHEEL_RADIUS_M:
            continue
        rolling = np.cross(spin, obj.up)
        rate = float(direction @ rolling) / (geometry.radius * float(rolling @ rolling))
        if abs(rate) > 1e-9:
            rates.append((geometry.joint, rate))
    return tuple(rates)


def is_vehicle(obj: ObjectGeometry) -> bool:
    """Rolls on wheels (its wheels turn when it moves forward)."""
    return bool(wheel_rates(obj.joints.values(), obj.front, obj))
