"""A part placed by the user's hand ("the latch nearest your left hand", "the knob closest to my right hand", "the one
by your left hand"): the user stands at the front, so it is the part on that side ("on the left")."""

from __future__ import annotations

from app.engine.offline.reading.token import Token

_NEAR = frozenset({"nearest", "closest", "nearer", "closer", "by", "at", "near"})
_HANDS = {"left_hand": "left", "right_hand": "right"}


def hand_side(tokens: list[Token]) -> list[Token]:
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        t = tokens[i]
        if t.text in _NEAR:
            j = i + 1 + (i + 1 < len(tokens) and tokens[i + 1].text in ("to", "the", "your", "my"))
            j += j < len(tokens) and tokens[j].text in ("the", "your", "my")
            if j < len(tokens) and tokens[j].text in _HANDS:
                side = _HANDS[tokens[j].text]
                out += [Token(w, w, t.start, tokens[j].end) for w in ("on", "the", side)]
                i = j + 1 + (j + 1 < len(tokens) and tokens[j + 1].text == "side")
                continue
        out.append(t)
        i += 1
    return out
