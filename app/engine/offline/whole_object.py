"""Frames whose theme is the whole object: is it a whole-object motion, and which one.

"Push the cart 1 m forward" translates the base (wheels roll); "turn it around" and
"rotate the box 90 degrees on the table" yaw it about the vertical through its centre;
"lift the bucket 20 cm" raises it. A pronoun means the object only with a verb that moves
whole objects, a direction or a world axis; a press-type verb moves it only when it
displaces ("push the box", not "squeeze the bottle").
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from app.engine.contracts.steps import BaseMotion, WheelRoll
from app.engine.lexicon.objects import OBJECT_FAMILIES
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.offline.base_motion import DEFAULT_SPEED_MPS, default_distance, heading, is_vehicle, wheel_rates
from app.engine.offline.geometry import ObjectGeometry
from app.engine.offline.reading.frames import Frame

_TRANSLATING = frozenset({VerbSense.MOVE, VerbSense.PRESS, VerbSense.PULL_OUT, VerbSense.PUSH_IN, VerbSense.RAISE, VerbSense.LOWER,
                          VerbSense.SPIN, VerbSense.RETURN})
_OBJECT_ONLY = frozenset({"roll", "drag", "carry", "pick", "transport", "drive", "move", "lift", "shove", "wheel", "tow", "haul", "kick",
                          "nudge", "scoot", "relocate", "reposition", "hoist", "coast"})
_PULLING = frozenset({"pull", "drag", "tow", "haul", "yank", "tug", "draw"})
_COASTING = frozenset({"coast", "glide", "roll"})
_IN_PLACE = frozenset({"table", "floor", "spot", "place", "ground", "counter", "axis", "itself", "vertical", "on_the_spot", "in_place", "where_it_stands"})


@dataclass(frozen=True)
class ObjectMotion:
    motion: BaseMotion
    notes: tuple[str, ...] = ()


def moves_object(frame: Frame, *, pronoun: bool, after_part: bool) -> bool:
    """Whether this clause moves the whole object (its theme is the object or "it")."""
    if frame.verb is None or frame.sense is None:
        return False
    info = VERBS.get(frame.verb)
    if info is None or (info.object_sense is None and frame.sense not in _TRANSLATING and frame.sense is not VerbSense.YAW):
        return False  # ("flip it round": its particle turns the object)
    if info.object_sense is None and info.motion == "hinge" and frame.sense is not VerbSense.YAW:
        return False  # "fold it down": a verb of hinged parts does not carry the whole object
    quantities = frame.quantities
    if pronoun and frame.let and frame.sense is VerbSense.LOWER:
        return False  # "the handle is upright. Let it fall toward me": a part let fall, not the object sent that way
    directional = quantities.direction in ("forward", "backward", "left", "right", "sideways") or quantities.axis is not None
    if pronoun and after_part and quantities.amount is not None and quantities.amount.unit == "fraction":
        return False  # "lift it halfway back up": a fraction of a part's range, not of the object's
    if pronoun and after_part and frame.returning and quantities.axis is None and quantities.direction in (None, "up", "down"):
        return False  # "then lift it back up to its starting angle": the part goes back, "back" is no direction here
    if pronoun and after_part and (frame.sense is VerbSense.TURN or frame.verb in _TURNING) and quantities.axis is None:
        return False  # "the handle is hanging down - turn it up so it points to the left": the handle turns
    if pronoun and after_part:
        explicit_back = frame.particle != "back" or any(w in frame.text.split() for w in ("backward", "backwards"))
        if not (quantities.axis is not None or frame.verb in _OBJECT_ONLY or (directional and explicit_back)):
            return False
    if frame.sense is VerbSense.PRESS and not info.displaces and not (directional or (quantities.amount is not None and quantities.amount.unit == "m")):
        return False
    if frame.particle in ("in", "out", "open", "shut", "closed") and not (quantities.amount is not None and quantities.amount.unit == "m" and (
            {"entire", "whole"} & set(frame.text.split()))):
        return False  # not "drag the entire dishwasher 40 cm out from under the counter": the whole object goes
    return info.object_sense is not None or frame.sense in _TRANSLATING or frame.sense is VerbSense.YAW


def is_yaw(frame: Frame) -> bool:
    """"turn it around", "rotate the box 90 degrees (on the table)", "spin the chair"."""
    info = VERBS.get(frame.verb or "")
    if info is not None and (frame.sense is VerbSense.YAW or (frame.sense is VerbSense.SPIN and frame.particle in ("around", "round"))):
        return True  # "flip it round", "yaw it", "make it go round"
    if info is None or info.object_sense is not VerbSense.YAW:
        return False
    words = set(frame.text.split())
    return frame.sense is VerbSense.YAW or frame.particle in ("around", "round") or bool(words & _IN_PLACE) or (
        frame.quantities.amount is not None and frame.quantities.amount.unit == "rad") or frame.quantities.sense is not None


def returning_motion(frame: Frame, previous: BaseMotion | None) -> ObjectMotion | None:
    """"... and set it back down", "then 0.3 m back to where it started": the previous motion, reversed."""
    if previous is None or frame.quantities.axis is not None or frame.quantities.direction not in (None, "backward", "down"):
        return None
    amount = frame.quantities.amount
    distance = amount.value if amount is not None and amount.unit == "m" else previous.distance_m
    axis = tuple(-a for a in previous.axis_world) if previous.axis_world is not None else None
    wheels = [w.model_copy(update={"rad_per_m": -w.rad_per_m}) for w in previous.wheels]
    motion = BaseMotion(axis_world=axis, distance_m=distance, yaw_rad=-previous.yaw_rad, pivot_world=previous.pivot_world, wheels=wheels)  # type: ignore[arg-type]
    return ObjectMotion(motion)


def _turned(axis: tuple[float, float, float], yaw: float) -> tuple[float, float, float]:
    """A direction named as seen from the object, after the object turned by ``yaw``."""
    c, s = math.cos(yaw), math.sin(yaw)
    x, y, z = axis
    return (round(c * x - s * y, 6) + 0.0, round(s * x + c * y, 6) + 0.0, z)


def _pivot(obj: ObjectGeometry) -> tuple[float, float, float]:
    """Where the object turns: about its own origin's vertical axis (as Blender and a robot's base frame do) when the
    origin lies within its footprint, else about the centre of its box."""
    c, half = obj.center, obj.extents / 2.0
    if abs(float(c[0])) <= float(half[0]) and abs(float(c[1])) <= float(half[1]):
        return (0.0, 0.0, float(c[2]))
    return (float(c[0]), float(c[1]), float(c[2]))


def object_motion(frame: Frame, obj: ObjectGeometry, yaw: float = 0.0) -> ObjectMotion:
    """The base motion a whole-object frame asks for (``yaw``: how far the object has turned so far)."""
    quantities = frame.quantities
    notes: list[str] = []
    pivot = _pivot(obj)
    if is_yaw(frame):
        angle = quantities.amount.value if quantities.amount is not None and quantities.amount.unit == "rad" else None
        words = frame.text.split()
        if angle is None and quantities.amount is not None and quantities.amount.unit == "fraction" and quantities.amount.value < 1 and (
                "way" in words or "halfway" in words) and ({"round", "around"} & set(words)):
            angle = 2 * math.pi * quantities.amount.value  # "a quarter of the way round": a quarter of a full circle (not "right round")
        if angle is None:
            around = frame.particle in ("around", "round") or "around" in words
            angle = math.pi if around else math.pi / 2
            if not around:
                notes.append("no angle given: turned the object a quarter turn")
        sign = -1.0 if quantities.sense == "cw" else 1.0  # counter-clockwise seen from above unless told
        return ObjectMotion(BaseMotion(yaw_rad=round(sign * angle, 9), pivot_world=pivot), tuple(notes))
    vertical = "up" if frame.sense is VerbSense.RAISE else "down" if frame.sense is VerbSense.LOWER else None
    if frame.particle in ("up", "down") and quantities.direction is None:
        vertical = frame.particle
    direction = quantities.direction if quantities.direction != "sideways" else "right"
    if direction is None and frame.particle in ("forward", "back", "away"):
        direction = {"forward": "forward", "back": "backward", "away": "backward"}[frame.particle]
    vehicle = is_vehicle(obj)
    head = heading(direction, quantities.axis, vertical, obj, vehicle=vehicle, pulling=frame.verb in _PULLING)
    if head.guessed:
        notes.append(f"no direction given: moved the object {'forward' if vehicle else 'away from its front'}")
    is_vertical = abs(head.axis[2]) > 0.9
    if quantities.amount is not None and quantities.amount.unit == "m":
        distance = quantities.amount.value
    elif quantities.duration_s is not None:
        distance = (quantities.speed_mps or DEFAULT_SPEED_MPS) * quantities.duration_s
    else:
        distance = default_distance(obj, is_vertical)
        notes.append(f"no distance given: moved it {distance:g} m")
    axis = head.axis if quantities.axis is not None or yaw == 0 else _turned(head.axis, yaw)
    wheels = () if is_vertical else wheel_rates(obj.joints.values(), head.axis, obj)
    coast = (bool(set(frame.text.split()) & _COASTING) and frame.verb not in ("roll",)) or "let" in frame.text.split()
    motion = BaseMotion(axis_world=axis, distance_m=round(abs(distance), 9), speed_mps=quantities.speed_mps, coast=coast and not is_vertical,
                        wheels=[WheelRoll(joint=j, rad_per_m=round(r, 9)) for j, r in wheels])
    return ObjectMotion(motion, tuple(notes))


_WHOLE = frozenset({"whole", "entire"})


def whole_named(frame: Frame, category: str | None) -> Frame:
    """"raise the whole door, frame and all" on a door asset: "whole" with the object's own name is the object, not
    its part of that name."""
    family = OBJECT_FAMILIES.get(category or "", frozenset())
    themes = tuple(replace(m, is_object=True, kind=None) if _WHOLE & set(m.modifiers) and (m.head == category or (m.head in family and m.kind is None)) else m
                   for m in frame.themes)
    frame = frame if themes == frame.themes else replace(frame, themes=themes)
    if frame.particle == "away" and frame.verb in _STOWING and frame.themes and all(m.is_object for m in frame.themes):
        return replace(frame, sense=VerbSense.CLOSE, particle="shut")  # "put my laptop away": folded shut, not pushed 1 m
    return frame


_STOWING = frozenset({"put", "pack", "stow", "tuck"})
_TURNING = frozenset({"turn", "rotate", "twist", "swivel"})
