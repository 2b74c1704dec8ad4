"""A clause that only says what the amounts are counted from ("measured from fully shut, I want it open 25 degrees"):
no step of its own; the next amount that names no zero of its own takes it."""

from __future__ import annotations

from app.engine.lexicon.words import STATES
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.quantities import Reference

_COUNTING = frozenset({"measured", "measuring", "counted", "counting", "reckoned", "taken", "starting"})
_HERE = frozenset({"where", "now", "current", "currently", "here", "is", "sits", "rest", "resting"})


def measured_from(frame: Frame) -> Reference | None:
    """The zero a clause such as "measured from fully shut" or "counting from where it is now" names, else None."""
    words = frame.text.split()
    amount = frame.quantities.amount
    if len(words) < 3 or words[0] not in _COUNTING or words[1] != "from" or (amount is not None and amount.unit != "fraction"):
        return None
    if any(STATES.get(w) == "closed" for w in words[2:]):
        return "closed"
    return "current" if _HERE & set(words[2:]) else None
