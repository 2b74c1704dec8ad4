"""A frame's verb sense, end state and amount applied to one part -> a contract :class:`Goal`.

The sense table (:mod:`app.engine.lexicon.senses`) gives the end state for the part's class;
the frame's words refine it (a rotation sense, a direction, an orientation, "back"), and the
amount gets what it is measured from: the closed end for openings ("to 90 degrees",
"halfway"), the current value for increments, closings and turns.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace

import numpy as np

from app.engine.contracts.steps import Goal, GoalState, MeasuredFrom
from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import PartKind, info
from app.engine.lexicon.senses import CLOSING_STATES, END_STATE, PartClass, part_class
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import CENTRE_WORDS
from app.engine.offline.geometry import JointGeometry
from app.engine.offline.grounding import Part
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.quantities import Amount, Quantities
from app.engine.offline.reading.word_class import lemma_of
from app.engine.offline.resolve import closed_of, direction_vector, resolve, spin_velocity
from app.engine.offline.tracker import Tracker

SCREW_AXIS_MIN_UP = 0.7
"""|axis . up| above this: a lid turning about a vertical axis is a screw cap."""
DEFAULT_UNSCREW_RAD = 2 * math.pi
LIMIT_EPS = 1e-9
MIDWAY_RAD = 0.1
"""A rest this far inside both limits: the part can go either way from rest."""
_DIRECTIONAL = frozenset({"left", "right", "forward", "backward"})
_RETURN_WORDS = frozenset({"original", "starting", "initial", "previous", "former"})
_FLIPPABLE = frozenset({VerbSense.TURN, VerbSense.OPERATE, VerbSense.TOGGLE, VerbSense.SWITCH_ON, VerbSense.UNLATCH, VerbSense.PRESS})
"""Senses whose turn direction is a default: a part that cannot turn that way turns the other way."""


@dataclass(frozen=True)
class GoalChoice:
    goal: Goal
    notes: tuple[str, ...] = ()


def is_screw_cap(part: Part, tracker: Tracker) -> bool:
    """A lid or cap with no open side that turns about the vertical: opening it means unscrewing."""
    geometry = part.geometry
    kind_ok = part.kind in (PartKind.CAP, PartKind.LID)
    return (kind_ok and geometry.open_value is None and geometry.type in ("revolute", "continuous")
            and abs(float(geometry.axis_world @ tracker.obj.up)) > SCREW_AXIS_MIN_UP)


def _class(part: Part) -> PartClass:
    if part.kind is None:
        return PartClass.OPENABLE if part.geometry.open_value is not None else PartClass.OTHER
    return part_class(info(part.kind))


_NOW_PLACES = (("where", "it", "is", "now"), ("where", "it's", "now"), ("where", "it", "is", "right", "now"), ("it's", "in", "right", "now"),
               ("it's", "in", "now"), ("where", "it", "sits", "now"), ("where", "it's", "sitting", "now"))


def _back_to_now(words: list[str]) -> bool:
    """"(flip it) back (up) to where it is now": the pose the prompt found it in, said with "back"."""
    return "back" in words and any(tuple(words[k:k + len(p)]) == p and "to" in words[max(0, k - 3):k] for p in _NOW_PLACES for k in range(len(words)))


def _back_home(words: list[str]) -> bool:
    """"back in", "back shut", "back up into the cover": "back" said with the way in (not "back to where it is in now")."""
    for k, word in enumerate(words[:-1]):
        if word == "back":
            nxt = words[k + 2] if words[k + 1] in ("up", "down") and k + 2 < len(words) else words[k + 1]
            if nxt in ("in", "into", "shut", "closed"):
                return True
    return False


def _amount(amount: Amount | None) -> tuple[float | None, str | None]:
    if amount is None:
        return None, None
    return amount.value, amount.unit


def _default_from(state: GoalState, sense: VerbSense) -> MeasuredFrom:
    if sense is VerbSense.RECLINE or state in CLOSING_STATES or state in ("cw", "ccw", "toward") or state in _DIRECTIONAL:
        return "current"
    if state in ("pressed", "up", "down", "vertical", "flat"):
        return "current"
    return "closed"


_POSES = frozenset({"vertical", "horizontal", "flat", "level"})


def _to_a_pose(said: list[str]) -> bool:
    """"bring it back up to vertical": the pose said is where it goes (not "stand it back up": back where it was)."""
    return any(w in _POSES and k and said[k - 1] == "to" for k, w in enumerate(said))


def state_for(frame: Frame, sense: VerbSense, part: Part, tracker: Tracker) -> GoalState:
    """The end state ``sense`` asks of ``part``, refined by the frame's words."""
    quantities = frame.quantities
    geometry = part.geometry
    rotates = geometry.type in ("revolute", "continuous")
    absolute = quantities.amount is not None and quantities.amount.reference == "closed"
    said = frame.text.split()
    if _back_to_now(said):
        return "rest"  # "close the lid, then flip it back up to exactly where it is now": where it was when the prompt began
    if absolute and sense in (VerbSense.MOVE, VerbSense.OPERATE) and geometry.open_value is not None and not frame.returning:
        return "open"  # "position the drawer so its front is 30 cm out from the fully closed position": that far open
    if frame.returning and any(w.replace("_", " ") in frame.text for w in CENTRE_WORDS) and geometry.lower is not None and geometry.upper is not None and (
            geometry.lower < geometry.rest < geometry.upper):
        return "rest"  # "then back to the middle": a lever resting midway goes back to rest
    if frame.returning and not absolute and not (_to_a_pose(said) and not frame.explicit_return) and (
            sense not in (VerbSense.OPEN, VerbSense.PULL_OUT) or set(said) & _RETURN_WORDS or frame.explicit_return):  # "back up to vertical": the pose said
        home = _back_home(said)  # "tuck the magazine back up into the cover", "slide it back in": shut
        closes = frame.verb is not None and frame.verb in VERBS and VERBS[frame.verb].sense is VerbSense.CLOSE and not frame.explicit_return and (
            any(lemma_of(w)[0] == frame.verb for w in said))  # "close it back up": closed (not "fold it ..., then back to where it was")
        shuts = home or closes or (bool({"down", "on"} & set(said)) and part.kind is not None and info(part.kind).lid_like)  # "put the lid back down on the pot"
        if (home or closes or part.joint not in tracker.before) and shuts and geometry.closed_value is not None and geometry.open_value is not None:
            return "closed"
        return "previous" if part.joint in tracker.before else "rest"
    if frame.returning and absolute:
        return "open"  # "let it fall back to 60 degrees": a position measured from closed
    if quantities.onto_body and geometry.closed_value is not None and quantities.amount is None:
        return "closed"  # "flip the latch up flat against the box": it ends lying on the body, whatever way the verb says
    if sense is VerbSense.SWITCH_OFF:
        return "rest"
    if sense is VerbSense.SWITCH_ON and rotates:
        return "cw"
    if quantities.orientation is not None and rotates and sense is not VerbSense.SPIN:
        return "vertical" if quantities.orientation == "vertical" else "flat"
    if is_screw_cap(part, tracker) and sense in (VerbSense.OPEN, VerbSense.CLOSE, VerbSense.TURN) and quantities.sense is None:
        return "ccw" if sense is VerbSense.OPEN else "cw"
    if quantities.sense is not None and rotates:
        return "cw" if quantities.sense == "cw" else "ccw"
    part_class_ = _class(part)
    if quantities.axis is None and quantities.direction == "backward" and part_class_ is PartClass.OPENABLE and sense in (
            VerbSense.PRESS, VerbSense.MOVE, VerbSense.PUSH_IN, VerbSense.RETURN):
        # "push it back 10 cm": toward closed, from where it is; a laptop's screen pushed back reclines (the way it moves back)
        return "backward" if rotates and part.kind is not None and info(part.kind).reclines else "closed"
    if quantities.axis is not None and sense is not VerbSense.SPIN and (part_class_ is not PartClass.OPENABLE or geometry.open_value is None):
        return "toward"  # "swing the handle down onto the rim on the -X side"
    if (frame.particle == "back" and quantities.direction is None and rotates and part_class_ is not PartClass.OPENABLE and not frame.returning
            and geometry.open_value is None and sense is not VerbSense.RELEASE):  # "let the knob spring back": it returns
        return "backward"  # "flip the handle back" (from where it rests): toward the back of the object
    rolls = part.kind is not None and info(part.kind).rolls
    rocker = VERBS[frame.verb].rocker_sense if frame.verb is not None and frame.verb in VERBS and frame.particle is None and frame.sense is sense else None
    if rocker is not None and part_class_ is PartClass.PUSHED and quantities.direction is None:
        sense = rocker  # "tilt the wall switch 10 degrees": rocked over, the way it can go
    midway = rotates and geometry.lower is not None and geometry.upper is not None and geometry.lower + MIDWAY_RAD < geometry.rest < geometry.upper - MIDWAY_RAD
    if quantities.direction in _DIRECTIONAL and (part_class_ is not PartClass.OPENABLE or geometry.open_value is None or midway) and not (
            part_class_ is PartClass.PUSHED and geometry.type == "prismatic"):
        # a part resting midway (a bucket handle upright) goes the way the user says: "let it drop forward"
        return quantities.direction  # type: ignore[return-value]
    if rolls and sense in (VerbSense.TURN, VerbSense.OPERATE, VerbSense.MOVE):
        return "forward"  # a wheel turned without a sense turns the way it rolls forward
    if part_class_ is PartClass.OPENABLE and sense in (VerbSense.RAISE, VerbSense.LOWER):
        lid = part.kind is not None and info(part.kind).lid_like and abs(float(geometry.home_face[2])) > 0.5  # a lid on a side face (a
        # standing suitcase's front lid) opens down like an oven door
        if not lid and geometry.up_value is not None and geometry.down_value is not None and geometry.open_value is not None:
            return "up" if sense is VerbSense.RAISE else "down"  # an oven door lowers open, a lid lifts open
    words = set(said)
    if sense is VerbSense.HOLD and words & {"open", "opened", "shut", "closed"} and geometry.closed_value is not None:
        return "open" if words & {"open", "opened"} else "closed"  # "leave the left one open"
    if sense is VerbSense.HOLD and words & {"up", "down"} and (geometry.up_value if "up" in words else geometry.down_value) is not None:
        return "up" if "up" in words else "down"  # "leave the front one up"
    if sense not in END_STATE or part_class_ not in END_STATE[sense]:
        raise GroundingError(f"'{frame.text}' does not say how {part.link} ({part.joint}) should move")
    state = END_STATE[sense][part_class_]
    if sense in (VerbSense.LOCK, VerbSense.CLOSE) and geometry.closed_value is not None and part_class_ is not PartClass.OPENABLE:
        return "closed"  # a latch whose shut end is known (from the lid it holds)
    if state == "rest" and sense in (VerbSense.LOCK, VerbSense.CLOSE) and geometry.closed_value is not None:
        return "closed"  # a latch whose shut end is known (from the lid it holds)
    if sense in (VerbSense.OPEN, VerbSense.UNLATCH) and part_class_ is not PartClass.OPENABLE and geometry.open_value is not None and (
            geometry.closed_value is not None and quantities.sense is None):
        return "open"  # a latch whose open end is known: "the other stays open" is that end, not a turn of the URDF's sense
    if state == "open" and geometry.open_value is None and part_class_ is PartClass.OPENABLE and geometry.up_value is not None and sense is VerbSense.RAISE:
        return "up"
    if sense in (VerbSense.RAISE, VerbSense.LOWER) and part_class_ is PartClass.TURNED and geometry.up_value is None and geometry.down_value is None:
        return state  # "turn up the browning knob": clockwise, more; "turn it down": less
    if sense is VerbSense.RAISE and part_class_ is not PartClass.OPENABLE and geometry.up_value is None:
        return "pressed"
    if sense is VerbSense.LOWER and part_class_ is not PartClass.OPENABLE and geometry.down_value is None:
        return "pressed"
    if state == "cw" and not rotates:
        return "pressed"
    if state in ("open", "closed") and geometry.type == "continuous" and geometry.open_value is None and (
            quantities.amount is not None and quantities.amount.unit == "rad"):
        return "cw"  # "show about half a turn of the plate": a turn, by the amount, of a part that only turns
    return state


