"""Whether the motion a clause asks for is one the named part can make: a refusal naming the mismatch, never a guess.

"fold down the tray" on a part that only slides, "twist the pot lid" on a lid that only lifts, "slide the sash 20 cm" on
one that only swings, "press the button" on a button already at the bottom of its travel.
"""

from __future__ import annotations

import math
import re

from app.engine.lexicon.kinds import info
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import HINGE_WORDS, SLIDE_WORDS
from app.engine.offline import mechanisms as mech
from app.engine.offline.grounding import Part
from app.engine.offline.reading.frames import Frame
from app.engine.offline.referents import Referents
from app.engine.offline.resolve import closed_of
from app.engine.offline.tracker import Tracker

REACHED = 1e-6
_FLAT_EPS = math.radians(5)
_PAST_FLAT = re.compile(r" (past|beyond|further than|farther than|more than) (flat|180 degrees|180 deg|180°) | like a tablet | tablet style | tablet-style | (under|beneath|underneath|below) the (keyboard|base) | underside of the (keyboard|base) | against the underside ")
_PRESSES = frozenset({VerbSense.PRESS, VerbSense.PUSH_IN, VerbSense.OPERATE})


def _label(part: Part) -> str:
    return part.kind.value if part.kind is not None else "part"


def check_press(refs: Referents, tracker: Tracker, frame: Frame, sense: VerbSense, parts: list[Part], notes: list[str]) -> None:
    """A button that cannot go deeper into its face cannot be pressed: refuse rather than pull it out."""
    if sense not in _PRESSES:
        return
    for part in (p for p in parts if p.kind is not None and info(p.kind).press == "into_face" and p.geometry.type == "prismatic"):
        geometry = part.geometry
        if geometry.press_value is None or abs(geometry.press_value - tracker.value(part.joint)) < REACHED:
            raise refs.refuse(f"'{frame.text}': the {_label(part)} ({part.link}) cannot be pressed in any further")
        if geometry.press_outward:
            notes.append(f"{part.link} ({part.joint}) rests at the deep end of its travel: pressed along the travel it has (outward)")


def check_motion(refs: Referents, frame: Frame, parts: list[Part], results: str = "") -> None:
    """A verb naming a motion the part cannot make is refused: a hinge verb or a twist on a part that only slides, a
    straight slide to one side on a part that only rotates."""
    motion = VERBS[frame.verb].motion if frame.verb is not None and frame.verb in VERBS else "any"
    named = [p for p in parts if not mech.is_control(p)]
    amount = frame.quantities.amount
    if motion == "any" and frame.sense is VerbSense.TURN and amount is not None and amount.unit == "rad":
        motion = "twist"  # "turn the lid a quarter turn": turned by an angle
    said = {word for mention in frame.themes for word in mention.modifiers}
    if parts and said & SLIDE_WORDS and all(p.geometry.type != "prismatic" for p in parts):
        raise refs.refuse(f"'{frame.text}' names a part that slides ({', '.join(sorted(said & SLIDE_WORDS))}), but the "
                          f"{_label(parts[0])} only swings or turns")
    if parts and said & HINGE_WORDS and all(p.geometry.type == "prismatic" for p in parts):
        raise refs.refuse(f"'{frame.text}' names a part on a hinge ({', '.join(sorted(said & HINGE_WORDS))}), but the {_label(parts[0])} "
                          "only slides")
    if not named:
        return
    flat = next((p for p in named if p.geometry.type == "revolute" and p.geometry.open_value is not None and abs(
        p.geometry.open_value - closed_of(p.geometry)) < math.pi + _FLAT_EPS), None) if _PAST_FLAT.search(f" {frame.text} {results} ") else None
    if flat is not None:
        reach = math.degrees(abs(flat.geometry.open_value - closed_of(flat.geometry)))  # type: ignore[operator]
        raise refs.refuse(f"'{frame.text}': the {_label(flat)} ({flat.link}) opens at most {reach:.0f} degrees from closed; it cannot fold past flat")
    slides_only = all(p.geometry.type == "prismatic" for p in named)
    if motion == "hinge" and slides_only:
        raise refs.refuse(f"'{frame.verb}' swings a part about a hinge, but the {_label(named[0])} only slides")
    if motion == "twist" and slides_only:
        raise refs.refuse(f"'{frame.text}' twists a part about its axis, but the {_label(named[0])} only slides: ask to lift, raise or "
                          "pull it instead")
    sideways = frame.quantities.direction == "sideways" or (amount is not None and amount.unit == "m")
    if motion == "slide" and sideways and all(p.geometry.type != "prismatic" for p in named):
        raise refs.refuse(f"'{frame.text}' slides a part in a straight line, but the {_label(named[0])} only rotates")
