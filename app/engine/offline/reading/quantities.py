"""Quantities of one clause, read from its tokens: how far (and from where), how fast, how long, which way, and end
orientations.

An amount carries what it is measured from: ``closed`` for an end position ("to 30 degrees", "30 degrees from closed",
"open by 20 degrees"), ``current`` for an increment ("another 10 degrees", "10 cm more", "by 5 cm"), ``None`` where the
verb decides (the resolver's conventions)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal

from app.engine.lexicon.relations import VIEWER_WORDS as _VIEWER_WORDS
from app.engine.lexicon.words import (
    AMOUNTS,
    ANGLE_UNITS,
    COMPARATIVES,
    DIRECTIONS,
    LENGTH_UNITS,
    LOOSE_AMOUNTS,
    MULTIPLIERS,
    OBJECT_NOUNS,
    ROTATION_SENSE,
    SPATIAL,
    SPEEDS,
    STATES,
    TIME_UNITS,
    TO_THE_END,
    TURN_UNITS,
)
from app.engine.offline.reading.numbers import RELATIVE_AFTER as _RELATIVE_AFTER
from app.engine.offline.reading.numbers import Unit, axis_at, bare_relative, fraction_of_turn, rate_at, target_value
from app.engine.offline.reading.part_words import shape_adjective
from app.engine.offline.reading.tokens import Token

Reference = Literal["closed", "current"]
_TO = frozenset({"to", "until"})
_RELATIVE_BEFORE = frozenset({"another", "additional", "extra", "further", "by"})
_ABOUT = frozenset({"about", "around", "roughly", "approximately", "exactly", "just", "nearly", "almost", "some", "only"})
_DURATION_BEFORE = frozenset({"for", "over", "during", "in", "within", "taking", "lasting"})
_FRACTION_WORDS = {"quarter": 0.25, "half": 0.5, "full": 1.0, "complete": 1.0, "whole": 1.0, "one": 1.0, "a": 1.0, "single": 1.0}
_CLOSED_WORDS = frozenset({"closed", "shut", "close"})
_NEAR_STATES = _CLOSED_WORDS | {"open", "opened", "flat", "upright", "vertical", "horizontal", "level", "straight", "down", "up"}


_DURATION_PHRASES = {"a_couple_of_seconds": 2.0, "a_few_seconds": 3.0, "a_second_and_a_half": 1.5, "half_a_second": 0.5,
                     "a_full_second": 1.0, "a_whole_second": 1.0, "a_full_minute": 60.0, "a_whole_minute": 60.0}
_POSITION_DIRECTIONS = {"to_the_top": "up", "to_the_very_top": "up", "to_the_bottom": "down", "to_the_very_bottom": "down",
                        "as_high_as_it_goes": "up", "as_high_as_possible": "up", "as_low_as_it_goes": "down", "as_low_as_possible": "down"}
_SIDE_PREPS = frozenset({"toward", "towards", "against", "onto", "over"})
_SIDE_DIRECTIONS = {"front": "forward", "back": "backward", "rear": "backward", "left": "left", "right": "right", "left-hand": "left", "right-hand": "right",
                    **dict.fromkeys(("me", "you", "us", "viewer", "camera", "user"), "forward"), "wall": "backward"}


def _viewer_after(tokens: list[Token], i: int) -> bool:
    """"(closer) to me", "(nearer) the camera": the viewer follows."""
    words = [t.text for t in tokens[i:i + 3] if t.text not in ("to", "the")]
    return bool(words) and words[0] in _VIEWER_WORDS


def _side_after(tokens: list[Token], j: int) -> str | None:
    """"(toward) the front / the back of the bucket / the left side": a side of the object as a direction."""
    while j < len(tokens) and tokens[j].text in ("the", "its", "their", "it's"):
        j += 1
    if j < len(tokens) and tokens[j].text in _SIDE_DIRECTIONS:
        return _SIDE_DIRECTIONS[tokens[j].text]
    return None


@dataclass(frozen=True)
class Amount:
    """How far: a fraction of the part's range, or an angle (rad) or a distance (m)."""

    value: float
    unit: Unit
    reference: Reference | None = None
    loose: bool = False
    """A reading of a vague word ("slightly", "a bit")."""
    words: str = ""


