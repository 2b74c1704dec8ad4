"""Things told rather than asked: where a thing is kept ("my keys are in the top drawer", "I need the napkins from the
drawer") opens the part that holds it; a code told after the request that needs it ("lock the safe, the code is 1-5-9")
is how it is done."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.lexicon.kinds import PartKind, info
from app.engine.lexicon.objects import names_other_object
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import FUNCTION_VERBS
from app.engine.offline.collisions import blocking_joints
from app.engine.offline.complaints import added, mishap
from app.engine.offline.reading.clauses import Link
from app.engine.offline.reading.codes import CODE_VERBS
from app.engine.offline.reading.holders import side_of_object
from app.engine.offline.reading.mention import Mention
from app.engine.offline.reading.mentions import parse_mentions
from app.engine.offline.reading.quantities import Quantities
from app.engine.offline.reading.stored import open_holder
from app.engine.offline.reading.tokens import tokenize

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.reading.acts import Act
    from app.engine.offline.reading.frames import Frame
    from app.engine.offline.reading.token import Token


_KEPT_PLACES = frozenset({"in", "inside", "on", "behind", "under", "at"})
_COPULA = frozenset({"is", "are", "was", "were", "'s", "live", "lives", "belong", "belongs"})


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
    if not places and frame.themes and (place := held_in(frame, frame.themes[0])) is not None:
        places = [place]  # "the milk is behind the fridge door on the left": the place is said with the thing
    if len(places) != 1:
        return False
    if not added(builder, replace(told[0], condition=False, goal=open_holder(replace(frame, heading=False, stative=False), places[0]))):
        return False
    thing = " ".join(words[:copula])
    builder.notes.append(f"no action was asked: '{thing}' is no part; opened {places[0].words or places[0].head}, where it is kept")
    return True


_FETCHING = frozenset({"get", "take", "grab", "fetch", "bring", "pull", "open"})
"""Verbs of reaching a thing told of before ("the casserole is in the bottom oven, I want to see how it's doing": read as
"open it" by then)."""
_FETCHED_FROM = frozenset({"from", "in", "inside", "out_of", "behind", "under", "on"})


def wanted_things(builder: Builder, frames: list[Frame]) -> tuple[list[Frame], list[str]]:
    """"I need the napkins from the drawer and then the plates behind the cabinet door": each wish for a thing that is no
    part of the object, where a part holds it, becomes opening that part (with a note)."""
    out, notes = [], []
    wishing = False
    kept: Mention | None = None  # where the things just told of are ("the sodas are behind the left-hand fridge door")
    told_where: set[int] = set()
    for frame in frames:
        first = frame.themes[0] if frame.themes else None
        category = builder.refs.obj.category
        if first is not None and (_told_of(frame, first, category) or _kept_by_user(frame, first)) and (place := held_in(frame, first)) is not None and _fetched_later(
                frames[frames.index(frame) + 1:]):
            kept = place  # "the lasagna on the very bottom rack should be done by now, I want to get it out": the rack, below
            out.append(frame)
            continue
        if first is not None and _told_of(frame, first, category):
            kept = held_in(frame, first) or kept
        elif kept is not None and frame.verb in _FETCHING and first is not None and first.head in _TAKEN and first.kind is None:
            out.append(open_holder(frame, kept))  # "... - get one out for me": one of them, out of where they are
            notes.append(f"'{frame.text}': opened {kept.words or kept.head}, where {'it is' if first.head == 'it' else 'they are'} kept")
            continue
        later = frames[frames.index(frame) + 1] if frame is not frames[-1] else None
        if frame.verb in _FETCHING and first is not None and _thing(first, builder.refs.obj.category) and held_in(frame, first) is None and (
                later is not None and (place := _where_it_is(later)) is not None and (place.is_object or (
                    place.kind is not None and builder.refs.of_kind(place.kind)))):
            out.append(open_holder(frame, place))  # "grab me the milk, it's on the right-hand side of the fridge"
            notes.append(f"'{first.words or first.head}' is no part: opened {place.words or place.head}, where it is kept")
            told_where.add(id(later))
            continue
        if id(frame) in told_where:
            continue  # where the thing just asked for is: said already
        wishing = frame.wish or (wishing and frame.verb is None)
        thing = frame.themes[0] if wishing and frame.verb is None and frame.themes else None
        if thing is None or thing.is_object or thing.pronoun or (thing.kind is not None and builder.refs.of_kind(thing.kind)) or (
                (thing.head in VERBS or thing.head in _LOOKING) and thing.words.split()[:1] == [thing.head]):  # "I need to check what's on ..."
            out.append(frame)
            continue
        holder = held_in(frame, thing) or kept  # "I keep my socks in the left drawer and I need a pair": from there
        if holder is None:
            out.append(frame)
            continue
        out.append(open_holder(replace(frame, wish=False), holder))
        notes.append(f"'{thing.words or thing.head}' is no part: opened {holder.words or holder.head}, where it is kept")
    return out, notes


_TAKEN = frozenset({"one", "some", "them", "it"})
_LOOKING = frozenset({"check", "see", "look", "find", "peek", "know"})
"""A wish to look ("I need to check what's on the bottom rack"): a verb after the wish, no thing wanted."""


def _told_of(frame: Frame, first: Mention | None, category: str | None) -> bool:
    """A clause about a thing that is no part, with no verb of its own: "the sodas are behind the left-hand door", "the
    lasagna on the very bottom rack should be done by now" (where it is, for a later "get it out")."""
    thing = first is not None and first.kind is None and not first.pronoun and (
        not first.is_object or names_other_object(first.head, category))  # "the casserole" on an oven is a dish in it
    return first is not None and thing and (
        frame.stative or (frame.verb is None and frame.link is Link.FIRST))  # "the chicken on the top shelf needs basting"