def _spin(quantities: Quantities, geometry: JointGeometry, tracker: Tracker) -> Goal:
    angle = quantities.amount.value if quantities.amount is not None and quantities.amount.unit == "rad" else None
    omega, duration = spin_velocity(geometry, quantities.sense, tracker.obj, angle, quantities.omega_radps, quantities.duration_s,
                                    quantities.speed_factor, quantities.direction)
    return Goal(state="velocity", omega_radps=round(omega, 9), duration_s=round(duration, 9))


_OTHER_END = re.compile(r"\bto (the|its) (other|opposite) (end|side|stop|limit)\b")
_END_STATES = frozenset({"just a crack", "a crack", "ajar", "barely", "partway", "part way", "partly", "partially"})
"""Loose amounts that name where a part ends ("leave the door open just a crack", "pushes it partway open"), measured from
closed wherever it rests."""


def _rate_times_duration(frame: Frame, geometry: JointGeometry) -> Frame:
    """A rate and a time with no amount on a part that stops at its limits ("open the door at 30 degrees a second for 2
    seconds", "slide the drawer out at 5 cm per second for 3 seconds"): that far from where it is, in that time. A part
    that turns for ever is spun instead (:func:`_spin`)."""
    q = frame.quantities
    rate = q.omega_radps if geometry.type == "revolute" else q.speed_mps if geometry.type == "prismatic" else None
    if rate is None or q.duration_s is None or q.amount is not None:
        return frame
    amount = Amount(round(abs(rate) * q.duration_s, 9), "rad" if geometry.type == "revolute" else "m", "current", words="rate x time")
    return replace(frame, quantities=replace(q, amount=amount))


