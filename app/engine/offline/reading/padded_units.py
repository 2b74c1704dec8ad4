"""Counts padded with a word of emphasis before their unit: "five long seconds", "a full 3 seconds", "two good
centimetres", "3 whole degrees", "two whole times". The emphasis is dropped so the count reads as the measure it is (before this stage
"stays open for five long seconds" lost its five seconds, and the hold lasted a blink)."""

from __future__ import annotations

from app.engine.lexicon.words import ANGLE_UNITS, LENGTH_UNITS, TIME_UNITS
from app.engine.offline.reading.token import Token

_EMPHASIS = frozenset({"long", "full", "whole", "good", "solid", "short", "quick", "brief", "entire", "straight", "clear", "mere"})
_DIMENSIONS = frozenset({"high", "tall", "long", "wide", "deep"})
_COUNTS = frozenset({"time"})
"""Counted repeats ("it spun two whole times": two turns, not "the whole" object for two seconds). Turns keep their word
of emphasis: "two full turns" is read as it stands."""
_UNITS = frozenset({*TIME_UNITS, *LENGTH_UNITS, *ANGLE_UNITS, *_COUNTS})


def _unit(word: str) -> bool:
    return word in _UNITS or (word.endswith("s") and word[:-1] in _UNITS) or (word.endswith("es") and word[:-2] in _UNITS)


def padded_units(tokens: list[Token]) -> list[Token]:
    """``tokens`` without a word of emphasis between a number and its unit, nor a dimension said after the unit ("one
    whole metre high": a metre)."""
    tokens = [t for k, t in enumerate(tokens) if not (
        t.text in _EMPHASIS and 0 < k < len(tokens) - 1 and tokens[k - 1].number is not None and _unit(tokens[k + 1].text) and not (
            tokens[k + 1].text.rstrip("s") in _COUNTS and (t.text != "whole" or tokens[k - 1].text in ("a", "an"))))]  # "two whole times" only
    return [t for k, t in enumerate(tokens) if not (t.text in _DIMENSIONS and k > 1 and _unit(tokens[k - 1].text) and tokens[k - 2].number is not None)]
