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
from app.engine.lexicon.words import BODY_WORDS, COMPLAINED_STATES, MISHAP_VERBS, PERSONS, ROOM_COMPLAINTS
from app.engine.offline.reading.acts import Act
from app.engine.offline.reading.mention import Mention

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.reading.frames import Frame

_COPULAS = frozenset({"is", "are", "was", "were", "been", "left", "keeps", "stays", "still", "always", "again", "now", "all", "the", "way",
                      "wide", "sticking", "hanging", "standing", "poking", "sitting", "partly", "half", "a", "bit", "little", "slightly", "both"})
_SOMEONE = frozenset({"someone", "somebody", "they", "you", "he", "she", "kids", "i", "we", "who"})
_TWO_WORD = {("sticking", "out"): "sticking_out", ("poking", "out"): "sticking_out", ("hanging", "open"): "hanging_open",
             ("sticking", "up"): "up", ("straight", "up"): "up"}


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
    if not frame.themes or (frame.verb is not None and frame.verb not in ("have", "leave", "keep", "stick", "hang", "get", "sit", "stand")):
        return None
    words = frame.text.split()
    copula = next((k for k, w in enumerate(words) if w in ("is", "are", "was", "were")), len(words))
    end = max((m.end for m in frame.themes if m.start < copula), default=max(m.end for m in frame.themes))  # not "... anyone can see my stuff"
    tail = [w for w in words[end:] if w not in ("again", "still", "now", "please", ".", "!", ",")]
    if _in_the_way(tail):
        return VerbSense.TOGGLE, "in the way"  # the pose decides which way is out of the way (``_out_of_the_way``)
    for a, b in pairwise(tail):
        if (a, b) in _TWO_WORD:
            return VerbSense(COMPLAINED_STATES[_TWO_WORD[a, b]]), f"{a} {b}"
    at = next((k for k, w in enumerate(tail) if w in COMPLAINED_STATES and k + 1 < len(tail) and tail[k + 1] in _WHO_ELSE), len(tail) - 1)
    tail = tail[:at + 1]  # "the safe is wide open anyone can see my stuff": the state, then what it lets happen
    state = tail[-1] if tail else ""
    told = any(w in ("is", "are", "was", "were", "left", "been") for w in tail[:-1]) or (words[0] in _SOMEONE and words[1:2] == ["had"])
    if state in COMPLAINED_STATES and all(w in _COPULAS for w in tail[:-1]) and told:
        return VerbSense(COMPLAINED_STATES[state]), state
    return None


_WHO_ELSE = frozenset({"anyone", "anybody", "everyone", "everybody", "someone", "somebody", "people", "and", "so", "the", "it", "i", "you", "we"})


_WAY_OWNERS = frozenset({"the", "my", "our", "your"})
_BLOCKING = frozenset({"blocking", "obstructing"})


def _in_the_way(tail: list[str]) -> bool:
    """"the lid is in the way", "keeps getting in my way", "it's blocking": a part whose pose is the trouble."""
    return any(tail[k:k + 3] in (["in", o, "way"] for o in _WAY_OWNERS) for k in range(len(tail))) or bool(_BLOCKING & set(tail))


def _bumped_into(act: Act) -> tuple[VerbSense, str] | None:
    """"I keep banging my knee on that drawer": the part named in a mishap sticks out, so it is shut."""
    return (VerbSense.CLOSE, "running into it") if mishap(act) and any(m.kind is not None for m in act.goal.themes) else None


def left_open(act: Act) -> bool:
    """"somebody left the bottom drawer open" (read as "somebody had ..."): a complaint whatever the part's pose."""
    words = act.goal.text.split()
    return words[:1] != [] and words[0] in _SOMEONE and words[1:2] == ["had"] and complained(act) is not None


def answer_complaint(builder: Builder, acts: list[Act]) -> bool:
    """The one told state, put the other way (with a note that says it was read from a complaint); False when none.
    A mishap on a part with no state told ("I keep banging my knee on that drawer") finds the part in the way. The
    clause is added to ``builder.turned`` (the audit does not flag its direction)."""
    told = [(act, found) for act in acts if (found := complained(act) or _bumped_into(act)) is not None]
    if len(told) != 1:
        return False
    act, (sense, state) = told[0]
    if sense is VerbSense.TOGGLE:
        way = _out_of_the_way(builder, act)
        if way is None:
            return False
        sense = way
    verb = {VerbSense.CLOSE: "close", VerbSense.OPEN: "open", VerbSense.LOWER: "lower", VerbSense.RAISE: "raise",
            VerbSense.SWITCH_OFF: "turn off"}[sense]
    if not added(builder, replace(act, condition=False, goal=replace(act.goal, verb=verb.split()[0], sense=sense, heading=False, stative=False))):
        return False
    builder.turned.add(act.goal.clause)
    _superseded(builder, act.goal.text)
    builder.notes.append(f"no action was asked: read '{act.goal.text}' as a wish to {verb} it ({state} is taken as the trouble)")
    return True


def _out_of_the_way(builder: Builder, act: Act) -> VerbSense | None:
    """The way a part "in the way" goes: open when it rests nearer its closed end (a lid over the seat), else shut (a
    door standing open); None when the clause names no one part with two ends."""
    parts, _ = builder.refs.resolve(act.goal.themes[0])
    geometry = parts[0].geometry if len(parts) == 1 else None
    if geometry is None or geometry.closed_value is None or not geometry.span:
        return None
    share = abs(builder.tracker.value(parts[0].joint) - geometry.closed_value) / geometry.span
    return VerbSense.OPEN if share < 0.5 else VerbSense.CLOSE


