"""Side words that cannot pick the part they name: "the upper door" of a one-door cabinet (a comparison with no
other), "the left drawer" when the only drawer is on the right, "the left-hand lever" of a toaster whose levers
sit front and back. Each is a refusal naming the parts, not a guess."""

from __future__ import annotations

from functools import lru_cache

from app.engine.asset.layout import AssetLayout, PartPlace, asset_layout
from app.engine.asset.model import ArticulatedAsset
from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.words import GENERIC_PART_NOUNS, Side
from app.engine.offline.geometry import ObjectGeometry
from app.engine.offline.grounding import _AXIS_OF, Part, position
from app.engine.offline.reading.mentions import Mention

_COMPARATIVES = frozenset({"lower", "upper", "higher"})
"""Sides that compare parts of a kind ("the lower door"): the user expects more than one."""
_DEFINITE = ("the", "this", "that", "its", "their", "your")
CLEARLY = 0.05
"""A lone part sits on the named side only when it is this far (a fraction of the object's diagonal) from the centre."""
SAME_PLACE = 0.03
"""Candidates closer than this (a fraction of the diagonal) along the named axis are not told apart by it."""


def lone_side_refusal(mention: Mention, kind: PartKind | None, candidates: list[Part], said: list[str], obj: ObjectGeometry,
                      parts: list[Part], asset: ArticulatedAsset) -> str | None:
    """Why the side words of ``mention`` cannot pick among ``candidates`` (None when they can)."""
    noun, asset_name = kind.value if kind is not None else mention.head, asset.name
    if not mention.sides or mention.plural:
        return None
    if len(candidates) == 1:
        compared = _compared(mention, said)
        if compared and (_beyond_others(candidates[0], mention, obj, parts) or (
                not _other_side(candidates[0], mention, obj) and _fixed_alike(kind, asset))):
            return None  # "the lower door" of a cabinet whose one door lies below its drawer; "the upper pane" of a window whose
            # one moving pane is its upper half, against a fixed one: that one ("the lower door" of a one-door oven is refused)
        if compared:  # "the lower door" of a one-door oven: the user expects another door
            return f"'{mention.words}' sets one {noun} against another, but {asset_name} has only one: say 'the {noun}'"
        if _other_side(candidates[0], mention, obj) and not (mention.modifiers and _beyond_others(candidates[0], mention, obj, parts)) and (
                not _shown_there(candidates[0], mention, asset)):
            return f"'{mention.words or mention.head}' names a side where {asset_name} has none: its only {noun} is elsewhere"
        return None
    if not mention.collective and _same_place(mention, candidates, obj):
        return f"'{mention.words or mention.head}' does not tell the {len(candidates)} {noun}s apart"
    return None


def _compared(mention: Mention, said: list[str]) -> bool:
    """"the upper door", not "the upper part" (of a laptop: its lid, against its fixed base)."""
    return any(w in _COMPARATIVES and k > 0 and said[k - 1] in _DEFINITE for k, w in enumerate(said)) and mention.head not in GENERIC_PART_NOUNS


def _fixed_alike(kind: PartKind | None, asset: ArticulatedAsset) -> bool:
    """A link that does not move is named like the kind ("window_frame" beside a window that opens): the other one of a
    comparison may be that fixed part."""
    if kind is None:
        return False
    moved = {j.child for j in asset.joints.values() if j.movable}
    return any(kind.value in (link.semantics.label or "").lower().split("_") for name, link in asset.links.items() if name not in moved)


def lone_compared(mention: Mention, kind: PartKind | None, candidates: list[Part], said: list[str], asset: ArticulatedAsset) -> str | None:
    """The note for a comparison that picks the only moving part of its kind beside a fixed one ("the upper pane" of a
    window whose lower pane is fixed): the user may have meant another part, so the choice is said."""
    if not mention.sides or mention.plural or len(candidates) != 1 or not _compared(mention, said) or not _fixed_alike(kind, asset):
        return None
    noun = kind.value if kind is not None else mention.head
    return f"'{mention.words}': {asset.name} has one {noun}; took it ({candidates[0].link}), which lies that way"


def _other_side(part: Part, mention: Mention, obj: ObjectGeometry) -> bool:
    """The one candidate sits clearly on the other side from the one named ("the left drawer" when the only drawer is
    on the right, "the lower door" of a one-door oven: not clearly on that side, so the user expects another)."""
    for side, _ in mention.sides:
        if side not in _AXIS_OF:
            continue
        axis, positive = _AXIS_OF[side]
        value = float(position(part, obj)[axis])
        if (value if positive else -value) < CLEARLY * obj.diag:
            return True
    return False


_PLACE = {Side.TOP: ("vertical", "top"), Side.BOTTOM: ("vertical", "bottom"), Side.LEFT: ("side", "left"), Side.RIGHT: ("side", "right"),
          Side.FRONT: ("depth", "front"), Side.BACK: ("depth", "back")}
"""Where ``artimo inspect`` says a part is that way: the field of its place and the word."""
_ORDER = {"bottom": 0, "middle": 1, "top": 2, "left": 0, "center": 1, "right": 2, "back": 0, "front": 2}


def _rank(place: PartPlace, side: Side) -> int:
    """How far ``side``'s way ``place`` lies, from inspect's words (a larger value is further)."""
    field, word = _PLACE[side]
    value = _ORDER[getattr(place, field)]
    return value if _ORDER[word] == 2 else -value


@lru_cache(maxsize=16)
def _layout(asset: ArticulatedAsset) -> AssetLayout:
    return asset_layout(asset)


def _shown_there(part: Part, mention: Mention, asset: ArticulatedAsset) -> bool:
    """``artimo inspect`` places the part on every side named (its box centre: "door (middle, left, front)")."""
    place = next((p for p in _layout(asset).parts if p.link == part.link), None)
    if place is None:
        return False
    if all(side in _PLACE and getattr(place, _PLACE[side][0]) == _PLACE[side][1] for side, _ in mention.sides):
        return True
    if mention.head not in GENERIC_PART_NOUNS:
        return False
    others = [p for p in _layout(asset).parts if p.link != part.link]  # "the upper half of the laptop": above its (fixed) base
    return bool(others) and all(side in _PLACE and all(_rank(place, side) > _rank(o, side) for o in others) for side, _ in mention.sides)


def _beyond_others(part: Part, mention: Mention, obj: ObjectGeometry, parts: list[Part]) -> bool:
    """``part`` lies further the named way than every other movable part (the door under a drawer is "lower")."""
    others = [position(p, obj) for p in parts if p.joint != part.joint]
    here = position(part, obj)
    for side, _ in mention.sides:
        if side not in _AXIS_OF or not others:
            return False
        axis, positive = _AXIS_OF[side]
        if any((here[axis] - o[axis]) * (1 if positive else -1) <= 0 for o in others):
            return False
    return True


def _same_place(mention: Mention, candidates: list[Part], obj: ObjectGeometry) -> bool:
    """No side named tells the candidates apart ("the left-hand lever" of a toaster whose levers sit at its front and
    back)."""
    spreads = []
    for side, _ in mention.sides:
        if side in _AXIS_OF:
            values = [float(position(p, obj)[_AXIS_OF[side][0]]) for p in candidates]
            spreads.append(max(values) - min(values))
    return bool(spreads) and all(spread < SAME_PLACE * obj.diag for spread in spreads)  # "the upper of the two dials on the right": upper tells