def _thing(mention: Mention, category: str | None) -> bool:
    return mention.kind is None and not mention.pronoun and (not mention.is_object or names_other_object(mention.head, category))


def _where_it_is(frame: Frame) -> Mention | None:
    """"it's on the right-hand side of the fridge", "they're in the top drawer": where the thing just asked for is."""
    words = frame.text.split()
    if words[:1] not in (["it's"], ["they're"]) and words[:2] not in (["it", "is"], ["they", "are"]):
        return None
    place = held_in(frame, Mention(head=words[0], pronoun=True, start=0, end=1)) if frame.stative or frame.verb is None else None
    side = side_of_object(words)
    return replace(place, sides=(side,)) if place is not None and place.is_object and side is not None else place  # "the right-hand side of the fridge"


def _kept_by_user(frame: Frame, first: Mention | None) -> bool:
    """"I keep my socks in the left drawer": where the user keeps a thing that is no part."""
    return frame.verb == "keep" and frame.text.split()[:1] in (["i"], ["we"]) and first is not None and first.kind is None and not (
        first.is_object or first.pronoun)


def _fetched_later(frames: list[Frame]) -> bool:
    """A later clause reaches for the thing told of: "get it out", "get one out", "I need a pair"."""
    return any((f.verb in _FETCHING or (f.wish and f.verb is None)) and f.themes and f.themes[0].kind is None and (
        f.themes[0].head in _TAKEN or (f.wish and not f.themes[0].is_object)) for f in frames)


def told_codes(frames: list[Frame]) -> list[Frame]:
    """"Lock the safe, the code is 1-5-9": the code told after a request that needs one is how it is done, as "lock the
    safe by entering 1-5-9" says."""
    out: list[Frame] = []
    frames = list(frames)
    for index, frame in enumerate(frames):
        told = frame.codes and frame.verb is None and ((frame.stative and frame.themes and all(m.kind is PartKind.CODE for m in frame.themes)) or (
            not frame.themes and bool(set(frame.text.split()) & _CODE_WORDS)))  # "my PIN's 1904"
        after = frames[index + 1] if index + 1 < len(frames) else None
        if told and after is not None and _enters_code(after):  # "the code is 2 5 8, punch it in": the next clause enters it
            frames[index + 1] = replace(after, codes=frame.codes, themes=tuple(m for m in after.themes if m.kind is PartKind.BUTTON),
                                        link=frame.link if not out else after.link)
            continue
        if not frame.codes and any(f.codes for f in out) and _code_said(frame) and (frame.stative or frame.verb in CODE_VERBS):
            continue  # "only after the code is complete", "once the code has been entered": the code entered before, not a step
        told = told or (frame.codes and frame.link is Link.MEANS and bool(out) and out[-1].sense is VerbSense.OPEN)  # "open it by entering 1-5-9"
        if told and out and out[-1].sense in (VerbSense.LOCK, VerbSense.UNLATCH, VerbSense.OPEN) and out[-1].themes and all(
                m.is_object or m.pronoun for m in out[-1].themes):  # "unlock it: my PIN is 9512"
            entered = replace(frame, verb="enter", sense=VerbSense.PRESS, themes=(), stative=False, conjoined=False)
            if out[-1].sense is VerbSense.LOCK:
                out.append(replace(entered, link=Link.MEANS, marker="by"))  # shut first, then the code locks it
            else:  # "open the safe, the code is 1-5-9": the code, then the door
                out[-1:] = [replace(entered, link=out[-1].link, clause=out[-1].clause), replace(out[-1], link=Link.SEQUENCE, clause=frame.clause)]
            continue
        out.append(frame)
    return out


