"""A part ruled out in note form: "Lift 0.5 m straight up. Handle not touched.", "Lid not moved." Read as the sentence it
stands for ("the handle is not touched"), a part that stays still. Before this stage the verbless note became a step of
its own that moved the part it rules out. "Not at the same time" / "never together" says the steps go in turn (the "not"
had been dropped and the steps run side by side, silently)."""

from __future__ import annotations

from app.engine.lexicon.words import SIMULTANEOUS
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

_LEFT_ALONE = frozenset({"touched", "moved", "disturbed", "changed", "opened", "operated", "used", "involved", "affected"})
_NAMING = frozenset({"the", "its", "that", "this", "their"})


def telegraphic_not(tokens: list[Token]) -> list[Token]:
    """``tokens`` with "<part> not <participle>" at the start of a sentence said as "<part> is not <participle>"."""
    out = list(tokens)
    k = 0
    while k < len(out):
        if out[k].text in ("not", "never") and k + 1 < len(out) and out[k + 1].text in SIMULTANEOUS:
            out[k:k + 2] = [Token("one_after_the_other", "one_after_the_other", out[k].start, out[k + 1].end)]  # "not at the same time"
        start = k == 0 or out[k - 1].is_sentence_end
        j = k + 1 if start and out[k].text in _NAMING else k
        if start and j + 2 < len(out) and kind_of_word(out[j].text) is not None and out[j + 1].text == "not" and out[j + 2].text in _LEFT_ALONE and (
                j + 3 == len(out) or out[j + 3].is_punct):
            at = out[j + 1]
            out.insert(j + 1, Token("is", "be", at.start, at.start))  # "handle not touched": the handle is not touched
            k = j + 4
            continue
        k += 1
    return out
