"""Units of an object made of several like ones: two fridges side by side, a column of cabinets, three toasters in a row.

A *unit* is the body a movable part hangs from (its joint's parent link). When like parts hang from two or more bodies,
"the lever on the left toaster", "the right toaster's lever" or "Left-hand fridge: open the right door" first choose the
unit by where the units stand (the mean place of the parts each carries), then the part within it. An object whose parts
all hang from one body has one unit, and these words place the part itself as before."""

from __future__ import annotations

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.lexicon.words import Side
from app.engine.offline.geometry import ObjectGeometry
from app.engine.offline.grounding import _AXIS_OF, QUALIFIER_TOLERANCE, Part, in_row, position
from app.engine.offline.reading.mentions import Mention


def _bodies(parts: list[Part], asset: ArticulatedAsset) -> dict[str, list[Part]]:
    bodies: dict[str, list[Part]] = {}
    for part in parts:
        bodies.setdefault(asset.joints[part.joint].parent, []).append(part)
    return bodies


def like_units(parts: list[Part], asset: ArticulatedAsset) -> int:
    """How many like units carry ``parts``: bodies of one label ("two dishwashers side by side"), else 1."""
    bodies = _bodies(parts, asset)
    labels = {(asset.links[b].semantics.label or "").lower() for b in bodies if b in asset.links}
    return len(bodies) if len(bodies) > 1 and len(labels) == 1 and "" not in labels else 1


def _chosen(centres: dict[str, np.ndarray], side: Side) -> set[str]:
    """The bodies furthest the named way, or the middle one of three or more."""
    if side in (Side.MIDDLE, Side.INNER, Side.OUTER):
        if len(centres) < 3:
            return set()
        spread = np.ptp(np.array(list(centres.values())), axis=0)
        axis = int(np.argmax(spread))
        order = sorted(centres, key=lambda b: float(centres[b][axis]))  # along the row or column the units stand in
        return set(in_row(order, side)) if side is not Side.MIDDLE or len(order) % 2 else set()  # "the two outer boxes"; one middle unit
    if side not in _AXIS_OF:
        return set()
    axis, largest = _AXIS_OF[side]
    values = {b: float(c[axis]) for b, c in centres.items()}
    best = max(values.values()) if largest else min(values.values())
    tolerance = QUALIFIER_TOLERANCE * (max(values.values()) - min(values.values()))
    if tolerance <= 1e-3:
        return set()  # the units stand side by side, not one above the other: "top" does not tell them apart
    return {b for b, v in values.items() if abs(v - best) <= tolerance}


def in_unit(sides: tuple[tuple[Side, bool], ...], candidates: list[Part], parts: list[Part], asset: ArticulatedAsset,
            obj: ObjectGeometry) -> list[Part]:
    """The candidates carried by the unit ``sides`` name; [] when the candidates hang from one body or the sides do not
    single out units."""
    if not sides or like_units(candidates, asset) < 2:
        return []
    centres = {b: np.mean([position(p, obj) for p in carried], axis=0) for b, carried in _bodies(parts, asset).items()
               if b in _bodies(candidates, asset)}
    chosen = set(centres)
    for side, _ in sides:
        picked = _chosen({b: centres[b] for b in chosen}, side)
        if not picked:
            return []
        chosen = picked
    return [p for p in candidates if asset.joints[p.joint].parent in chosen]


def unit_topic(mentions: tuple[Mention, ...], parts: list[Part], asset: ArticulatedAsset, part_said: bool) -> tuple[tuple[Side, bool], ...]:
    """The unit a clause names by place, when the object is several like units: "the microwave on the right", "the one
    in the middle" (of the fridges), "the left one" (when no part was named before it: "the top drawer, then the bottom
    one" is a drawer). Its parts are what "its lid", "the door" mean next. () if none."""
    if like_units(parts, asset) < 2:
        return ()
    return next((named for mention in mentions if (named := unit_named(mention, part_said))), ())


def unit_named(mention: Mention, part_said: bool) -> tuple[tuple[Side, bool], ...]:
    """The sides by which ``mention`` names a unit (see :func:`unit_topic`), else ()."""
    if mention.sides and (mention.is_object or (mention.anaphor and mention.kind is None and not mention.other and not part_said)):
        return mention.sides
    if mention.region and mention.kind is not None:
        return mention.region  # "the carry handle of the left-hand suitcase ..., then open that suitcase's lid"
    return ()
