"""A control named by what it does, then told how to work it: "Set the timer — twist the bottom knob a quarter turn
clockwise". The first clause says what the second does; it is no second control. Before this stage "the timer" (alone it
could be either knob) was taken as the other knob, and both turned, silently."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.words import FUNCTION_NAME_WORDS
from app.engine.offline.grounding import Part
from app.engine.offline.reading.acts import Act
from app.engine.offline.reading.mentions import Mention

_SAID_AGAIN = frozenset({",", ":", ";", "-", "—", "–", "."})
"""What may stand between the two: a pause in the words, not "then" (two controls, one after the other)."""


def _by_use(mention: Mention) -> bool:
    return mention.kind is not None and mention.head in FUNCTION_NAME_WORDS and not (mention.sides or mention.ordinal is not None or mention.size)


def _placed(mention: Mention) -> bool:
    return bool(mention.sides or mention.ordinal is not None or mention.size or mention.relation is not None)


def said_by_use(acts: list[Act], parts: list[Part]) -> list[Act]:
    """``acts`` with each such first clause made a summary (a heading) of the clause after it."""
    out = list(acts)
    for k in range(len(out) - 1):
        first, then = out[k].goal, out[k + 1].goal
        if out[k].means is not None or out[k].condition or not first.themes or not all(_by_use(m) for m in first.themes):
            continue
        kinds = {m.kind for m in first.themes}
        if len([p for p in parts if p.kind in kinds]) < 2:
            continue  # one knob: "the timer" is it
        if any(m.kind in kinds and _placed(m) for m in then.themes) and then.verb is not None and then.marker in _SAID_AGAIN:
            out[k] = replace(out[k], goal=replace(first, heading=True), condition=True)
    return out
