"""What kind a bare "one" stands for when nothing was named before it: the object's only kind of movable part ("On the
chest of drawers, the upper one ..."), or, for a place in a row or column ("the second one from the left in the bottom
row"), the only kind laid out in rows and columns (a keypad's keys)."""

from __future__ import annotations

from collections import Counter

from app.engine.lexicon.kinds import PartKind
from app.engine.offline.grounding import Part
from app.engine.offline.reading.mentions import Mention

_GRID = 4
"""At least this many parts of one kind to form rows and columns."""


def kind_of_one(mention: Mention, parts: list[Part], asset_name: str) -> tuple[PartKind, str] | None:
    """(the kind, a note saying why) for an unqualified "one" placed by side, ordinal, row or column; ``None`` otherwise."""
    if not (mention.anaphor and "one" in mention.words.split() and not mention.other):
        return None
    kinds = Counter(p.kind for p in parts)
    if (mention.sides or mention.ordinal is not None) and len(kinds) == 1 and (only := next(iter(kinds))) is not None:
        return only, f"read '{mention.words or mention.head}' as a {only.value}: every movable part of {asset_name} is one"
    grid = [kind for kind, n in kinds.items() if kind is not None and n >= _GRID]
    if (mention.row is not None or mention.column is not None) and len(grid) == 1:
        return grid[0], f"read '{mention.words or mention.head}' as a {grid[0].value}: the only parts of {asset_name} in rows and columns"
    return None
