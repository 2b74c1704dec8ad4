"""Quantities in a prompt clause: amounts, angles, turns, distances, speeds, durations, directions."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace

from app.engine.offline.vocabulary import AMOUNTS, NUMBER_WORDS, ROTATION_SENSE, SPEEDS

_NUM = r"(\d+(?:\.\d+)?|\.\d+)"
_UNITS_M = {"mm": 1e-3, "millimeter": 1e-3, "millimeters": 1e-3, "millimetre": 1e-3, "millimetres": 1e-3,
            "cm": 1e-2, "centimeter": 1e-2, "centimeters": 1e-2, "centimetre": 1e-2, "centimetres": 1e-2,
            "m": 1.0, "meter": 1.0, "meters": 1.0, "metre": 1.0, "metres": 1.0,
            "in": 0.0254, "inch": 0.0254, "inches": 0.0254, "ft": 0.3048, "foot": 0.3048, "feet": 0.3048}
_ANGLE = re.compile(_NUM + r"\s*(?:degrees|degree|deg|°)")
_RADIANS = re.compile(_NUM + r"\s*(?:radians|radian|rad)(?!\s*/|\s*per|ps)")
_TURNS = re.compile(_NUM + r"\s*(?:full\s+)?(?:turns|turn|revolutions|revolution|rotations|rotation|spins|times around)")
_DISTANCE = re.compile(_NUM + r"\s*(" + "|".join(sorted(_UNITS_M, key=len, reverse=True)) + r")\b(?!\s*/|\s*per)")
_OMEGA = re.compile(_NUM + r"\s*(rad/s|rad\s*per\s*second|radps|rad/sec|rpm|revolutions per minute|deg/s|degrees per second)")
_SPEED = re.compile(_NUM + r"\s*(m/s|meters per second|metres per second|cm/s)")
_DURATION = re.compile(r"(?:for|over|during|in|within|taking)\s+(?:about\s+|roughly\s+)?" + _NUM + r"\s*(?:s|sec|secs|second|seconds)\b")
_ABSOLUTE_BEFORE = re.compile(r"\bto\s+(?:about\s+|around\s+|roughly\s+|approximately\s+|exactly\s+|just\s+)?$")
_ABSOLUTE_AFTER = re.compile(r"\s*(?:open\s+)?(?:from|off)\s+(?:the\s+)?(?:closed|shut)\b")
_PERCENT = re.compile(_NUM + r"\s*(?:%|percent|per cent)")
_AXIS = re.compile(r"([+-])\s*([xyz])\b|\b(?:positive|negative)\s+([xyz])\b|\b([xyz])\s*[- ]?axis\b")
_SPECIAL = (
    ("quarter turn", 0.25), ("quarter-turn", 0.25), ("half turn", 0.5), ("half a turn", 0.5), ("half-turn", 0.5),
    ("quarter twist", 0.25), ("quarter-twist", 0.25), ("half twist", 0.5), ("half-twist", 0.5), ("half a twist", 0.5),
    ("full turn", 1.0), ("full rotation", 1.0), ("full revolution", 1.0), ("complete turn", 1.0),
    ("one turn", 1.0), ("a turn", 1.0),
)
DIRECTION_WORDS: dict[str, str] = {
    "forward": "forward", "forwards": "forward", "ahead": "forward", "backward": "backward", "backwards": "backward",
    "back": "backward", "to the left": "left", "to the right": "right", "leftward": "left", "leftwards": "left",
    "rightward": "right", "rightwards": "right", "up": "up", "upward": "up", "upwards": "up",
    "down": "down", "downward": "down", "downwards": "down", "away": "away", "toward": "toward", "towards": "toward",
}


@dataclass(frozen=True)
class Quantity:
    """What a clause says about how much, how fast and which way."""

    fraction: float | None = None
    angle_rad: float | None = None
    distance_m: float | None = None
    omega_radps: float | None = None
    speed_mps: float | None = None
    duration_s: float | None = None
    speed_factor: float = 1.0
    sense: str | None = None
    axis: tuple[float, float, float] | None = None
    direction: str | None = None
    orientation: str | None = None
    """``vertical`` (upright, straight up) or ``flat`` (horizontal, lies flat)."""
    absolute: bool = False
    """The angle is an opening measured from closed ("to 30 degrees", "45 degrees from closed"), not an increment."""

    def merged(self, other: Quantity) -> Quantity:
        """``self`` with unset fields taken from ``other``."""
        values = {k: getattr(self, k) if getattr(self, k) is not None else getattr(other, k) for k in self.__dataclass_fields__}
        values["speed_factor"] = self.speed_factor if self.speed_factor != 1.0 else other.speed_factor
        values["absolute"] = self.absolute if self.angle_rad is not None else other.absolute
        return Quantity(**values)


def words_to_numbers(text: str) -> str:
    """Replace spelled-out numbers before units ("two seconds", "ninety degrees")."""
    pattern = re.compile(r"\b(" + "|".join(sorted((w for w in NUMBER_WORDS if w not in ("a", "an", "half", "quarter")), key=len, reverse=True)) + r")\b")
    return pattern.sub(lambda m: f"{NUMBER_WORDS[m.group(1)]:g}", text)


def _axis(text: str) -> tuple[float, float, float] | None:
    match = _AXIS.search(text)
    if match is None:
        return None
    sign_char, letter, signed_word, plain = match.groups()
    if letter:
        sign = -1.0 if sign_char == "-" else 1.0
    elif signed_word:
        letter = signed_word
        sign = -1.0 if "negative" in match.group(0) else 1.0
    else:
        letter, sign = plain, 1.0
    axis = [0.0, 0.0, 0.0]
    axis["xyz".index(letter)] = sign
    return (axis[0], axis[1], axis[2])


def _amount(text: str) -> float | None:
    percent = _PERCENT.search(text)
    if percent:
        return min(1.0, float(percent.group(1)) / 100.0)
    found = []
    for phrase in AMOUNTS:
        match = re.search(r"(?<![\w-])" + re.escape(phrase) + r"(?![\w-])", text)
        if match:
            found.append((match.start(), -len(phrase), AMOUNTS[phrase]))
    return min(found)[2] if found else None


def _turn_angle(text: str) -> float | None:
    match = _TURNS.search(text)
    if match:
        return 2 * math.pi * float(match.group(1))
    for phrase, turns in _SPECIAL:
        if phrase in text:
            return 2 * math.pi * turns
    counted = re.search(r"\b(twice|thrice)\b", text)
    if counted:
        return 2 * math.pi * (2 if counted.group(1) == "twice" else 3)
    if re.search(r"\bunscrew|\bloosen", text):
        return 2 * math.pi
    return None


def _omega(text: str) -> float | None:
    match = _OMEGA.search(text)
    if not match:
        return None
    value, unit = float(match.group(1)), match.group(2)
    if unit.startswith(("rpm", "revolutions")):
        return value * 2 * math.pi / 60.0
    if unit.startswith(("deg", "degrees")):
        return math.radians(value)
    return value


def parse_quantity(clause: str) -> Quantity:
    """Every quantity mentioned in one clause (lower case text)."""
    text = re.sub(r"\bhalf an?\s+(metre|meter|foot|inch|centimetre|centimeter)\b", r"0.5 \1", words_to_numbers(clause))
    angle = None
    absolute = False
    for pattern, convert in ((_ANGLE, math.radians), (_RADIANS, float)):
        match = pattern.search(text)
        if match:
            angle = convert(float(match.group(1)))
            absolute = bool(_ABSOLUTE_BEFORE.search(text[: match.start()]) or _ABSOLUTE_AFTER.match(text[match.end():]))
            break
    turn = _turn_angle(text)
    if turn is not None and angle is None:
        angle = turn
    distance = None
    match = _DISTANCE.search(text)
    if match and angle is None:
        distance = float(match.group(1)) * _UNITS_M[match.group(2)]
    speed = None
    match = _SPEED.search(text)
    if match:
        speed = float(match.group(1)) * (0.01 if match.group(2) == "cm/s" else 1.0)
    duration = None
    match = _DURATION.search(text)
    if match:
        duration = float(match.group(1))
    elif re.search(r"\bfor a (?:second|moment)\b", text):
        duration = 1.0
    factor = 1.0
    for word, word_factor in SPEEDS.items():
        if re.search(r"\b" + word + r"\b", text):
            factor = word_factor
            break
    sense: str | None = "ccw" if re.search(r"\b(?:unscrew|loosen)", text) else "cw" if re.search(r"\b(?:screw|tighten)", text) else None
    for word, turning in sorted(ROTATION_SENSE.items(), key=lambda item: -len(item[0])):
        if re.search(r"(?<![\w-])" + re.escape(word) + r"(?![\w-])", text):
            sense = turning
            break
    direction: str | None = None
    for word, heading in DIRECTION_WORDS.items():
        if re.search(r"\b" + word + r"\b", text):
            direction = heading
            break
    orientation = None
    if re.search(r"\b(?:vertical|vertically|upright|straight up|stands? up|perpendicular)\b", text):
        orientation = "vertical"
    elif re.search(r"\b(?:flat|horizontal|horizontally|level)\b", text):
        orientation = "flat"
    fraction = None
    if angle is None:
        fraction = _amount(clause)
        if fraction is None:
            fraction = _amount(text)
    return Quantity(
        orientation=orientation,
        fraction=fraction,
        angle_rad=angle,
        distance_m=distance,
        omega_radps=_omega(text),
        speed_mps=speed,
        duration_s=duration,
        speed_factor=factor,
        sense=sense,
        axis=_axis(text),
        direction=direction,
        absolute=absolute,
    )


def without_direction(quantity: Quantity) -> Quantity:
    return replace(quantity, direction=None)
