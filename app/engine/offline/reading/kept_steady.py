"""How the object is kept while it moves, said after the motion: "ease the entire oven back ..., keeping it square to the
room", "lift it, keeping it level". The object only translates unless a turn is asked, so the words ask for nothing more and
are dropped, as are "no tipping it", "without tilting it" and ", lid and all,". Before this stage "keeping it square to the room" was read
as a step that named no part, and refused; "Just up, no tipping it" lifted the bucket a second time."""

from __future__ import annotations

from app.engine.offline.reading.token import Token

_KEEPING = frozenset({"keeping", "holding"})
_STEADY = frozenset({"square", "level", "straight", "steady", "upright", "flat", "parallel", "aligned"})
_ENDS = frozenset({".", ",", ";", "!", "?", "and", "then"})
_TIPPING = frozenset({"tipping", "tilting", "tipping_it", "rocking", "wobbling"})


def kept_steady(tokens: list[Token]) -> list[Token]:
    """``tokens`` without ", keeping it square (to the room)" and the like."""
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        words = [t.text for t in tokens[k:k + 4]]
        if words[:1] == [","] and len(words) >= 4 and words[1] in _KEEPING and words[2] in ("it", "them") and words[3] in _STEADY:
            k = next((j for j in range(k + 4, len(tokens)) if tokens[j].text in _ENDS), len(tokens))
            continue
        if words[:1] == [","] and len(words) >= 4 and words[2:4] == ["and", "all"] and k + 4 < len(tokens) and tokens[k + 4].text == ",":
            k += 4  # "heave the whole pot, lid and all, straight up": the pot with what it carries
            continue
        if words[:1] in (["no"], ["without"]) and len(words) >= 2 and words[1] in _TIPPING:
            k += 2 + (len(words) > 2 and words[2] in ("it", "them", "over"))  # "no tipping it"
            continue
        out.append(tokens[k])
        k += 1
    return out
