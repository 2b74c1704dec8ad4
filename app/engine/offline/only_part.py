"""A part name the lexicon does not know, read by elimination: the one movable part that can do what the verb
says ("pull out the magazine" on a stapler, "press the toast plunger down" on a toaster whose one pressed part is its slider).
Always with a note naming the part chosen and why; never a bare guess: two parts that fit is a refusal."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import info
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import (
    GENERIC_PART_NOUNS,
    HINGE_WORDS,
    NEGATIONS,
    SHAPE_WORDS,
    SLIDE_WORDS,
    UNJOINTED_NOUNS,
    WHOLE_WORDS,
)
from app.engine.offline.grounding import Part, narrow
from app.engine.offline.reading.clauses import Link
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.mentions import Mention
from app.engine.offline.units import in_unit

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder

_CLOSURE_SENSES = frozenset({VerbSense.OPEN, VerbSense.CLOSE, VerbSense.RECLINE})
_SLIDE_SENSES = frozenset({VerbSense.PULL_OUT, VerbSense.PUSH_IN})
_TURN_SENSES = frozenset({VerbSense.TURN})
_LIFT_SENSES = frozenset({VerbSense.RAISE, VerbSense.LOWER})
_NOTHING_SAID = Mention(head="")


def _fits(frame: Frame, mention: Mention, part: Part) -> bool:
    """Whether ``part`` can do what the frame's verb says: a closure opens and shuts, a sliding part pulls out, a
    control that turns is turned, a button is pressed, a switch flipped; the verb's own motion (swing: a hinge, slide: a
    slide) and the mention's ("the hinged glass") must agree."""
    sense = frame.sense
    control = part.kind is not None and info(part.kind).control
    kind = part.geometry.type
    motion = _motion(frame)
    words = set(mention.modifiers)
    hinge, slide = motion == "hinge" or bool(words & HINGE_WORDS), motion == "slide" or bool(words & SLIDE_WORDS)
    if (hinge and kind == "prismatic") or (slide and kind != "prismatic"):
        return False
    if sense in _CLOSURE_SENSES:
        return not control and part.geometry.open_value is not None
    if sense in _LIFT_SENSES:
        return part.geometry.open_value is not None or (control and kind == "revolute")
    if sense in _SLIDE_SENSES:  # "push the hinged glass out": a hinged closure swings out
        return not control and (kind == "prismatic" or (hinge and part.geometry.open_value is not None))
    if sense in _TURN_SENSES:
        return control and kind in ("revolute", "continuous")
    if sense is VerbSense.PRESS:
        return control and kind == "prismatic"
    if sense is VerbSense.TOGGLE:
        return control and kind == "revolute"
    if sense is VerbSense.SPIN:
        return kind == "continuous"
    return False


def _fits_only(frame: Frame, part: Part) -> bool:
    """The object's one movable part, tied to it by name: any closing or lifting verb, or a slide for a sliding part."""
    if frame.sense in _SLIDE_SENSES:
        return part.geometry.type == "prismatic"
    return (frame.sense in _CLOSURE_SENSES or frame.sense in _LIFT_SENSES) and part.geometry.open_value is not None


_SPECIFIC_SENSES = _SLIDE_SENSES | _TURN_SENSES | {VerbSense.PRESS, VerbSense.TOGGLE, VerbSense.SPIN}
_ONE_MOTION_SENSES = _SPECIFIC_SENSES | _CLOSURE_SENSES | _LIFT_SENSES


def _motion(frame: Frame) -> str:
    """The verb's own motion ("swing": hinge, "slide": slide), "any" for other or unknown verbs."""
    return VERBS[frame.verb].motion if frame.verb is not None and frame.verb in VERBS else "any"


def _described(frame: Frame, mention: Mention) -> bool:
    """Whether the words say more than "open the X": a place or size ("the little flap at the bottom"), a verb of one
    motion ("swing", "slide", "twist", "pull out"), or a word that names no kind on purpose ("the panel"). A bare "open the
    flux capacitor" says nothing a part could be chosen by: refused."""
    return bool(mention.sides or mention.size or mention.ordinal is not None or _motion(frame) != "any" or frame.sense in _SPECIFIC_SENSES
                or mention.head in GENERIC_PART_NOUNS or set(mention.modifiers) & SHAPE_WORDS or mention.relation is not None)