def goal_for(frame: Frame, sense: VerbSense, part: Part, tracker: Tracker) -> GoalChoice:
    """The goal of ``sense`` (from ``frame``) on ``part``."""
    geometry = part.geometry
    frame = _rate_times_duration(frame, geometry)
    quantities = frame.quantities
    spin = sense is VerbSense.SPIN or (geometry.type == "continuous" and sense in (VerbSense.TURN, VerbSense.OPERATE)
                                       and (quantities.omega_radps is not None or quantities.duration_s is not None) and quantities.amount is None)
    counted = quantities.times > 1 and quantities.duration_s is None and quantities.omega_radps is None  # "spin the dial twice": two turns
    if spin and geometry.type == "continuous" and not counted:
        return GoalChoice(_spin(quantities, geometry, tracker))
    if quantities.target is not None and any(m.head in (part.joint, part.link) and "_" in m.head for m in frame.themes):
        # "set joint_1 to -1.0 rad": a raw joint value, for users who name joints as the URDF does
        return GoalChoice(Goal(state="value", value=round(quantities.target, 9), measured_from="current"))
    if _OTHER_END.search(frame.text) and geometry.lower is not None and geometry.upper is not None and geometry.type != "continuous":
        now = tracker.value(part.joint)  # "slide it all the way to the other end": the end furthest from where it is
        far: GoalState = "upper" if geometry.upper - now >= now - geometry.lower else "lower"
        return GoalChoice(Goal(state=far), (f"read 'the other end' as the {far} limit of {part.joint}, the end furthest from where it is",))
    state = state_for(frame, sense, part, tracker)
    if state == "velocity" and not counted:  # "work the tray": a spinner set going, at the default speed unless told
        return GoalChoice(_spin(quantities, geometry, tracker))
    state = "cw" if state == "velocity" else state
    value, unit = _amount(quantities.amount)
    if value is not None and unit == "fraction" and geometry.type == "continuous" and {"round", "around"} & set(frame.text.split()):
        value, unit = value * 2 * math.pi, "rad"  # "half way round": a share of a whole turn of a part that turns for ever
    if value is None and sense is VerbSense.YAW and geometry.type == "continuous" and quantities.times <= 1:
        value, unit = math.pi, "rad"  # "turn the mug around" (on the turntable): a half turn, as an object turned around
    if value is not None and unit == "m" and geometry.type != "prismatic":
        value, unit = None, None
    if value is not None and unit == "rad" and geometry.type == "prismatic":
        value, unit = None, None
    notes: list[str] = []
    if is_screw_cap(part, tracker) and state in ("cw", "ccw") and value is None and geometry.type == "continuous":
        value, unit = DEFAULT_UNSCREW_RAD, "rad"
    if value is None and quantities.times > 1 and sense in (VerbSense.TURN, VerbSense.SPIN, VerbSense.YAW) and geometry.type in ("revolute", "continuous"):
        value, unit = quantities.times * 2 * math.pi, "rad"  # "rotate it twice"
    if state in ("cw", "ccw") and quantities.sense is None and (value is None or (unit == "fraction" and value >= 1.0) or unit == "rad") and (
            geometry.type != "continuous" and sense in _FLIPPABLE):  # "turn the handle (a half turn)": the way it can turn
        ahead = resolve(Goal(state=state), geometry, tracker.obj, tracker.asset, tracker.value(part.joint)).value
        if ahead is not None and abs(ahead - tracker.value(part.joint)) < LIMIT_EPS:
            state = "ccw" if state == "cw" else "cw"  # it only turns the other way
    reference = quantities.amount.reference if quantities.amount is not None else None
    measured: MeasuredFrom = reference or _default_from(state, sense)
    if reference is None and unit == "fraction" and state in ("up", "down") and geometry.open_value is not None and not (
            quantities.amount is not None and quantities.amount.loose) and (geometry.up_value if state == "up" else geometry.down_value) == geometry.open_value:
        measured = "closed"  # "lower the oven door halfway down": half of its closed-to-open range, wherever it rests
    if reference is None and unit == "fraction" and state == "open" and quantities.amount is not None and quantities.amount.loose and (
            quantities.amount.words not in _END_STATES):
        measured = "current"  # "pull the drawer out a little (more)": a little further than it is, never back toward closed
    if reference is None and unit == "m" and sense in (VerbSense.RAISE, VerbSense.LOWER):
        measured = "current"  # "raise the lid 20 cm": a distance raised is from where it is (a lid resting ajar goes 20 cm higher)
    if state == "closed" and unit == "fraction" and value is not None and value >= 1.0:
        value, unit = None, None
    if value is not None and unit == "fraction" and state == "open" and sense in (VerbSense.CLOSE,):
        measured = "current"
    toward = _toward_part(frame, part, tracker) if state in ("down", "vertical", "flat", "rest", "previous") and quantities.direction in (
        None, "down", "up", "backward") else None
    if state in ("rest", "previous") and toward is not None and geometry.type == "revolute":
        state = "toward"  # "fold the handle (back) away from the lid": toward the side away from that part, not back to rest
    if state == "down" and value is None and part.geometry.type == "revolute" and toward is not None:
        state = "flat"  # "fold the handle down on the side away from the lid": down flat, on that side
    goal = Goal(state=state, amount=value, unit=unit, measured_from=measured,  # type: ignore[arg-type]
                direction_world=(quantities.axis or toward) if state == "toward" else _tipping(state, quantities.direction, tracker, toward))
    if state == "open" and unit in ("rad", "m") and reference is None and sense is VerbSense.MOVE and quantities.direction is None and (
            geometry.open_value is not None and min(abs(tracker.value(part.joint) - e) for e in (closed_of(geometry), geometry.open_value)) > LIMIT_EPS):
        raise GroundingError(f"'{frame.text}': {part.link} ({part.joint}) rests part open and can go either way; say 'open it "
                             f"{quantities.amount.words if quantities.amount else 'that much'} more' or 'close it "
                             f"{quantities.amount.words if quantities.amount else 'that much'}'")  # "move screen 30 deg" on a laptop open at 90
    if state == "open" and unit in ("rad", "m") and reference is None:
        goal, note = _opening_amount(goal, part, tracker)
        notes.extend(note)
    notes.extend(_either_way(goal, part, tracker))
    return GoalChoice(goal, tuple(notes))


