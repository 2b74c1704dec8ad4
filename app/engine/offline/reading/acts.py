"""Frames -> :class:`Act` list in execution order: a goal with the means that achieves it,
waits and holds attached to their neighbours, conditions as states to reach first,
negations as exclusions, verbs carried into verbless clauses ("then the right door").
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

from app.engine.lexicon.kinds import info
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import ASPECT_VERBS, COUPLING_WORDS, FUNCTION_VERBS, PAUSE_NOUNS
from app.engine.offline.reading.clauses import Link
from app.engine.offline.reading.corrected import corrected, recast
from app.engine.offline.reading.ellipsis import carry
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.how_it_is import ENDS_AS_BEGAN
from app.engine.offline.reading.measured_from import measured_from
from app.engine.offline.reading.pointed import pointed_out
from app.engine.offline.reading.quantities import Quantities, Reference
from app.engine.offline.reading.results import merged_result
from app.engine.offline.reading.stored import open_holder, place_of, unknown_things
from app.engine.offline.reading.told_first import put_in_order
from app.engine.offline.reading.told_first_verb import told_first_verb

DEFAULT_WAIT_S = 1.0
UNDERWAY_S = 0.2
"""How long after the step before starts a step told "while it's still (moving)" starts."""


@dataclass(frozen=True)
class Act:
    goal: Frame
    means: Frame | None = None
    parallel: bool = False
    conjoined: bool = False
    wait_before_s: float = 0.0
    hold_s: float = 0.0
    condition: bool = False
    """A state to reach first ("while the door is open"): skipped when it already holds."""
    results: tuple[Frame, ...] = ()
    """What the user says the act causes ("so the door pops open"): refines or adds its effects."""
    exclusions: tuple[Frame, ...] = ()
    """What the user says not to do ("without touching the knob")."""
    runs: bool = False
    """Said to set the object going ("turn the dial to start the wash"): its doors and lids are shut first."""
    note: str = ""
    """How the act was read when that is not plain from its words (a stored thing's holder opened)."""

    @property
    def frames(self) -> tuple[Frame, ...]:
        return tuple(f for f in (self.means, self.goal, *self.results) if f is not None)


_SETTLING = frozenset({"rest", "lie", "sit", "settle", "hang", "lean"})
"""Verbs that say where a motion ends ("... and rest against the side"), not a step."""
_LOOKING = frozenset({"see", "look", "peek", "peep", "check", "watch", "view", "inspect", "glance"})
_USE_VERBS = frozenset({"use", "try", "clean", "fill", "load", "empty", "check"})
"""What a person wants to do with the whole object ("I need to use the loo"): their aim, not a motion."""
_IDLE_VERBS = frozenset({"run", "brew", "cook", "boil", "drain", "drip", "cool", "dry", "sit", "steep", "soak", "heat", "warm", "rest", "spin"})
_STAY_WORDS = frozenset({"rests", "stays", "sits", "remains", "waits", "pauses", "hangs", "stay", "remain", "hang", "sit"})


_SELECTING = frozenset({"take", "grab", "get"})
"""Verbs that pick a part out for the next clause's "it" when nothing else follows them."""
_BY_HAND = frozenset({"reach", "wipe", "grab", "touch", "clean"})
"""What a person's aim does by hand ("so I can reach the mess"): the step before is done by hand, reaching in."""
_GOAL_SENSES = frozenset({VerbSense.LOCK, VerbSense.UNLATCH, VerbSense.OPERATE, VerbSense.SWITCH_ON, VerbSense.SWITCH_OFF})
"""What a task states as its goal on the whole object ("secure the safe", "start the microwave")."""


def _task(frame: Frame, after: list[Frame]) -> bool:
    """"Task: secure the safe. Step 1: close the door. Step 2: ...": a goal on the whole object, a sentence
    of its own, followed by at least two steps that each name a part."""
    steps = [f for f in after if f.verb is not None and any(not m.is_object for m in f.themes)]
    return (frame.clause == 0 and bool(frame.themes) and all(m.is_object for m in frame.themes) and frame.sense in _GOAL_SENSES
            and bool(after) and after[0].marker == "." and len(steps) >= 2)


def _summarises(frame: Frame, after: list[Frame]) -> bool:
    """A clause on several parts followed by verbless clauses that give each its own amount."""
    if _task(frame, after):
        return True
    if frame.verb is None or not any(m.plural or m.collective for m in frame.themes) or not after:
        return False
    following = after[0]
    return following.verb is None and bool(following.themes) and following.quantities.amount is not None


def _topic(frame: Frame, after: list[Frame]) -> bool:
    """A clause that only names one part, followed by one that works "it" ("middle knob, rotate 90 degrees", "top drawer, open")."""
    bare = frame.verb is None and not frame.heading and len(frame.themes) == 1 and not frame.themes[0].is_object and not frame.themes[0].pronoun
    plain, nxt = frame.quantities == Quantities() and frame.particle is None and not frame.returning, after[0] if after else None
    return bare and plain and nxt is not None and nxt.verb is not None and (any(m.pronoun and not m.plural for m in nxt.themes) or (
        not nxt.themes and not nxt.instruments and nxt.marker == "," and (nxt.quantities != Quantities() or nxt.text.split()[:1] == [nxt.verb])))


def _is_subjectless_event(frame: Frame) -> bool:
    """"... and swings open 30 degrees": a finite verb with no subject continues the event before."""
    return frame.conjoined and not frame.themes and frame.verb is not None and frame.text.split()[0] != frame.verb


def _is_event(frame: Frame) -> bool:
    """"(and) the door opens 90 degrees", "watch the lid lift": what the act before caused, told as an event."""
    told_next = frame.marker in ("then", "and_then", "after_that", "next", "finally", "afterwards", "later")
    return (frame.subject_theme and frame.verb is not None and not frame.stative and frame.link is not Link.PURPOSE and not told_next) or (
        frame.let and frame.text.split()[0] in ("watch", "see"))


_AS_IT_IS = re.compile(r" (like|as) (it|they) (is|are|sits|sit|stands) | as_is ")
_BACK = frozenset({VerbSense.RETURN, VerbSense.CLOSE})
_ROLLING = frozenset({VerbSense.TURN, VerbSense.SPIN, VerbSense.MOVE, VerbSense.OPERATE})


def _rolls_along(frame: Frame, previous: Frame | None) -> bool:
    """Wheels said to turn, with no amount or way of their own, right after the whole object moves: how it moves."""
    q = frame.quantities
    return (previous is not None and bool(previous.themes) and all(m.is_object for m in previous.themes) and bool(frame.themes)
            and all(m.kind is not None and info(m.kind).rolls for m in frame.themes) and q.amount is None and q.direction is None
            and q.sense is None and q.omega_radps is None and (frame.verb is None or frame.sense in _ROLLING))


def _progressive_of(frame: Frame, before: Frame) -> bool:
    """"(the door opens, and while) it is opening": the -ing form of the verb before, said again, or of another motion
    verb on "it" ("lower it flat, and while it's opening, ..."): the motion before, told as it goes."""
    from lemminflect import getAllLemmas

    def moving(lemma: str) -> bool:
        return lemma == before.verb or (lemma in VERBS and VERBS[lemma].sense is not VerbSense.WAIT)

    return before.verb is not None and any(w.endswith("ing") and any(moving(v) for v in getAllLemmas(w).get("VERB", ())) for w in frame.text.split())


def _narrated(before: Frame, frame: Frame) -> bool:
    """"door drops all the way; its rack slides halfway out": one told event after another, the first of a part
    that operates nothing (a door, not a pedal), is the next step of the story, not what the first one caused."""
    alike = {m.kind for m in frame.themes} == {m.kind for m in before.themes}  # "swing the right door ...; the left door follows"
    return (before.subject_theme or before.wish or alike) and frame.link is not Link.RESULT and bool(before.themes) and all(
        m.kind is not None and not info(m.kind).control for m in before.themes) and all(not m.pronoun for m in frame.themes)


def _appositive_amount(before: Act, frame: Frame) -> bool:
    """An amount alone after a comma, with the step before saying none: the same step, said again with its amount."""
    q = frame.quantities
    return (frame.verb is None and not frame.themes and not frame.instruments and frame.marker == "," and q.amount is not None
            and q.duration_s is None and not frame.returning and not before.condition and before.goal.verb is not None
            and bool(before.goal.themes) and before.goal.quantities.amount is None)


def build_acts(frames: list[Frame]) -> list[Act]:
    frames = told_first_verb(frames)  # a negation may take in the subject said before it (so a list of our own)
    acts: list[Act] = []
    pending_wait = 0.0
    restated = said_aside = False
    pending_conditions: list[Frame] = []
    previous_goal: Frame | None = None
    measured: Frame | None = None
    said: Frame | None = None  # the frame before, whatever became of it
    manner: Frame | None = None  # "Slowly, over about 3 seconds, ...": how the next action goes
    together = False  # a summary said the steps after it go at the same time
    leading: list[Frame] = []  # negations told before any step
    zero: Reference | None = None  # "measured from fully shut, ...": what the next amount counts from
    moved: int | None = None  # where a step told after the one it precedes went
    for index, frame in enumerate(frames):
        if (counted := measured_from(frame)) is not None:
            zero = counted
            continue
        if zero is not None and frame.quantities.amount is not None and frame.quantities.amount.reference is None:
            frame, zero = replace(frame, quantities=replace(frame.quantities, amount=replace(frame.quantities.amount, reference=zero))), None
        verbless = frame.verb is None
        wished = len(acts) > 1 and acts[-1].goal.wish and acts[-1].goal.verb is None and not acts[-1].goal.themes  # "..., I only want to peek inside"
        if frame.link is Link.PURPOSE and acts and (frame.guessed_verb or frame.verb) in _LOOKING | FUNCTION_VERBS and not any(m.kind is not None for m in frame.themes) and (
                (acts[-1].goal.verb is not None and bool(acts[-1].goal.themes)) or wished):
            acts = acts[:-1] if wished else acts
            if (frame.guessed_verb or frame.verb) in FUNCTION_VERBS:
                acts[-1] = replace(acts[-1], runs=True)  # "turn the dial to start the wash": it runs shut
            continue  # "open the door 45 degrees to see inside", "push the button to start it": what follows, not a motion
        if verbless and index and frames[index - 1].link is Link.NEGATED and frame.quantities == Quantities() and frame.themes and any(
                w.endswith("ing") for w in frame.text.split()) and {m.head for m in frame.themes} <= {m.head for a in acts for m in a.goal.themes}:
            continue  # "the bin shouldn't go anywhere - just the wheel turning in place": the step before, said again
        if acts and frame.conjoined and frame.verb in _SETTLING and frame.quantities.duration_s is None and all(m.is_object for m in frame.themes):
            continue  # "drop down and rest against the side of the bucket": where the motion before ends, no step of its own
        if acts and acts[-1].goal.wish and acts[-1].goal.verb is None and acts[-1].goal.sense is not None and frame.link is Link.RESULT and frame.returning and (
                frame.quantities.amount is None and frame.themes and all(m.pronoun for m in frame.themes) and frame.text.split()[:1] == [frame.verb]):
            continue  # "I want it sitting flush in its frame again, so swing it back": how the wish is done, not a step back
        if acts and frame.link is Link.RESULT and frame.marker in ("until", "till") and frame.subject_theme and frame.verb is not None and (
                acts[-1].goal.sense is VerbSense.HOLD and frame.themes and all(m.kind is not None for m in frame.themes)):
            frame = replace(frame, link=Link.SEQUENCE, subject_theme=False)  # "hold it open until the rack has slid all the way out": the rack's step
        merged = merged_result(acts[-1], frame) if acts and not acts[-1].condition else None
        if merged is not None:
            acts[-1] = merged  # "drop the handle so it lies flat along the back side", "swing it back so it sits flush"
            continue
        opened_object = bool(acts) and acts[-1].goal.sense is VerbSense.OPEN and bool(acts[-1].goal.themes) and all(m.is_object for m in acts[-1].goal.themes)
        place = place_of(frame) if acts and not acts[-1].condition and (unknown_things(acts[-1].goal) or opened_object) else None
        if place is not None and opened_object and (place.kind is None or info(place.kind).hinged):
            place = None  # "get the roast out of the oven, it's on the lowest rack": the rack; a door is no place a thing sits
        if place is not None:
            things = ", ".join(m.words or m.head for m in acts[-1].goal.themes)
            note = f"'{frame.text}': opened {place.words or place.head}, where it is kept" if opened_object else (
                f"'{things}' is no part: opened {place.words or place.head}, where it is kept")
            acts[-1] = replace(acts[-1], goal=open_holder(acts[-1].goal, place), note=note)  # "I need the ketchup, which lives in the left door"
            continue
        revised = (corrected(acts[-1], frame) or recast(acts[-1], frame)) if acts and frame.correction else None
        if revised is not None:
            acts[-1] = revised  # "open it 60 degrees... no wait, make it 45"
            continue
        if acts and not acts[-1].condition and frame.marker == "," and frame.themes and all(m.pronoun for m in frame.themes) and (
                frame.sense is VerbSense.OPEN and frame.quantities == Quantities() and acts[-1].goal.quantities.amount is not None
                and acts[-1].goal.sense in (None, VerbSense.OPEN) and bool(acts[-1].goal.themes)):
            continue  # "Safe door at ninety degrees please - swing it out": how the step before goes, not another step
        if acts and not acts[-1].condition and frame.conjoined and frame.text.split()[0].endswith("ing") and not frame.themes and (
                frame.quantities.amount is None and frame.quantities.sense is not None and acts[-1].goal.quantities.sense is None):
            goal = acts[-1].goal  # "dial - one and a quarter revolutions, going clockwise": which way the step before goes
            acts[-1] = replace(acts[-1], goal=replace(goal, quantities=replace(goal.quantities, sense=frame.quantities.sense)))
            continue
        if acts and not acts[-1].condition and _rolls_along(frame, acts[-1].goal):
            continue  # "roll the bin 1 m forward - the wheels should turn as it goes": they roll with it already
        said_for = -2 if len(acts) > 1 and acts[-1].goal.link is Link.PURPOSE else -1  # "spin it round to face the other way, a half turn"
        if acts and _appositive_amount(acts[said_for], frame):
            goal = acts[said_for].goal  # "roll the wheel around once, a full revolution": how far the step before goes
            acts[said_for] = replace(acts[said_for], goal=replace(goal, quantities=replace(goal.quantities, amount=frame.quantities.amount)))
            continue
        if frame.verb is None and frame.simultaneous and all(m.collective or m.pronoun for m in frame.themes) and len(acts) > 1:
            acts[-1] = replace(acts[-1], parallel=True)  # "..., both at the same time"
            continue
        if frame.verb is None and frame.quantities.amount is None and frame.quantities.target is not None and measured is not None and (
                measured.quantities.amount is not None and measured.quantities.amount.unit == "rad"):
            # "the left to 120 degrees, the right to 60": the unit of the one before
            amount = replace(measured.quantities.amount, value=abs(frame.quantities.target) * 3.141592653589793 / 180.0, words=f"{frame.quantities.target:g}")
            frame = replace(frame, quantities=replace(frame.quantities, amount=amount))
        if frame.verb is None and frame.themes and all(m.is_object for m in frame.themes) and frame.quantities == Quantities() and (
                frame.particle is None and index + 1 < len(frames) and frames[index + 1].verb is not None and frames[index + 1].themes):
            frame = replace(frame, heading=True)  # "toilet - put the cover up": the object named as a topic, not worked
        if frame.verb is None and frame.text.split()[0].isdigit() and frame.themes and any(m.plural for m in frame.themes) and (
                index + 1 < len(frames) and frames[index + 1].verb is not None):
            frame = replace(frame, heading=True)  # "Two catches on the front of this toolbox. Swing the one on the right ...": there are two
        if (seen := pointed_out(frame, frames[index + 1:])) is not None or _topic(frame, frames[index + 1:]):
            frame = seen or replace(frame, heading=True)  # "Upper knob - rotate it 1.5 rad", "See the dial ...? Give it a turn"
        if (frame.text.startswith("of ") or (frame.verb is None and frame.text.split()[0] in ("on", "at"))) and frame.themes and index + 1 < len(frames):
            frame = replace(frame, heading=True, verb=None, sense=None)  # "Of the three knobs on the washer, twist ...", "On the keypad, tap ..."
        if frame.sense is VerbSense.LOCK and frame.themes and all(m.is_object for m in frame.themes) and any(
                f.verb is not None and any(not (m.is_object or m.pronoun) for m in f.themes) for f in frames[index + 1:]) and not (
                index + 1 < len(frames) and frames[index + 1].link is Link.MEANS):
            frame = replace(frame, heading=True)  # "lock up the toolbox - shut the lid and snap both clasps closed": what follows says how
        if _summarises(frame, frames[index + 1:]):
            frame = replace(frame, heading=True)  # "open both doors at once, the left to 120 degrees, the right to 60"
        if frame.let and frame.verb in _IDLE_VERBS and frame.quantities.duration_s is not None and all(m.pronoun or m.is_object for m in frame.themes):
            pending_wait += frame.quantities.duration_s  # "let it run for 4 seconds": time passes, nothing moves
            continue
        if (((frame.verb is None or frame.sense is VerbSense.HOLD) and frame.text.split()[0] in _STAY_WORDS) or (frame.verb == "hover" and acts and (
                frame.quantities.amount is None and all(m.pronoun for m in frame.themes)))) and frame.quantities.duration_s is not None:  # "let it hover there for 2 s"
            frame = replace(frame, verb="hold", sense=VerbSense.HOLD, themes=(), subject_theme=False, stative=False)  # "..., rests there for 2 s"
        if (frame.verb is None or (frame.sense in (VerbSense.HOLD, VerbSense.WAIT) and frame.text.split()[-1] == frame.verb)) and not frame.themes and (
                frame.quantities.duration_s is not None and set(frame.text.split()) & (PAUSE_NOUNS | {"hold"})):
            pending_wait += frame.quantities.duration_s  # "up to vertical, 2 s pause, then ...": a wait, not a manner
            continue
        if frame.verb is None and not frame.themes and not frame.returning and (
                frame.quantities.duration_s is not None or frame.quantities.speed_factor != 1.0) and frame.quantities.amount is None:
            manner = frame
            continue
        if manner is not None:
            q, m = frame.quantities, manner.quantities
            frame = replace(frame, quantities=replace(q, duration_s=q.duration_s if q.duration_s is not None else m.duration_s,
                                                      speed_factor=q.speed_factor if q.speed_factor != 1.0 else m.speed_factor))
            manner = None
        if frame.marker == "which" and not frame.themes and said is not None and said.themes:
            frame = replace(frame, themes=said.themes[-1:], subject_theme=True)  # "..., which flips up": the noun just before
        if said is not None and said.stative and COUPLING_WORDS & set(said.text.split()) and said.themes and acts and (
                frame.conjoined and not frame.themes and frame.verb is not None):
            # "its rack is hooked to the door and slides out 15 cm": what the tied part does, with the act before
            acts[-1] = replace(acts[-1], results=(*acts[-1].results, replace(frame, themes=said.themes[:1], subject_theme=True)))
            said = frame
            continue
        said = frame
        if frame.heading and frame is not frames[-1]:
            # "Turn both knobs at once: the top one ..., the bottom one ...": a summary naming the parts; what follows says what each does
            parts_named = tuple(m for m in frame.themes if not m.is_object or m.sides) or frame.themes  # "On the washer, the third knob: ..."
            acts.append(Act(goal=replace(frame, sense=None, verb=None, themes=parts_named, quantities=replace(frame.quantities, amount=None)),
                            condition=True))
            together = frame.simultaneous
            previous_goal = replace(frame, themes=parts_named)  # the clauses after the colon may only name an amount: they take its verb and parts
            continue
        if frame.link is Link.RESULT and frame.themes and all(m.is_object for m in frame.themes) and ASPECT_VERBS & set(frame.text.split()) and (
                frame.verb is None or frame.verb not in VERBS):
            continue  # "... so the machine starts brewing": what the object then does, not a part's motion
        if frame.link is Link.PURPOSE and said_aside:
            continue  # "I'm about | to roll the chair under the desk", "Someone needs | to use the toilet": a person's aim
        said_aside = False
        if frame.aside and (frame.link in (Link.RESULT, Link.PURPOSE) or frame.verb is None or frame.guessed_verb) and (acts or index + 1 < len(frames)):
            said_aside = True
            if acts and frame.link is Link.PARALLEL and frame.quantities.duration_s is not None and not acts[-1].hold_s and not acts[-1].condition:
                acts[-1] = replace(acts[-1], hold_s=frame.quantities.duration_s)  # "keep your foot on the pedal while I scrape the plates, 5 s or so"
            if acts and frame.link in (Link.RESULT, Link.PURPOSE) and _BY_HAND & set(frame.text.split()):
                acts[-1] = replace(acts[-1], goal=replace(acts[-1].goal, manual=True))  # "..., so I can reach the mess": by hand
            if frame.link is Link.FIRST and frame.stative and len(frame.themes) == 1 and frame.themes[0].kind is not None:
                acts.append(Act(goal=replace(frame, heading=True, verb=None, sense=None), condition=True))  # "Somebody left this door
                # sticking straight out. Swing it back ...": the scene names what "it" is
            continue  # "..., so I can put my plate in", "nothing else": why, or a remark, not what
        if frame.link is Link.PARALLEL and acts and not acts[-1].condition and (
                (frame.themes and all(m.pronoun for m in frame.themes)) or frame.text.split()[0] in ("it's", "they're")) and (
                (frame.sense is acts[-1].goal.sense and frame.sense is not None) or _progressive_of(frame, acts[-1].goal)):
            restated = True  # "the door opens, and while it is opening the plate starts turning": the next step runs with it
            pending_wait += UNDERWAY_S if "still" in frame.text.split() else 0.0  # "while it's still rising": once it is under way
            continue
        if frame.link is Link.PARALLEL and frame.verb is None and frame.themes and all(
                m.kind is None and not m.is_object and not m.pronoun for m in frame.themes):
            continue  # "..., while the narrator talks": what else happens meanwhile, not a part's motion
        if frame.stative and COUPLING_WORDS & set(frame.text.split()):
            continue  # "the two carriages are linked": how the parts are tied, told for what follows
        if (frame.stative or frame.verb is None) and _AS_IT_IS.search(f" {frame.text} "):
            continue  # "don't touch the drawer, it stays out like it is": nothing to do
        if (frame.verb is None or frame.stative) and ENDS_AS_BEGAN.search(frame.text) and any(a.goal.sense in _BACK for a in acts[-1:]):
            continue  # "..., then raise it back to its starting position. Expected: it ends exactly where it began": said again
        if frame.link is Link.PARALLEL and frame.subject_theme and frame.themes and all(m.pronoun for m in frame.themes) and (
                frame.sense is VerbSense.MOVE and frame.quantities == Quantities()):
            continue  # "Neither door should open while it moves": the motion said, no step of its own
        if verbless and frame.themes and frame.quantities == Quantities() and "only" in frame.text.split()[:1] + frame.text.split()[-1:] and len(
                frame.text.split()) <= 3 and not any(m.sides for m in frame.themes) and (
                {m.head for m in frame.themes} <= {m.head for a in acts for m in a.goal.themes}):
            continue  # "open the lid. Lid only.": which part moves, said again
        if verbless and frame.themes and frame.quantities == Quantities() and index + 1 < len(frames) and frames[index + 1].link is Link.NEGATED and (
                frames[index + 1].subject_theme):  # "The bottom door and the racks must not move": both are kept still
            frames[index + 1] = replace(frames[index + 1], themes=(*frame.themes, *frames[index + 1].themes))
            continue
        frame = carry(frame, previous_goal, measured)
        if frame.quantities.amount is not None:
            measured = frame
        if frame.sense is VerbSense.WAIT and all(m.pronoun for m in frame.themes):  # "wait 2 s", "pause it"
            pending_wait += frame.quantities.duration_s or DEFAULT_WAIT_S
            continue
        if frame.link is Link.NEGATED:
            if acts:
                acts[-1] = replace(acts[-1], exclusions=(*acts[-1].exclusions, frame))
            else:
                leading.append(frame)  # "Without using the pedal, lift the lid ...": told before the step it limits
            continue
        waits_for = frame.marker in ("once", "when", "after") and frame.link is not Link.RESULT
        after_act = bool(acts) and not acts[-1].condition and acts[-1].goal.verb is not None and not acts[-1].goal.aside
        # a summary, a state or a clause about the user has no results of its own
        imperative = frame.verb is not None and not frame.subject_theme and frame.text.split()[0] in (frame.verb, frame.guessed_verb, "get")  # "..., so get the oven open"
        if (frame.link is Link.RESULT and after_act and not imperative) or (_is_event(frame) and after_act and not waits_for and not _narrated(acts[-1].goal, frame)):
            acts[-1] = replace(acts[-1], results=(*acts[-1].results, frame))
            continue
        if _is_subjectless_event(frame) and acts and acts[-1].results:
            previous = acts[-1].results[-1]
            acts[-1] = replace(acts[-1], results=(*acts[-1].results, replace(frame, themes=previous.themes, subject_theme=True)))
            continue
        if frame.link is Link.CONDITION or frame.stative or (waits_for and _is_event(frame)):
            if frame.link is Link.CONDITION and acts and frame.clause > acts[-1].goal.clause and frame.marker in ("while", "whilst", "as"):
                acts.insert(len(acts) - 1, Act(goal=frame, condition=True))  # "B while the door is open": before B
            elif frame.link is Link.CONDITION or frame.marker in ("once", "when", "after"):
                pending_conditions.append(frame)  # "A and, once it is out, B": a state to reach before B
            else:
                acts.append(Act(goal=frame, condition=True))  # "the drawer is sticking out; push it shut": sets "it"
            continue
        if frame.link is Link.PURPOSE and acts and acts[-1].means is None and acts[-1].goal.wish and not acts[-1].goal.themes and (
                acts[-1].goal.verb is None) and frame.verb in _USE_VERBS and all(m.is_object for m in frame.themes):
            acts.pop()  # "I need to use the loo, ...": what the person will do with the object, not a motion of it
            said_aside = True
            continue
        if frame.link is Link.PURPOSE and acts and acts[-1].means is None and acts[-1].goal.wish and not acts[-1].goal.themes and (
                acts[-1].goal.verb is None):
            acts[-1] = replace(acts[-1], goal=replace(frame, link=acts[-1].goal.link))  # "I want to check on the roast ...": the wish is the rest
            previous_goal = acts[-1].goal
            continue
        if frame.link is Link.PURPOSE and acts and acts[-1].means is None and acts[-1].goal.wish and acts[-1].goal.themes and not frame.themes:
            # "I need its drawer to come out 12 inches": the wished part is what the verb after "to" moves
            acts[-1] = replace(acts[-1], goal=replace(frame, themes=acts[-1].goal.themes, subject_theme=True, link=acts[-1].goal.link))
            previous_goal = acts[-1].goal
            continue
        if frame.link is Link.PURPOSE and acts and acts[-1].means is None:
            last = acts.pop()
            acts.append(replace(last, goal=frame, means=last.goal))
            previous_goal = frame
            continue
        if frame.link is Link.MEANS and acts and acts[-1].means is None:
            acts[-1] = replace(acts[-1], means=frame)
            continue
        for condition in pending_conditions:
            acts.append(Act(goal=condition, condition=True))
        pending_conditions = []
        parallel = frame.link is Link.PARALLEL or restated or ((together or (frame.simultaneous and (verbless or frame.conjoined))) and any(
            not a.condition for a in acts))  # "press the button and drop the door open at the same time"
        restated = False
        if frame.verb in _SELECTING and frame.particle is None and frame.quantities == Quantities() and index + 1 < len(frames) and (
                frames[index + 1].conjoined and frames[index + 1].themes and all(m.pronoun for m in frames[index + 1].themes)):
            frame = replace(frame, sense=VerbSense.GRASP)  # "take the smaller one and rotate it": which one, not a motion
        act = Act(goal=frame, parallel=parallel, conjoined=frame.conjoined, wait_before_s=pending_wait)
        pending_wait = 0.0
        moved = put_in_order(acts, act, moved)
        previous_goal = frame
    for condition in pending_conditions:  # "B once the door is open": the state comes before B
        acts.insert(max(len(acts) - 1, 0), Act(goal=condition, condition=True))
    first = next((k for k, a in enumerate(acts) if not a.condition), None)
    if leading and first is not None:
        acts[first] = replace(acts[first], exclusions=(*leading, *acts[first].exclusions))
    if pending_wait and acts:
        acts[-1] = replace(acts[-1], hold_s=acts[-1].hold_s + pending_wait)
    return acts
