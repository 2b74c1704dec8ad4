"""A row or column found by counting first, then pointed back to ("Count three rows down from the top of the keypad and
press the button at the far right end of that row"): the counting clause moves nothing; "that row" is "the third row
from the top", which the mention reader counts by."""

from __future__ import annotations

from app.engine.lexicon.words import ORDINALS
from app.engine.offline.reading.token import Token

_LINES = {"row": "row", "rows": "row", "column": "column", "columns": "column"}
_WAYS = frozenset({"down", "up", "across", "over", "in", "along"})
_ENDS = frozenset({"and", ",", "then", "and_then", ".", ";"})
_SIDES = frozenset({"top", "bottom", "left", "right", "front", "back"})
_WORDS = {n: w for w, n in ORDINALS.items() if w.isalpha() and n > 0}


def _counted(tokens: list[Token], i: int) -> tuple[int, str, str, int] | None:
    """(count, "row" or "column", the side counted from, the index after the clause) of "count 3 rows down from the top
    (of ...)" at ``i``, else None."""
    words = [t.text for t in tokens[i:i + 7]]
    if len(words) < 6 or words[0] not in ("count", "counting", "go") or tokens[i + 1].number is None or words[2] not in _LINES:
        return None
    j = i + 3 + (words[3] in _WAYS)
    if j + 2 >= len(tokens) or tokens[j].text != "from" or tokens[j + 1].text != "the" or tokens[j + 2].text not in _SIDES:
        return None
    end = next((k for k in range(j + 3, len(tokens)) if tokens[k].text in _ENDS), None)
    count = int(tokens[i + 1].number or 0)
    if end is None or tokens[end].text in (".", ";") or count not in _WORDS:
        return None
    return count, _LINES[words[2]], tokens[j + 2].text, end + 1


def count_lines(tokens: list[Token]) -> list[Token]:
    out: list[Token] = []
    i = 0
    counted: tuple[int, str, str] | None = None
    while i < len(tokens):
        t = tokens[i]
        found = _counted(tokens, i) if not out or out[-1].is_sentence_end else None
        if found is not None:
            counted, i = found[:3], found[3]
            continue
        if counted is not None and t.text in ("that", "this", "the") and i + 1 < len(tokens) and tokens[i + 1].text == counted[1]:
            count, line, side = counted
            out += [Token(w, w, t.start, tokens[i + 1].end) for w in ("the", _WORDS[count], line, "from", "the", side)]
            i += 2
            continue
        counted = None if t.is_sentence_end else counted
        out.append(t)
        i += 1
    return out
