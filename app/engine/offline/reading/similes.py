"""Likenesses said after a step: "Close the laptop like the evening forecast wrapping up", "let it rest there five seconds,
as you'd let a wine breathe", "Crack the door open, just a sliver, the way you'd ease a door to see if anyone's home",
"a clean vertical pull, like drawing a pin out of a cylinder". They colour the step and ask for nothing; dropped up to the
end of their clause. Before this stage their nouns were read as parts ("the laptop like", "a wine") and the prompt was
refused, or the door opened all the way after "just a sliver"."""

from __future__ import annotations

from app.engine.lexicon.verbs import VERBS
from app.engine.offline.reading.token import Token

_YOU_WOULD = (("as", "you'd"), ("as", "you", "would"), ("as", "one", "would"), ("the", "way", "you'd"), ("the", "way", "you", "would"),
              ("the", "way", "one", "would"), ("like", "you'd"), ("like", "you", "would"))
_LIKE_STARTS = frozenset({"a", "an", "the", "when", "someone", "somebody"})
_KEPT_AFTER_THE = frozenset({"other", "first", "second", "last", "top", "bottom", "left", "right", "upper", "lower", "one", "same"})
_ENDS = frozenset({",", ".", ";", "!", "?", ":", "then", "and_then"})


def _simile_at(tokens: list[Token], k: int, verb_before: bool) -> bool:
    words = [t.text for t in tokens[k:k + 4]]
    if any(tuple(words[:len(lead)]) == lead for lead in _YOU_WOULD):
        return verb_before
    if words[:1] != ["like"] or len(words) < 2 or not verb_before:
        return False
    if words[1] in ("a_little", "a_bit", "a_big") and len(words) > 2 and words[2].isalpha() and words[2] not in _ENDS:
        return True  # "like a little bed" (not "like a little": about a little)
    if words[1] in _LIKE_STARTS:
        return not (words[1] == "the" and len(words) > 2 and words[2] in _KEPT_AFTER_THE)  # not "like the other one"
    return words[1].endswith("ing") and words[1][:-3] in VERBS  # "like drawing a pin out"


def similes(tokens: list[Token]) -> list[Token]:
    """``tokens`` without a likeness said after a verb (anywhere before it), up to the end of its clause."""
    out: list[Token] = []
    verb_before = False  # a verb said before: the likeness colours a step, it does not start the prompt
    k = 0
    while k < len(tokens):
        if _simile_at(tokens, k, verb_before):
            k = next((j for j in range(k + 1, len(tokens)) if tokens[j].text in _ENDS), len(tokens))
            continue
        out.append(tokens[k])
        verb_before = verb_before or tokens[k].text in VERBS or tokens[k].lemma in VERBS
        k += 1
    return out
