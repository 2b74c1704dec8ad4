"""A part asked to come off its object, or to be put somewhere else: refused, never animated as some motion of it.

Every movable part hangs on a joint: "remove the handle from the bucket entirely and lay it on the floor", "detach the lid",
"pull the cap off and set it down next to the bottle" ask for what no joint can do. "take the lid off" and "remove the
lid" alone still lift it (as far as its joint goes): only a word that it comes right off, a verb of detaching, or a place
off the object where it is put, refuse.
"""

from __future__ import annotations

from app.engine.lexicon.words import PLACES
from app.engine.offline.grounding import Part
from app.engine.offline.reading.frames import Frame
from app.engine.offline.referents import Referents

_DETACHING = frozenset({"detach", "unattach", "disconnect", "unmount", "dismount"})
_FULLY_OFF = frozenset({"entirely", "completely", "altogether"})
_REMOVING = frozenset({"remove", "unhook", "unclip"})
_TAKING_OFF = frozenset({"take", "pull", "lift", "yank", "twist", "prise", "pry"})
"""With "off" and a word that it comes right off ("take the handle off entirely"); "pull the drawer out completely" is fully out."""
_PUTTING = frozenset({"lay", "put", "set", "place", "rest", "drop", "leave", "stand", "prop"})
_BESIDE = frozenset({"beside", "alongside"})


def _put_elsewhere(words: list[str]) -> str | None:
    """"on the floor", "on the table", "next to the bottle", "beside it": a place off the object, as said."""
    for k, word in enumerate(words):
        if word in ("on", "onto") and k + 2 < len(words) and words[k + 1] in ("the", "a") and words[k + 2] in PLACES:
            return " ".join(words[k:k + 3])
        if (word in _BESIDE or words[k:k + 2] == ["next", "to"]) and k + 2 < len(words):
            return " ".join(words[k:k + 3 + (word == "next")])
    return None


def check_detached(refs: Referents, frame: Frame, parts: list[Part]) -> None:
    """Refuse a clause that takes a part off its object or puts it somewhere else."""
    if not parts or frame.verb is None or any(m.is_object for m in frame.themes):
        return
    words = frame.text.split()
    label = parts[0].kind.value if parts[0].kind is not None else "part"
    why = None
    if frame.verb in _DETACHING or frame.guessed_verb in _DETACHING:
        why = f"'{frame.guessed_verb or frame.verb}'"
    elif (frame.verb in _REMOVING or (frame.verb in _TAKING_OFF and "off" in words)) and (said := set(words) & _FULLY_OFF):
        why = f"'{frame.verb} ... {sorted(said)[0]}'"
    elif frame.verb in _PUTTING and (place := _put_elsewhere(words)) is not None:
        why = f"'{place}'"
    if why is not None:
        raise refs.refuse(f"'{frame.text}': the {label} ({parts[0].link}) is fixed to {refs.asset.name} by a joint, so {why} cannot be "
                          "animated; ask for the motion its joint allows (open, lift, swing it down)")
