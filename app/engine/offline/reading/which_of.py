"""A choice among named parts said as a relative clause ("open whichever of the two oven doors is the smaller one",
"whichever drawer is lower"): read as the plain superlative ("the smaller of the 2 oven doors"), which the mention
parser knows; "whichever knob is farthest to the left" is "the knob that is farthest to the left"; "whichever drawer you
like" is "any drawer". Without this, "whichever" was read as "the" and the clause after
it was lost."""

from __future__ import annotations

from app.engine.offline.reading.framing import scan
from app.engine.offline.reading.token import Token

_IS = frozenset({"is", "'s", "sits", "looks"})
_PLACING = frozenset({"nearer", "closer", "further", "farther", "nearest", "closest", "furthest", "farthest", "over", "under"})
_PLACE_PREPS = frozenset({"on", "at", "in", "near", "next_to", "by", "beside", "nearer", "closer"})
_LIKED = frozenset({"like", "want", "prefer", "choose", "fancy", "pick"})


def _adjective_end(tokens: list[Token], j: int) -> int | None:
    """After "is": "(the) smaller (one)" -> the index after it, else None."""
    j += j < len(tokens) and tokens[j].text == "the"
    if j >= len(tokens) or not tokens[j].text.isalpha() or not tokens[j].text.endswith(("er", "est", "most")) or tokens[j].text in _PLACING:
        return None
    end = j + 1 + (j + 1 < len(tokens) and tokens[j + 1].text == "one")
    return end if end == len(tokens) or tokens[end].is_punct or tokens[end].text in ("and", "then", "please") else None  # not "nearer the floor"


def _chosen(tokens: list[Token], i: int, out: list[Token]) -> int | None:
    """At "whichever": write the choice it says into ``out``; the index after what it read, or None."""
    t = tokens[i]
    if t.text != "whichever":
        return None
    liked = next((j for j in range(i + 1, min(len(tokens) - 1, i + 5)) if tokens[j].text in ("you", "u") and tokens[j + 1].text in _LIKED), None)
    if liked is not None:  # "open whichever drawer you like": any drawer
        out += [Token("any", "any", t.start, t.end), *tokens[i + 1:liked]]
        return liked + 2
    k = i + 1 + (i + 1 < len(tokens) and tokens[i + 1].text == "one")
    is_at = next((j for j in range(k, min(len(tokens), k + 7)) if tokens[j].text in _IS), None)
    end = _adjective_end(tokens, is_at + 1) if is_at is not None and is_at > k else None
    if end is None and is_at is not None and is_at > k and is_at + 1 < len(tokens) and (
            tokens[is_at + 1].text in _PLACING | _PLACE_PREPS or tokens[is_at + 1].text.endswith("most")):
        out += [Token("the", "the", t.start, t.end), *tokens[k:is_at], Token("that", "that", t.start, t.end)]
        return is_at  # "whichever knob is farthest to the left": the knob that is farthest to the left
    if end is None or is_at is None:
        return None
    adjective = next(tokens[j] for j in range(is_at + 1, end) if tokens[j].text not in ("the", "one"))
    out += [Token("the", "the", t.start, t.end), adjective, *tokens[k:is_at]]  # "of the 2 oven doors" or "drawer"
    return end


def which_of(tokens: list[Token]) -> list[Token]:
    return scan(tokens, _chosen)
