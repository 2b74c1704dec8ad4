"""A correction said after a step ("60 degrees... no wait, make it 45", "the right drawer, no wait, I meant the other
one"): the step before, with the new amount or on the part the correction names."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.lexicon.words import OPPOSITE_SIDES
from app.engine.offline.reading.frames import Frame

if TYPE_CHECKING:
    from app.engine.offline.reading.acts import Act


def corrected(act: Act, frame: Frame) -> Act | None:
    """``act`` with the amount a correction gives ("make that 20 cm" replaces it, "make it 20 more" adds to it)."""
    said, new = act.goal.quantities.amount, frame.quantities.amount
    if said is None or new is None or new.unit != said.unit or any(m.kind is not None or m.is_object for m in frame.themes) or act.condition:
        return None
    value = said.value + new.value if new.reference == "current" else new.value
    amount = replace(said, value=value, words=f"{said.words}, corrected to {new.words}")
    return replace(act, goal=replace(act.goal, quantities=replace(act.goal.quantities, amount=amount)))


def recast(act: Act, frame: Frame) -> Act | None:
    """``act`` on the part a correction names instead ("... the right drawer, no wait, I meant the other one"): "the
    other one" is the said part's opposite side, "the left one" the said part on that side."""
    said = act.goal.themes
    if frame.verb is not None or frame.quantities.amount is not None or len(frame.themes) != 1 or len(said) != 1 or act.condition:
        return None
    new, old = frame.themes[0], said[0]
    if new.is_object or new.pronoun or old.is_object or old.pronoun or (new.kind is not None and new.kind is not old.kind):
        return None
    if new.other:
        if not old.sides:
            return None
        sides = tuple((OPPOSITE_SIDES.get(side, side), strict) for side, strict in old.sides)
        theme = replace(old, sides=sides, words=f"{old.words}, corrected to {new.words}")
    else:
        theme = replace(old, sides=new.sides, ordinal=new.ordinal, ordinal_from=new.ordinal_from, size=new.size,
                        words=f"{old.words}, corrected to {new.words}")
    return replace(act, goal=replace(act.goal, themes=(theme,)))
