"""A time said with "for" after a motion to an end ("I need the bin open for about five seconds", "open the door for 3 s,
then shut it"): how long the part stays there, not how long the motion takes ("over 3 s", "in 3 s")."""

from __future__ import annotations

from app.engine.lexicon.verbs import VerbSense
from app.engine.lexicon.words import TIME_UNITS
from app.engine.offline.reading.token import Token

_TO_AN_END = frozenset({VerbSense.OPEN, VerbSense.CLOSE, VerbSense.RAISE, VerbSense.LOWER, VerbSense.PULL_OUT, VerbSense.PUSH_IN})
_ABOUT = frozenset({"about", "around", "roughly", "approximately", "a", "another", "just", "maybe"})


def held_for(tokens: list[Token], sense: VerbSense | None, speed_said: bool) -> bool:
    """Whether a "for <time>" in ``tokens`` is a stay at the end of a motion of ``sense`` (none when a speed is said)."""
    if sense not in _TO_AN_END or speed_said:
        return False
    for i, token in enumerate(tokens):
        if token.text != "for":
            continue
        j = i + 1
        while j < len(tokens) and tokens[j].text in _ABOUT:
            j += 1
        if j + 1 < len(tokens) and tokens[j].number is not None and tokens[j + 1].lemma in TIME_UNITS:
            return True
        if j + 1 < len(tokens) and tokens[j].text in ("few", "couple") and tokens[j + 1].lemma in TIME_UNITS:
            return True  # "for a few seconds"
    return False