def _asked(frame: Frame) -> bool:
    """A clause that asks for a motion ("swing the hatch open"), not a purpose, a result or a state ("to let the steam out",
    "so it's a bit past square"): only there is the one part a verb fits what the words mean."""
    return frame.verb is not None and not frame.let and not frame.stative and frame.link in (Link.FIRST, Link.SEQUENCE, Link.PARALLEL, Link.MEANS)


def _unknown(mention: Mention) -> bool:
    """A head noun that says no part kind ("the portal", "the panel"), not the whole object or a pronoun."""
    return mention.kind is None and mention.head not in WHOLE_WORDS and mention.head not in UNJOINTED_NOUNS and not (
        mention.pronoun or mention.anaphor or mention.is_object or mention.plural or mention.collective or mention.other)


def only_part(builder: Builder, frame: Frame, mention: Mention) -> list[Part]:
    """The one movable part a name we do not know can mean: the only movable part of an object the name is tied to
    ("the stapler's magazine"), or, when the name is all the clause says moves, the only part the verb fits, placed by
    the mention's own words ("the upper hatch"). [] when it cannot be told that way (the caller then refuses)."""
    generic = mention.head in GENERIC_PART_NOUNS  # "the thing at the top": the verb may say which of the parts there
    side_only = mention.anaphor and mention.words.split()[-1:] != ["one"] and bool(mention.sides) and builder.refs.last_kind is None
    if side_only:  # "close the top" with nothing named before: the part there that the verb fits ("the lid")
        mention = replace(mention, anaphor=False)
    elif not _unknown(mention):
        return []
    category = builder.tracker.obj.category or ""  # "the staple magazine": tied to a stapler by its own word too
    tied = (mention.whose is not None or any(len(m) >= 4 and category.startswith(m) for m in mention.modifiers)) and len(builder.parts) == 1
    chosen = len(frame.themes) == 1 and not frame.instruments and _asked(frame) and _described(frame, mention)
    if not (tied or chosen) or (not side_only and _grounded(builder, mention, generic)):
        return []  # a generic name placed ("the top part") is grounding's, and only its ambiguity comes here
    if tied:
        fitting = [p for p in builder.parts if _fits_only(frame, p) or _fits(frame, mention, p)]
        how = "the only movable part"
    else:
        fitting = [p for p in builder.parts if _fits(frame, mention, p)]
        fitting = in_unit(builder.refs.scene, fitting, builder.parts, builder.asset, builder.tracker.obj) or fitting  # on the unit said
        if mention.sides or mention.size or mention.ordinal is not None:
            fitting, _ = narrow(mention, fitting, builder.asset, builder.tracker.obj, [], set())
        how = f"the only movable part that can {frame.verb or (frame.sense.value if frame.sense else 'move')}"
        how += " there" if mention.sides else ""
    if len(fitting) != 1:
        return []
    part = fitting[0]
    unknown = "" if generic or side_only else " (a name the agent does not know)"
    builder.notes.append(f"read '{mention.words}'{unknown} as {part.describe(builder.asset)}, {how}")
    return [part]


def _grounded(builder: Builder, mention: Mention, generic: bool) -> bool:
    """Grounding names the part; a generic name placed where several parts are ("the round thing on the front": the
    door and the knob) is left to the verb here."""
    try:
        return bool(builder.refs.ground(mention).parts)
    except GroundingError as exc:
        if generic and exc.candidates:
            return False
        raise


def sole_fit(builder: Builder, frame: Frame) -> tuple[list[Part], list[str]]:
    """A clause that asks for a motion of one kind and names nothing the reader could take ("spin the round thing on the
    front", "flip the top all the way open"): the one movable part the verb fits, with a note; none or several: ([], [])."""
    words = frame.text.split()
    if not _asked(frame) or frame.sense not in _ONE_MOTION_SENSES or len(words) < 3 or words[0] in NEGATIONS or words[0] == "nothing":
        return [], []  # "..., nothing opens or closes": a bare verb, or what stays still, names no part to guess
    fitting = [p for p in builder.parts if _fits(frame, _NOTHING_SAID, p)]
    if len(fitting) != 1:
        return [], []
    builder.notes.append(f"nothing in '{frame.text}' names a part the agent knows: read as {fitting[0].describe(builder.asset)}, "
                         f"the only movable part that can {frame.verb}")
    return fitting, [frame.text]
