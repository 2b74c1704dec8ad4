"""Clauses that state a condition or set the scene rather than ask for a step: "while the door is open"
(a state to reach first), "the door starts partly open" (how the scene begins), a summary before a
colon (it only names the parts the steps after it work)."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.errors import GroundingError
from app.engine.lexicon.objects import carrier_of
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.offline import mechanisms as mech
from app.engine.offline.reading.acts import Act
from app.engine.offline.reading.clauses import Link
from app.engine.offline.reading.holders import side_of_object
from app.engine.offline.things_you_can import things_you_can
from app.engine.offline.told import held_in

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.grounding import Part
    from app.engine.offline.reading.frames import Frame
    from app.engine.offline.reading.mentions import Mention


_HAVING = frozenset({"has", "have"})
"""A description that names parts on another ("the door has two knobs"; "carries", "features" ... are read as "has" by
:mod:`.reading.word_forms`): the parts after it."""
_GROUPS = frozenset({"keypad", "key pad", "number pad", "panel", "control panel", "console", "keyboard"})
"""Heads that name a group of parts ("Keypad: press 7 and 3"), not one part."""


def condition(builder: Builder, act: Act) -> None:
    """A state to reach first ("while the door is open"), or a description that only sets "it"."""
    frame = act.goal
    if len(told := things_you_can(builder, frame)) > 1:
        builder.refs.remember(told, [])  # "There are two things you can turn on that door. Turn the lower one."
        return
    if frame.heading:
        builder.notes.append(f"read '{frame.text}' as a summary of the steps after it")
        summary = VERBS.get(frame.text.split()[0]) if frame.text else None
        if summary is not None and summary.sense is VerbSense.LOCK and frame.themes and all(m.is_object for m in frame.themes):
            from app.engine.offline.completion import shut_open_doors

            shut_open_doors(builder, act, "locks")  # "Lock up the safe, give the dial a spin": shut, then the steps after
        builder.refs.scene = next((m.sides for m in frame.themes if m.is_object and m.sides), builder.refs.scene)  # "top oven:"
        if frame.themes and all(m.is_object for m in frame.themes):
            builder.refs.last_object = True  # "Chest: slide it 60 cm forward": the object named as a topic is "it"
            return
        if any(not m.is_object for m in frame.themes):
            frame = replace(frame, themes=tuple(m for m in frame.themes if not m.is_object))
        there = next((k for k, w in enumerate(frame.text.split()) if w in ("there's", "there")), None)
        if there is not None and any(m.start > there and m.kind is not None for m in frame.themes):  # "on the end opposite the dial
            frame = replace(frame, themes=tuple(m for m in frame.themes if m.start > there))  # there's a small slider": the slider
        if any(m.kind is not None for m in frame.themes):  # "The sodas are behind the left-hand fridge door - ...": the door
            frame = replace(frame, themes=tuple(m for m in frame.themes if m.kind is not None or m.pronoun))
        try:
            builder.refs.remember(builder.ground(frame, VerbSense.OPEN, frame.themes)[0], [], topic=True)
        except GroundingError:
            if (each := _each_alone(builder, frame)) is not None:
                builder.refs.remember(each, [], topic=True)  # "There's a big wheel on the door and a smaller dial higher up."
                return
            if len(found := [p for m in frame.themes for p in _grounded_alone(builder, frame, m)]) == 1:
                builder.refs.remember(found, [], topic=True)  # "the round thing the food sits on: give it a quarter turn": the turntable
                return
            if any(m.kind is not None and m.head not in _GROUPS and not (m.plural or m.collective) for m in frame.themes):
                raise  # "The oven door: open it" on a two-door oven (which one?), "the left drawer: ..." where there is none
            set_topic(builder, frame)  # "Quick anim: ...": a summary that names no part; "the chicken is on the lowest shelf - ..."
        return
    if _placed_on(builder, frame):
        return  # "the baking tray is sitting on the rack nearest the floor; slide that rack out": a thing on the rack
    if any(m.is_object for m in frame.themes) and not all(m.is_object for m in frame.themes):
        frame = replace(frame, themes=tuple(m for m in frame.themes if not m.is_object))  # "the safe has two dials": the dials
    copula = next((k for k, word in enumerate(frame.text.split()) if word in ("is", "are")), None)
    if copula is not None and frame.verb is None and any(m.start < copula for m in frame.themes) and any(m.start > copula for m in frame.themes):
        frame = replace(frame, themes=tuple(m for m in frame.themes if m.start < copula))  # "the little knob is the lid release": the knob
    having = next((k for k, word in enumerate(frame.text.split()) if word in _HAVING), None)
    if having is not None and frame.verb is None and any(m.start > having for m in frame.themes):
        frame = replace(frame, themes=tuple(m for m in frame.themes if m.start > having))  # "the door has two knobs on it": the knobs
    try:
        parts, words = builder.ground(frame, VerbSense.OPEN, frame.themes) if frame.themes else ([], [])
    except GroundingError:
        if (each := _each_alone(builder, frame)) is None and "already" in frame.text.split():
            builder.notes.append(f"ignored '{frame.text}': how things already are, no step")  # "The combination is already dialled in."
            return
        owners = [p for m in frame.themes if m.kind is None and m.owner is not None for p in _grounded_alone(builder, frame, m.owner)]
        if each is None and len(owners) == 1 and frame.verb is None:
            builder.notes.append(f"read '{frame.text}' as about the {owners[0].kind} it is in, no step")
            builder.refs.remember(owners, [], topic=True)  # "The spring in the oven door's shot. Unlatch it ...": it is the door
            return
        if each is None:
            raise
        parts, words = each, []  # "There's a big wheel on the door and a smaller dial higher up": both, each named alone
    words_in = set(frame.text.split())
    if words_in & {"starts", "begins", "started", "already"} or ("left" in words_in and words_in & {"was", "were", "been", "got"}):
        builder.refs.remember(parts, [])  # "the door starts partly open", "it was left half open": how the scene begins, not a step
        return
    last = {m.joint for m in (*builder.steps[-1].controls, *builder.steps[-1].effects)} if builder.steps else set()
    if frame.link is not Link.CONDITION and frame.stative and frame.marker not in ("once", "when", "after", "until", "while") and parts and all(
            p.joint in last for p in parts):
        builder.notes.append(f"read '{frame.text}' as how things were before the step before it, no step of its own")
        builder.refs.remember(parts, [])  # "swing the safe door closed, the safe's standing open": why, not a new state
        return
    if words_in & {"locked", "latched"} and parts and not any(p.joint in builder.tracker.releases for p in parts):
        builder.notes.append(f"'{frame.text}': found no part that releases it; it is worked directly")  # "the door is latched until ..."
    wanted = frame.sense if frame.sense is not None else (
        VerbSense.OPEN if words_in & {"open", "opened"} else VerbSense.CLOSE if words_in & {"closed", "shut"} else None)
    if wanted is None or not parts:
        builder.refs.remember(parts, [])
        return
    amount = frame.quantities.amount
    said = not frame.wish and (amount is None or amount.loose)  # the scene told, not a pose asked for ("I need it at 90 degrees")
    moves = [m for m in builder.moves(frame, wanted, parts, words, None) if not builder.reached(m) and not (said and _already(builder, m.part, wanted))]
    if moves:
        builder.complete(replace(act, goal=replace(frame, sense=wanted)), wanted, [], moves, why="prerequisite")
    builder.refs.remember(parts, [])


_AJAR_SHARE = 0.02
"""A part this far (a share of its travel) from its closed end is already open, as a scene says ("the door's sitting open")."""


def _already(builder: Builder, part: Part, wanted: VerbSense) -> bool:
    """The scene a clause states holds already: "both doors are hanging open" on doors resting ajar moves nothing."""
    geometry = part.geometry
    if geometry.closed_value is None or geometry.span is None or wanted not in (VerbSense.OPEN, VerbSense.CLOSE):
        return False
    away = abs(builder.tracker.value(part.joint) - geometry.closed_value) > _AJAR_SHARE * geometry.span
    return away if wanted is VerbSense.OPEN else not away


def _grounded_alone(builder: Builder, frame: Frame, mention: Mention) -> list[Part]:
    """The parts one mention of a heading names on its own ("the food": the turntable that carries it), [] if none."""
    try:
        return builder.ground(frame, VerbSense.OPEN, (mention,))[0]
    except GroundingError:
        return []


def _each_alone(builder: Builder, frame: Frame) -> list[Part] | None:
    """The parts of a heading that names several parts each on its own ("a big wheel ... and a smaller dial"), or None."""
    if len(frame.themes) < 2:
        return None
    parts: list[Part] = []
    for mention in frame.themes:
        try:
            found, _ = builder.refs.resolve(mention)
        except GroundingError:
            return None
        parts += [p for p in found if p not in parts]
    return parts if len({p.kind for p in parts}) == 1 else None


_SITTING = frozenset({"sitting", "sits", "resting", "rests", "lying", "lies", "placed", "standing", "stands"})


def _placed_on(builder: Builder, frame: Frame) -> bool:
    """"The baking tray is sitting on the rack nearest the floor": what sits on a part is a thing of the user's, whatever
    its name; the part it sits on is what comes next ("that rack"). False when the clause says no such thing."""
    words = frame.text.split()
    if frame.verb is not None or len(frame.themes) != 1 or frame.themes[0].kind is None or not _SITTING & set(words):
        return False
    place = held_in(frame, frame.themes[0])
    if place is None or place.kind is None:
        return False
    try:
        parts, _ = builder.refs.resolve(place)
    except GroundingError:
        return False
    builder.refs.remember(parts, [], topic=True)
    builder.refs.assigned.setdefault(place.head, parts[0])
    builder.notes.append(f"read '{frame.themes[0].words or frame.themes[0].head}' as a thing on {place.words or place.head}, not a part")
    return True


def set_topic(builder: Builder, frame: Frame) -> None:
    """"The roast is sitting on the middle shelf - get it out to me", "check on the roast on the top shelf": a skipped
    clause that places something on one part makes that part what "it" means next (when nothing else does yet)."""
    places = [*frame.instruments, *(m.owner for m in frame.themes if m.kind is None and not m.is_object and m.owner is not None)]
    if frame.stative and frame.themes and frame.themes[0].kind is None:
        places += frame.themes[1:]  # "the ketchup is in the left-hand door, open that one": where the thing is
        if not places and (holder := held_in(frame, frame.themes[0])) is not None and holder.kind is not None:
            places = [holder]  # "the sodas are behind the left-hand fridge door - get one out for me"
    if not builder.refs.scene:  # "the cookies are in the top oven, get that rack out": that oven's
        builder.refs.scene = next((m.sides for m in places if m.is_object and m.sides), ())
    places = [m for m in places if m.kind is not None]
    side = side_of_object(frame.text.split())
    if frame.stative and side is not None and not builder.refs.scene:
        builder.refs.scene = (side,)  # "the milk is on the left side of the fridge, get that door open": the left one
    told = [m for m in frame.themes[:1] if (m.kind is not None or carrier_of(m.head, builder.refs.obj.category)) and not m.pronoun] if (
        frame.verb is None or frame.stative) else []  # "the toast is sitting too low": what carries it
    if len(told) == 1:
        places = told  # "The clasps on this box are spring-loaded, so both of them snap shut", "The little knob on the far right is
        # the lid release. Give it a quarter turn": the subject of a description is what "it" / "them" means next
    elif builder.refs.last or len(places) != 1:
        return
    try:
        found, _ = builder.refs.resolve(places[0])
    except GroundingError:
        return
    if len(found) == 1 or (told and found and told[0].plural):
        builder.refs.last, builder.refs.last_kind = list(found), found[0].kind
        if places[0].region and not builder.refs.scene:
            builder.refs.scene = places[0].region  # "check what's on the bottom rack of the lower oven. Drop that door open": its door


def exclude(builder: Builder, frame: Frame) -> None:
    """"without touching the knob", "don't use the pedal", "without using the pedal": keep those parts still. What is kept
    still is not what "it" names next ("Neither door should open while it moves": the fridge)."""
    last, last_kind = builder.refs.last, builder.refs.last_kind
    for mention in (*frame.themes, *frame.instruments):
        try:
            parts, _ = builder.ground(frame, builder.frame_sense(frame), (mention,))
        except GroundingError:
            continue
        builder.excluded.update(p.joint for p in parts)
        builder.excluded_as.update({p.joint: mention.kind for p in parts})  # by what name: "leave the cover lid where it is"
        if any(mech.is_control(p) for p in parts):
            builder.manual = True
    builder.refs.last, builder.refs.last_kind = last, last_kind
