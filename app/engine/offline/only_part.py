"""A part name the lexicon does not know, on an object with one movable part ("the stapler's magazine")."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.engine.lexicon.verbs import VerbSense
from app.engine.offline.grounding import Part
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.mentions import Mention

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder


def only_part(builder: Builder, frame: Frame, mention: Mention) -> list[Part]:
    """A part name we do not know, tied to the object ("the stapler's magazine") on an object with one
    movable part, with a verb that part can do: that part, with a warning; never a bare guess."""
    category = builder.tracker.obj.category or ""  # "the staple magazine": tied to a stapler by its own word too
    tied = mention.whose is not None or any(len(m) >= 4 and category.startswith(m) for m in mention.modifiers)
    if not tied or mention.kind is not None or len(builder.parts) != 1 or builder.refs.ground(mention).parts:
        return []
    part = builder.parts[0]
    sense = frame.sense
    fits = sense in (VerbSense.OPEN, VerbSense.CLOSE, VerbSense.RAISE, VerbSense.LOWER, VerbSense.RECLINE) and part.geometry.open_value is not None
    if sense in (VerbSense.PULL_OUT, VerbSense.PUSH_IN):
        fits = part.geometry.type == "prismatic"
    if not fits:
        return []
    builder.notes.append(f"read '{mention.words}' as {part.describe(builder.asset)}, the only movable part")
    return [part]
