"""A row (or column) said first and the key in it said after a comma: "top row, the middle key", "the key in the bottom
row, the left corner one". Said the way the mention reader counts: "the middle key in the top row", "the left key in the
bottom row". A side said with "corner" before a part ("the left corner one") is that side."""

from __future__ import annotations

from app.engine.lexicon.words import ORDINALS, SPATIAL
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

_LINES = frozenset({"row", "column"})
_UNITS = frozenset({"one", "key", "button"})


def _place_word(word: str) -> bool:
    return word in SPATIAL or word in ORDINALS or word in ("middle", "centre", "center", "last")


def _line_at(tokens: list[Token], k: int) -> int | None:
    """The start of "(the) <place> row" ending at ``k`` (``tokens[k]`` is "row"), else None."""
    j = k - 1
    while j >= 0 and _place_word(tokens[j].text):
        j -= 1
    if j == k - 1:
        return None
    return j if j >= 0 and tokens[j].text == "the" else j + 1


def row_apposed(tokens: list[Token]) -> list[Token]:
    """``tokens`` with "<line>, the <place> key" (and "the key in <line>, the <place> one") put as "the <place> key in <line>"."""
    tokens = [t for k, t in enumerate(tokens) if not (t.text == "corner" and 0 < k < len(tokens) - 1 and tokens[k - 1].text in SPATIAL and (
        tokens[k + 1].text in _UNITS or kind_of_word(tokens[k + 1].text) is not None))]  # "the left corner one": the left one
    for k, t in enumerate(tokens):
        if t.text not in _LINES or k + 3 >= len(tokens) or tokens[k + 1].text != "," or tokens[k + 2].text != "the":
            continue
        start = _line_at(tokens, k)
        end = next((j for j in range(k + 3, min(len(tokens), k + 7)) if tokens[j].text in _UNITS), None)
        if start is None or end is None or not all(_place_word(w.text) for w in tokens[k + 3:end]) or end == k + 3:
            continue
        line = [Token("the", "the", tokens[start].start, tokens[start].start), *[w for w in tokens[start:k + 1] if w.text != "the"]]
        lead = start
        if start >= 3 and tokens[start - 1].text == "in" and tokens[start - 2].text in _UNITS:  # "the key in the bottom row, ..."
            lead = start - 2 - (tokens[start - 3].text == "the")
        unit = tokens[end] if tokens[end].text != "one" else Token("key", "key", tokens[end].start, tokens[end].end)
        said = [Token("the", "the", tokens[lead].start, tokens[lead].start), *tokens[k + 3:end], unit, Token("in", "in", unit.end, unit.end), *line]
        return [*tokens[:lead], *said, *tokens[end + 1:]]
    return tokens
