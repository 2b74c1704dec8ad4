"""Where the object faces: the horizontal direction a user stands in to use it.

Cues, strongest first: parts named front/rear (a car's wheels), the way drawers pull out, the faces doors sit on, lids
hinged at the back, knobs on a panel tilted toward the user. Without any of those: a tap's spout (the body reaching out
over its foot), then the side faces the controls sit on. Without any cue at all, PartNet-Mobility's convention
(:data:`DEFAULT_FRONT`), which every reading from it must say is a guess.
"""

from __future__ import annotations

from enum import StrEnum
from typing import TYPE_CHECKING

import numpy as np

from app.engine.asset.kinematics import drives_mimics, subtree_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.lexicon.kinds import CONTROL_KINDS, PartKind, info
from app.engine.lexicon.objects import SPOUTED
from app.engine.offline.naming import tokens
from app.engine.offline.rest_points import posed
from app.engine.types import FloatArray

if TYPE_CHECKING:
    from app.engine.offline.geometry import JointGeometry

UP = np.array([0.0, 0.0, 1.0])
SNAP_ANGLE_DEG = 35.0
DEFAULT_FRONT = np.array([-1.0, 0.0, 0.0])
"""PartNet-Mobility objects face -X after their root rotation; used only without any cue."""
FOOT_SHARE = 0.15
"""The lowest share of a body's height that stands on the counter (a tap's foot)."""
MIN_REACH = 0.08
"""Least horizontal reach of a spouted body's mean point from its foot, as a share of its box diagonal, that says where
it faces (the dev taps reach 0.16 to 0.36)."""
MIN_BODY_POINTS = 20
_CONTROL_LABELS = frozenset(label for kind in CONTROL_KINDS for label in info(kind).labels)
"""PartNet labels of control links (a toaster's "slider"): fixed in place, they still show the side the user stands on."""
SIDE_FACE = 0.5
"""A control's face is a side face when its normal's upward part is under this."""


def _flat(vector: FloatArray) -> FloatArray:
    return np.array([vector[0], vector[1], 0.0])


def _horizontal(vector: FloatArray) -> FloatArray:
    flat = _flat(vector)
    norm = float(np.linalg.norm(flat))
    return flat / norm if norm > 1e-9 else np.zeros(3)


def _front_vote(geometry: JointGeometry, center: FloatArray, asset: ArticulatedAsset, points: dict[str, FloatArray],
                rest: dict[str, FloatArray]) -> FloatArray:
    """One part's vote for the object's front (zero when it says nothing)."""
    if geometry.category in CONTROL_KINDS:
        # a knob on a tilted control panel: its axis, taken pointing up and out of the panel,
        # leans toward the user (a washer's back panel); vertical or level axes say nothing
        if geometry.type in ("revolute", "continuous") and 0.2 < abs(float(geometry.axis_world @ UP)) < 0.7:
            outward = geometry.axis_world if geometry.axis_world @ UP > 0 else -geometry.axis_world
            return 1.0 * _horizontal(outward)
        return np.zeros(3)
    if geometry.open_value is not None and geometry.closed_value is not None:
        if geometry.type == "prismatic":
            ends = np.array([geometry.closed_value, geometry.open_value])
            if drives_mimics(asset, geometry.joint):  # mimic followers move with it: where its parts go on average
                poses = subtree_poses(asset, geometry.joint, ends, rest)
                shift = posed(points, poses, geometry.moving_links, 1).mean(axis=0) - posed(points, poses, geometry.moving_links, 0).mean(axis=0)
                return 2.0 * _horizontal(shift)
            return 2.0 * _horizontal(geometry.axis_world * (geometry.open_value - geometry.closed_value))
        if abs(geometry.axis_world @ UP) < 0.7 and abs(geometry.home_face @ UP) > 0.5:
            # a lid (or laptop screen) on top, hinged at the back: the front is away from the hinge
            offset = geometry.pivot_world - center
            offset = offset - (offset @ geometry.axis_world) * geometry.axis_world
            return -0.5 * _horizontal(offset)
        if abs(float(geometry.axis_world @ geometry.home_face)) > 0.7:
            return np.zeros(3)  # hinged about the normal of its nearest face (a stapler's arm): that face is no front
        return 1.0 * _horizontal(geometry.home_face)
    # controls say nothing reliable: a washer's knobs sit on a back panel facing the user,
    # a faucet's lever on a column whose nearest box face is a side
    return np.zeros(3)


def _named_front(joints: dict[str, JointGeometry]) -> FloatArray:
    """Front from part names: parts named front/rear (a car's wheels) point along the object's front."""
    front, rear = [], []
    for geometry in joints.values():
        words = set(tokens(geometry.child)) | set(tokens(geometry.joint))
        if "front" in words:
            front.append(geometry.centroid)
        elif words & {"rear", "back"}:
            rear.append(geometry.centroid)
    if front and rear:
        return 3.0 * _horizontal(np.mean(front, axis=0) - np.mean(rear, axis=0))
    return np.zeros(3)


