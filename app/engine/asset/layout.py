"""Where each part sits and which end of each joint is closed, open and rest: what a user needs to name parts.

Positions are given as seen by someone facing the object's front (the front the offline
agent infers from where doors, drawers and controls face): top/middle/bottom,
left/center/right, front/middle/back of the object's box, from the centre of each link's
box at rest. Parts that share a label are told apart by where they differ most
("drawer (upper, link_0)", "drawer (lower, link_1)"). Closed and open come from the
geometry (the end where the part sits flush with the rest of the object), never from the
sign of a limit.
"""

from __future__ import annotations

from collections import defaultdict
from typing import Literal

import numpy as np
from pydantic import BaseModel, ConfigDict

from app.engine.asset.kinematics import link_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.offline.geometry import ObjectGeometry, analyse
from app.engine.types import FloatArray

SIDE_FRACTION = 0.2
"""A part whose centre is more than this fraction of the half-size off-centre sits on that side."""
END_TOLERANCE = 1e-9
MIXED_AXES_RATIO = 0.5
"""Same-label parts differing along a second axis by at least this share of the first are placed along both."""
ROUND_DIGITS = 6

Vertical = Literal["top", "middle", "bottom"]
Side = Literal["left", "center", "right"]
Depth = Literal["front", "middle", "back"]
End = Literal["lower", "upper", "between"]
# axis index in (front, right, up) -> words from its low end to its high end
_PAIR_WORDS = {2: ("lower", "upper"), 1: ("left", "right"), 0: ("back", "front")}
_TRIPLE_WORDS = {2: ("bottom", "middle", "top"), 1: ("left", "middle", "right"), 0: ("back", "middle", "front")}
_COUNT_FROM = {2: "top", 1: "left", 0: "front"}
"""Where the counting starts for four or more same-label parts ("2nd from top")."""


class PartPlace(BaseModel):
    """Where one link sits, as seen from the object's front."""

    model_config = ConfigDict(frozen=True)
    link: str
    label: str | None
    name: str
    """How to call it: the label, told apart from same-label parts ("drawer (upper, link_0)")."""
    vertical: Vertical
    side: Side
    depth: Depth
    joint: str | None
    """The movable joint that moves it directly (None for parts fixed to their parent)."""


class JointEnds(BaseModel):
    """Which end of a movable joint's range is closed, open and rest (values in radians or metres)."""

    model_config = ConfigDict(frozen=True)
    joint: str
    child: str
    type: str
    lower: float | None
    upper: float | None
    rest: float
    rest_end: End | None
    closed: float | None
    """Where the part sits flush with (or inside) the rest of the object; None when the geometry cannot tell."""
    closed_end: End | None
    open: float | None
    open_end: End | None


class AssetLayout(BaseModel):
    """Part positions and joint ends of an asset."""

    model_config = ConfigDict(frozen=True)
    front: tuple[float, float, float]
    """World direction the object faces (+Z up)."""
    right: tuple[float, float, float]
    """World direction of the viewer's right when facing the front."""
    front_by_convention: bool = False
    """Nothing on the object shows where it faces: ``front`` is PartNet-Mobility's convention (-X)."""
    front_shown_by: str = ""
    """What showed the front: its doors, drawers, lids or control panel; its spout; the side its controls sit on; or
    nothing (the convention)."""
    parts: list[PartPlace]
    joints: list[JointEnds]


def _round(value: float) -> float:
    return round(float(value), ROUND_DIGITS) + 0.0


def _vector(values: FloatArray) -> tuple[float, float, float]:
    return (_round(values[0]), _round(values[1]), _round(values[2]))


def _box_centres(asset: ArticulatedAsset) -> dict[str, FloatArray]:
    """World centre of each visual link's box at rest."""
    poses = link_poses(asset, {}, frames=1)
    centres = {}
    for name in asset.visual_links:
        vertices = asset.links[name].vertices()
        pose = poses[name][0]
        world = vertices @ pose[:3, :3].T + pose[:3, 3]
        centres[name] = (world.min(axis=0) + world.max(axis=0)) / 2.0
    return centres


def _half_sizes(geometry: ObjectGeometry) -> FloatArray:
    """Half the object's size along (front, right, up)."""
    return np.array([0.5 * float(np.abs(axis) @ geometry.extents) for axis in (geometry.front, geometry.right, geometry.up)])


def _word(offset: float, low: str, middle: str, high: str) -> str:
    return high if offset > SIDE_FRACTION else low if offset < -SIDE_FRACTION else middle


