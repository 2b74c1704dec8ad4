"""The last tie-breaks among similar parts one mention fits, each named in a warning: the one control on the
front, the one lid on top, the one the asset itself calls by the word used, else the largest when they differ."""

from __future__ import annotations

from app.engine.asset.model import ArticulatedAsset
from app.engine.lexicon.kinds import PartKind, info
from app.engine.lexicon.words import GENERIC_PART_NOUNS, WHEEL_SHAPED
from app.engine.offline.geometry import ObjectGeometry
from app.engine.offline.grounding import Part, by_name, position, similar
from app.engine.offline.reading.mentions import Mention

TOP_GAP = 0.25
"""How much higher (a fraction of the object's height) the top lid sits than the next."""


def tie_break(mention: Mention, kind: PartKind | None, kept: list[Part], obj: ObjectGeometry, asset: ArticulatedAsset) -> tuple[Part, str] | None:
    """(the part taken, how it was chosen) among ``kept``; None when nothing tells them apart."""
    front = [p for p in kept if position(p, obj)[0] > 0]
    if all(p.kind is not None and info(p.kind).control for p in kept) and len(front) == 1:
        return front[0], "the one on the front"
    if (kind is not None and info(kind).lid_like) or all(p.kind is not None and info(p.kind).lid_like for p in kept):
        heights = sorted(((position(p, obj)[2], p) for p in kept), key=lambda hp: hp[0], reverse=True)
        if heights[0][0] - heights[1][0] > TOP_GAP * obj.extents[2]:
            return heights[0][1], "the one on top"
    called = by_name(kept, (mention.head,), asset)
    if len(called) == 1:
        return called[0], f"the one its asset calls '{mention.head}'"
    if not similar(kept) and {"combination", "dial"} & set(mention.words.split()) and kind is PartKind.KNOB:
        return min(kept, key=lambda p: p.geometry.size), "the smallest knob (a combination dial beside a handle wheel)"
    if not similar(kept):
        return max(kept, key=lambda p: p.geometry.size), f"the largest {kind.value if kind is not None else mention.head}"
    return None


def carried_alike(mention: Mention, kept: list[Part], candidates: list[Part], asset: ArticulatedAsset) -> tuple[str, ...]:
    """A note when a part named only by place ("the top part") is carried by another movable part that moves it too (a
    jug carrying its lid): which of the two the words mean is a guess."""
    if mention.kind is not None or mention.head not in GENERIC_PART_NOUNS or len(kept) != 1:
        return ()
    carriers = [p for p in candidates if p.joint != kept[0].joint and kept[0].link in asset.descendants(p.link)]
    if not carriers:
        return ()
    return (f"'{mention.words or mention.head}' may mean {kept[0].link} ({kept[0].joint}) or {carriers[-1].link} ({carriers[-1].joint}), "
            f"which carries it: took {kept[0].link}; name the part to choose",)


def wheel_shaped(mention: Mention, candidates: list[Part]) -> str | None:
    """"the wheel handle", "the spoked handle" among several turning controls: the note for taking the clearly largest
    (1.3 times the next), else None."""
    said = [*mention.modifiers, *mention.head.split()] if mention.relation is not None else mention.words.split() + mention.head.split()
    if len(candidates) < 2 or mention.size is not None or not WHEEL_SHAPED & set(said):  # not "the knob right of the spoked wheel"
        return None
    sizes = sorted((p.geometry.size for p in candidates), reverse=True)
    return f"read '{mention.words or mention.head}' as the largest of {len(candidates)} similar parts" if sizes[0] >= 1.3 * sizes[1] else None
