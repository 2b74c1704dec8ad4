"""Number shapes inside a clause: a world axis ("+X", "along negative y"), a fraction of a turn ("5/8 of a turn"),
the unit of the last amount said (for a bare "then 20 more"), a bare relative number, and a signed joint value
("set joint_1 to -1.0 rad")."""

from __future__ import annotations

from typing import Literal

from app.engine.lexicon.words import ANGLE_UNITS, DENOMINATORS, LENGTH_UNITS, RATE_UNITS, TIME_UNITS, TURN_UNITS
from app.engine.offline.reading.tokens import Token

Unit = Literal["fraction", "rad", "m"]
RELATIVE_AFTER = frozenset({"more", "further", "farther", "extra"})
_TWO_PI = 6.283185307179586


def axis_at(tokens: list[Token], i: int) -> tuple[tuple[float, float, float], int] | None:
    text = tokens[i].text
    if len(text) == 2 and text[0] in "+-" and text[1] in "xyz":
        vector = [0.0, 0.0, 0.0]
        vector["xyz".index(text[1])] = -1.0 if text[0] == "-" else 1.0
        return (vector[0], vector[1], vector[2]), 1
    if text in ("positive", "negative") and i + 1 < len(tokens) and tokens[i + 1].text in ("x", "y", "z"):
        vector = [0.0, 0.0, 0.0]
        vector["xyz".index(tokens[i + 1].text)] = -1.0 if text == "negative" else 1.0
        return (vector[0], vector[1], vector[2]), 2
    if text in ("x", "y", "z") and i + 1 < len(tokens) and tokens[i + 1].lemma in ("axis", "direction"):
        vector = [0.0, 0.0, 0.0]
        vector["xyz".index(text)] = 1.0
        return (vector[0], vector[1], vector[2]), 2
    return None


_ONE = frozenset({"a", "an", "one", "single"})


def fraction_of_turn(tokens: list[Token], i: int) -> tuple[float, int] | None:
    """(fraction of a turn, tokens read) for "5/8 of a turn", "three-eighths of a revolution" (a number by now), "an eighth of
    a turn", "3 eighths of a turn"."""
    j, fraction, number = i, None, tokens[i].number
    if number is not None and j + 1 < len(tokens) and tokens[j + 1].text in DENOMINATORS:
        fraction, j = number / DENOMINATORS[tokens[j + 1].text], j + 2  # "3 eighths"
    elif tokens[j].text in _ONE and j + 1 < len(tokens) and tokens[j + 1].text in DENOMINATORS and tokens[j + 1].text not in ("half", "quarter", "third"):
        fraction, j = 1.0 / DENOMINATORS[tokens[j + 1].text], j + 2  # "an eighth" ("a quarter" / "a third" are read elsewhere)
    elif tokens[j].text in DENOMINATORS and j + 1 < len(tokens) and tokens[j + 1].text == "of":
        fraction, j = 1.0 / DENOMINATORS[tokens[j].text], j + 1  # "eighth of a turn", "quarter of a turn" with no article
    elif number is not None and 0 < number < 1:
        fraction, j = number, j + 1  # "5/8", "0.375"
    if fraction is None or j >= len(tokens) or tokens[j].text != "of":
        return None
    j += 1
    if j < len(tokens) and tokens[j].text in _ONE:
        j += 1
    if j < len(tokens) and tokens[j].lemma in TURN_UNITS:
        return fraction, j + 1 - i
    return None


def unit_factor(lemma: str) -> tuple[str, float] | None:
    """(kind, factor to SI) of a unit word: "degree" -> ("rad", pi/180), "turn" -> ("rad", 2 pi), "cm" -> ("m", 0.01),
    "s" -> ("s", 1), "percent" -> ("fraction", 0.01); ``None`` for any other word ("in" is never inches here)."""
    if lemma in ANGLE_UNITS:
        return "rad", ANGLE_UNITS[lemma]
    if lemma in TURN_UNITS:
        return "rad", TURN_UNITS[lemma] * _TWO_PI
    if lemma in LENGTH_UNITS and lemma != "in":
        return "m", LENGTH_UNITS[lemma]
    if lemma in TIME_UNITS:
        return "s", TIME_UNITS[lemma]
    if lemma == "percent":
        return "fraction", 0.01
    return None