EITHER_WAY_RATIO = 0.8
"""Travel one way from rest at least this fraction of the other: neither end is "the far one"."""


def _either_way(goal: Goal, part: Part, tracker: Tracker) -> list[str]:
    """A part that can go about as far either way from rest, whose shape says neither which end is open nor which
    is pressed (a mixer tap's lever, a rocker): the end taken is the URDF's sign, a guess worth a warning."""
    geometry = part.geometry
    if goal.state not in ("open", "pressed") or geometry.closed_value is not None or geometry.lower is None or geometry.upper is None:
        return []
    if geometry.press_value is not None and abs(geometry.press_value - geometry.rest) > LIMIT_EPS:
        return []
    if goal.state == "pressed" and part.kind is not None and info(part.kind).press == "down" and geometry.down_value is not None:
        return []
    up, down = geometry.upper - geometry.rest, geometry.rest - geometry.lower
    if min(up, down) < EITHER_WAY_RATIO * max(up, down):
        return []
    value = resolve(goal, geometry, tracker.obj, tracker.asset, tracker.value(part.joint)).value
    if value is None:
        return []
    end = "upper" if value > geometry.rest else "lower"
    return [f"{part.link} ({part.joint}) goes about as far either way from where it rests, and its shape does not say which way "
            f"to take it: took it toward its {end} limit; say which way (e.g. 'to the left', 'clockwise') to choose"]


