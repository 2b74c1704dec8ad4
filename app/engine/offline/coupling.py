"""Coupled amounts: a pedal and the lid it lifts move in proportion.

The fraction of the pedal's travel is the fraction of the lid's opening (up to upright, or its
open limit when that comes first). When only one side states an amount the other follows it;
with none (or both) nothing changes.
"""

from __future__ import annotations

from dataclasses import replace

from app.engine.asset.model import ArticulatedAsset
from app.engine.offline.geometry import JointGeometry, ObjectGeometry
from app.engine.offline.grounding import Part
from app.engine.offline.intent import JointGoal
from app.engine.offline.orientation import orientation_value
from app.engine.offline.quantities import Quantity
from app.engine.offline.targets import goal_value, target_expression
from app.engine.offline.vocabulary import HINGED

EPS = 1e-6


def lid_span(asset: ArticulatedAsset, geometry: JointGeometry) -> tuple[float, float]:
    """(closed value, signed opening a fully pressed pedal gives): to upright, or the open limit if nearer."""
    closed = geometry.closed_value if geometry.closed_value is not None else geometry.rest
    opened = geometry.open_value if geometry.open_value is not None else closed
    upright = orientation_value(asset, geometry, "vertical", opening=True)
    if upright is not None and abs(upright - closed) > EPS and abs(upright - closed) < abs(opened - closed):
        return closed, upright - closed
    return closed, opened - closed


def couple_amounts(
    controls: list[JointGoal], effects: list[JointGoal], control_amount: bool, effect_amount: bool,
    parts: list[Part], obj: ObjectGeometry, asset: ArticulatedAsset,
) -> tuple[list[JointGoal], list[JointGoal], str | None]:
    """``controls`` and ``effects`` with the side that states no amount following the other, and a note
    saying so (``None`` when nothing changed)."""
    if control_amount == effect_amount:
        return controls, effects, None
    pedals = [c for c in controls if c.category == "pedal" and c.value is not None]
    lids = [e for e in effects if e.category in HINGED and e.value is not None]
    if len(pedals) != 1 or not lids:
        return controls, effects, None
    geometry_of = {p.joint: p.geometry for p in parts}
    pedal = pedals[0]
    pedal_geometry = geometry_of[pedal.joint]
    pedal_part = next(p for p in parts if p.joint == pedal.joint)
    full = goal_value("press", None, pedal_part, Quantity(), obj, asset)
    rest = pedal_geometry.rest
    if full is None or abs(full - rest) < EPS:
        return controls, effects, None
    if control_amount:
        fraction = (pedal.value - rest) / (full - rest)  # type: ignore[operator]
        coupled = []
        for effect in effects:
            if effect in lids:
                closed, span = lid_span(asset, geometry_of[effect.joint])
                value = closed + fraction * span
                effect = replace(effect, value=value, expr=target_expression(geometry_of[effect.joint], value))
            coupled.append(effect)
        return controls, coupled, f"{lids[0].joint} opens the fraction {fraction:.3g} its pedal is pressed"
    closed, span = lid_span(asset, geometry_of[lids[0].joint])
    fraction = min(max((lids[0].value - closed) / span, 0.0), 1.0) if abs(span) > EPS else 1.0  # type: ignore[operator]
    value = rest + fraction * (full - rest)
    pressed = replace(pedal, value=value, expr=target_expression(pedal_geometry, value))
    return [pressed if c is pedal else c for c in controls], effects, f"{pedal.joint} is pressed the fraction {fraction:.3g} its lid opens"