_CODE_WORDS = frozenset(w for w in info(PartKind.CODE).words if " " not in w)


def _on_code(frame: Frame) -> bool:
    """Every theme is "it", the code or the keypad."""
    return bool(frame.themes) and all(m.pronoun or m.kind in (PartKind.CODE, PartKind.BUTTON) for m in frame.themes)


def _code_said(frame: Frame) -> bool:
    return _on_code(frame) and any(m.kind is PartKind.CODE for m in frame.themes)


def _enters_code(frame: Frame) -> bool:
    """A code verb on "it", "the code" or the keypad with no digits of its own ("type it in on the keypad")."""
    return frame.verb in CODE_VERBS and not frame.codes and _on_code(frame) and not any(
        m.kind is PartKind.BUTTON and (m.plural or m.sides or m.ordinal is not None) for m in frame.themes)


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
    related = thing.relation[1] if thing.relation is not None and thing.relation[0] in _FETCHED_FROM and thing.relation[1].kind else None
    if related is not None and related.sides:
        return related
    words = frame.text.split()
    head = thing.head.split()[-1]  # "baking tray": its noun
    said = next((k for k, w in enumerate(words) if w in (head, f"{head}s", f"{head}es")), None)
    begin = min(thing.end, said + 1 if said is not None else thing.end)  # the mention may reach over its place
    at = next((k for k in range(begin, len(words)) if words[k] in _FETCHED_FROM or words[k:k + 2] == ["out", "of"]), None)
    tail = parse_mentions(tokenize(" ".join(words[at + 1:]).replace(" 's", "'s")), 0) if at is not None else []  # "the lower oven 's rack"
    if related is not None and not (tail and tail[0].head == related.head and tail[0].sides):
        return related
    return tail[0] if tail and (tail[0].kind is not None or tail[0].is_object) else None  # "behind the fridge door on the left"


_SLIDING = frozenset({PartKind.TRAY, PartKind.SHELF, PartKind.DRAWER})
_TAKING_OUT = frozenset({"take", "get", "grab", "fetch", "remove", "retrieve", "pull", "bring"})


def fetched_through(builder: Builder, act: Act, tokens: list[Token], before: int) -> None:
    """"Take the pizza out of the top oven": a thing taken out of a compartment, read as opening its door (the steps from
    ``before`` on), comes out on the one rack behind that door, which slides out too (with a note); nothing when the
    door hides no sliding part or several."""
    if not any(t.text == "open" and t.corrected_from and t.corrected_from.split()[0] in _TAKING_OUT and " out" in f" {t.corrected_from}"
               for t in tokens):
        return
    opened = {m.joint for step in builder.steps[before:] for m in step.effects}
    doors = [p for p in builder.parts if p.joint in opened and p.kind is not None and info(p.kind).hinged]
    closed = doors[0].geometry.closed_value if len(doors) == 1 else None
    if closed is None:
        return
    door = doors[0]
    shut = {**builder.tracker.now, door.joint: closed}
    behind = [p for p in builder.parts if p.kind in _SLIDING and p.joint not in opened and p.geometry.open_value is not None and door.joint in
              blocking_joints(builder.asset, p.joint, p.geometry.open_value, shut)]
    if len(behind) != 1:
        return
    rack = behind[0]
    frame = replace(act.goal, verb="pull", sense=VerbSense.PULL_OUT, particle="out", themes=(), instruments=(), wish=False, heading=False,
                    stative=False, quantities=Quantities(speed_factor=act.goal.quantities.speed_factor))
    builder.complete(replace(act, goal=frame, means=None, condition=False), VerbSense.PULL_OUT, [],
                     builder.moves(frame, VerbSense.PULL_OUT, [rack], [rack.link], None))
    builder.notes.append(f"'{act.goal.text}': also slid out {rack.link} ({rack.joint}), the one {rack.kind} behind {door.link}, "
                         "to take the thing out on it")
