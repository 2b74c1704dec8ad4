"""A complaint instead of a command: the prompt tells a part's state and asks for no step ("the lower drawer is
sticking out and I keep bumping my knee on it", "the toilet seat is up again", "someone left the oven door open").
The part is put the other way, and a note says the action was read from the complaint: it is a guess."""

from __future__ import annotations

from dataclasses import replace
from itertools import pairwise
from typing import TYPE_CHECKING

from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.verbs import VerbSense
from app.engine.lexicon.words import BODY_WORDS, COMPLAINED_STATES, LIGHTING_COMPLAINTS, MISHAP_VERBS, PERSONS
from app.engine.offline.reading.clauses import Link
from app.engine.offline.reading.mention import Mention
from app.engine.offline.reading.mentions import parse_mentions
from app.engine.offline.reading.stored import open_holder
from app.engine.offline.reading.tokens import tokenize

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.reading.acts import Act
    from app.engine.offline.reading.frames import Frame

_COPULAS = frozenset({"is", "are", "was", "were", "been", "left", "keeps", "stays", "still", "always", "again", "now", "all", "the", "way",
                      "wide", "sticking", "hanging", "standing", "poking", "sitting", "partly", "half", "a", "bit", "little", "slightly"})
_SOMEONE = frozenset({"someone", "somebody", "they", "you", "he", "she", "kids", "i", "we", "who"})
_TWO_WORD = {("sticking", "out"): "sticking_out", ("poking", "out"): "sticking_out", ("hanging", "open"): "hanging_open"}


def mishap(act: Act) -> bool:
    """A clause about the user running into a part ("I keep bumping my knee on it", "the kids trip over it")."""
    words = act.goal.text.split()
    if not words or not (words[0] in PERSONS or act.goal.aside):
        return False
    verbs = {_stem(w) if w.endswith("ing") else w.rstrip("s") for w in words[1:4]} & MISHAP_VERBS
    return bool(verbs) and (bool(verbs & _ALONE) or (any(w in BODY_WORDS for w in words[2:] if w not in ("my", "our")) and "my" in words))


_ALONE = frozenset({"bump", "trip", "stumble", "stub", "snag"})


def _stem(word: str) -> str:
    base = word[:-3]
    return base[:-1] if len(base) > 2 and base[-1] == base[-2] else base  # "bumping" -> bump, "hitting" -> hit


def complained(act: Act) -> tuple[VerbSense, str] | None:
    """The sense that puts the part of a told state the other way, and the state word ("sticking out")."""
    frame = act.goal
    if not frame.themes or (frame.verb is not None and frame.verb not in ("have", "leave", "keep", "stick", "hang")):
        return None
    words = frame.text.split()
    end = max(m.end for m in frame.themes)
    tail = [w for w in words[end:] if w not in ("again", "still", "now", "please", ".", "!", ",")]
    for a, b in pairwise(tail):
        if (a, b) in _TWO_WORD:
            return VerbSense(COMPLAINED_STATES[_TWO_WORD[a, b]]), f"{a} {b}"
    state = tail[-1] if tail else ""
    told = any(w in ("is", "are", "was", "were", "left", "been") for w in tail[:-1]) or (words[0] in _SOMEONE and words[1:2] == ["had"])
    if state in COMPLAINED_STATES and all(w in _COPULAS for w in tail[:-1]) and told:
        return VerbSense(COMPLAINED_STATES[state]), state
    return None


def left_open(act: Act) -> bool:
    """"somebody left the bottom drawer open" (read as "somebody had ..."): a complaint whatever the part's pose."""
    words = act.goal.text.split()
    return words[:1] != [] and words[0] in _SOMEONE and words[1:2] == ["had"] and complained(act) is not None


