"""Ground part mentions of a prompt to the asset's movable joints.

Candidates come from part categories (semantics.txt labels, link and visual names,
with related categories as a fallback), are narrowed by an owner ("the knob on the
door"), spatial qualifiers (top/bottom, left/right as you face the object, front/back,
middle) and ordinals (first/second: top to bottom for stacked parts, else left to
right), and a singular mention keeps the most salient candidate.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.offline.geometry import JointGeometry, ObjectGeometry
from app.engine.offline.language import Mention
from app.engine.offline.naming import describe_link, link_words
from app.engine.offline.vocabulary import CONTROL_CATEGORIES as CONTROLS
from app.engine.offline.vocabulary import ORDINALS, SPATIAL, STOP_WORDS

RELATED: dict[str, tuple[str, ...]] = {
    "lid": ("door", "screen", "window"),
    "door": ("lid", "window", "screen"),
    "screen": ("lid", "door"),
    "window": ("door", "lid"),
    "drawer": ("tray", "container"),
    "tray": ("drawer", "container", "turntable"),
    "container": ("drawer", "tray"),
    "turntable": ("tray",),
    "knob": ("handle", "latch", "switch", "lever"),
    "handle": ("knob", "lever", "latch", "switch"),
    "lever": ("handle", "switch", "knob"),
    "latch": ("handle", "knob", "lever"),
    "button": ("switch", "key"),
    "switch": ("button", "lever"),
    "pedal": ("lever", "button"),
    "wheel": (),
    "code": ("knob", "button"),
}
OPENABLE = ("door", "lid", "screen", "window", "drawer", "tray", "container")
NON_NAME_WORDS = frozenset(SPATIAL) | frozenset(ORDINALS) | STOP_WORDS
QUALIFIER_TOLERANCE = 0.25
"""Candidates within this fraction of the candidates' spread of the extreme value all qualify."""
MIN_QUALIFIER_TOLERANCE_M = 1e-3


@dataclass(frozen=True)
class Part:
    joint: str
    link: str
    category: str | None
    geometry: JointGeometry

    def describe(self, asset: ArticulatedAsset) -> str:
        return f"{describe_link(asset, self.link)} via {self.joint} ({self.geometry.type})"


def movable_parts(asset: ArticulatedAsset, geometry: ObjectGeometry) -> list[Part]:
    """Every controllable joint whose moving links have geometry."""
    parts = []
    for joint, info in geometry.joints.items():
        if any(asset.links[n].has_geometry for n in info.moving_links):
            parts.append(Part(joint=joint, link=info.child, category=info.category, geometry=info))
    return parts


def _position(part: Part, geometry: ObjectGeometry) -> np.ndarray:
    return geometry.local(part.geometry.home_centroid)


def _extreme(candidates: list[Part], geometry: ObjectGeometry, axis: int, largest: bool, strict: bool = False) -> list[Part]:
    values = np.array([_position(p, geometry)[axis] for p in candidates])
    best = values.max() if largest else values.min()
    tolerance = MIN_QUALIFIER_TOLERANCE_M if strict else max(QUALIFIER_TOLERANCE * float(np.ptp(values)), MIN_QUALIFIER_TOLERANCE_M)
    return [p for p, v in zip(candidates, values, strict=True) if abs(v - best) <= tolerance]


