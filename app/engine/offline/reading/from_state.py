"""A motion said from one state to another: "actuate the safe door from its closed state to fully open", "swing the door
from shut to wide open". The first state is where the part starts (how it is now), the second where it goes: the span
"from ... to" is dropped, leaving the end state. Before this stage the first state ("closed") was taken as the goal and
the door swung shut. A zero said as where the part sits in a state ("90 degrees measured from where it sits when
shut") is said as the state ("from shut")."""

from __future__ import annotations

from app.engine.lexicon.words import STATES
from app.engine.offline.reading.spans import drop_spans
from app.engine.offline.reading.token import Token

_DETERMINERS = frozenset({"its", "the", "a", "their", "it's"})
_ADVERBS = frozenset({"fully", "completely", "totally", "all", "wide"})
_NOUNS = frozenset({"state", "position", "pose", "setting", "end"})


def _span_end(tokens: list[Token], k: int) -> int | None:
    """The index after "from (its) (fully) closed (state) to" at ``k``, else None."""
    if tokens[k].text != "from":
        return None
    j = k + 1
    j += j < len(tokens) and tokens[j].text in _DETERMINERS
    j += j < len(tokens) and tokens[j].text in _ADVERBS
    if j >= len(tokens) or tokens[j].text not in STATES or tokens[j].text in ("up", "down", "in", "out", "on", "off"):
        return None
    j += 1
    j += j < len(tokens) and tokens[j].text in _NOUNS
    if j >= len(tokens) or tokens[j].text not in ("to", "into"):
        return None
    return j + 1


def from_state(tokens: list[Token]) -> list[Token]:
    """``tokens`` without "from <state> to" before an end state."""
    return drop_spans(tokens, _span_end)


_SITS = frozenset({"sits", "is", "rests", "stands", "lies", "was"})


def _where_in_state(tokens: list[Token], k: int) -> tuple[int, Token] | None:
    """The end of "where it sits when (it is) (fully) shut" at ``k`` and the state token, else None."""
    words = [t.text for t in tokens[k:k + 4]]
    if words[:1] != ["where"] or words[1:2] != ["it"] or words[2:3] == [] or words[2] not in _SITS or words[3:4] != ["when"]:
        return None
    j = k + 4
    j += 2 if [t.text for t in tokens[j:j + 2]] == ["it", "is"] else int(j < len(tokens) and tokens[j].text in ("it's", "fully", "completely"))
    j += j < len(tokens) and tokens[j].text in _ADVERBS
    if j < len(tokens) and STATES.get(tokens[j].text) == "closed":
        return j + 1, tokens[j]
    return None


def where_in_state(tokens: list[Token]) -> list[Token]:
    """``tokens`` with "from where it sits when shut" said as "from shut"."""
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        found = _where_in_state(tokens, k) if out and out[-1].text == "from" else None
        if found is None:
            out.append(tokens[k])
            k += 1
            continue
        k, state = found
        out.append(state)
    return out
