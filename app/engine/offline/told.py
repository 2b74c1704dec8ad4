"""Things told rather than asked: where a thing is kept ("my keys are in the top drawer", "I need the napkins from the
drawer") opens the part that holds it; a code told after the request that needs it ("lock the safe, the code is 1-5-9")
is how it is done."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.lexicon.kinds import PartKind, info
from app.engine.lexicon.verbs import VerbSense
from app.engine.lexicon.words import FUNCTION_VERBS
from app.engine.offline.complaints import added, mishap
from app.engine.offline.reading.clauses import Link
from app.engine.offline.reading.mentions import parse_mentions
from app.engine.offline.reading.stored import open_holder
from app.engine.offline.reading.tokens import tokenize

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.reading.acts import Act
    from app.engine.offline.reading.frames import Frame
    from app.engine.offline.reading.mention import Mention


_KEPT_PLACES = frozenset({"in", "inside", "on", "behind", "under", "at"})
_COPULA = frozenset({"is", "are", "was", "were", "'s"})


def answer_stored(builder: Builder, acts: list[Act]) -> bool:
    """"My keys are in the top drawer", "the casserole is in the bottom oven" and nothing asked: the part (or the
    compartment) that holds the thing is opened, with a note; False when the prompt is not one such statement."""
    told = [a for a in acts if not mishap(a)]
    if len(told) != 1 or told[0].means is not None:
        return False
    frame = told[0].goal
    words = frame.text.split()
    copula = next((k for k, w in enumerate(words) if w in _COPULA), None)
    if copula is None or copula == 0 or (frame.verb is not None and frame.verb != "keep"):
        return False
    at = copula + 1 + (words[copula + 1:copula + 2] in (["kept"], ["still"], ["stored"], ["somewhere"]))
    if words[at:at + 1] == [] or words[at] not in _KEPT_PLACES or any(m.start < copula and m.kind is not None for m in frame.themes):
        return False
    places = [m for m in frame.themes if m.start > at and (m.kind is not None or m.is_object)]
    if len(places) != 1:
        return False
    if not added(builder, replace(told[0], condition=False, goal=open_holder(replace(frame, heading=False, stative=False), places[0]))):
        return False
    thing = " ".join(words[:copula])
    builder.notes.append(f"no action was asked: '{thing}' is no part; opened {places[0].words or places[0].head}, where it is kept")
    return True


_FETCHING = frozenset({"get", "take", "grab", "fetch", "bring", "pull"})
_FETCHED_FROM = frozenset({"from", "in", "inside", "out_of", "behind", "under", "on"})


def wanted_things(builder: Builder, frames: list[Frame]) -> tuple[list[Frame], list[str]]:
    """"I need the napkins from the drawer and then the plates behind the cabinet door": each wish for a thing that is no
    part of the object, where a part holds it, becomes opening that part (with a note)."""
    out, notes = [], []
    wishing = False
    kept: Mention | None = None  # where the things just told of are ("the sodas are behind the left-hand fridge door")
    for frame in frames:
        first = frame.themes[0] if frame.themes else None
        if frame.stative and first is not None and first.kind is None and not (first.is_object or first.pronoun):
            kept = held_in(frame, first)
        elif kept is not None and frame.verb in _FETCHING and first is not None and first.head in ("one", "some", "them") and first.kind is None:
            out.append(open_holder(frame, kept))  # "... - get one out for me": one of them, out of where they are
            notes.append(f"'{frame.text}': opened {kept.words or kept.head}, where they are kept")
            continue
        wishing = frame.wish or (wishing and frame.verb is None)
        thing = frame.themes[0] if wishing and frame.verb is None and frame.themes else None
        if thing is None or thing.is_object or thing.pronoun or (thing.kind is not None and builder.refs.of_kind(thing.kind)):
            out.append(frame)
            continue
        holder = held_in(frame, thing)
        if holder is None:
            out.append(frame)
            continue
        out.append(open_holder(replace(frame, wish=False), holder))
        notes.append(f"'{thing.words or thing.head}' is no part: opened {holder.words or holder.head}, where it is kept")
    return out, notes


def told_codes(frames: list[Frame]) -> list[Frame]:
    """"Lock the safe, the code is 1-5-9": the code told after a request that needs one is how it is done, as "lock the
    safe by entering 1-5-9" says."""
    out: list[Frame] = []
    for frame in frames:
        told = frame.codes and frame.verb is None and frame.stative and frame.themes and all(m.kind is PartKind.CODE for m in frame.themes)
        told = told or (frame.codes and frame.link is Link.MEANS and bool(out) and out[-1].sense is VerbSense.OPEN)  # "open it by entering 1-5-9"
        if told and out and out[-1].sense in (VerbSense.LOCK, VerbSense.UNLATCH, VerbSense.OPEN) and out[-1].themes and all(
                m.is_object for m in out[-1].themes):
            entered = replace(frame, verb="enter", sense=VerbSense.PRESS, themes=(), stative=False, conjoined=False)
            if out[-1].sense is VerbSense.LOCK:
                out.append(replace(entered, link=Link.MEANS, marker="by"))  # shut first, then the code locks it
            else:  # "open the safe, the code is 1-5-9": the code, then the door
                out[-1:] = [replace(entered, link=out[-1].link, clause=out[-1].clause), replace(out[-1], link=Link.SEQUENCE, clause=frame.clause)]
            continue
        out.append(frame)
    return out


_APPOSED = frozenset({",", "-", "—", ":", ";"})


def told_how(frames: list[Frame]) -> list[Frame]:
    """"Start the washer, turn the big dial a quarter turn clockwise", "Start a wash - turn the big dial ...": a request to
    set the object going, then the control that does it: the control is worked, said as "turn the dial to start the
    wash" (what is open is shut first)."""
    out: list[Frame] = []
    for frame in frames:
        before = out[-1] if out else None
        if before is not None and before.verb in FUNCTION_VERBS and frame.verb is not None and frame.marker in _APPOSED and frame.themes and all(
                m.kind is not None and info(m.kind).control for m in frame.themes):
            out[-1:] = [replace(frame, link=before.link, clause=before.clause, marker=before.marker),
                        replace(before, link=Link.PURPOSE, clause=frame.clause, marker="to", themes=())]
            continue
        out.append(frame)
    return out


def held_in(frame: Frame, thing: Mention) -> Mention | None:
    """The part (or the object) that holds ``thing`` in ``frame``: "the napkins from the drawer", "the sodas are behind
    the left-hand fridge door", "the plates behind the cabinet door"; None when no such place is said."""
    if thing.relation is not None and thing.relation[0] in _FETCHED_FROM and thing.relation[1].kind:
        return thing.relation[1]
    words = frame.text.split()
    at = next((k for k in range(thing.end, len(words)) if words[k] in _FETCHED_FROM or words[k:k + 2] == ["out", "of"]), None)
    tail = parse_mentions(tokenize(" ".join(words[at + 1:])), 0) if at is not None else []
    return tail[0] if tail and (tail[0].kind is not None or tail[0].is_object) else None