@dataclass(frozen=True)
class Quantities:
    amount: Amount | None = None
    speed_factor: float = 1.0
    duration_s: float | None = None
    omega_radps: float | None = None
    speed_mps: float | None = None
    direction: str | None = None
    """forward, backward, left, right, up, down, sideways (as seen facing the object)."""
    target: float | None = None
    """A signed joint value after "to" (used when a part is named by its URDF joint or link name)."""
    sense: str | None = None
    """cw / ccw as seen facing the part."""
    axis: tuple[float, float, float] | None = None
    """A world axis named in the prompt ("+X", "along negative y")."""
    orientation: str | None = None
    """vertical or flat (an end orientation: "until the lid is upright")."""
    onto_body: bool = False
    """The part ends lying on the body ("flat against the box", "flush with the front"): its shut end."""
    times: int = 1
    """"twice", "three times"."""
    used: frozenset[int] = field(default_factory=frozenset)
    """Token indices these quantities were read from."""


_STATE_COPULAS = frozenset({"is", "it's", "stands", "sits", "stays", "remains", "be", "hangs", "left", "leave", "keep"})


def _clock_turn(tokens: list[Token], i: int) -> tuple[Amount, str] | None:
    """"from 12 o'clock to 2 o'clock": the shorter way round the dial face, 30 degrees an hour."""
    words = [t.text for t in tokens[i:i + 6]]
    if len(words) < 6 or words[0] != "from" or words[2] != "o'clock" or words[3] != "to" or words[5] != "o'clock":
        return None
    start, end = tokens[i + 1].number, tokens[i + 4].number
    if start is None or end is None:
        return None
    hours = (end - start) % 12
    sense = "cw" if hours <= 6 else "ccw"
    hours = hours if hours <= 6 else 12 - hours
    return Amount(hours * math.pi / 6, "rad", reference="current", words=" ".join(words)), sense


def unit_is_angle(tokens: list[Token], end: int) -> bool:
    return end > 0 and tokens[end - 1].lemma in ANGLE_UNITS


def _reference(tokens: list[Token], start: int, end: int) -> Reference | None:
    """What an amount at tokens[start:end] is measured from, from the words around it."""
    before = [t.text for t in tokens[max(0, start - 4):start] if t.text not in _ABOUT and t.text not in ("only", "just")]
    after = [t.text for t in tokens[end:end + 4] if t.text != "measured"][:3]  # "90 degrees (measured) from closed"
    if after[:2] in (["up", "from"], ["down", "from"], ["out", "from"], ["open", "from"]):
        after = [t.text for t in tokens[end + 1:end + 5] if t.text != "measured"][:3]  # "90 degrees up from closed": the way, then the zero
    later = [t.text for t in tokens[end:end + 10]]
    since = next((k for k, w in enumerate(later[:4]) if w == "from" and all(v in (",", "measured", "counting", "counted") for v in later[:k])), None)
    if since is not None and any(w in _CLOSED_WORDS for w in later[since + 1:since + 6]):
        return "closed"  # "30 degrees, measured from where it sits shut"; "by 0.52 rad, counting from where it's shut"
    if (before and before[-1] in _RELATIVE_BEFORE) or (after and after[0] in _RELATIVE_AFTER):  # not "should be open by 10 cm", "tilt it open by 20 degrees"
        return "closed" if before[-1:] == ["by"] and before[-2:-1] in (["open"], ["opened"], ["ajar"]) else "current"  # how far open it stands, from shut
    around = after + [t.text for t in tokens[end + 3:end + 5]] + [t.text for t in tokens[max(0, start - 3):start]]
    if after and after[0] in ("open", "opened") and before[-1:] != ["by"]:
        return "closed"  # "nearly shut, just 10 degrees open": a position, measured from closed
    if any(word in ("sticks", "sticking", "stick", "protrudes", "protruding", "showing", "shows", "in_total", "gap", "opening", "ajar")
           for word in around):
        return "closed"  # "until only 5 cm of it sticks out": how far out, measured from closed
    if before and before[-1] in ("open", "opened", "ajar") and len(before) > 1 and before[-2] in _STATE_COPULAS:
        return "closed"  # "until it is open only about 45 degrees": a position, measured from closed
    if {"angle", "between"} <= {t.text for t in tokens[max(0, start - 10):start]}:
        return "closed"  # "the angle between it and the keyboard is 45 degrees": the angle the part makes, from shut
    if before[-2:] in (["angle", "of"], ["opening", "of"], ["angle", "to"]) or (after[:1] == ["angle"] and before[-1:] not in (["through"], ["by"])):
        return "closed"  # "at an angle of 120 degrees", "makes a 45 degree angle with the keyboard": the part's angle, from shut
    if (before and before[-1] in _TO) or before[-2:] == ["up", "to"] or (before and before[-1] == "at" and unit_is_angle(tokens, end)):
        return "closed"
    zero = next((later[k + 1:k + 6] for k in range(min(2, len(later))) if later[k] in ("from", "off", "past")), [])  # "... out from the fully shut"
    if len(after) >= 2 and any(w in _CLOSED_WORDS for w in [w for w in zero if w not in ("the", "fully", "completely", "its")][:1]):
        return "closed"
    if len(after) >= 2 and after[0] in ("above", "over", "clear_of") and after[1] in ("the", "its") and "current" not in after:
        return "closed"  # "so it hovers 10 cm above the pot": a height over what it closes on
    if since is not None and {"where", "now", "current", "currently", "here", "present"} & set(later[since + 1:since + 5]):
        return "current"  # "raise the lid 30 degrees from where it is"
    if (after[:1] and after[0] in COMPARATIVES) or ("than" in later[:4] and {"now", "is", "currently"} & set(later[:7])):
        return "current"  # "lift the lid 20 degrees higher than it is now"
    return None