def _apply_spatial(candidates: list[Part], words: tuple[str, ...], geometry: ObjectGeometry) -> list[Part]:
    # local axes: 0 = front, 1 = right (as you face the object), 2 = up
    rules = {"top": (2, True), "bottom": (2, False), "left": (1, False), "right": (1, True), "front": (0, True), "back": (0, False)}
    for word in words:
        if len(candidates) < 2:
            break
        if word in rules:
            axis, largest = rules[word]
            candidates = _extreme(candidates, geometry, axis, largest)
        elif word.endswith("most") and word[:-4] in rules:  # "leftmost": the single extreme one
            axis, largest = rules[word[:-4]]
            candidates = _extreme(candidates, geometry, axis, largest, strict=True)
        elif word == "middle":
            candidates = [_ordered(candidates, geometry)[len(candidates) // 2]]
        elif word in ("inner", "outer"):
            distances = [float(np.linalg.norm(_position(p, geometry))) for p in candidates]
            index = int(np.argmin(distances) if word == "inner" else np.argmax(distances))
            candidates = [candidates[index]]
    return candidates


def _lines_of(candidates: list[Part], geometry: ObjectGeometry, axis: int, descending: bool) -> list[list[Part]]:
    """Group candidates into rows (axis 2, top first) or columns (axis 1, left first) by 1-D gaps."""
    ordered = sorted(candidates, key=lambda p: -_position(p, geometry)[axis] if descending else _position(p, geometry)[axis])
    values = [float(_position(p, geometry)[axis]) for p in ordered]
    sizes = sorted(p.geometry.size for p in ordered)
    gap = max(0.5 * sizes[len(sizes) // 2] / 3.0, MIN_QUALIFIER_TOLERANCE_M)
    lines: list[list[Part]] = [[ordered[0]]]
    for previous, value, part in zip(values, values[1:], ordered[1:], strict=False):
        if abs(value - previous) > gap:
            lines.append([])
        lines[-1].append(part)
    return lines


def _pick_line(candidates: list[Part], geometry: ObjectGeometry, index: int, axis: int) -> list[Part]:
    lines = _lines_of(candidates, geometry, axis, descending=axis == 2)
    if index == 0:
        return lines[len(lines) // 2]
    return lines[index - 1] if index > 0 and index <= len(lines) else lines[-1]


NAME_SIDES = {"front": {"front"}, "back": {"back", "rear"}, "left": {"left"}, "right": {"right"}, "top": {"top", "upper"}, "bottom": {"bottom", "lower"},
              "leftmost": {"left"}, "rightmost": {"right"}, "topmost": {"top", "upper"}, "bottommost": {"bottom", "lower"}}


def _named_spatial(candidates: list[Part], words: tuple[str, ...], asset: ArticulatedAsset) -> list[Part]:
    """Candidates whose own names say where they are ("wheel_front_left"): the object's own
    left/right, which for a car differs from the left/right of someone facing it."""
    if not words or len(candidates) < 2:
        return []
    chosen = candidates
    for word in words:
        if word not in NAME_SIDES:
            return []
        chosen = [p for p in chosen if link_words(asset, p.link, visuals=False) & NAME_SIDES[word]]
    return chosen


def _ordered(candidates: list[Part], geometry: ObjectGeometry) -> list[Part]:
    """Reading order: top to bottom when stacked, else left to right."""
    positions = np.array([_position(p, geometry) for p in candidates])
    vertical = np.ptp(positions[:, 2]) >= np.ptp(positions[:, 1])
    keys = [(-pos[2], pos[1]) if vertical else (pos[1], -pos[2]) for pos in positions]
    return [p for _, p in sorted(zip(keys, candidates, strict=True), key=lambda item: item[0])]


def _salient(candidates: list[Part], geometry: ObjectGeometry) -> Part:
    """The part a singular mention most likely means: the largest, then top-most, then left-most."""
    return max(candidates, key=lambda p: (round(p.geometry.size, 3), _position(p, geometry)[2], -_position(p, geometry)[1]))


LID_MAX_VERTICAL_AXIS = 0.7
"""|cos| between a hinge axis and up above which the hinge is a side hinge (a door's), never a lid's."""


def _fits(part: Part, category: str, up: np.ndarray | None) -> bool:
    """Whether a part of a related category can be what the named kind of part means."""
    if category == "knob" and part.geometry.type == "prismatic":
        return False  # a knob turns: a sliding lever is not what "the knob" means
    if category == "lid" and up is not None and part.geometry.type != "prismatic":
        # a lid swings up about a horizontal hinge: a side-hinged door is not "the lid"
        axis = np.asarray(part.geometry.axis_world, dtype=float)
        norm = float(np.linalg.norm(axis))
        if norm > 0 and abs(float(axis @ up)) / norm > LID_MAX_VERTICAL_AXIS:
            return False
    return True


def _by_category(parts: list[Part], category: str, up: np.ndarray | None = None) -> list[Part]:
    exact = [p for p in parts if p.category == category]
    if exact:
        return exact
    for related in RELATED.get(category, ()):
        found = [p for p in parts if p.category == related and _fits(p, category, up)]
        if found:
            return found
    return []


def openable_parts(parts: list[Part]) -> list[Part]:
    """Parts that open and close (geometry decided which way): doors/lids first, then drawers,
    then any other part with an open side (a stapler's arm); controls never."""
    found = [p for p in parts if p.geometry.open_value is not None and p.category not in CONTROLS]
    return sorted(found, key=lambda p: (OPENABLE.index(p.category) if p.category in OPENABLE else len(OPENABLE), -p.geometry.size, p.joint))


SIZE_TOLERANCE = 0.15
"""Relative size difference within which parts count as the same size ("both small knobs")."""


def ground_mention(mention: Mention, asset: ArticulatedAsset, geometry: ObjectGeometry, parts: list[Part], words: set[str] | None = None) -> list[Part]:
    """Joints a mention refers to (empty when nothing matches).

    ``words`` are extra prompt words that may pick a part by name ("release" button).
    """
    candidates = _by_category(parts, mention.category, np.asarray(geometry.up, dtype=float))
    if mention.owner is not None and candidates:
        owners = ground_mention(mention.owner, asset, geometry, parts)
        owned = [p for p in candidates if any(p.link in asset.descendants(o.link) and p.joint != o.joint for o in owners)]
        candidates = owned or candidates
    if words and len(candidates) > 1:
        distinctive = words - NON_NAME_WORDS - {mention.category, mention.head}
        named = [p for p in candidates if link_words(asset, p.link, visuals=False) & distinctive]
        candidates = named or candidates
    if mention.row is not None and len(candidates) > 1:
        candidates = _pick_line(candidates, geometry, mention.row, axis=2)
    if mention.column is not None and len(candidates) > 1:
        candidates = _pick_line(candidates, geometry, mention.column, axis=1)
    if mention.size == "large" and len(candidates) > 1:
        # "the large dial on the right": size is intrinsic, left/right depends on the inferred front
        candidates = [max(candidates, key=lambda p: p.geometry.size)]
    candidates = _named_spatial(candidates, mention.spatial, asset) or _apply_spatial(candidates, mention.spatial, geometry)
    if mention.size is not None and len(candidates) > 1:
        pick = max if mention.size == "large" else min
        chosen = pick(candidates, key=lambda p: p.geometry.size)
        # "each small knob": every part of (about) the chosen size
        candidates = [p for p in candidates if abs(p.geometry.size - chosen.geometry.size) <= SIZE_TOLERANCE * chosen.geometry.size] if mention.plural else [chosen]
    if mention.ordinal is not None and mention.ordinal > len(candidates) and mention.row is None and mention.column is None:
        return []  # "the second drawer" of a one-drawer nightstand names nothing
    if mention.ordinal is not None and len(candidates) > 1:
        ordered = _ordered(candidates, geometry)
        index = mention.ordinal - 1 if mention.ordinal > 0 else len(ordered) - 1
        candidates = [ordered[min(index, len(ordered) - 1)]]
    if not candidates or mention.plural:
        return candidates
    return [_salient(candidates, geometry)]
