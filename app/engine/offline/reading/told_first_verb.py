"""A step told without its verb first and its verb after ("Forward half a metre the wheelie bin, roll it please."): the
verbless clause says the part or object and how far; the clause after, with "it" and nothing measured, says how. One
step: "roll the wheelie bin forward half a metre". Before this the bin rolled twice, the second time a default metre."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.words import DIRECTIONS, NUMBER_WORDS
from app.engine.offline.reading.frames import Frame


def told_first_verb(frames: list[Frame]) -> list[Frame]:
    """``frames`` with a verbless clause that has an amount or a way merged into the verb clause right after it."""
    out: list[Frame] = []
    skip = False
    for k, frame in enumerate(frames):
        if skip:
            skip = False
            continue
        after = frames[k + 1] if k + 1 < len(frames) else None
        q = frame.quantities
        first = frame.text.split()[0] if frame.text.split() else ""
        fronted = first in DIRECTIONS or first in NUMBER_WORDS or first.replace(".", "", 1).isdigit() or first in ("half", "a", "about", "roughly")
        if after is not None and frame.verb is None and fronted and not frame.stative and frame.themes and (q.amount is not None or q.direction is not None) and (
                after.verb is not None and after.themes and all(m.pronoun for m in after.themes) and after.quantities.amount is None and (
                    after.quantities.direction is None) and not after.heading and not frame.heading):
            out.append(replace(after, themes=frame.themes, quantities=replace(after.quantities, amount=q.amount, direction=q.direction),
                               clause=frame.clause, link=frame.link))
            skip = True
            continue
        out.append(frame)
    return out
