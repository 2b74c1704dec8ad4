"""Things kept in a part: "I need the ketchup, which lives in the left door", "get the milk out - it's on the shelf in
the right door". The thing is no part; the request is to open the part that holds it."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.verbs import VerbSense
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.mention import Mention
from app.engine.offline.reading.quantities import Quantities

_PLACES = frozenset({"in", "on", "inside", "behind", "at", "under", "within"})
_SUBJECTS = frozenset({"it", "it's", "they", "they're", "which", "that", "these", "those"})


def unknown_things(frame: Frame) -> bool:
    """``frame`` asks for things the lexicon does not know as parts ("the ketchup", "my socks")."""
    return bool(frame.themes) and all(m.kind is None and not (m.is_object or m.pronoun or m.anaphor) for m in frame.themes) and (
        frame.verb is not None or frame.wish)


def place_of(frame: Frame) -> Mention | None:
    """The part a clause says something is kept in ("it's on the shelf in the right door": the right door)."""
    words = frame.text.split()
    if (frame.verb is not None and not frame.stative) or not words or words[0] not in _SUBJECTS or not _PLACES & set(words[1:4]):
        return None
    places = [m for m in frame.themes if m.kind is not None and not m.pronoun]
    if len(places) != 1:
        return None
    place = places[0]
    return place.owner if place.owner is not None and place.owner.kind is not None else place


def open_holder(request: Frame, place: Mention) -> Frame:
    """The request to reach a stored thing, as opening the part that holds it."""
    return replace(request, verb="open", sense=VerbSense.OPEN, particle=None, themes=(place,), instruments=(), wish=False,
                   guessed_verb=None, quantities=Quantities(speed_factor=request.quantities.speed_factor))
