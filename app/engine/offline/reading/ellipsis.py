"""Verbless clauses completed from the clause before ("open the left door, then the right one", "drawer out 30 cm /
wait 1 s / back in", "then back shut")."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.verbs import VERBLESS_SENSES, VERBS, VerbSense
from app.engine.lexicon.words import STATES
from app.engine.offline.reading.clauses import Link
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.step_labels import step_label

_TURN_WORDS = frozenset({"turn", "turns", "revolution", "revolutions", "rotation", "rotations", "spin", "spins"})


_STEPS = frozenset({Link.FIRST, Link.SEQUENCE, Link.PARALLEL})
"""Clauses that are steps of their own (not the result, condition or purpose of another)."""
_OPENING = frozenset({VerbSense.OPEN, VerbSense.PULL_OUT, VerbSense.RAISE})
_CLOSING = frozenset({VerbSense.CLOSE, VerbSense.PUSH_IN, VerbSense.LOWER})


def _alike(way: VerbSense, sense: VerbSense | None) -> bool:
    """Both senses open (pull out, raise) or both close (push in, lower): the verb before may go on ("pull the right
    drawer out, then the left one out too")."""
    return (way in _OPENING and sense in _OPENING) or (way in _CLOSING and sense in _CLOSING)


_STATE_VERBS = {"open": ("open", VerbSense.OPEN), "shut": ("close", VerbSense.CLOSE), "closed": ("close", VerbSense.CLOSE)}
"""A part and its end state, said with no verb after a step of another kind ("..., the plate gets one full turn, door shut")."""


def carry(frame: Frame, previous: Frame | None, measured: Frame | None = None) -> Frame:
    if frame.link is Link.NEGATED:
        return frame  # "keep your hands off the drawer": what not to touch takes no verb
    if previous is not None and step_label(previous.text):
        previous = None  # "Step 2: left drawer halfway": the label's "step" is no verb to carry
    said = frame.text.split()
    if frame.verb is None and len(said) <= 3 and said[-1:] and said[-1] in _STATE_VERBS and frame.themes and not any(m.is_object for m in frame.themes) and (
            previous is not None and previous.sense not in (None, _STATE_VERBS[said[-1]][1]) and frame.quantities.amount is None):
        verb, sense = _STATE_VERBS[said[-1]]
        return replace(frame, verb=verb, sense=sense)  # "door shut" after a turn: shut the door, not turn it
    if frame.verb is None and not frame.themes and previous is not None and previous.verb is None and previous.themes and (
            frame.quantities.amount is not None or frame.quantities.orientation is not None):
        # "blender dial: 1/8 turn clockwise": the part before the colon, moved by the amount after it
        verb = "turn" if frame.quantities.amount is not None and frame.quantities.amount.unit == "rad" else "move"
        return replace(frame, verb=verb, sense=VerbSense.TURN if verb == "turn" else VerbSense.MOVE, themes=previous.themes)
    if frame.verb is not None and not frame.themes and not frame.instruments and not frame.let and previous is not None and (
            previous.heading and previous.verb is None and previous.themes and frame.link in _STEPS):
        return replace(frame, themes=previous.themes)  # "Bucket handle: grab and bring up till vertical": the part in the heading
    amount = frame.quantities.amount
    if frame.verb is None and frame.themes and all(m.is_object for m in frame.themes) and amount is not None and amount.unit == "m" and (
            frame.quantities.direction is not None):
        return replace(frame, verb="move", sense=VerbSense.MOVE)  # "whole stapler, 0.2 m to my left": the object moves
    if frame.verb is None and frame.themes and amount is not None and amount.unit == "rad" and set(amount.words.split()) & _TURN_WORDS:
        return replace(frame, verb="turn", sense=VerbSense.TURN)  # "then the turntable makes a half revolution"
    if frame.same_direction and previous is not None:
        q, before = frame.quantities, previous.quantities
        frame = replace(frame, quantities=replace(q, direction=q.direction or before.direction, sense=q.sense or before.sense,
                                                  axis=q.axis or before.axis))
    return _carried(frame, previous, measured)


def _carried(frame: Frame, previous: Frame | None, measured: Frame | None = None) -> Frame:
    """A verbless clause takes the verb of the one before ("open the left door, then the right one");
    an amount-only clause takes its parts too ("push it 0.3 m forward and then 0.3 m back"); "do the same
    with the other one" and "the same amount" take its verb and amount."""
    if frame.same and previous is not None and previous.verb is None and frame.quantities.amount is None and previous.quantities.amount is not None:
        # "1) upper drawer out 0.3 m 2) lower drawer out the same distance": the amount, even when neither clause has a verb
        return replace(frame, quantities=replace(frame.quantities, amount=previous.quantities.amount))
    if frame.same and previous is not None and previous.verb is not None:
        source = previous if previous.quantities.amount is not None or measured is None else measured  # "the same amount": the last one said
        quantities = replace(frame.quantities, amount=frame.quantities.amount or source.quantities.amount)
        if frame.verb is None or frame.verb == "do" or frame.guessed_verb is not None:  # "give the other one the same"
            quantities = replace(quantities, sense=quantities.sense or previous.quantities.sense,  # "... counterclockwise, then do the same"
                                 direction=quantities.direction or previous.quantities.direction)
            themes = frame.themes or frame.instruments  # "do the same with the other one": the other one is the theme
            return replace(frame, verb=previous.verb, sense=previous.sense, particle=previous.particle, quantities=quantities,
                           themes=themes or previous.themes, instruments=() if not frame.themes else frame.instruments)
        return replace(frame, quantities=quantities)
    if frame.verb is not None and not frame.themes and not frame.instruments and previous is not None and previous.themes and (
            frame.text.split()[0] not in ("it", "they", "the")) and frame.quantities.axis is None and frame.sense not in (None, VerbSense.WAIT) and (
            not frame.let and frame.marker in ("then", "and_then", "after_that", "next", "afterwards", "finally")) and not (
            frame.verb in VERBS and VERBS[frame.verb].implies) and frame.sense is not VerbSense.RELEASE:  # "put the lid up, then flush":
        # the part flushing works; "..., then step off": the control let go, not the part it moved
        return replace(frame, themes=previous.themes)  # "the handle swings up, then drops back down": the same part
    if frame.verb is None and frame.returning and not frame.themes and frame.quantities.amount is None and previous is not None and (
            previous.verb is None and previous.themes and not previous.heading):
        return replace(frame, verb="return", sense=VerbSense.RETURN, themes=previous.themes)  # "drawer out 30cm / wait 1s / back in"
    if frame.verb is not None or previous is None or previous.verb is None:
        return frame
    amount_only = not frame.themes and (frame.quantities.amount is not None or frame.quantities.direction is not None or frame.quantities.axis is not None
                                        or frame.returning)  # "..., then back to the middle"
    if not frame.themes and frame.particle in ("on", "off") and previous.verb in VERBS:
        # "flick the switch on and then off again": the same verb with this particle, on the same part
        sense = VERBS[previous.verb].particles.get(frame.particle, previous.sense)
        return replace(frame, verb=previous.verb, sense=sense, themes=previous.themes, instruments=previous.instruments)
    if frame.codes and not frame.themes and not frame.returning:
        return replace(frame, verb=previous.verb, sense=previous.sense, particle=previous.particle)
    if (amount_only or all(m.pronoun for m in frame.themes)) and frame.returning and frame.quantities.amount is None and (
            previous.sense in (VerbSense.HOLD, VerbSense.WAIT)):
        # "leave it there 4 s, then back to where it started", "... then back up to the angle it started at": the return
        # is the step, not another hold
        return replace(frame, verb="return", sense=VerbSense.RETURN, themes=previous.themes, instruments=previous.instruments)
    if frame.themes and frame.quantities.amount is None and previous.quantities.amount is not None and not frame.returning and frame.particle is None and (
            frame.link in (Link.SEQUENCE, Link.PARALLEL) and not frame.stative and not frame.heading):
        # "open the left drawer 25 cm, then the right one": the ellipsis repeats the whole request, amount included
        frame = replace(frame, quantities=replace(frame.quantities, amount=previous.quantities.amount))
    ends = {STATES[w] for w in frame.text.split() if STATES.get(w) in ("open", "closed")}
    if frame.verb is None and len(ends) == 1 and frame.quantities.amount is None and (frame.themes or amount_only):
        # "a 4-second beat, then back shut": the state named is where it goes, whatever the verb before did
        verb, sense = ("close", VerbSense.CLOSE) if ends == {"closed"} else ("open", VerbSense.OPEN)
        return replace(frame, verb=verb, sense=sense, particle=None, returning=False, themes=frame.themes or previous.themes,
                       instruments=frame.instruments or previous.instruments)
    own_way = next((VERBLESS_SENSES[w] for w in reversed(frame.text.split()) if w in VERBLESS_SENSES), None)  # the last: where it ends
    if frame.themes and not frame.returning and own_way is not None and not _alike(own_way, previous.sense) and frame.link in _STEPS:
        # "... 2. push it back shut 3. upper drawer out 20 cm", "Steps: * top drawer out 30 cm": its own word says which way
        return replace(frame, sense=own_way)
    if frame.stative and not amount_only and not frame.wish and not ends and frame.link is not Link.CONDITION and frame.quantities.amount is None and not (
            set(frame.text.split()) & set(VERBLESS_SENSES)):
        return frame  # "the clasps on this box are spring-loaded": what a part is, no step of the verb before
    if frame.marker in (".", "!") and frame.themes and not amount_only and all(m.kind is None and not (
            m.is_object or m.pronoun or m.anaphor) for m in frame.themes):
        return frame  # "Push the mixer handle right. Cold only!": a word on its own after a full stop, no step of the verb before
    if frame.themes or amount_only:
        own = VERBS[previous.verb].particles.get(frame.particle or "") if previous.verb in VERBS and frame.particle != "back" else None
        if amount_only and frame.particle == "back" and frame.quantities.sense is None and previous.verb in VERBS and "back" not in VERBS[previous.verb].particles:
            own = VerbSense.RETURN  # "loosen the cap half a turn, then half a turn back": back the way it came
        return replace(frame, verb=previous.verb, sense=own or previous.sense, particle=frame.particle or (previous.particle if frame.themes else None),
                       themes=frame.themes or previous.themes, instruments=frame.instruments or previous.instruments)
    return frame
