"""Counts in words before a unit of measure: "a degree", "a full radian", "an inch and a half", "a half inch", "a dozen
degrees", "a couple of inches", "a few degrees", "several centimetres". The vague ones ("a few") keep what was typed, so
the reading notes the number taken. And numbers said around their unit: "2 and a half inches", "2 inches and a half",
"2 more centimetres" (the number, then its unit, then "more")."""

from __future__ import annotations

from app.engine.lexicon.words import DENOMINATORS
from app.engine.offline.reading.token import Token

_SINGULAR_MEASURES = ("degree", "deg", "radian", "rad", "cm", "mm", "centimeter", "centimetre", "millimeter", "millimetre", "meter", "metre", "°",
                      "decimeter", "decimetre")
_MEASURES = frozenset({*_SINGULAR_MEASURES, *(f"{unit}s" for unit in _SINGULAR_MEASURES), "inch", "inches"})
"""Units a count in words can measure ("a degree", "a couple of inches"); not "foot" ("press it with a foot") nor turns
(read as fractions of a turn)."""
_TURNS = frozenset({"turn", "turns", "revolution", "revolutions", "rotation", "rotations"})
_ONE_INTENSIFIERS = frozenset({"full", "whole", "single", "good", "mere", "bare", "solid"})
_MORE = frozenset({"more", "extra", "further", "additional"})
_FRACTIONS = {"a_quarter": 0.25, "a_third": 1 / 3, "three_quarters": 0.75, "three-quarters": 0.75, "two_thirds": 2 / 3, "two-thirds": 2 / 3}
"""Fractions said straight before a unit ("a quarter metre", "three quarters inch"): that share of one unit."""
_VAGUE_COUNTS = {"a_couple_of": 2.0, "couple": 2.0, "a_couple": 2.0, "a_few": 3.0, "few": 3.0, "several": 4.0}
"""Counts in words a unit follows ("a few degrees"): read with a note that says the number taken."""


def _count(tokens: list[Token], i: int) -> tuple[float, int, bool]:
    """(count, tokens spent before its unit, vague) for "a (full) radian", "an inch and a half", "a couple of inches", "a
    few degrees"; (0, 0, False) when the tokens at ``i`` are no such phrase."""
    word = tokens[i].text
    if i > 0 and (tokens[i - 1].text in ("half", "of", "and") or tokens[i - 1].text in DENOMINATORS):
        return 0.0, 0, False  # "half a metre", "a quarter of an inch": a fraction of the unit; "2 and a half inches"
    j, count, vague = i + 1, 1.0, False
    if word in ("a", "an") and j < len(tokens) and tokens[j].text in ("couple", "half", "dozen"):
        count, vague = {"couple": (2.0, True), "half": (0.5, False), "dozen": (12.0, False)}[tokens[j].text]
        j += 1 + (tokens[j].text == "couple" and j + 1 < len(tokens) and tokens[j + 1].text == "of")
    elif word in ("a", "an") and j < len(tokens) and tokens[j].text in DENOMINATORS and tokens[j].text not in ("half", "quarter", "third"):
        count, j = 1.0 / DENOMINATORS[tokens[j].text], j + 1  # "an eighth inch"
    elif word in ("a", "an"):
        j += j < len(tokens) and tokens[j].text in _ONE_INTENSIFIERS
    elif word in _FRACTIONS:
        count = _FRACTIONS[word]
    elif word in _VAGUE_COUNTS:
        count, vague = _VAGUE_COUNTS[word], True
        j += word in ("couple", "few") and j < len(tokens) and tokens[j].text == "of"
    else:
        return 0.0, 0, False
    if j + 1 < len(tokens) and tokens[j].text in _MORE and vague:
        j += 1  # "a couple more centimetres"
    unit = tokens[j].text if j < len(tokens) else ""
    turns = unit in _TURNS and (vague or count > 1.0)  # "a couple of turns", "a dozen turns" ("a turn" is read with the fractions)
    return (count, j - i, vague) if unit in _MEASURES or turns else (0.0, 0, False)


def _and_a_half(tokens: list[Token], j: int) -> bool:
    return j + 2 < len(tokens) and (tokens[j].text, tokens[j + 1].text, tokens[j + 2].text) == ("and", "a", "half")


def counted_unit(tokens: list[Token], i: int) -> tuple[list[Token], int] | None:
    """The count at ``i`` as a number token followed by its unit, and how many tokens that replaces (None when the
    tokens at ``i`` are no such phrase)."""
    count, spent, vague = _count(tokens, i)
    if not spent:
        return None
    half = count == 1.0 and _and_a_half(tokens, i + spent + 1)
    count += 0.5 * half
    more = [tokens[i + spent - 1]] if tokens[i + spent - 1].text in _MORE else []
    said = " ".join(t.text.replace("_", " ") for t in tokens[i:i + spent - len(more)])
    number = Token(f"{count:g}", f"{count:g}", tokens[i].start, tokens[i + spent - 1].end, number=count, corrected_from=said if vague else None)
    return [number, tokens[i + spent], *more], spent + 1 + 3 * half



def tidy_counts(tokens: list[Token]) -> list[Token]:
    """Numbers said around their unit, put as the amount reader takes them: "2 and a half inches" and "2 inches and a
    half" are 2.5 inches; "2 more centimetres" is "2 centimetres more"."""
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        t = tokens[i]
        if t.number is not None and _and_a_half(tokens, i + 1):
            out.append(Token(f"{t.number + 0.5:g}", f"{t.number + 0.5:g}", t.start, tokens[i + 3].end, number=t.number + 0.5))
            i += 4
        elif t.number is not None and i + 1 < len(tokens) and tokens[i + 1].text in _MEASURES and _and_a_half(tokens, i + 2):
            out += [Token(f"{t.number + 0.5:g}", f"{t.number + 0.5:g}", t.start, t.end, number=t.number + 0.5), tokens[i + 1]]
            i += 5
        elif t.number is not None and i + 2 < len(tokens) and tokens[i + 1].text in _MORE and tokens[i + 2].text in _MEASURES:
            out += [t, tokens[i + 2], tokens[i + 1]]
            i += 3
        else:
            out.append(t)
            i += 1
    return out