def _tipping(state: GoalState, direction: str | None, tracker: Tracker,
             toward: tuple[float, float, float] | None = None) -> tuple[float, float, float] | None:
    """"fold the handle forward until it lies flat": the way it moves to the orientation (``toward``, the way to another
    part the prompt names, "toward the lid side", wins over a bare up/down)."""
    if state not in ("vertical", "flat"):
        return None
    if toward is not None or direction not in _DIRECTIONAL:
        return toward  # "fold it down on the side away from the lid": down, and that way
    x, y, z = (round(float(v), 6) + 0.0 for v in direction_vector(direction, tracker.obj))  # no -0.0
    return (x, y, z)


def _toward_part(frame: Frame, part: Part, tracker: Tracker) -> tuple[float, float, float] | None:
    """"fold the handle down toward the lid side" / "on the side away from the lid": the side another movable part of the
    kind named closes on (else the way to it), horizontal (None when no one such part)."""
    words = frame.text.split()
    lead = next((k for k, w in enumerate(words) if w in ("toward", "towards", "away")), None)
    if lead is None:
        return None
    kinds = [kind_of_word(w) for w in words[lead + 1:lead + 5] if w not in ("from", "the", "its", "side")]
    kind = next((k for k in kinds if k is not None), None)
    others = [g for g in tracker.obj.joints.values() if kind is not None and g.category is kind and g.joint != part.joint]
    if len(others) != 1:
        return None
    face = others[0].home_face - (others[0].home_face @ tracker.obj.up) * tracker.obj.up  # the side it closes on (a case's lid: its front)
    way = face if float(np.linalg.norm(face)) > 0.5 else others[0].home_centroid - part.geometry.home_centroid
    way = way - (way @ tracker.obj.up) * tracker.obj.up
    if float(np.linalg.norm(way)) < 1e-9:
        return None
    way = (-1.0 if words[lead] == "away" else 1.0) * way / float(np.linalg.norm(way))
    x, y, z = (round(float(v), 6) + 0.0 for v in way)
    return (x, y, z)


def _opening_amount(goal: Goal, part: Part, tracker: Tracker) -> tuple[Goal, list[str]]:
    """"Open it 20 degrees" is an opening measured from closed, even on a part that rests open further than that (it
    then closes to that opening, said in a note: three blind writers read it so, none the other way)."""
    geometry = part.geometry
    now = tracker.value(part.joint)
    absolute = resolve(goal, geometry, tracker.obj, tracker.asset, now).value
    closed = closed_of(geometry)
    if absolute is None or geometry.open_value is None:
        return goal, []
    opening = 1.0 if geometry.open_value >= closed else -1.0
    if (absolute - now) * opening < -LIMIT_EPS:
        return goal, [f"{part.link} rests open further than that: set it to that opening, measured from closed (it closes a little); "
                      "say 'that much more' to open it further"]
    return goal, []
