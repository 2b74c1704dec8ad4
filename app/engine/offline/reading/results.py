"""A result clause about the part the step before moves ("so it lies flat along the back side", "so it sits flush")
that says where that part ends: it completes the step instead of adding an effect."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.lexicon.verbs import VerbSense
from app.engine.lexicon.words import STATES
from app.engine.offline.reading.clauses import Link
from app.engine.offline.reading.frames import Frame

if TYPE_CHECKING:
    from app.engine.offline.reading.acts import Act


_RELATIVE = frozenset({"perpendicular", "parallel", "square", "level", "flush"})
"""Words that set the part against another ("perpendicular to the front"): the side named is no way to go."""


def _about_it(frame: Frame) -> bool:
    """A result clause on "it" with no verb of its own ("it lies flat", "it sits flush")."""
    return frame.link is Link.RESULT and bool(frame.themes) and all(m.pronoun for m in frame.themes) and (frame.verb is None or frame.sense is None)


def merged_result(act: Act, frame: Frame) -> Act | None:
    """``act`` completed by the result ``frame``; None when the result is an effect of its own."""
    if not _about_it(frame) or not act.goal.themes:
        return None
    goal, q, r = act.goal, act.goal.quantities, frame.quantities
    if r.direction is not None and q.direction is None and not _RELATIVE & set(frame.text.split()):
        # "drop the handle so it lies flat along the back side": which way the part itself goes
        return replace(act, goal=replace(goal, quantities=replace(q, direction=r.direction, orientation=r.orientation or q.orientation,
                                                                   amount=q.amount or r.amount)))
    ends = {STATES[w] for w in frame.text.split() if STATES.get(w) in ("open", "closed")}
    if len(ends) == 1 and goal.sense in (VerbSense.RETURN, VerbSense.MOVE):
        # "swing it back so it sits flush": back to where it shuts
        sense = VerbSense.CLOSE if ends == {"closed"} else VerbSense.OPEN
        return replace(act, goal=replace(goal, sense=sense, particle=None, returning=False))
    return None
