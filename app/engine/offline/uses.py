"""What a user will do with the whole object, with no part named and nothing else asked: a use that needs it open
("I need to use the toilet", "get the toilet ready for me to use", "I need to grab the pistol that's stored in there")
opens the object; a trip or a storing that needs it shut ("I'm done packing, get it ready to carry", "lock my jewelry
away in the safe") shuts it. The object's own reading of "open" and "shut" picks the part (its door, its lid), and a
note says the request was read as that wish."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.engine.lexicon.verbs import VerbSense
from app.engine.offline.complaints import added, whole_object_goal
from app.engine.offline.reading.acts import Act

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.reading.frames import Frame

_USING = frozenset({"use", "using"})
_TAKING = frozenset({"grab", "get", "take", "fetch", "retrieve", "reach"})
_INSIDE = frozenset({"inside", "stored", "kept", "there"})
_THINGS = frozenset({"something", "whatever", "whatever's", "stuff", "things"})
_CARRYING = frozenset({"carry", "carrying", "transport", "transporting"})
_TRIPS = frozenset({"carry", "travel", "transport", "ship", "go", "move"})
_STORING = frozenset({"lock", "put", "store", "stow", "tuck"})


def _wish(words: list[str]) -> str | None:
    """"open" or "close" for what the words say the user will do with the object, else None."""
    said = set(words)
    if said & _USING:
        return "open"
    if said & _TAKING and said & (_INSIDE | _THINGS):
        return "open"  # "I need to grab the pistol that's stored in there", "there's something in this chest I need to get out"
    if ("ready" in said and said & _TRIPS) or said & _CARRYING:
        return "close"  # "get it ready to carry", "make sure nothing falls out when I carry this box around"
    if "away" in said and said & _STORING:
        return "close"  # "lock my jewelry away in the safe"
    return None


def answer_use(builder: Builder, frames: list[Frame]) -> bool:
    """The object opened or shut for what the user will do with it; False when the prompt names a part or says no
    such use, or when nothing moves (already that way)."""
    if not frames or any(m.kind is not None for f in frames for m in (*f.themes, *f.instruments)):
        return False
    words = [w for f in frames for w in f.text.split()]
    way = _wish(words)
    if way is None:
        return False
    goal = whole_object_goal(frames[0], way, VerbSense.OPEN if way == "open" else VerbSense.CLOSE, builder.asset.name)
    if not added(builder, Act(goal=goal)):
        return False
    said = " ".join(f.text for f in frames)
    builder.notes.append(f"no part was named: read '{said}' as a wish to {'open' if way == 'open' else 'shut'} {builder.asset.name}")
    return True
