"""Steps told after the step they come before: "let the lever go back up after holding it down for 2 s", "release the
lever, but only after you've depressed it fully and held it down for 3 s". The earlier step is put first; an "it" in it
points forward to the part of the step it precedes, and a step joined to it by "and" goes with it."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.offline.reading.clauses import Link

if TYPE_CHECKING:
    from app.engine.offline.reading.acts import Act


def put_in_order(acts: list[Act], act: Act, moved: int | None) -> int | None:
    """Put ``act`` in ``acts`` (in execution order); the index of a step put first, for the steps joined to it."""
    frame = act.goal
    if frame.goes_first and acts:
        main = acts[-1].goal
        if frame.themes and all(m.pronoun for m in frame.themes) and main.themes and not any(m.pronoun for m in main.themes):
            act = replace(act, goal=replace(frame, themes=main.themes))  # "after holding it down": the lever of the step it precedes
        acts.insert(len(acts) - 1, act)
        return len(acts) - 2
    if moved is not None and frame.conjoined and frame.marker == "and" and frame.link is Link.SEQUENCE and frame.verb is not None and (
            not frame.themes or all(m.pronoun for m in frame.themes)):
        acts.insert(moved + 1, act)  # "after you've depressed it fully and held it down for 3 s": both go first
        return moved + 1
    acts.append(act)
    return None