def said_unit(tokens: list[Token]) -> tuple[Unit, float] | None:
    """The unit of the last measured amount in ``tokens`` ("30 degrees" -> rad per degree), for a bare "20 more" after it."""
    found: tuple[Unit, float] | None = None
    for i in range(len(tokens) - 1):
        unit = unit_factor(tokens[i + 1].lemma) if tokens[i].number is not None else None
        if unit is not None and unit[0] in ("rad", "m"):
            found = ("rad" if unit[0] == "rad" else "m", unit[1])
    return found


def bare_relative(tokens: list[Token], i: int) -> bool:
    """A number without a unit that says how much more: "20 more", "another 15", "back 5"."""
    after = tokens[i + 1].text if i + 1 < len(tokens) else ""
    before = tokens[i - 1].text if i > 0 else ""
    return after in RELATIVE_AFTER or before in ("another", "additional", "back", "by")


def target_value(tokens: list[Token]) -> float | None:
    """"set joint_1 to -1.0 rad", "to 0.2": a signed joint value (SI units; a bare number is taken as is)."""
    for i in range(len(tokens) - 1):
        if tokens[i].text not in ("to", "=", "at") or tokens[i + 1].number is None:
            continue
        number = tokens[i + 1].number
        if number is None:
            continue
        unit = tokens[i + 2].lemma if i + 2 < len(tokens) else ""
        if unit in ANGLE_UNITS:
            return number * ANGLE_UNITS[unit]
        if unit in LENGTH_UNITS:
            return number * LENGTH_UNITS[unit]
        return number
    return None



_PER = frozenset({"per", "a", "an", "every", "each", "/"})
_COUNTS = {"half": 0.5, "a_half": 0.5, "quarter": 0.25, "a_quarter": 0.25, "a": 1.0, "an": 1.0, "one": 1.0}
"""Counts said as words before a unit of a rate ("half a turn per second", "a quarter turn a second")."""


def _count(tokens: list[Token], i: int) -> tuple[float, int] | None:
    if tokens[i].number is not None:
        return abs(tokens[i].number or 0.0), i + 1
    count = _COUNTS.get(tokens[i].text)
    if count is None:
        return None
    j = i + 1
    if count < 1.0 and j < len(tokens) and tokens[j].text == "of":
        j += 1
    if count < 1.0 and j < len(tokens) and tokens[j].text in ("a", "an"):
        j += 1
    return count, j


def rate_at(tokens: list[Token], i: int) -> tuple[Literal["omega", "speed"], float, int] | None:
    """(quantity, value in rad/s or m/s, tokens read) of a rate at ``i``: an amount per time ("1 radian per second",
    "5 cm per second", "90 degrees a second", "half a turn per second", "10 cm every second") or a rate unit of the
    lexicon ("2 rad/s", "30 rpm", "90 degrees per second" once joined), else None."""
    counted = _count(tokens, i)
    if counted is None or counted[1] >= len(tokens):
        return None
    number, j = counted
    named = RATE_UNITS.get(tokens[j].text.replace("_", " "))
    if named is not None and tokens[i].number is not None:
        return ("omega" if named[0] == "omega" else "speed"), number * named[1], 2
    if j + 2 >= len(tokens) or tokens[j + 1].text not in _PER or tokens[j + 2].lemma not in TIME_UNITS:
        return None
    unit, seconds, read = tokens[j].lemma, TIME_UNITS[tokens[j + 2].lemma], j + 3 - i
    if unit in ANGLE_UNITS:
        return "omega", number * ANGLE_UNITS[unit] / seconds, read
    if unit in TURN_UNITS:
        return "omega", number * _TWO_PI / seconds, read
    if unit in LENGTH_UNITS and unit != "in":
        return "speed", number * LENGTH_UNITS[unit] / seconds, read
    return None
