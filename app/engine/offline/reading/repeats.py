"""Presses said with a count: "press the 5 key twice", "tap the button three times" are that many presses, one after
another (a count on a turn is a number of turns, read by the goal stage; a count on a hold is not repeated)."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.verbs import VerbSense
from app.engine.offline.reading.acts import Act

MAX_REPEATS = 10
"""More presses than this is no animation anyone asks for: the count is kept at this, with a note saying so."""


def repeated(acts: list[Act]) -> list[Act]:
    """``acts`` with each counted press written out once per press."""
    out: list[Act] = []
    for act in acts:
        times = act.goal.quantities.times
        if times > 1 and act.goal.sense is VerbSense.PRESS and not act.goal.hold and act.hold_s == 0.0 and not act.condition:
            once = replace(act, goal=replace(act.goal, quantities=replace(act.goal.quantities, times=1)))
            first = replace(once, note=f"'{act.goal.text}': pressed {MAX_REPEATS} times, not {times}") if times > MAX_REPEATS else once
            out += [first, *(replace(once, wait_before_s=0.0, parallel=False) for _ in range(min(times, MAX_REPEATS) - 1))]
        else:
            out.append(act)
    return out
