"""The offline perceiver: prompt + asset -> the contract (Causal.json with its ``artimo`` block).

Stages, each reading only the typed output of the one before:
normalise (:mod:`.reading.tokens`) -> clauses (:mod:`.reading.clauses`) -> frames
(:mod:`.reading.frames`) -> acts (:mod:`.reading.acts`) -> grounding and causal completion
(:mod:`.builder`) -> contract (:mod:`.contract_io`). A prompt it cannot ground raises
:class:`GroundingError` naming the problem (a missing part, the candidates of an ambiguous one).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache
from typing import Any

from app.engine.asset.layout import direction_name
from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.steps import Extension
from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.objects import names_other_object
from app.engine.lexicon.relations import FRONT_RELATIVE_RELATIONS, RELATIONS, VIEWER_WORDS
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import AGENT_NOUNS, CAUSER_NOUNS, OBJECT_TILTS, PERSON_NOUNS, PERSONS, Side
from app.engine.offline.audit import audit
from app.engine.offline.builder import Builder
from app.engine.offline.complaints import answer_complaint, answer_finished, answer_room, left_open, mishap
from app.engine.offline.conditions import set_topic
from app.engine.offline.geometry import object_category
from app.engine.offline.intent import Intent
from app.engine.offline.it_named_before import named_before_it
from app.engine.offline.naming import GENERIC, tokens
from app.engine.offline.reading.acts import Act, build_acts
from app.engine.offline.reading.between import paused_between
from app.engine.offline.reading.clauses import Clause, Link, split_clauses
from app.engine.offline.reading.frames import Frame, read_frames
from app.engine.offline.reading.holders import put_in_only
from app.engine.offline.reading.mention import Mention
from app.engine.offline.reading.mentions import parse_mentions
from app.engine.offline.reading.repeats import repeated
from app.engine.offline.reading.tokens import Token, tokenize
from app.engine.offline.stated import record_release, stated_latched, stated_no_handle
from app.engine.offline.told import answer_stored, fetched_through, told_codes, told_how, wanted_things
from app.engine.offline.tracker import resolve_steps
from app.engine.offline.unit_scene import prompt_unit, unit_clause
from app.engine.offline.use_summary import said_by_use
from app.engine.offline.uses import answer_use
from app.engine.offline.whole_object import whole_named


@dataclass(frozen=True)
class Reading:
    extension: Extension
    intent: Intent
    understanding: list[dict[str, Any]]
    notes: tuple[str, ...]


@lru_cache(maxsize=64)
def asset_words(asset: ArticulatedAsset) -> frozenset[str]:
    """Words of the asset's own part names (never corrected; misspellings may be corrected to them)."""
    words: set[str] = set()
    for name, link in asset.links.items():
        for source in (link.semantics.label or "", name, *link.semantics.visual_names):
            if source and not GENERIC.match(source.lower()):
                words.update(w for w in tokens(source) if len(w) >= 3)
    category = object_category(asset)
    if category:
        words.update(tokens(category))
    return frozenset(words)


def _corrections(tokens_: list[Token]) -> list[str]:
    said: dict[tuple[str, int], list[str]] = {}  # "toiletlid": one slip read as two words
    for t in tokens_:
        if t.corrected_from:
            said.setdefault((t.corrected_from, t.start), []).append(t.text.replace("_", " "))
    return [f"read '{typed}' as '{' '.join(words)}'" for (typed, _), words in said.items()]


def _incidental(frame: Frame) -> bool:
    """A clause that may only set the scene when it names nothing movable: a heading ("Lock up the safe: ..."), a
    clause with no action verb ("The dishes are done."), one about a person, or one whose verb we do not know
    ("Check on the roast: ..."). A known action verb on a missing part is still refused ("open the trunk")."""
    return (frame.heading or frame.verb is None or frame.link in (Link.RESULT, Link.PURPOSE) or frame.stative or frame.aside or frame.verb not in VERBS or frame.sense is None
            or ((frame.clause == 0 or frame.marker in (".", "?", "!")) and frame.text.split()[0] in ("to", "in order to"))  # "To unlock it, press
            # ...": why, told first; "... ? Only enough to see whether the light comes on.": why, said after
            or (frame.wish and frame.clause > 0 and frame.text.split()[:1] in (["i"], ["we"], ["i'd"], ["we'd"]))  # "..., I need the counter space"
            or (frame.let and bool(frame.themes) and all(m.kind is None and not m.is_object and not m.pronoun for m in frame.themes))  # "let some steam out"
            or (frame.guessed_verb is not None and (frame.link in (Link.PARALLEL, Link.CONDITION) or bool(_BE & set(frame.text.split())) or (
                _said_of_someone(frame) and all(m.kind is None and not m.is_object and not m.pronoun for m in frame.themes))))  # "grandpa liked his water hot"
            # "while the narrator talks", "dishes are all loaded"
            or (not frame.themes and not frame.instruments and _said_of_someone(frame))  # "... when the arm lets go": about who acts
            or bool({"must", "should"} & set(frame.text.split()[1:4])))  # "..., lever must end up on the back side": how it ends


