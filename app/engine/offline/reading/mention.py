"""A mention: a reference to a part (or to the whole object) in a clause, as the mention parser
(:mod:`.mentions`) reads it."""

from __future__ import annotations

from dataclasses import dataclass

from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.words import Side
from app.engine.offline.reading.token import Token

ALTERNATE = frozenset({"every_other", "alternate", "alternating"})
"""Words that keep every second one of the parts named (\"every other drawer\")."""


@dataclass(frozen=True)
class Mention:
    """A reference to a part (or to the whole object) in a clause."""

    head: str
    """The head noun as written (after spelling correction), e.g. "door", "it", "spoiler"."""
    kind: PartKind | None = None
    is_object: bool = False
    pronoun: bool = False
    anaphor: bool = False
    """"the left one", "the other one": the head is the kind of an earlier mention."""
    other: bool = False
    sides: tuple[tuple[Side, bool], ...] = ()
    """(side, extreme) qualifiers: "upper" -> (TOP, False), "leftmost" -> (LEFT, True)."""
    ordinal: int | None = None
    ordinal_from: Side | None = None
    """"the second drawer from the bottom": counted from that side (default: reading order)."""
    row: int | None = None
    column: int | None = None
    size: str | None = None
    plural: bool = False
    collective: bool = False
    alternate: bool = False
    """"every other drawer", "alternate doors": every second one of them, from the end the order starts at."""
    modifiers: tuple[str, ...] = ()
    """Other words before the head ("release" in "the release button")."""
    owner: Mention | None = None
    region: tuple[tuple[Side, bool], ...] = ()
    possessive: bool = False
    """"its rack", "their handles": owned by what the clause before was about."""
    """Sides of the object the part sits in: "the rack of the top oven" (the compartment behind the top door)."""
    whose: str | None = None
    """The object that owns the part, when the prompt says so ("the stapler's magazine", "the magazine of the stapler")."""
    one_of: bool = False
    """"one of the knobs": the user leaves the choice among them."""
    relation: tuple[str, Mention] | None = None
    """"the key right below it", "the knob next to the door": (below / above / beside / left / right, the reference)."""
    start: int = 0
    end: int = 0
    """Token span inside the clause."""
    words: str = ""


def apposed(tokens: list[Token], before: Mention, mention: Mention) -> bool:
    """``mention`` ("the one on the left") only says which of ``before`` (a part noun, just before it after a comma)."""
    return (mention.anaphor and not mention.other and before.kind is not None and not (before.pronoun or before.is_object or before.plural)
            and [t.text for t in tokens[before.end:mention.start]] in ([","], [",", "the"]) and bool(
                mention.sides or mention.ordinal is not None or mention.size))
