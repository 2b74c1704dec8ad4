"""A motion said from one state to another: "actuate the safe door from its closed state to fully open", "swing the door
from shut to wide open". The first state is where the part starts (how it is now), the second where it goes: the span
"from ... to" is dropped, leaving the end state. Before this stage the first state ("closed") was taken as the goal and
the door swung shut."""

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