def _distinguish(places: list[tuple[str, FloatArray]]) -> dict[str, str]:
    """Words telling same-label links apart, from the axes along which they differ.

    Along one axis: "lower"/"upper", "bottom"/"middle"/"top", or "2nd from top" for more.
    Along several (four wheels): the side of the group each part is on, e.g. "front right".
    """
    coordinates = np.array([local for _, local in places])
    spread = coordinates.max(axis=0) - coordinates.min(axis=0)
    if spread.max() <= END_TOLERANCE:
        return {}
    axes = [axis for axis in (2, 0, 1) if spread[axis] >= MIXED_AXES_RATIO * spread.max()]
    if len(axes) > 1:
        middle = (coordinates.max(axis=0) + coordinates.min(axis=0)) / 2.0
        words = {}
        for (name, local) in places:
            parts = []
            for axis in axes:
                offset = (local[axis] - middle[axis]) / spread[axis]
                low, high = _PAIR_WORDS[axis]
                parts.append(high if offset > SIDE_FRACTION / 2 else low if offset < -SIDE_FRACTION / 2 else "middle")
            words[name] = " ".join(parts)
        return words
    axis = axes[0]
    ascending = [places[i][0] for i in sorted(range(len(places)), key=lambda i: (coordinates[i, axis], places[i][0]))]
    if len(places) == 2:
        return dict(zip(ascending, _PAIR_WORDS[axis], strict=True))
    if len(places) == 3:
        return dict(zip(ascending, _TRIPLE_WORDS[axis], strict=True))
    start = _COUNT_FROM[axis]
    counted = ascending if axis == 1 else ascending[::-1]
    return {name: start if rank == 1 else f"{_ordinal(rank)} from {start}" for rank, name in enumerate(counted, start=1)}


def _ordinal(number: int) -> str:
    suffix = "th" if 10 <= number % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(number % 10, "th")
    return f"{number}{suffix}"


def _end(joint_lower: float | None, joint_upper: float | None, value: float | None) -> End | None:
    if value is None or joint_lower is None or joint_upper is None:
        return None
    if abs(value - joint_lower) <= END_TOLERANCE:
        return "lower"
    if abs(value - joint_upper) <= END_TOLERANCE:
        return "upper"
    return "between"


def _parts(asset: ArticulatedAsset, geometry: ObjectGeometry) -> list[PartPlace]:
    half = np.maximum(_half_sizes(geometry), 1e-9)
    local = {name: geometry.local(centre) / half for name, centre in _box_centres(asset).items()}
    by_label: dict[str, list[tuple[str, FloatArray]]] = defaultdict(list)
    for name in asset.link_order:
        if name in local:
            by_label[asset.links[name].semantics.label or name].append((name, local[name]))
    told_apart: dict[str, str] = {}
    for group in by_label.values():
        if len(group) > 1:
            told_apart.update(_distinguish(group))
    places = []
    for name in asset.link_order:
        if name not in local:
            continue
        label = asset.links[name].semantics.label
        front, right, up = local[name]
        qualifiers = [told_apart[name]] if name in told_apart else []
        shown = label or name
        name_text = f"{shown} ({', '.join([*qualifiers, name])})" if shown != name or qualifiers else name
        parent = asset.parent_joint(name)
        places.append(PartPlace(
            link=name, label=label, name=name_text,
            vertical=_word(up, "bottom", "middle", "top"),  # type: ignore[arg-type]
            side=_word(right, "left", "center", "right"),  # type: ignore[arg-type]
            depth=_word(front, "back", "middle", "front"),  # type: ignore[arg-type]
            joint=parent.name if parent is not None and parent.movable else None,
        ))
    return places


def _joints(asset: ArticulatedAsset, geometry: ObjectGeometry) -> list[JointEnds]:
    ends = []
    for name in asset.movable_joints:
        spec = asset.joints[name]
        facts = geometry.joints.get(name)
        closed = None if facts is None else facts.closed_value
        opened = None if facts is None else facts.open_value
        ends.append(JointEnds(
            joint=name, child=spec.child, type=spec.type, lower=spec.lower, upper=spec.upper, rest=_round(spec.rest),
            rest_end=_end(spec.lower, spec.upper, spec.rest),
            closed=None if closed is None else _round(closed), closed_end=_end(spec.lower, spec.upper, closed),
            open=None if opened is None else _round(opened), open_end=_end(spec.lower, spec.upper, opened),
        ))
    return ends


def asset_layout(asset: ArticulatedAsset) -> AssetLayout:
    """Part positions (as seen from the front) and joint ends of ``asset``."""
    geometry = analyse(asset)
    return AssetLayout(front=_vector(geometry.front), right=_vector(geometry.right), front_by_convention=geometry.front_by_convention,
                       front_shown_by=geometry.front_cue.value,
                       parts=_parts(asset, geometry), joints=_joints(asset, geometry))


def direction_name(vector: tuple[float, float, float]) -> str:
    """``-X``, ``+Y`` ... for an axis-aligned world direction, else the vector."""
    values = np.asarray(vector)
    index = int(np.argmax(np.abs(values)))
    if abs(abs(values[index]) - 1.0) < 1e-6:
        return f"{'+' if values[index] > 0 else '-'}{'XYZ'[index]}"
    return "(" + ", ".join(f"{v:+.2f}" for v in values) + ")"
