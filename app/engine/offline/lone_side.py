"""Side words that cannot pick the part they name: "the upper door" of a one-door cabinet (a comparison with no
other), "the left drawer" when the only drawer is on the right, "the left-hand lever" of a toaster whose levers
sit front and back. Each is a refusal naming the parts, not a guess."""

from __future__ import annotations

from app.engine.lexicon.kinds import PartKind
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
                      parts: list[Part], asset_name: str) -> str | None:
    """Why the side words of ``mention`` cannot pick among ``candidates`` (None when they can)."""
    noun = kind.value if kind is not None else mention.head
    if not mention.sides or mention.plural:
        return None
    if len(candidates) == 1:
        compared = any(w in _COMPARATIVES and k > 0 and said[k - 1] in _DEFINITE for k, w in enumerate(said))
        if compared and not (mention.modifiers and _beyond_others(candidates[0], mention, obj, parts)):  # "the lower cabinet door"
            return f"'{mention.words}' sets one {noun} against another, but {asset_name} has only one: say 'the {noun}'"
        if _other_side(candidates[0], mention, obj) and not (mention.modifiers and _beyond_others(candidates[0], mention, obj, parts)):
            return f"'{mention.words or mention.head}' names a side where {asset_name} has none: its only {noun} is elsewhere"
        return None
    if not mention.collective and _same_place(mention, candidates, obj):
        return f"'{mention.words or mention.head}' does not tell the {len(candidates)} {noun}s apart"
    return None


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
    """The side named does not tell the candidates apart ("the left-hand lever" of a toaster whose levers sit at its
    front and back)."""
    for side, _ in mention.sides:
        if side in _AXIS_OF:
            values = [float(position(p, obj)[_AXIS_OF[side][0]]) for p in candidates]
            if max(values) - min(values) < SAME_PLACE * obj.diag:
                return True
    return False
