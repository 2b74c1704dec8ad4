"""A part placed by the user's hand ("the latch nearest your left hand", "the knob closest to my right hand", "the one
by your left hand"): the user stands at the front, so it is the part on that side ("on the left")."""

from __future__ import annotations

from app.engine.offline.reading.spans import replace_spans
from app.engine.offline.reading.token import Token

_NEAR = frozenset({"nearest", "closest", "nearer", "closer", "by", "at", "near"})
_HANDS = {"left_hand": "left", "right_hand": "right"}


def _hand_at(tokens: list[Token], i: int) -> int | None:
    """The index after "nearest (to) your left hand (side)" at ``i``, else None."""
    if tokens[i].text not in _NEAR:
        return None
    j = i + 1 + (i + 1 < len(tokens) and tokens[i + 1].text in ("to", "the", "your", "my"))
    j += j < len(tokens) and tokens[j].text in ("the", "your", "my")
    if j >= len(tokens) or tokens[j].text not in _HANDS:
        return None
    return j + 1 + (j + 1 < len(tokens) and tokens[j + 1].text == "side")


def _on_that_side(tokens: list[Token], i: int, end: int) -> list[Token]:
    hand = next(t for t in tokens[i:end] if t.text in _HANDS)
    return [Token(w, w, tokens[i].start, hand.end) for w in ("on", "the", _HANDS[hand.text])]


def hand_side(tokens: list[Token]) -> list[Token]:
    return replace_spans(tokens, _hand_at, _on_that_side)