def _markers(tokens: list[Token], start: int, end: int) -> set[int]:
    """Indices of the words around an amount that say what it is measured from ("another", "more")."""
    out = {j for j in range(max(0, start - 2), start) if tokens[j].text in _RELATIVE_BEFORE | _ABOUT | _TO}
    out.update(j for j in range(end, min(len(tokens), end + 1)) if tokens[j].text in _RELATIVE_AFTER)
    return out


_TURN_FRACTIONS = frozenset({"three quarters", "three-quarters", "a third", "one third", "two thirds", "two-thirds", "a quarter",
                             "one quarter", "half", "full"})
"""Amount words that may count turns ("a third of a turn"); "as far as it will turn" is all the way, not one turn."""
_OF_RANGE = frozenset({"the", "its", "their", "full", "whole", "entire", "total", "available", "way", "travel", "range", "extension",
                       "stroke", "opening", "swing", "motion", "run"})
"""Words of "(2/3) of the full extension": the range an amount is a fraction of."""


_BODY_NOUNS = frozenset({*OBJECT_NOUNS, "body", "base", "frame", "case", "shell", "housing", "carcass", "keyboard"}) - {
    "table", "desk", "floor", "ground", "counter", "worktop", "bench", "workbench", "shelf"}
"""What a part shuts flat on; a surface the object stands on is not one ("flat on the table": laid open)."""


def _on_the_body(tokens: list[Token], i: int) -> bool:
    """"(flat) on the box", "onto its body", "against the case": what the part closes on."""
    words = [t.text for t in tokens[i:i + 4]]
    lower_half = bool({"lower", "bottom"} & set(words[1:])) and bool({"half", "part", "section"} & set(words[1:]))  # "on the lower half"
    return bool(words) and words[0] in ("on", "onto", "against", "down_on") and (any(w in _BODY_NOUNS for w in words[1:]) or lower_half)


def _against_a_face(tokens: list[Token], i: int) -> bool:
    """"(flat) against the front", "flush with the frame", "flush in its frame", "flat against it": lying on a face of the body."""
    words = [t.text for t in tokens[i:i + 4]]
    return bool(words) and ((words[0] in ("against", "with", "in", "into", "on", "onto", "toward", "towards") and bool({"front", "frame", "face"} & set(words)))
                            or words[:2] in (["against", "it"], ["against", "them"]))


def _region_noun(tokens: list[Token], i: int) -> bool:
    """"the front half of the case", "the top half": a part of the object, not an amount."""
    previous = tokens[i - 1].text if i > 0 else ""
    following = tokens[i + 1].text if i + 1 < len(tokens) else ""
    return tokens[i].text == "half" and (previous in SPATIAL or (previous in ("the", "its") and following == "of"))


