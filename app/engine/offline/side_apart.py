"""A side said apart from its part: "the left side drawer" (a side the noun phrase did not take), "the refrigerator door that is on the right", "the fridge door
located on the right-hand side". When a part's words fit several parts and a side word stands in them or right after them
("(that is / located) on the right"), that side picks among them, with a note that says so (a side that picks none of
them, or that is the direction the clause moves in, leaves the refusal as it was)."""

from __future__ import annotations

from dataclasses import replace

from app.engine.errors import GroundingError
from app.engine.lexicon.words import SPATIAL
from app.engine.offline.grounding import Part
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.mentions import Mention
from app.engine.offline.referents import Referents

_PLACED = frozenset({"that", "which", "is", "sits", "sitting", "located", "placed", "positioned", "mounted", "found"})
_LATERAL = frozenset({"left", "right", "up", "down", "forward", "backward", "back", "front"})
"""Directions a motion may be said in: a side word that is the clause's direction is not a part's side."""


def side_apart(refs: Referents, frame: Frame, mention: Mention, error: GroundingError) -> tuple[list[Part], list[str]] | None:
    """The one part ``mention`` means when the clause's one loose side word picks it among the parts it fits, with a note."""
    if not error.candidates or mention.sides or mention.pronoun or mention.is_object or mention.anaphor or mention.ordinal or (
            mention.owner is not None or mention.region or mention.relation is not None or mention.row is not None):
        return None  # "the rack of the lower oven", "the key left of the 9": the side is said of something else
    said = (mention.words or mention.head).split()
    words = frame.text.replace("-hand", "").split()
    at = next((k for k in range(len(words)) if words[k:k + len(said)] == said), None)
    if at is None:
        return None
    after = words[at + len(said):at + len(said) + 6]
    while after and after[0] in _PLACED:
        after = after[1:]  # "the door (that is / located) on the right"
    before = words[max(at - 2, 0):at]
    near = [w for w in said if w in SPATIAL] + [w for w in before if w in SPATIAL and before[-1] in (w, "side")] + ([after[2]] if after[:2] in (["on", "the"], ["to", "the"]) and len(after) > 2 and after[2] in SPATIAL else [])
    loose = {w for w in near if not (w in _LATERAL and frame.quantities.direction is not None)}
    sides = {SPATIAL[w] for w in loose}
    if len(sides) != 1:
        return None
    try:
        parts, notes = refs.resolve(replace(mention, sides=tuple(sides)))
    except GroundingError:
        return None
    if len(parts) != 1:
        return None
    return parts, [*notes, f"read '{next(iter(loose))}' in '{frame.text}' as the side of '{mention.words or mention.head}'"]
