"""Stage 4 — grounding: a :class:`Mention` -> the asset's movable parts it names.

Candidates come from the part's kind (registry: labels, link and visual names), then
related kinds that fit (a "lid" may be a door, never a side-hinged one), then the asset's own
part names ("the slot"). They are narrowed by an owner ("the knob on the door"), name words
("the release button"), rows and columns, sides as seen facing the object (top/bottom,
left/right, front/back, middle), size, ordinals ("second from the top") and "the other".
A singular mention left with several similar parts is ambiguous: the result lists the
candidates with a phrase that names each, and the perceiver refuses (or, when the parts
differ clearly in size, takes the largest and warns).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Literal, TypeVar

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.lexicon.kinds import OPENABLE_ORDER, PartKind, info
from app.engine.lexicon.words import Side
from app.engine.offline.geometry import JointGeometry, ObjectGeometry
from app.engine.offline.naming import describe_link, link_words
from app.engine.offline.reading.mentions import Mention

_T = TypeVar("_T")
QUALIFIER_TOLERANCE = 0.25
"""Candidates within this fraction of the candidates' spread of the extreme value all qualify."""
MIN_QUALIFIER_TOLERANCE_M = 1e-3
SIZE_TOLERANCE = 0.15
"""Relative size difference within which parts count as the same size ("both small knobs")."""
SIZE_TIE = 0.01
"""Within this relative difference "the small knob" cannot pick one of two: a tie (refused with both named)."""
SALIENT_RATIO = 1.5
"""A part this much larger than every other candidate is what a bare singular mention means."""
LID_MAX_VERTICAL_AXIS = 0.7
"""|cos| between a hinge axis and up above which the hinge is a side hinge (a door's), never a lid's."""
How = Literal["kind", "related", "name", "none"]


@dataclass(frozen=True)
class Part:
    joint: str
    link: str
    kind: PartKind | None
    geometry: JointGeometry

    def describe(self, asset: ArticulatedAsset) -> str:
        return f"{describe_link(asset, self.link)} via {self.joint} ({self.geometry.type})"


@dataclass(frozen=True)
class Grounding:
    parts: tuple[Part, ...] = ()
    how: How = "none"
    ambiguous: tuple[Part, ...] = ()
    """Several similar parts a singular mention could mean (``parts`` is then empty)."""
    notes: tuple[str, ...] = field(default_factory=tuple)
    """Loose matches to report (a related kind, a tie-break)."""
    ordinal_overflow: int | None = None
    """"the third drawer" of two: how many there are."""


def movable_parts(asset: ArticulatedAsset, geometry: ObjectGeometry) -> list[Part]:
    """Every controllable joint whose moving links have geometry."""
    return [Part(joint=j, link=g.child, kind=g.category, geometry=g) for j, g in geometry.joints.items()
            if any(asset.links[n].has_geometry for n in g.moving_links)]


def position(part: Part, geometry: ObjectGeometry) -> np.ndarray:
    """(front, right, up) of the part's centre in its closed state, relative to the object centre."""
    return geometry.local(part.geometry.home_centroid)


_AXIS_OF = {Side.TOP: (2, True), Side.BOTTOM: (2, False), Side.LEFT: (1, False), Side.RIGHT: (1, True), Side.FRONT: (0, True), Side.BACK: (0, False)}


def _extreme(candidates: list[Part], obj: ObjectGeometry, axis: int, largest: bool, strict: bool = False) -> list[Part]:
    values = np.array([position(p, obj)[axis] for p in candidates])
    best = values.max() if largest else values.min()
    tolerance = MIN_QUALIFIER_TOLERANCE_M if strict else max(QUALIFIER_TOLERANCE * float(np.ptp(values)), MIN_QUALIFIER_TOLERANCE_M)
    return [p for p, v in zip(candidates, values, strict=True) if abs(v - best) <= tolerance]


def reading_order(candidates: list[Part], obj: ObjectGeometry) -> list[Part]:
    """Top to bottom when stacked, else left to right."""
    positions = np.array([position(p, obj) for p in candidates])
    vertical = np.ptp(positions[:, 2]) >= np.ptp(positions[:, 1])
    keys = [(-pos[2], pos[1]) if vertical else (pos[1], -pos[2]) for pos in positions]
    return [p for _, p in sorted(zip(keys, candidates, strict=True), key=lambda item: item[0])]


