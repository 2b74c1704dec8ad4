"""Where a count starts, said the long way: "the third drawer counting up from the floor", "the second key counted from
the right", "the fourth shelf up from the ground". Rewritten to the words the mention reader counts by ("the third drawer
from the bottom"). Before this stage "up" and "floor" were not read, and the count went from the top (silently)."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.words import ORDINALS
from app.engine.offline.reading.token import Token

_COUNTING = frozenset({"counting", "counted", "numbering", "going"})
_WAYS = frozenset({"up", "down", "across", "over", "in"})
_GROUND = frozenset({"floor", "ground"})
_REACH = 6
"""How far before "from" an ordinal may stand ("the third of the six drawers counting up from the floor")."""


def _counted(tokens: list[Token], i: int) -> bool:
    """An ordinal stands shortly before ``tokens[i]``."""
    return any(t.text in ORDINALS for t in tokens[max(0, i - _REACH):i])


def counted_from(tokens: list[Token]) -> list[Token]:
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        token = tokens[i]
        rest = [t.text for t in tokens[i + 1:i + 3]]
        if token.text in _COUNTING and _counted(tokens, i) and (rest[:1] == ["from"] or (rest[:1] and rest[0] in _WAYS and rest[1:] == ["from"])):
            i += 1 if rest[:1] == ["from"] else 2  # "counting up from": the side it counts from follows
            continue
        if token.text in _WAYS and rest[:1] == ["from"] and _counted(tokens, i):
            i += 1  # "the fourth shelf up from the ground"
            continue
        if token.text in _GROUND and len(out) >= 2 and out[-1].text == "the" and out[-2].text == "from" and _counted(out, len(out) - 2):
            token = replace(token, text="bottom", lemma="bottom", corrected_from=token.text)  # counted from the floor: from the bottom
        out.append(token)
        i += 1
    return out