def by_convention(vote: FloatArray) -> bool:
    """No cue to the front at all: it is taken as :data:`DEFAULT_FRONT`."""
    return bool(np.linalg.norm(vote) < 1e-6)


class FrontCue(StrEnum):
    """What showed the object's front (``artimo inspect`` says it)."""

    PARTS = "its doors, drawers, lids or control panel"
    SPOUT = "its spout"
    CONTROLS = "the side its controls sit on"
    SCREEN = "a screen or control fixed in place"
    CONVENTION = "nothing: PartNet-Mobility's convention"


def front_votes(joints: dict[str, JointGeometry], center: FloatArray, asset: ArticulatedAsset,
                points: dict[str, FloatArray], rest: dict[str, FloatArray], category: str | None = None) -> tuple[FloatArray, FrontCue]:
    """The sum of the strongest cues to the object's front (zero when nothing on it says where it faces) and what they
    are. Doors, drawers, lids and parts named front come first; without them a spouted object's reach (a tap, by
    ``category``), then the faces its controls sit on (a toaster's lever and knob)."""
    vote = _named_front(joints)
    for geometry in joints.values():
        vote = vote + _front_vote(geometry, center, asset, points, rest)
    if not by_convention(vote):
        return vote, FrontCue.PARTS
    if category in SPOUTED and not by_convention(vote := _reach(asset, joints, points, rest)):
        return vote, FrontCue.SPOUT
    vote = _control_faces(joints)
    if by_convention(vote) and not by_convention(screen := _fixed_parts(asset, joints, points, rest)):
        return screen, FrontCue.SCREEN
    return vote, FrontCue.CONVENTION if by_convention(vote) else FrontCue.CONTROLS


def _fixed_parts(asset: ArticulatedAsset, joints: dict[str, JointGeometry], points: dict[str, FloatArray],
                  rest: dict[str, FloatArray]) -> FloatArray:
    """Parts the URDF fixed: the user sits on the far side of the base from a screen (a laptop that cannot fold), and on
    the side a control sits on (a toaster whose lever is fixed)."""
    moving = {link for geometry in joints.values() for link in geometry.moving_links}
    still = [link for link in asset.visual_links if link not in moving]
    screens = [link for link in still if asset.links[link].semantics.label in info(PartKind.SCREEN).labels]
    controls = [link for link in still if asset.links[link].semantics.label in _CONTROL_LABELS]
    shown = screens or controls
    if not shown or len(shown) == len(still):
        return np.zeros(3)
    base = posed(points, rest, [link for link in still if link not in shown])
    away = _flat(base.mean(axis=0) - posed(points, rest, shown).mean(axis=0)) * (1.0 if screens else -1.0)
    span = float(np.linalg.norm(base.max(axis=0) - base.min(axis=0))) if base.shape[0] else 0.0
    return _horizontal(away) if span > 0 and float(np.linalg.norm(away)) > MIN_REACH * span else np.zeros(3)


def _reach(asset: ArticulatedAsset, joints: dict[str, JointGeometry], points: dict[str, FloatArray],
           rest: dict[str, FloatArray]) -> FloatArray:
    """Where the fixed body reaches out over its foot (a tap's spout, toward the user); zero when it barely does."""
    moving = {link for geometry in joints.values() for link in geometry.moving_links}
    body = posed(points, rest, [link for link in asset.visual_links if link not in moving])
    if body.shape[0] < MIN_BODY_POINTS:
        return np.zeros(3)
    low, high = body.min(axis=0), body.max(axis=0)
    foot = body[body[:, 2] <= low[2] + FOOT_SHARE * (high[2] - low[2])]
    reach = _flat(body.mean(axis=0) - foot.mean(axis=0))
    return _horizontal(reach) if float(np.linalg.norm(reach)) > MIN_REACH * float(np.linalg.norm(high - low)) else np.zeros(3)


def _control_faces(joints: dict[str, JointGeometry]) -> FloatArray:
    """The sum of the side faces the controls sit on (zero when they sit on top or on opposite sides alike)."""
    vote = np.zeros(3)
    for geometry in joints.values():
        if geometry.category in CONTROL_KINDS and abs(float(geometry.home_face @ UP)) < SIDE_FACE:
            vote = vote + _horizontal(geometry.home_face)
    return vote


def front_of(vote: FloatArray) -> FloatArray:
    """The front :func:`front_votes` point to, snapped to an axis when near one (:data:`DEFAULT_FRONT` without any)."""
    if by_convention(vote):
        return DEFAULT_FRONT.copy()
    front = _horizontal(vote)
    snapped = np.round(front)
    if np.count_nonzero(snapped) == 1 and np.degrees(np.arccos(np.clip(front @ snapped, -1, 1))) < SNAP_ANGLE_DEG:
        return snapped.astype(np.float64)
    return front
