"""How far an amount the user gave can go: the limit it runs into, the travel left that way, and whether it is so far
past the stop that it is refused rather than clamped ("open the oven door to 150 degrees" on a 90 degree hinge)."""

from __future__ import annotations

import math

from app.engine.contracts.steps import Goal
from app.engine.offline.goals import LIMIT_EPS
from app.engine.offline.grounding import Part
from app.engine.offline.resolve import closed_of, resolve
from app.engine.offline.tracker import Tracker


def beyond_limit(goal: Goal, part: Part, tracker: Tracker) -> float | None:
    """The limit an angle or distance amount runs into (``None`` when the joint can go that far)."""
    geometry = part.geometry
    if goal.amount is None or goal.unit not in ("rad", "m") or geometry.lower is None or geometry.upper is None:
        return None
    now = tracker.value(part.joint)
    value = resolve(goal, geometry, tracker.obj, tracker.asset, now).value
    start = closed_of(geometry) if goal.measured_from == "closed" else geometry.rest if goal.measured_from == "rest" else now
    if value is None:
        return None
    wanted = abs(goal.amount)
    if abs(abs(value - start) - wanted) > 1e-6 and value in (geometry.lower, geometry.upper):
        return value
    return None


IMPOSSIBLE_FACTOR = 1.25
"""An explicit amount more than this many times the travel left that way is refused, not clamped (clamping it would
be a guess at what the user wants); a nearer miss is clamped with a warning."""


def travel_left(goal: Goal, part: Part, tracker: Tracker, limit: float) -> float:
    """How far the part can go from where ``goal`` is measured to ``limit``."""
    geometry = part.geometry
    start = closed_of(geometry) if goal.measured_from == "closed" else geometry.rest if goal.measured_from == "rest" else tracker.value(part.joint)
    return abs(limit - start)


def impossible(goal: Goal, part: Part, tracker: Tracker, limit: float) -> bool:
    """An explicit amount far beyond the travel left that way ("rotate the switch 360 degrees" on an 18 degree
    rocker, "20 degrees more" at the stop): a refusal, not a clamp."""
    if goal.amount is None or goal.unit not in ("rad", "m"):
        return False
    left = travel_left(goal, part, tracker, limit)
    return left < LIMIT_EPS or goal.amount > IMPOSSIBLE_FACTOR * left


def shown(amount: float, unit: str | None) -> str:
    return f"{amount:.3g} m" if unit == "m" else f"{math.degrees(amount):.0f} degrees"
