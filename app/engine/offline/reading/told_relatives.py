"""A part described by what it does to the object, in a relative clause: "the curved flap that covers the front of the
brewing head", "the panel which hides the wiring", "the lid that protects the buttons". The clause tells which part is
meant by how it sits; its verb is no step and its nouns are no parts to move. Before this stage "covers" was read as
the lids (a cover is a lid) and the lids rose with the flap."""

from __future__ import annotations

from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.spans import drop_spans
from app.engine.offline.reading.token import Token

_RELATIVES = frozenset({"that", "which"})
_DESCRIBING = frozenset({"covers", "hides", "protects", "shields", "guards", "conceals", "caps", "seals"})
"""Verbs of what a part covers (not where it sits: "the knob that sits just above the long button" chooses by place)."""
_ENDS = frozenset({",", ".", ";", ":", "!", "?", "and", "then", "and_then", "to", "so", "so_that", "until", "while", "before", "after", "but"})


def _relative_at(tokens: list[Token], k: int) -> int | None:
    """The end of "that covers the front of the brewing head" at ``k``, after a part noun (or "one"), else None."""
    if tokens[k].text not in _RELATIVES or k == 0 or k + 2 >= len(tokens) or tokens[k + 1].text not in _DESCRIBING:
        return None
    before = tokens[k - 1].text
    if before not in ("one", "ones") and kind_of_word(before) is None:
        return None
    return next((j for j in range(k + 2, len(tokens)) if tokens[j].text in _ENDS), len(tokens))


def told_relatives(tokens: list[Token]) -> list[Token]:
    """``tokens`` without a relative clause that describes a part by what it covers or holds."""
    return drop_spans(tokens, _relative_at)
