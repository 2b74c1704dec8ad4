"""A result clause about the part the step before moves ("so it lies flat along the back side", "so it sits flush")
that says where that part ends: it completes the step instead of adding an effect."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.verbs import VerbSense
from app.engine.lexicon.words import FACE_RELATIONS, PLACES, STATES
from app.engine.offline.reading.clauses import Link
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.quantities import Amount

if TYPE_CHECKING:
    from app.engine.offline.reading.acts import Act


_NEGATIONS = frozenset({"not", "no", "never", "isn't", "aren't", "longer", "without"})
_TO_A_SHARE = frozenset({VerbSense.RETURN, VerbSense.MOVE, VerbSense.CLOSE, VerbSense.OPEN, VerbSense.PULL_OUT, None})
_CONTRACTED = frozenset({"it's", "they're"})
"""A pronoun and its verb in one word: "until it's properly shut" is about "it" though it reads no theme."""


def _about_it(frame: Frame) -> bool:
    """A result clause on "it" with no verb of its own ("it lies flat", "it sits flush", "it's properly shut")."""
    first = frame.text.split()[0] if frame.text.split() else ""
    themes = [m for m in frame.themes if m.head not in FACE_RELATIONS]  # "it sits 200 mm proud of the front": not a part
    # "it" and at most the body it is measured against ("the angle between it and the keyboard")
    said = any(m.pronoun for m in themes) and all(m.pronoun or m.kind is PartKind.BODY for m in themes) if themes else first in _CONTRACTED
    return frame.link is Link.RESULT and said and (frame.verb is None or frame.sense is None)


def _restates(act: Act, frame: Frame) -> bool:
    """A result that names the part the step moves, by the same word, and says nothing the reader can measure (no
    amount, way or state): a picture of where the step ends, which the step already says."""
    heads = {m.head for m in act.goal.themes if m.kind is not None}
    r, words = frame.quantities, frame.text.split()
    return frame.link is Link.RESULT and bool(heads) and (frame.verb is None or frame.sense is None) and bool(frame.themes) and (
        all(m.head in heads or m.kind is None for m in frame.themes) and any(m.head in heads for m in frame.themes)) and (
        r.amount is None and r.target is None and r.direction is None and r.orientation is None) and not any(
        w in STATES and not (w == "up" and k and words[k - 1] in ("ends", "end", "ended")) for k, w in enumerate(words))


_STOPS = frozenset({"stop", "stops", "end", "limit", "end-stop", "endstop", "backstop", "bumper"})
_MEETS = frozenset({"hit", "reach", "touch", "meet", "bump", "come"})


def _at_its_stop(frame: Frame) -> bool:
    """ "(so) it hits the stop", "it should reach the end": the step runs to its limit, which it says already."""
    words = frame.text.split()
    return frame.link is Link.RESULT and frame.verb in _MEETS and bool(words) and words[0] in ("it", "they") and bool(_STOPS & set(words[1:]))


def merged_result(act: Act, frame: Frame) -> Act | None:
    """``act`` completed by the result ``frame``; None when the result is an effect of its own."""
    if not act.goal.themes:
        return None
    if _at_its_stop(frame):
        return act  # "open the drawer all the way out, it should hit the stop"
    if _restates(act, frame):
        return act  # "drive the handle to its far limit so the handle ends up lying across the back rim": where it goes, said twice
    if not _about_it(frame):
        return None
    if all(m.is_object for m in act.goal.themes) and PLACES & set(frame.text.split()):
        return act  # "push the cabinet back 10 cm so it sits flush against the wall": where the object ends, not a part shut
    goal, q, r = act.goal, act.goal.quantities, frame.quantities
    if "perpendicular" in frame.text.split() and q.amount is None and r.amount is None and goal.sense in (VerbSense.OPEN, VerbSense.MOVE, None):
        # "swing the door open until it's perpendicular to the front": a right angle from shut, not an upright part
        square = Amount(math.pi / 2, "rad", reference="closed", words="perpendicular")
        return replace(act, goal=replace(goal, quantities=replace(q, amount=square, orientation=None)))
    if r.onto_body and q.amount is None:  # "flip both latches up so they sit flat against the front": shut on the body
        shut = VerbSense.CLOSE if goal.sense in (VerbSense.RETURN, VerbSense.MOVE, None) else goal.sense  # "swing it back so it sits flush"
        return replace(act, goal=replace(goal, brief=False, sense=shut, returning=False, quantities=replace(q, onto_body=True, orientation=None,
                                                                                                             direction=None)))
    if r.direction is not None and q.direction is None and not FACE_RELATIONS & set(frame.text.split()):
        # "drop the handle so it lies flat along the back side": which way the part itself goes
        return replace(act, goal=replace(goal, quantities=replace(q, direction=r.direction, orientation=r.orientation or q.orientation,
                                                                   amount=q.amount or r.amount)))
    if r.amount is not None and q.amount is None and r.amount.unit != "fraction":
        # "ease it back up until it's sitting at 45 degrees": the angle says where it stops, not the way back
        return replace(act, goal=replace(goal, returning=False, quantities=replace(q, amount=r.amount, target=r.target)))
    if r.amount is not None and q.amount is None and r.amount.unit == "fraction" and not r.amount.loose and goal.sense in _TO_A_SHARE:
        # "push it back until it's about halfway": where it stops, a share of its range from shut
        share_sense = VerbSense.OPEN if goal.sense in (VerbSense.RETURN, VerbSense.MOVE, VerbSense.CLOSE, None) else goal.sense
        return replace(act, goal=replace(goal, returning=False, sense=share_sense, quantities=replace(q, amount=replace(r.amount, reference="closed"))))
    said = frame.text.split()
    ends = {STATES[w] for k, w in enumerate(said) if STATES.get(w) in ("open", "closed") and not {"from", "since"} & set(said[max(0, k - 3):k])}
    said_end = q.amount is None and not _NEGATIONS & set(frame.text.split()) and goal.sense in (VerbSense.OPEN, VerbSense.RAISE, VerbSense.LOWER)
    if len(ends) == 1 and (goal.sense in (VerbSense.RETURN, VerbSense.MOVE) or said_end):
        # "swing it back so it sits flush": back to where it shuts; "flip the latch up so it's closed": the end it names
        sense = VerbSense.CLOSE if ends == {"closed"} else VerbSense.OPEN
        return replace(act, goal=replace(goal, sense=sense, particle=None, returning=False))
    return None