def _landmarks(clauses: list[Clause], clause: int) -> list[Mention]:
    """Parts a clause names only as where another is, in an apposition the frame drops ("..., the one behind the small door
    on top, ..."): said before, for "the door" later; never parts to move."""
    if clause >= len(clauses):
        return []
    return [m.relation[1] for m in parse_mentions(list(clauses[clause].tokens), 0) if m.anaphor and m.relation is not None and (
        m.relation[1].kind is not None)]


_BE = frozenset({"is", "are", "was", "were"})
_WHEN = frozenset({"when", "whenever", "while"})
_FACING = frozenset({"facing", "face", "faces", "pointing", "points", "point"})


def _said_of_someone(frame: Frame) -> bool:
    """A clause whose subject is a person, a robot or the scene ("the arm lets go", "the character looks inside")."""
    words = frame.text.split()
    if words[:1] in (["the"], ["a"], ["an"], ["their"], ["his"], ["her"], ["your"], ["our"]):
        return len(words) > 1 and words[1] in AGENT_NOUNS
    return bool(words) and ((words[0] in PERSONS and words[0] not in ("my", "me")) or words[0] in PERSON_NOUNS or (words[0] == "my" and words[1:2] != [] and words[1] in PERSON_NOUNS))


def read_prompt(prompt: str, asset: ArticulatedAsset) -> Reading:
    """Deterministic reading of ``prompt`` on ``asset``.

    Raises
    ------
    GroundingError
        Nothing in the prompt maps to a movable part, a named part is missing, or a mention is
        ambiguous (the message lists the candidates and how to name each).
    """
    words = tokenize(prompt, asset_words(asset))
    clauses = split_clauses(words)
    category = object_category(asset)
    frames = [whole_named(f, category) for f in read_frames(clauses)]
    builder = Builder(asset)
    frames, fetched = wanted_things(builder, told_how(told_codes(frames)))  # "I need the napkins from the drawer": open it
    builder.notes.extend(fetched)
    acts, gaps = paused_between(repeated(build_acts(frames)))  # "…, pausing a moment between each digit"
    acts = named_before_it(said_by_use(acts, builder.parts))  # "Set the timer — twist the bottom knob ...": what the knob is for
    builder.refs.plan([m for act in acts for frame in act.frames for m in (*frame.themes, *frame.instruments)])
    landmarks = {k: _landmarks(clauses, k) for k in {frame.clause for frame in frames}}  # each clause parsed once
    builder.refs.said = [m for frame in frames for m in (*frame.themes, *frame.instruments, *landmarks[frame.clause])]  # "so you can get at
    # the bottom rack"; "the upper rack — the one behind the small door on top — ... The door you may open": that door
    if not builder.parts and not any(a.goal.verb for a in acts):
        raise GroundingError(f"{asset.name} has no movable parts to animate", movable_parts=[])
    skipped: list[GroundingError] = []
    pending = 0.0  # the wait before a clause that moved nothing goes before the next ("2 s pause while it's open, then shut")
    prompt_unit(builder, frames)  # of like units (two fridges side by side), the one the prompt names
    for index, act in enumerate(acts):
        act, pending, steps = replace(act, wait_before_s=act.wait_before_s + pending), 0.0, len(builder.steps)
        if unit_clause(builder, acts, index, act):
            continue  # "Two mixer taps side by side.", "Take the left one and ...": which unit, no step
        try:
            if len(acts) > 1 and not act.condition and not act.goal.themes and not act.goal.instruments and not act.results and (
                    act.goal.sense is not VerbSense.RELEASE and _said_of_someone(act.goal)):  # "the foot comes off" still lets go
                builder.notes.append(f"ignored '{act.goal.text}': it is about who acts, not a part of {asset.name}")  # "then the robot lets go"
                continue
            if len(acts) > 1 and act.goal.aside and act.goal.text.split()[:1] in (["i"], ["we"]) and act.goal.verb is not None and act.goal.themes and all(
                    m.kind is None and not m.pronoun for m in act.goal.themes) and not all(m.is_object for m in act.goal.themes):
                builder.notes.append(f"ignored '{act.goal.text}': it tells what the user did, not a step")  # "I put my bowl in off-centre"
                continue
            if index < len(acts) - 1 and act.goal.subject_theme and {"has", "have"} & set(act.goal.text.split()[1:5]) and act.goal.verb is not None and (
                    not act.condition and act.goal.link is not Link.CONDITION) and (
                    not act.goal.text.startswith(("i ", "you ", "we "))):  # "the handle has flopped over the side - stand it straight up"
                builder.notes.append(f"read '{act.goal.text}' as how it is now, not a step")
                set_topic(builder, replace(act.goal, stative=True, verb=None))
                continue
            if len(acts) > 1 and act.goal.guessed_verb and not act.goal.themes and not act.goal.instruments and act.goal.marker in _WHEN:
                builder.notes.append(f"ignored '{act.goal.text}': it says when, not what moves")  # "... where it was when the scene loaded"
                continue
            if builder.steps and builder.steps[-1].base is not None and builder.steps[-1].base.yaw_rad and act.goal.quantities.amount is None and (
                    act.goal.particle in ("around", "round") and act.goal.themes and all(m.is_object or m.pronoun for m in act.goal.themes)) and not (
                    {"again", "back", "twice", "more"} & set(act.goal.text.split())):
                builder.notes.append(f"read '{act.goal.text}' as the turn said again")  # "turn the toaster round ... Just spin it around"
                continue
            if len(acts) > 1 and act.goal.text.split()[:1] == ["nothing"] and all(m.is_object for m in act.goal.themes) and not act.goal.instruments:
                continue  # "Nothing else moves.": what stays still, which it does unless asked
            if len(acts) > 1 and mishap(act):
                builder.notes.append(f"ignored '{act.goal.text}': it is about what happens to a person, not a step")  # "I keep bumping my knee on it"
                continue
            if ((left_open(act) and sum(not mishap(a) for a in acts) == 1) or (len(acts) == 1 and mishap(act))) and answer_complaint(builder, [act]):
                continue  # "somebody left the bottom drawer open": shut it, whatever its pose
            if not builder.steps and len(acts) == 1 and answer_stored(builder, acts):
                continue  # "my keys are in the top drawer": open it
            if act.means is not None and act.goal.link is Link.PURPOSE and act.means.themes and all(m.is_object for m in act.means.themes) and (
                    _FACING & set(act.goal.text.split())):  # "turn the whole safe 90 degrees to make its door end up facing left"
                builder.notes.append(f"read '{act.goal.text}' as where turning the whole {asset.name} leaves it")
                act = replace(act, goal=act.means, means=None)
            if act.means is not None and act.goal.link is Link.PURPOSE and act.goal.verb is None and act.goal.sense is None and not act.goal.themes:
                builder.notes.append(f"ignored the purpose '{act.goal.text}': it names no part and no motion")  # "so it's ready to travel"
                act = replace(act, goal=act.means, means=None)
            if act.goal.verb in OBJECT_TILTS and act.goal.themes and all(m.is_object for m in act.goal.themes) and not act.means:
                if len(acts) == 1:
                    raise builder.refs.refuse(f"'{act.goal.text}': tilting the whole {asset.name} is not animated (it can be moved and "
                                              "turned, or its parts worked)")
                builder.notes.append(f"did not animate '{act.goal.text}': tilting the whole {asset.name} is not animated, only moving and turning it")
                builder.refs.last_object = True
                continue  # "tilt the bin back and wheel it backwards": the wheeling is animated, and "it" is the bin
            if index < len(acts) - 1 and (record_release(builder, act) or stated_latched(builder, act) or stated_no_handle(builder, act)):
                continue  # "Turning the handle pulls back the bolts": how it works, not a step
            try:
                builder.add(act)
                if index in gaps:  # "…, pausing a moment between each digit": before each press after the first
                    builder.steps[steps + 1:] = [s.model_copy(update={"wait_before_s": s.wait_before_s + gaps[index]}) for s in builder.steps[steps + 1:]]
                fetched_through(builder, act, list(clauses[act.goal.clause].tokens) if act.goal.clause < len(clauses) else [], steps)
            except GroundingError as exc:
                if act.means is not None and act.goal.link is Link.PURPOSE and not exc.candidates:
                    # "get the door down, which makes room to slide the baking tray in": the purpose names nothing here
                    builder.notes.append(f"ignored the purpose '{act.goal.text}': {str(exc).split('. Movable parts')[0]}")
                    try:
                        builder.add(replace(act, goal=act.means, means=None))
                    except GroundingError:
                        if builder.steps or not (answer_finished(builder, frames) or answer_use(builder, frames)):
                            raise
                        break  # "I'm done packing, get it ready to carry": neither names a part; the wish says what is wanted
                    continue
                if len(acts) > 1 and any(m.kind is PartKind.CODE for m in act.goal.themes) and all(m.kind in (None, PartKind.CODE) for m in act.goal.themes) and (
                        not act.goal.codes):
                    builder.notes.append(f"did not animate '{act.goal.text}': the prompt does not say the code (say its keys, e.g. 'enter 1-2-3-4')")
                    continue  # "Punch the code into the keypad and open up the safe": which keys is not said
                if len(acts) > 1 and not exc.candidates and put_in_only(act.goal.text.split(), act.goal.verb, all(m.kind is None and not m.pronoun and (
                        not m.is_object or names_other_object(m.head, builder.tracker.obj.category, "")) for m in act.goal.themes)):  # "chuck the bag in"
                    builder.notes.append(f"ignored '{act.goal.text}': what is put in is no part of {asset.name}")
                    continue  # "open the bin with my foot, drop the banana peel in, then let the lid fall shut"
                story = any(a.goal.verb is not None for a in acts[index + 1:]) and bool(CAUSER_NOUNS & set(act.goal.text.split()[:3]))  # "a draft catches the door and ..."
                if not exc.candidates and not builder.steps and not story and (answer_room(builder, acts, frames) or answer_finished(builder, frames)
                                                                               or answer_use(builder, frames)):
                    break  # "there's a cold draft coming through the doorway", "I'm finished with the laptop": shut it (with a note)
                if len(acts) < 2 or not _incidental(act.goal) or (exc.candidates and not {"already"} & set(act.goal.text.split()) and not (
                        act.goal.verb is not None and _said_of_someone(act.goal))):  # not "Grandpa left me the combination on a note": a story
                    raise  # a clause that names parts but not which one is never skipped, unless it tells how things already are
                skipped.append(exc)
                set_topic(builder, act.goal)
                builder.notes.append(f"ignored '{act.goal.text}': it asks for no motion of a part of {asset.name}")
        finally:
            pending = act.wait_before_s if len(builder.steps) == steps else 0.0
    for told in [f for f in frames if f.heading and f.verb is not None and f.themes and all(m.is_object or m.kind is not None for m in f.themes)] if (
            not builder.steps) else []:  # "Tap the top-left key: in and straight back out": the heading was the step
        builder.add(Act(goal=replace(told, heading=False)))  # "Close this cabinet up properly: the door and the drawer are both sitting open"
    if not builder.steps and (answer_complaint(builder, acts) or answer_room(builder, acts, frames) or answer_finished(builder, frames)
                              or answer_use(builder, frames)):
        skipped = []  # "the lower drawer is sticking out and I keep bumping my knee on it": shut it (with a note)
    if not builder.steps:
        if skipped:
            raise skipped[0]
        raise builder.refs.refuse(f"could not find an action in '{prompt}'")
    extension = Extension(steps=builder.steps)
    understanding = builder.explanation.entries()
    checked = audit(clauses, extension, understanding, builder.explanation.obj, frozenset(builder.turned))
    notes = tuple(dict.fromkeys([*_corrections(words), *builder.notes, *checked, *_conventional_front(frames, builder)]))
    return Reading(extension=extension, intent=resolve_steps(extension, asset, prompt, notes), understanding=understanding, notes=notes)