def _apply_sides(candidates: list[Part], sides: tuple[tuple[Side, bool], ...], obj: ObjectGeometry, plural: bool = False) -> list[Part]:
    for side, extreme in sides:
        if len(candidates) < 2:
            break
        if plural and side in (Side.MIDDLE, Side.INNER, Side.OUTER) and len(candidates) > 2:
            candidates = in_row(reading_order(candidates, obj), side)  # "the two middle drawers", "the outer pair of doors"
        elif side in _AXIS_OF:
            axis, largest = _AXIS_OF[side]
            candidates = _extreme(candidates, obj, axis, largest, strict=extreme)
        elif side is Side.MIDDLE:
            ordered = reading_order(candidates, obj)
            candidates = [ordered[len(ordered) // 2]] if len(ordered) % 2 else candidates
        elif side in (Side.INNER, Side.OUTER):
            distances = [float(np.linalg.norm(position(p, obj))) for p in candidates]
            candidates = [candidates[int(np.argmin(distances) if side is Side.INNER else np.argmax(distances))]]
    return candidates


def in_row(ordered: list[_T], side: Side) -> list[_T]:
    """Of things in a row (parts, or the units of :mod:`.units`): its two ends (outer), all but its ends (inner), or its
    middle one or two (middle)."""
    if side is Side.OUTER:
        return [ordered[0], ordered[-1]]
    if side is Side.INNER:
        return ordered[1:-1]
    half = len(ordered) // 2
    return ordered[half - 1:half + 1] if len(ordered) % 2 == 0 else ordered[half:half + 1]


def _lines(candidates: list[Part], obj: ObjectGeometry, axis: int) -> list[list[Part]]:
    """Rows (axis 2, top first) or columns (axis 1, left first), split at gaps."""
    descending = axis == 2
    ordered = sorted(candidates, key=lambda p: -position(p, obj)[axis] if descending else position(p, obj)[axis])
    values = [float(position(p, obj)[axis]) for p in ordered]
    sizes = sorted(p.geometry.size for p in ordered)
    gap = max(0.5 * sizes[len(sizes) // 2] / 3.0, MIN_QUALIFIER_TOLERANCE_M)
    lines: list[list[Part]] = [[ordered[0]]]
    for previous, value, part in zip(values, values[1:], ordered[1:], strict=False):
        if abs(value - previous) > gap or _stacked(part, lines[-1], obj, axis):
            lines.append([])
        lines[-1].append(part)
    return lines


def _stacked(part: Part, line: list[Part], obj: ObjectGeometry, axis: int) -> bool:
    """``part`` lies beyond every member of ``line`` along ``axis`` more than beside it: three oven racks close
    together are three rows, not one (two drawers side by side stay one row)."""
    here = position(part, obj)
    for other in line:
        offset = here - position(other, obj)
        if abs(float(offset[axis])) <= max(float(np.linalg.norm(np.delete(offset, axis))), MIN_QUALIFIER_TOLERANCE_M):
            return False
    return True


def _pick_line(candidates: list[Part], obj: ObjectGeometry, index: int, axis: int) -> list[Part]:
    lines = _lines(candidates, obj, axis)
    if index == 0:
        return lines[len(lines) // 2]
    return lines[index - 1] if 0 < index <= len(lines) else lines[-1]


_NAME_SIDES = {Side.FRONT: {"front"}, Side.BACK: {"back", "rear"}, Side.LEFT: {"left"}, Side.RIGHT: {"right"}, Side.TOP: {"top", "upper"},
               Side.BOTTOM: {"bottom", "lower"}}


def _named_sides(candidates: list[Part], sides: tuple[tuple[Side, bool], ...], asset: ArticulatedAsset) -> list[Part]:
    """Candidates whose own names say where they are ("wheel_front_left"): the object's own left and
    right, which for a car differ from the left and right of someone facing it."""
    if not sides or len(candidates) < 2:
        return []
    chosen = candidates
    for side, _ in sides:
        if side not in _NAME_SIDES:
            return []
        chosen = [p for p in chosen if link_words(asset, p.link, visuals=False) & _NAME_SIDES[side]]
    return chosen


def _fits(part: Part, kind: PartKind, up: np.ndarray) -> bool:
    """Whether a part of a related kind can be what the named kind means."""
    wanted = info(kind)
    if (wanted.turns_only or (wanted.hinged and not wanted.lid_like)) and part.geometry.type == "prismatic":
        return False  # a knob turns, a flap swings: a sliding part is not "the knob" or "the flap"
    if wanted.lid_like and part.geometry.type != "prismatic":
        axis = np.asarray(part.geometry.axis_world, dtype=float)
        norm = float(np.linalg.norm(axis))
        if norm > 0 and abs(float(axis @ up)) / norm > LID_MAX_VERTICAL_AXIS:
            return False  # a lid swings up about a horizontal hinge: a side-hinged door is not "the lid"
    return True


def by_kind(parts: list[Part], kind: PartKind, up: np.ndarray, *, singular: bool = False) -> tuple[list[Part], How]:
    exact = [p for p in parts if p.kind is kind]
    if exact:
        return exact, "kind"
    for related in (*info(kind).related, *(info(kind).related_one if singular else ())):
        found = [p for p in parts if p.kind is related and _fits(p, kind, up)]
        if found:
            return found, "related"
    return [], "none"


def by_name(parts: list[Part], words: tuple[str, ...], asset: ArticulatedAsset) -> list[Part]:
    """Parts whose own names contain the mention's head word ("the slot", "the spoiler")."""
    wanted = {w for w in words if w}
    return [p for p in parts if link_words(asset, p.link) & wanted]


def openable(parts: list[Part]) -> list[Part]:
    """Parts with an open side, doors and lids first, then drawers; controls never."""
    found = [p for p in parts if p.geometry.open_value is not None and not (p.kind is not None and info(p.kind).control)]
    rank = {k: i for i, k in enumerate(OPENABLE_ORDER)}
    return sorted(found, key=lambda p: (rank.get(p.kind, len(rank)) if p.kind is not None else len(rank), -p.geometry.size, p.joint))


def similar(parts: list[Part]) -> bool:
    """All of (about) the same size: nothing but a qualifier tells them apart."""
    sizes = sorted((p.geometry.size for p in parts), reverse=True)
    return len(sizes) < 2 or sizes[0] < SALIENT_RATIO * sizes[1]


def narrow(mention: Mention, candidates: list[Part], asset: ArticulatedAsset, obj: ObjectGeometry, owners: list[Part],
           excluded: set[str]) -> tuple[list[Part], int | None]:
    """Apply the mention's qualifiers to ``candidates``; (kept, how many there were when an ordinal overflows)."""
    if owners:
        owned = [p for p in candidates if any(p.link in asset.descendants(o.link) and p.joint != o.joint for o in owners)]
        candidates = owned or candidates
    if mention.modifiers and len(candidates) > 1:
        named = [p for p in candidates if link_words(asset, p.link, visuals=False) & set(mention.modifiers)]
        candidates = named or candidates
    if mention.other and len(candidates) > 1:
        remaining = [p for p in candidates if p.joint not in excluded]
        candidates = remaining or candidates
    if mention.row is not None and len(candidates) > 1:
        candidates = _pick_line(candidates, obj, mention.row, axis=2)
    if mention.column is not None and len(candidates) > 1:
        candidates = _pick_line(candidates, obj, mention.column, axis=1)
    sizes = sorted((p.geometry.size for p in candidates), reverse=True)
    if mention.size == "large" and len(candidates) > 1 and not mention.plural and (not mention.sides or mention.kind is None or sizes[0] > (1 + SIZE_TOLERANCE) * sizes[1]):
        candidates = [max(candidates, key=lambda p: p.geometry.size)]  # not "the lower big drawer" of two alike: the lower one
    if mention.ordinal is not None and mention.ordinal_from is not None:
        return _ordinal_from(candidates, mention, obj)
    counted = next((int(w) for w in mention.modifiers if w.isdigit()), None) if mention.plural else None
    if counted and len(mention.sides) == 1 and mention.sides[0][0] in _AXIS_OF and len(candidates) >= counted:
        axis, largest = _AXIS_OF[mention.sides[0][0]]  # "the top 3 keys of the right-hand column", "the bottom two drawers"
        candidates, mention = sorted(candidates, key=lambda p: float(position(p, obj)[axis]), reverse=largest)[:counted], replace(mention, sides=())
    candidates = _named_sides(candidates, mention.sides, asset) or _apply_sides(candidates, mention.sides, obj, mention.plural or mention.collective)
    if mention.size is not None and len(candidates) > 1:
        pick = max if mention.size == "large" else min
        chosen = pick(candidates, key=lambda p: p.geometry.size)
        tie = SIZE_TOLERANCE if mention.plural else SIZE_TIE  # "the small knob" of two alike is either: a tie, not a choice
        candidates = [p for p in candidates if abs(p.geometry.size - chosen.geometry.size) <= tie * chosen.geometry.size]
    if mention.ordinal is not None and (mention.row is None) != (mention.column is None):
        # "the third key of the second row": counted along the row (left to right) or down the column
        axis = 1 if mention.row is not None else 2
        ordered = sorted(candidates, key=lambda p: float(position(p, obj)[axis]) * (1 if axis == 1 else -1))
        if mention.ordinal > len(ordered):
            return [], len(ordered)
        return [ordered[mention.ordinal - 1 if mention.ordinal > 0 else len(ordered) - 1]], None
    if mention.ordinal is not None and mention.row is None and mention.column is None:
        if mention.ordinal > len(candidates):
            return [], len(candidates)
        if len(candidates) > 1:
            ordered = reading_order(candidates, obj)
            candidates = [ordered[mention.ordinal - 1 if mention.ordinal > 0 else len(ordered) - 1]]
    return candidates, None


def _ordinal_from(candidates: list[Part], mention: Mention, obj: ObjectGeometry) -> tuple[list[Part], int | None]:
    """"the second drawer from the bottom": count from that side."""
    assert mention.ordinal is not None and mention.ordinal_from is not None
    candidates = _apply_sides(candidates, tuple(s for s in mention.sides if s[0] is not mention.ordinal_from), obj)
    axis, largest = _AXIS_OF.get(mention.ordinal_from, (2, True))
    ordered = sorted(candidates, key=lambda p: -position(p, obj)[axis] if largest else position(p, obj)[axis])
    lines = _lines(ordered, obj, axis) if axis in (1, 2) else [[p] for p in ordered]
    if (axis == 2 and not largest) or (axis == 1 and largest):
        lines = lines[::-1]
    index = mention.ordinal if mention.ordinal > 0 else len(lines)
    if index > len(lines):
        return [], len(lines)
    return list(lines[index - 1]), None


def with_kind(mention: Mention, kind: PartKind | None) -> Mention:
    return replace(mention, kind=kind)
