"""Parts told by what can be done with them: "There are two things you can turn on that door. Turn the lower one." The
parts "one" then picks from are those the verb works (controls that turn, buttons that press), on the part named if one
is ("on that door"). Before this, "the lower one" was taken for a door, and refused."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.offline import mechanisms as mech

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.grounding import Part
    from app.engine.offline.reading.frames import Frame

_THINGS = frozenset({"things", "parts", "bits", "controls", "pieces", "ones"})
_CAN = frozenset({"can", "could", "may"})
_TURNING = frozenset({VerbSense.TURN, VerbSense.SPIN})


def _worked_by(sense: VerbSense, part: Part) -> bool:
    if sense in _TURNING:
        return part.geometry.type in ("revolute", "continuous")
    if sense is VerbSense.PRESS:
        return part.geometry.type == "prismatic"
    return False


def things_you_can(builder: Builder, frame: Frame) -> list[Part]:
    """The parts "things you can <verb> (on X)" names, [] when the clause says no such thing."""
    words = frame.text.split()
    at = next((k for k, w in enumerate(words) if w in _THINGS and words[k + 1:k + 2] == ["you"] and words[k + 2:k + 3] and words[k + 2] in _CAN), None)
    if at is None or at + 3 >= len(words) or words[at + 3] not in VERBS:
        return []
    sense = VERBS[words[at + 3]].sense
    hosts = [p for m in frame.themes if m.kind is not None for p in builder.refs.of_kind(m.kind)]
    inside = {link for host in hosts for link in builder.asset.descendants(host.link)} if len(hosts) == 1 else None
    return [p for p in builder.parts if mech.is_control(p) and _worked_by(sense, p) and (inside is None or p.link in inside)]