def read_quantities(tokens: list[Token], carried: tuple[Unit, float] | None = None, *, correction: bool = False) -> Quantities:
    """Everything quantitative in one clause's tokens; ``carried`` is the unit of the amount said before
    (a bare "then 20 more" takes it, and so does the bare number of a correction: "... no wait, make it 45")."""
    values: dict[str, object] = {}
    used: set[int] = set()
    amount: Amount | None = None
    i, shut_words = 0, any(t.text in _CLOSED_WORDS for t in tokens)  # "fold it flat shut", "close it flat": its shut end
    while i < len(tokens):
        token, nxt = tokens[i], tokens[i + 1] if i + 1 < len(tokens) else None
        clock = _clock_turn(tokens, i)
        if clock is not None and amount is None:
            amount, values["sense"] = clock
            used.update(range(i, i + 6))
            i += 6
            continue
        of_turn = fraction_of_turn(tokens, i) if amount is None else None
        if of_turn is not None:
            amount = Amount(of_turn[0] * 2 * math.pi, "rad", words=" ".join(t.text for t in tokens[i:i + of_turn[1]]))
            used.update(range(i, i + of_turn[1]))
            i += of_turn[1]
            continue
        axis = axis_at(tokens, i)
        if axis is not None:
            values["axis"] = axis[0]
            used.update(range(i, i + axis[1]))
            i += axis[1]
            continue
        if token.number is not None and nxt is not None and nxt.text in ("full", "complete", "whole") and i + 2 < len(tokens) and tokens[i + 2].lemma in TURN_UNITS:
            amount = Amount(abs(token.number) * 2 * math.pi, "rad", words=f"{token.text} {nxt.text} {tokens[i + 2].text}")  # "two full turns"
            used.update((i, i + 1, i + 2))
            i += 3
            continue
        if token.number is not None and carried is not None and amount is None and (bare_relative(tokens, i) or correction) and (
                nxt is None or not (nxt.lemma in ANGLE_UNITS or nxt.lemma in TURN_UNITS or nxt.lemma in LENGTH_UNITS or nxt.lemma in TIME_UNITS)):
            relative = bare_relative(tokens, i)
            amount = Amount(abs(token.number) * carried[1], carried[0], "current" if relative else None,
                            words=f"{token.text} {nxt.text if nxt and relative else ''}".strip())
            used.add(i)
            used.update(j for j in (i - 1, i + 1) if 0 <= j < len(tokens) and tokens[j].text in _RELATIVE_AFTER | _RELATIVE_BEFORE)
            i += 1
            continue
        if token.number is not None and 0 < token.number < 1 and nxt is not None and nxt.text == "of" and amount is None:
            j = i + 2  # "2/3 of the full extension", "0.4 of its travel": a fraction of the range
            while j < min(len(tokens), i + 6) and tokens[j].text in _OF_RANGE:
                j += 1
            amount = Amount(token.number, "fraction", words=" ".join(t.text for t in tokens[i:j]))
            used.update(range(i, j))
            i = j
            continue
        if (rate := rate_at(tokens, i)) is not None:  # "5 cm per second", "half a turn per second"
            values["omega_radps" if rate[0] == "omega" else "speed_mps"] = rate[1]
            used.update(range(i, i + rate[2]))
            i += rate[2]
            continue
        if token.number is not None and nxt is not None:
            unit = nxt.lemma
            if unit in ANGLE_UNITS:
                amount = Amount(abs(token.number) * ANGLE_UNITS[unit], "rad", _reference(tokens, i, i + 2), words=f"{token.text} {nxt.text}")
            elif unit in TURN_UNITS:
                amount = Amount(abs(token.number) * 2 * math.pi, "rad", _reference(tokens, i, i + 2), words=f"{token.text} {nxt.text}")
            elif unit in LENGTH_UNITS and not (unit == "in" and i + 2 < len(tokens) and tokens[i + 2].text in ("the", "a", "its")):
                amount = Amount(abs(token.number) * LENGTH_UNITS[unit], "m", _reference(tokens, i, i + 2), words=f"{token.text} {nxt.text}")
            elif unit in TIME_UNITS:
                values["duration_s"] = token.number * TIME_UNITS[unit]
                used.update(j for j in (i - 1,) if j >= 0 and tokens[j].text in _DURATION_BEFORE)
            elif unit == "percent":
                amount = Amount(min(token.number / 100.0, 1.0), "fraction", words=f"{token.text}%")
            elif nxt.lemma == "time" or nxt.text == "times":
                values["times"] = max(1, round(token.number))
            else:
                i += 1
                continue
            used.update((i, i + 1))
            used.update(_markers(tokens, i, i + 2))
            i += 2
            continue
        if token.text in ("half", "a", "an", "one", "quarter") and nxt is not None and (nxt.text in ("a", "an") or token.text in ("a", "an")):
            # "half a metre", "a foot", "a quarter of a metre"
            j = i + (2 if nxt.text in ("a", "an") else 1)
            if j < len(tokens) and tokens[j].lemma in LENGTH_UNITS and tokens[j].text not in ("in", "m"):
                factor = {"half": 0.5, "quarter": 0.25}.get(token.text, 1.0)
                amount = Amount(factor * LENGTH_UNITS[tokens[j].lemma], "m", words=" ".join(t.text for t in tokens[i:j + 1]))
                used.update(range(i, j + 1))
                i = j + 1
                continue
        if token.text in ("seen", "viewed", "looking", "looked") and nxt is not None and nxt.text == "from":
            # "(as) seen from above / from the front": a viewpoint, not a part
            j = i
            while j < len(tokens) and not tokens[j].is_punct and tokens[j].text not in ("then", "and_then", "and", "by", "to"):
                used.add(j)
                j += 1
            if i > 0 and tokens[i - 1].text == "as":
                used.add(i - 1)
            i = j
            continue
        if "-" in token.text and token.text.split("-")[0] in DIRECTIONS and "direction" not in values:
            values["direction"] = DIRECTIONS[token.text.split("-")[0]]  # "the forward-rolling direction"
            used.add(i)
        pronoun_one = token.text == "one" and i > 0 and (tokens[i - 1].text in SPATIAL or tokens[i - 1].text in ("the", "other", "that"))
        if token.text in _FRACTION_WORDS and nxt is not None and not pronoun_one:
            # "a quarter turn", "half a turn", "a full rotation", "one complete turn"
            j = i + 1
            fraction = _FRACTION_WORDS[token.text]
            while j < len(tokens) and tokens[j].text in _FRACTION_WORDS and j < i + 3:
                fraction = _FRACTION_WORDS[tokens[j].text] if tokens[j].text not in ("a", "one", "single") else fraction
                j += 1
            if j < len(tokens) and tokens[j].lemma in TURN_UNITS and (j > i + 1 or token.text in ("quarter", "half", "full")):
                amount = Amount(fraction * 2 * math.pi, "rad", words=" ".join(t.text for t in tokens[i:j + 1]))
                used.update(range(i, j + 1))
                used.update(_markers(tokens, i, j + 1))  # "then another full turn": more of the same, not the other part
                i = j + 1
                continue
        if token.text.replace("_", " ") in AMOUNTS and nxt is not None:
            # "a quarter turn", "a third of a turn", "three quarters of a revolution"
            j = i + 1
            if tokens[j].text == "of" and j + 1 < len(tokens) and tokens[j + 1].text in ("a", "an", "one"):
                j += 2
            words = " ".join(t.text.replace("_", " ") for t in tokens[i:j + 1])
            if j < len(tokens) and tokens[j].lemma in TURN_UNITS and token.text.replace("_", " ") in _TURN_FRACTIONS:
                amount = Amount(AMOUNTS[token.text.replace("_", " ")] * 2 * math.pi, "rad", words=words)
            elif j > i + 1 and j < len(tokens) and tokens[j].lemma in LENGTH_UNITS:  # "a quarter of a metre"
                amount = Amount(AMOUNTS[token.text.replace("_", " ")] * LENGTH_UNITS[tokens[j].lemma], "m", words=words)
            if amount is not None and amount.words == words:
                used.update(range(i, j + 1))
                i = j + 1
                continue
        if token.text == "right_angle":
            amount = Amount(math.pi / 2, "rad", _reference(tokens, i, i + 1) or "closed", words="a right angle")  # a position: 90 degrees open
            used.add(i)
            i += 1
            continue
        if token.text in _DURATION_PHRASES:
            values["duration_s"] = _DURATION_PHRASES[token.text]
            used.add(i)
            i += 1
            continue
        if token.text in _POSITION_DIRECTIONS and "direction" not in values:
            values["direction"] = _POSITION_DIRECTIONS[token.text]  # "to the very top": all the way up
        if token.text == "away" and nxt is not None and nxt.text == "from" and i + 2 < len(tokens) and (
                tokens[i + 2].text in _VIEWER_WORDS or (tokens[i + 2].text == "the" and i + 3 < len(tokens) and tokens[i + 3].text in _VIEWER_WORDS)):
            values.setdefault("direction", "backward")  # "push it 20 cm away from me"
        if token.text in ("closer", "nearer", "near") and _viewer_after(tokens, i + 1):
            values.setdefault("direction", "forward")  # "10 cm closer to me", "near to me"
        if token.text in _SIDE_PREPS and nxt is not None:
            side = _side_after(tokens, i + 1)
            if side is not None and "direction" not in values:
                values["direction"] = side  # "fold the handle down toward the front", "let it fall against the back"
        if token.text in MULTIPLIERS:
            values["times"] = int(MULTIPLIERS[token.text])
            used.add(i)
        elif token.text in ("almost", "nearly") and amount is None and nxt is not None and (tokens[i + 1].text in _NEAR_STATES or tokens[i + 1].text in TO_THE_END):
            amount = Amount(0.9, "fraction", loose=True, words=f"{token.text} {tokens[i + 1].text}")  # "almost shut": most of the way
            used.add(i)
        elif token.text.replace("_", " ") in AMOUNTS and amount is None and not _region_noun(tokens, i):
            phrase = token.text.replace("_", " ")
            amount = Amount(AMOUNTS[phrase], "fraction", loose=phrase in LOOSE_AMOUNTS, words=phrase)
            used.add(i)
            if token.text in ("as_far_as", "as_wide_as", "as_high_as"):  # "as far as its hinge allows": the rest only says "all the way"
                j = i + 1
                while j < len(tokens) and not tokens[j].is_punct and tokens[j].text not in ("then", "and_then"):
                    used.add(j)
                    j += 1
        elif token.text in SPEEDS and "speed_factor" not in values:
            values["speed_factor"] = SPEEDS[token.text]
            used.add(i)
        elif token.text.replace("_", "-") in ROTATION_SENSE or token.text in ROTATION_SENSE:
            values["sense"] = ROTATION_SENSE.get(token.text, ROTATION_SENSE.get(token.text.replace("_", "-"), None))
            used.add(i)
        elif token.text == "back" and nxt is not None and nxt.text in TO_THE_END and "direction" not in values and i > 0 and (
                tokens[i - 1].text not in ("it", "them", "bring", "put", "go", "come", "get", "move", "set")):
            values["direction"] = "backward"  # "push the screen back as far as it'll go": that way to its end (a drawer: shut)
        elif token.text == "back" and i > 0 and tokens[i - 1].text in ("further", "farther", "more") and "direction" not in values:
            values["direction"] = "backward"  # "5 cm further back"
            used.update((i - 1, i))
        elif (token.text in DIRECTIONS and "direction" not in values) or token.text in ("to_the_left", "to_the_right"):
            values["direction"] = DIRECTIONS[token.text] if token.text in DIRECTIONS else token.text.rsplit("_", 1)[1]
            used.add(i)
        elif token.text in ("flat", "flush") and (_on_the_body(tokens, i + 1) or _against_a_face(tokens, i + 1) or shut_words):
            used.add(i)  # "down flat on the box", "fold it flat shut": shut on the body, not the other flat pose
            values["onto_body"] = True
        elif ((token.text in STATES and STATES[token.text] in ("vertical", "flat")) or token.text == "straight_up") and not shape_adjective(tokens, i):
            values["orientation"] = STATES.get(token.text, "vertical")
            used.add(i)
        elif token.text in ("moment", "beat", "second", "sec") and i > 0 and tokens[i - 1].text in ("a", "one"):
            values.setdefault("duration_s", 1.0)
            used.update((i - 1, i))
        i += 1
    if tokens and tokens[0].lemma == "stand" and "orientation" not in values and any(t.text in ("up", "upright") for t in tokens):
        values["orientation"] = "vertical"  # "stand the handle up (again)": upright
    target = target_value(tokens)
    if target is not None:
        values["target"] = target
    return Quantities(amount=amount, used=frozenset(used), **values)  # type: ignore[arg-type]
