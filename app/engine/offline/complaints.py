"""A complaint instead of a command: the prompt tells how a part is, or how the room is, and asks for no step ("the
lower drawer is sticking out and I keep bumping my knee on it", "the toilet seat is up again", "someone left the oven door
open", "it's way too dark in here"). The part is put the other way (the light switched), and a note says the action
was read from the complaint: it is a guess."""

from __future__ import annotations

from dataclasses import replace
from itertools import pairwise
from typing import TYPE_CHECKING

from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.verbs import VerbSense
from app.engine.lexicon.words import BODY_WORDS, COMPLAINED_STATES, LIGHTING_COMPLAINTS, MISHAP_VERBS, PERSONS
from app.engine.offline.reading.mention import Mention

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.reading.acts import Act

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
    if not added(builder, replace(act, condition=False, goal=replace(act.goal, verb=verb.split()[0], sense=sense, heading=False, stative=False))):
        return False
    builder.turned.add(act.goal.clause)
    _superseded(builder, act.goal.text)
    builder.notes.append(f"no action was asked: read '{act.goal.text}' as a wish to {verb} it ({state} is taken as the trouble)")
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
    if not added(builder, replace(act, condition=False, goal=replace(act.goal, verb="turn", sense=sense, themes=(mention,), heading=False,
                                                                    stative=False, particle=None, wish=False,
                                                                    quantities=replace(act.goal.quantities, amount=None)))):
        return False
    _superseded(builder, act.goal.text)
    builder.notes.append(f"no action was asked: read '{act.goal.text}' as a wish to turn the light {'on' if sense is VerbSense.SWITCH_ON else 'off'}")
    return True


def _superseded(builder: Builder, text: str) -> None:
    """The earlier notes on a clause now read as a complaint ("ignored '...'", "read '...' as a summary") no longer hold."""
    builder.notes[:] = [n for n in builder.notes if not n.startswith((f"ignored '{text}'", f"read '{text}' as a summary"))]


def added(builder: Builder, act: Act) -> bool:
    """``act`` added to ``builder``; whether it made a step (a part already where it was asked moves nothing)."""
    steps = len(builder.steps)
    builder.add(act)
    return len(builder.steps) > steps
