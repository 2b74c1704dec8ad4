"""A part put right before it is asked for: "Not the spout - the lever sitting on top! Push it all the way round",
"Um, not the little button up at the top, sorry, the big panel underneath it. Could you open that one all the way?". The
part ruled out is dropped, so the one named after it is what "it" and "that one" mean next (before this stage they meant
the part ruled out: the whole faucet slid to the right, the button was pressed)."""

from __future__ import annotations

from app.engine.offline.reading.token import Token

_NAMING = frozenset({"the", "that", "this", "its", "my", "your", "those", "these"})
_MENDS = frozenset({"sorry", "but", "rather", "i_mean", "instead", "no", "oops"})


def _sentence_start(tokens: list[Token], k: int) -> bool:
    return all(t.is_punct for t in tokens[:k]) or tokens[k - 1].is_sentence_end


def not_that_one(tokens: list[Token]) -> list[Token]:
    """``tokens`` without a verbless "not the A," said before "the B" at the start of a sentence."""
    out = list(tokens)
    k = 0
    while k < len(out) - 3:
        if out[k].text == "not" and _sentence_start(out, k) and out[k + 1].text in _NAMING:
            comma = next((j for j in range(k + 2, len(out)) if out[j].is_punct), None)
            if comma is not None and out[comma].text in (",", ":"):
                after = comma + 1
                while after < len(out) and (out[after].text in _MENDS or out[after].text == ","):
                    after += 1  # "sorry,", "but"
                if after < len(out) and out[after].text in _NAMING:
                    out[k:after] = []
                    continue
        k += 1
    return out