def answer_room(builder: Builder, acts: list[Act], frames: list[Frame]) -> bool:
    """"It's way too dark in here" on a light switch, "it's stuffy in here" on a window, "there's a cold draft coming
    through the doorway", "I don't want dust getting into this box", and nothing asked: the one part that answers it is
    worked (the switch on, the window open, the door or lid shut), with a note; False when the words say nothing of the
    room or the object has not exactly one such part."""
    told = [f.text for f in frames]  # "I don't want dust getting in": said as what not to have (no act)
    said = {ROOM_COMPLAINTS[w] for f in frames for w in f.text.split() if w in ROOM_COMPLAINTS and not (
        w in (f.verb, f.guessed_verb) and ROOM_COMPLAINTS[w][1] == ("switch",))}  # "dim the lights" asks for a dimmer, no complaint
    if len(said) != 1:
        return False
    (sense_name, kinds, category), = said
    if category and category != builder.refs.obj.category:
        return False
    found = next((parts for kind in kinds if (parts := builder.refs.of_kind(PartKind(kind)))), [])
    if len(found) != 1:
        return False
    sense, part = VerbSense(sense_name), found[0]
    act = acts[0] if acts else Act(goal=frames[0])
    mention = Mention(head=str(part.kind), kind=part.kind, words=f"the {part.kind}")
    verb = {VerbSense.SWITCH_ON: "turn", VerbSense.SWITCH_OFF: "turn"}.get(sense, sense.value)
    goal = replace(act.goal, verb=verb, sense=sense, themes=(mention,), instruments=(), heading=False, stative=False, particle=None, wish=False,
                   quantities=replace(act.goal.quantities, amount=None))
    if not added(builder, replace(act, condition=False, exclusions=(), means=None, results=(), goal=goal)):
        return False
    _superseded(builder, act.goal.text, frames)
    builder.turned.update(f.clause for f in frames)  # "... is hanging open and the cat keeps getting in": shut, as asked
    thing = "the light" if kinds == ("switch",) else f"the {part.kind}"
    done = {VerbSense.SWITCH_ON: f"turn {thing} on", VerbSense.SWITCH_OFF: f"turn {thing} off"}.get(sense, f"{sense.value} {thing}")
    builder.notes.append(f"no action was asked: read '{' '.join(told)}' as a wish to {done}")
    return True


_FINISHED = frozenset({"done", "finished", "through", "packed"})
_LEADS = frozenset({"ok", "okay", "right", "so", "well", "alright", "and", ",", "all"})
_USER_IS = (("i'm",), ("i", "am"), ("we're",), ("we", "are"), ("i've", "been"), ("i've",), ("we've",), ("i", "have"))


def whole_object_goal(frame: Frame, verb: str, sense: VerbSense, asset_name: str) -> Frame:
    """``frame`` made a plain request to ``verb`` the whole object (no amount, no other part, not a wish or a heading)."""
    whole = Mention(head="it", is_object=True, words=asset_name)
    return replace(frame, verb=verb, sense=sense, themes=(whole,), instruments=(), heading=False, stative=False, particle=None, wish=False,
                   guessed_verb=None, quantities=replace(frame.quantities, amount=None))


def answer_finished(builder: Builder, frames: list[Frame]) -> bool:
    """"I'm done working for today", "I'm finished with the laptop", "OK, I've finished packing the suitcase" and nothing
    asked: the object is shut (a laptop folded), with a note; False when no clause says so or nothing of it is open."""
    for act in (Act(goal=frame) for frame in frames):
        words = act.goal.text.split()
        while words and words[0] in _LEADS:
            words = words[1:]  # "OK, I've finished packing the suitcase"
        said = next((len(lead) for lead in _USER_IS if tuple(words[:len(lead)]) == lead), 0)  # "done with work for today": the user
        if words[said:said + 1] == [] or words[said] not in _FINISHED or any(m.kind is not None for m in act.goal.themes):
            continue
        goal = whole_object_goal(act.goal, "close", VerbSense.CLOSE, builder.asset.name)
        if added(builder, replace(act, condition=False, exclusions=(), means=None, results=(), goal=goal)):
            _superseded(builder, act.goal.text, [act.goal])
            builder.notes.append(f"no action was asked: read '{act.goal.text}' as a wish to shut {builder.asset.name}")
            return True
    return False


def _superseded(builder: Builder, text: str, frames: list[Frame] | None = None) -> None:
    """The earlier notes on a clause now read as a complaint ("ignored '...'", "read '...' as a summary") no longer hold,
    nor the guesses at the verbs of ``frames`` ("read the verb 'finished' as 'move'")."""
    stale = (f"ignored '{text}'", f"read '{text}' as a summary", *(f"read the verb '{f.guessed_verb}'" for f in frames or [] if f.guessed_verb))
    builder.notes[:] = [n for n in builder.notes if not n.startswith(stale)]


def added(builder: Builder, act: Act) -> bool:
    """``act`` added to ``builder``; whether it made a step (a part already where it was asked moves nothing)."""
    steps = len(builder.steps)
    builder.add(act)
    return len(builder.steps) > steps