_FRONT_SIDES = frozenset({Side.LEFT, Side.RIGHT, Side.FRONT, Side.BACK})
_FRONT_WAYS = frozenset({"left", "right", "forward", "backward"})


def _conventional_front(frames: list[Frame], builder: Builder) -> list[str]:
    """A warning when a left / right / front / back was read from a front that nothing on the object shows (a faucet,
    a toaster with its knob on a side, a pot): the front is PartNet-Mobility's convention, and on an asset modelled
    facing elsewhere every such word lands on the wrong side."""
    obj = builder.tracker.obj
    if not obj.front_by_convention:
        return []
    mentions = [m for f in frames for m in (*f.themes, *f.instruments)]
    mentions += [m.relation[1] for m in mentions if m.relation is not None]
    relations = [(RELATIONS.get(m.relation[0], m.relation[0]), m.relation[1]) for m in mentions if m.relation is not None]
    used = any(side in _FRONT_SIDES for m in mentions for side, _ in m.sides) or any(
        way in FRONT_RELATIVE_RELATIONS or (way in ("near", "far") and landmark.head in VIEWER_WORDS) for way, landmark in relations) or any(
        f.quantities.direction in _FRONT_WAYS for f in frames)
    if not used:
        return []
    facing = direction_name((float(obj.front[0]), float(obj.front[1]), float(obj.front[2])))
    return [f"took {builder.asset.name}'s front to face {facing}, the PartNet-Mobility convention: nothing on it shows where it faces, "
            f"and left, right, front and back were read from there"]
