"""Parts placed within a group said before. A part between the others of its row ("the knob that sits between the
other two", "the drawer sandwiched between the others", "flanked by the other two") is the middle one: rewritten to "in
the middle", which the mention parser reads as a place. "The left one of that pair" is the left one of its kind."""

from __future__ import annotations

from app.engine.offline.reading.spans import replace_spans
from app.engine.offline.reading.token import Token

_LEADS = frozenset({"between", "flanked", "sandwiched"})
_OTHERS = (("the", "other", "2"), ("the", "2", "others"), ("the", "others"), ("the", "other", "ones"), ("the", "2", "other", "ones"),
           ("the", "2", "outer", "ones"), ("the", "outer", "2"))


def _others_at(tokens: list[Token], k: int) -> int:
    """Length of the words that name the others at ``k`` (0: none)."""
    words = tuple(t.text for t in tokens[k:k + 4])
    return next((len(o) for o in _OTHERS if words[:len(o)] == o), 0)


def _flanked_at(tokens: list[Token], i: int) -> int | None:
    """The index after "between the other 2" / "flanked by the others" at ``i``, else None."""
    if tokens[i].text not in _LEADS:
        return None
    lead = 1 + (tokens[i].text in ("flanked", "sandwiched") and i + 1 < len(tokens) and tokens[i + 1].text in ("by", "between"))
    said = _others_at(tokens, i + lead)
    return i + lead + said if said else None


def flanked(tokens: list[Token]) -> list[Token]:
    return replace_spans(tokens, _flanked_at, lambda ts, i, end: [Token(w, w, ts[i].start, ts[end - 1].end) for w in ("in", "the", "middle")])


_GROUPS = frozenset({"pair", "2", "trio", "3", "group", "set", "lot", "bunch", "row"})


def of_that_group(tokens: list[Token]) -> list[Token]:
    """"Rotate the left one of that pair", "the top one of those two": the group was described before; the part is
    placed among the parts of its kind ("the left one")."""
    return replace_spans(tokens, _group_at, lambda *_: [])


def _group_at(tokens: list[Token], i: int) -> int | None:
    """The index after "of that pair" right after "one" at ``i``, else None."""
    words = [t.text for t in tokens[i:i + 3]]
    bare = i + 3 >= len(tokens) or tokens[i + 3].is_punct or tokens[i + 3].text in ("and", "then")  # not "of the 2 fridge doors"
    if i and tokens[i - 1].text in ("one", "ones") and len(words) == 3 and words[0] == "of" and words[1] in ("that", "this", "those", "these", "the") and (
            words[2] in _GROUPS) and (bare or words[2] not in ("2", "3")):
        return i + 3
    return None