def answer_complaint(builder: Builder, acts: list[Act]) -> bool:
    """The one told state, put the other way (with a note that says it was read from a complaint); False when none.
    The clause is added to ``builder.turned`` (the audit does not flag its direction)."""
    told = [(act, found) for act in acts if (found := complained(act)) is not None]
    if len(told) != 1:
        return False
    act, (sense, state) = told[0]
    verb = {VerbSense.CLOSE: "close", VerbSense.OPEN: "open", VerbSense.LOWER: "lower", VerbSense.RAISE: "raise",
            VerbSense.SWITCH_OFF: "turn off"}[sense]
    steps = len(builder.steps)
    builder.add(replace(act, condition=False, goal=replace(act.goal, verb=verb.split()[0], sense=sense, heading=False, stative=False)))
    if len(builder.steps) == steps:
        return False
    builder.turned.add(act.goal.clause)
    _superseded(builder, act.goal.text)
    builder.notes.append(f"no action was asked: read '{act.goal.text}' as a wish to {verb} it ({state} is taken as the trouble)")
    return True


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
    steps = len(builder.steps)
    builder.add(replace(told[0], condition=False, goal=open_holder(replace(frame, heading=False, stative=False), places[0])))
    if len(builder.steps) == steps:
        return False
    thing = " ".join(words[:copula])
    builder.notes.append(f"no action was asked: '{thing}' is no part; opened {places[0].words or places[0].head}, where it is kept")
    return True


def answer_lighting(builder: Builder, acts: list[Act]) -> bool:
    """"It's way too dark in here" on a light switch, and nothing asked: the switch is turned on (off for "too bright"),
    with a note; False when the words say nothing of the light or the object has not exactly one switch."""
    said = [LIGHTING_COMPLAINTS[w] for a in acts for w in a.goal.text.split() if w in LIGHTING_COMPLAINTS]
    switches = builder.refs.of_kind(PartKind.SWITCH)
    if len(set(said)) != 1 or len(switches) != 1:
        return False
    sense = VerbSense(said[0])
    act = acts[0]
    mention = Mention(head="switch", kind=PartKind.SWITCH, words="the switch")
    steps = len(builder.steps)
    builder.add(replace(act, condition=False, goal=replace(act.goal, verb="turn", sense=sense, themes=(mention,), heading=False, stative=False,
                                                                 particle=None, wish=False, quantities=replace(act.goal.quantities, amount=None))))
    if len(builder.steps) == steps:
        return False
    _superseded(builder, act.goal.text)
    builder.notes.append(f"no action was asked: read '{act.goal.text}' as a wish to turn the light {'on' if sense is VerbSense.SWITCH_ON else 'off'}")
    return True


_FETCHED_FROM = frozenset({"from", "in", "inside", "out_of", "behind", "under", "on"})


def wanted_things(builder: Builder, frames: list[Frame]) -> tuple[list[Frame], list[str]]:
    """"I need the napkins from the drawer and then the plates behind the cabinet door": each wish for a thing that is no
    part of the object, where a part holds it, becomes opening that part (with a note)."""
    out, notes = [], []
    wishing = False
    for frame in frames:
        wishing = frame.wish or (wishing and frame.verb is None)
        thing = frame.themes[0] if wishing and frame.verb is None and frame.themes else None
        if thing is None or thing.is_object or thing.pronoun or (thing.kind is not None and builder.refs.of_kind(thing.kind)):
            out.append(frame)
            continue
        holder = thing.relation[1] if thing.relation is not None and thing.relation[0] in _FETCHED_FROM and thing.relation[1].kind else None
        if holder is None:
            words = frame.text.split()
            at = next((k for k in range(thing.end, len(words)) if words[k] in _FETCHED_FROM or words[k:k + 2] == ["out", "of"]), None)
            tail = parse_mentions(tokenize(" ".join(words[at + 1:])), 0) if at is not None else []
            holder = tail[0] if tail and (tail[0].kind is not None or tail[0].is_object) else None
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


def _superseded(builder: Builder, text: str) -> None:
    """The earlier notes on a clause now read as a complaint ("ignored '...'", "read '...' as a summary") no longer hold."""
    builder.notes[:] = [n for n in builder.notes if not n.startswith((f"ignored '{text}'", f"read '{text}' as a summary"))]
