"""A choice the user leaves open, said after the part: "open a door, either one is fine", "take a lid off one of the
pots - either pot is fine", "press a button, any will do". Rewritten as the choice said in the phrase ("open any door"),
which grounding reads as one part picked in reading order, with a note. Before this stage the phrase was dropped and the
prompt refused as ambiguous, though the user had said which answer they accept."""

from __future__ import annotations

from dataclasses import replace

from app.engine.offline.reading.token import Token

_CHOOSERS = frozenset({"either", "any", "whichever"})
_ACCEPTED = frozenset({"fine", "ok", "okay", "do", "work", "works", "good"})
_INDEFINITE = frozenset({"a", "an"})
_REACH = 5
"""Words from "either" to what accepts it ("either of the two pots is fine")."""


def _accepted_end(tokens: list[Token], k: int) -> int | None:
    """The index after "either one is fine" / "any will do" starting at ``k``, else None."""
    if tokens[k].text not in _CHOOSERS:
        return None
    for j in range(k + 1, min(len(tokens), k + _REACH + 1)):
        if tokens[j].text in _ACCEPTED:
            return j + 1
        if tokens[j].is_punct:
            return None
    return None


def free_choice(tokens: list[Token]) -> list[Token]:
    out = list(tokens)
    k = 0
    while k < len(out):
        end = _accepted_end(out, k) if k and out[k - 1].text in (",", "-", ";", "—", "and") else None
        indefinite = next((i for i in range(k - 1, max(-1, k - 12), -1) if out[i].text in _INDEFINITE), None) if end else None
        if end is None or indefinite is None:
            k += 1
            continue
        out[indefinite] = replace(out[indefinite], text="any", lemma="any")  # "open a door, either one is fine": any door
        del out[k - 1:end]
        k = indefinite + 1
    return out
