"""A part placed relative to another: "the key right below it", "the knob furthest from the big one", "the rack behind
the upper door", "the door in front of the middle rack", "the lever closest to me" (the user stands at the front)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from app.engine.lexicon.kinds import PartKind, info
from app.engine.offline.grounding import Part, position
from app.engine.offline.reading.mentions import Mention

if TYPE_CHECKING:
    from app.engine.offline.referents import Referents


def placed(self: Referents, relation: tuple[str, Mention], candidates: list[Part]) -> list[Part]:
    """The candidate nearest to the reference part in the named direction ("the key right below it")."""
    side, reference_mention = relation
    if side in ("near", "far"):
        nearest = _nearest(self, reference_mention, candidates)
        if side == "near" or len(nearest) != 1:
            return nearest
        return _farthest(self, reference_mention, candidates)
    from app.engine.offline.keypad import code_keys

    reference = self.pronoun() if reference_mention.pronoun else list(self.ground(reference_mention).parts) if (
        reference_mention.kind is not PartKind.CODE) else code_keys((("digit", reference_mention.head),), self)
    if len(reference) != 1:
        return candidates
    if side == "behind":  # "the rack (right) behind the upper door": the one that door closes in
        return self._behind(reference[0], candidates) if reference[0].kind is not None and info(reference[0].kind).hinged else candidates
    if side == "in_front":  # "the door in front of the middle rack": the one that closes it in
        return [p for p in candidates if p.kind is not None and info(p.kind).hinged and self._behind(p, reference)] or candidates
    anchor = position(reference[0], self.obj)
    axis, sign = {"below": (2, -1.0), "above": (2, 1.0), "left": (1, -1.0), "right": (1, 1.0)}.get(side, (None, 0.0))
    scored = []
    for part in candidates:
        if part.joint == reference[0].joint:
            continue
        offset = position(part, self.obj) - anchor
        if axis is not None and offset[axis] * sign <= 1e-6:
            continue
        across = float(np.linalg.norm(np.delete(offset, axis))) if axis is not None else abs(float(offset[2])) if side == "beside" else 0.0
        scored.append((round(across, 4), round(float(np.linalg.norm(offset)), 4), part.joint, part))
    scored.sort(key=lambda entry: entry[:3])
    if len(scored) > 1 and scored[0][:2] == scored[1][:2]:
        return [entry[3] for entry in scored if entry[:2] == scored[0][:2]]  # "next to the 5": the 4 and the 6 are as near
    return [scored[0][3]] if scored else []

def _farthest(self: Referents, reference_mention: Mention, candidates: list[Part]) -> list[Part]:
    """"the knob furthest from the big one", "the knob farther from the hinge", "the lever furthest from me" (the back)."""
    if reference_mention.head == "viewer":
        return [min(candidates, key=lambda p: (round(float(position(p, self.obj)[0]), 4), p.joint))]
    return _by_distance(self, reference_mention, candidates, max)

def _nearest(self: Referents, reference_mention: Mention, candidates: list[Part]) -> list[Part]:
    """"the knob nearest the lid's hinge", "the lever closest to me" (the user stands at the front)."""
    if reference_mention.head == "viewer":
        return [max(candidates, key=lambda p: (round(float(position(p, self.obj)[0]), 4), p.joint))]
    return _by_distance(self, reference_mention, candidates, min)

def _by_distance(self: Referents, reference_mention: Mention, candidates: list[Part], pick: Callable[..., Part]) -> list[Part]:
    hinge = "hinge" in reference_mention.modifiers
    mention = replace(reference_mention, modifiers=tuple(m for m in reference_mention.modifiers if m != "hinge"))
    reference = self.pronoun() if mention.pronoun else list(self.ground(mention).parts)
    if len(reference) != 1:
        return candidates
    anchor = self.obj.local(reference[0].geometry.pivot_world) if hinge else position(reference[0], self.obj)
    others = [p for p in candidates if p.joint != reference[0].joint]
    return [pick(others, key=lambda p: (round(float(np.linalg.norm(position(p, self.obj) - anchor)), 4), p.joint))] if others else []

