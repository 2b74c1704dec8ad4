"""What the asset's geometry says about its parts.

For every movable joint: which limit is closed and which open (the closed state is the
one where the part sits flush against or inside the rest of the object — measured as
protrusion outside the other links' box plus the growth of the whole object's box), which
way is "pressed" (into the nearest face of the parent), which way is up, the part's
radius about its axis (wheels, knobs) and the face it sits on. For the whole object: the
front (where doors, drawers and controls face), up (+Z) and the viewer's right.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np

from app.engine.asset.kinematics import link_poses, subtree_motion, subtree_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.lexicon.kinds import HINGED_KINDS, PartKind, info, kind_of_label
from app.engine.offline.front import UP, FrontCue, by_convention, front_of, front_votes
from app.engine.offline.naming import link_kind
from app.engine.offline.rest_points import RestPoints
from app.engine.offline.rest_points import posed as _posed
from app.engine.types import FloatArray

MAX_POINTS_PER_LINK = 1500
MAX_MOVED_POINTS = 8192
"""Most points one joint's questions are asked of: a joint moving more (a long chain's first joints) is judged on an
even stride of its moved points, so each joint costs at most this much and the whole asset stays linear in its size.
The largest moved set among the 103 shared PartNet assets is 5786 points, so none of them is sampled."""
OPEN_CLOSED_MIN_GAP = 0.02
"""Smallest difference of the normalised closedness score that decides open vs closed."""
WIDE_SWING_RAD = 1.25 * np.pi
"""A hinge that swings further than this (a bucket's carry handle over 270 degrees) may be highest between its ends."""


@dataclass(frozen=True, eq=False)
class JointGeometry:
    """Geometric facts about one movable joint (world frame, rest pose unless stated)."""

    joint: str
    type: str
    child: str
    category: PartKind | None
    moving_links: tuple[str, ...]
    axis_world: FloatArray
    pivot_world: FloatArray
    lower: float | None
    upper: float | None
    rest: float
    centroid: FloatArray
    home_centroid: FloatArray
    """Centroid of the moving links at the closed value (rest when unknown)."""
    home_face: FloatArray
    """Outward normal of the static box face nearest to the part in its closed state."""
    closed_value: float | None
    open_value: float | None
    press_value: float | None
    up_value: float | None
    down_value: float | None
    face_normal: FloatArray
    radius: float
    size: float
    tip: FloatArray
    """The moving part's point farthest from the joint axis at rest (the end a hand pushes)."""
    press_outward: bool = False
    """A button resting at the deep end of its travel: a press moves it along the only travel it has (outward)."""

    @property
    def span(self) -> float | None:
        return None if self.lower is None or self.upper is None else self.upper - self.lower


@dataclass(frozen=True, eq=False)
class ObjectGeometry:
    center: FloatArray
    extents: FloatArray
    diag: float
    front: FloatArray
    up: FloatArray
    right: FloatArray
    joints: dict[str, JointGeometry]
    category: str | None
    front_by_convention: bool = False
    """No door, drawer, lid, tilted panel, part named front, tap's spout or control on a side shows where the object
    faces (:mod:`app.engine.offline.front`): ``front`` is :data:`DEFAULT_FRONT`, PartNet-Mobility's convention, and every left/right/front/back read from it a guess."""
    front_cue: FrontCue = FrontCue.PARTS
    """What showed the front."""

    def local(self, point: FloatArray) -> FloatArray:
        """(front, right, up) coordinates of a world point relative to the object centre."""
        offset = np.asarray(point) - self.center
        return np.array([offset @ self.front, offset @ self.right, offset @ self.up])


def _subsample(points: FloatArray) -> FloatArray:
    if points.shape[0] <= MAX_POINTS_PER_LINK:
        return points
    step = int(np.ceil(points.shape[0] / MAX_POINTS_PER_LINK))
    return points[::step]


def _bounded(points: FloatArray) -> FloatArray:
    if points.shape[0] <= MAX_MOVED_POINTS:
        return points
    return points[::int(np.ceil(points.shape[0] / MAX_MOVED_POINTS))]


def _local_points(asset: ArticulatedAsset) -> dict[str, FloatArray]:
    return {name: _subsample(asset.links[name].vertices()) for name in asset.visual_links}


def _highest(asset: ArticulatedAsset, joint: str, values: FloatArray, rest: dict[str, FloatArray], points: dict[str, FloatArray],
             moved: FloatArray) -> float:
    heights = [float(posed[:, 2].mean()) for posed in _moved_at(asset, joint, values, rest, points, moved)]
    return float(values[int(np.argmax(heights))])


def _moved_at(asset: ArticulatedAsset, joint: str, values: FloatArray, rest: dict[str, FloatArray],
              points: dict[str, FloatArray], moved: FloatArray) -> list[FloatArray]:
    """The points of the links ``joint`` moves (``moved``: at rest, world frame), at each of its ``values``."""
    motion = subtree_motion(asset, joint, values, rest)
    if motion is None:
        poses = subtree_poses(asset, joint, values, rest)
        return [_bounded(_posed(points, poses, asset.moving_links(joint), frame)) for frame in range(len(values))]
    return [moved @ m[:3, :3].T + m[:3, 3] for m in motion]


def _closedness(moving: FloatArray, static_low: FloatArray, static_high: FloatArray) -> tuple[float, float]:
    """(protrusion, box volume) of a configuration: lower = more closed."""
    outside = np.maximum(static_low - moving, 0.0) + np.maximum(moving - static_high, 0.0)
    protrusion = float(np.linalg.norm(outside, axis=1).mean())
    low, high = np.minimum(moving.min(axis=0), static_low), np.maximum(moving.max(axis=0), static_high)
    volume = float(np.prod(np.maximum(high - low, 1e-9)))
    return protrusion, volume


def _nearest_face_normal(point: FloatArray, box_low: FloatArray, box_high: FloatArray) -> FloatArray:
    distances = np.concatenate([point - box_low, box_high - point])
    index = int(np.argmin(np.abs(distances)))
    normal = np.zeros(3)
    normal[index % 3] = -1.0 if index < 3 else 1.0
    return normal


def _radius(asset: ArticulatedAsset, points: dict[str, FloatArray], joint: str, poses: dict[str, FloatArray]) -> float:
    spec = asset.joints[joint]
    child_points = _posed(points, poses, [spec.child])
    if child_points.shape[0] == 0:
        return 0.0
    pose = poses[spec.parent][0] @ spec.origin
    axis = pose[:3, :3] @ spec.axis
    offset = child_points - pose[:3, 3]
    radial = offset - np.outer(offset @ axis, axis)
    return float(np.linalg.norm(radial, axis=1).max())


def _tip(moved: FloatArray, pivot: FloatArray, axis: FloatArray, fallback: FloatArray) -> FloatArray:
    if moved.shape[0] == 0:
        return fallback
    offset = moved - pivot
    radial = offset - np.outer(offset @ axis, axis)
    return moved[int(np.argmax(np.linalg.norm(radial, axis=1)))]


def _joint_geometry(asset: ArticulatedAsset, joint: str, points: dict[str, FloatArray], rest: dict[str, FloatArray],
                    laid_out: RestPoints) -> JointGeometry:
    spec = asset.joints[joint]
    moving = asset.moving_links(joint)
    static = laid_out.box_without(spec.child)
    moved = _bounded(laid_out.below(spec.child))
    frame = rest[spec.parent][0] @ spec.origin
    axis_world = frame[:3, :3] @ spec.axis
    centroid = moved.mean(axis=0) if moved.shape[0] else frame[:3, 3]
    category = link_kind(asset, spec.child)
    closed = opened = press = up = down = None
    press_outward = False
    face = np.zeros(3)
    size = float(np.linalg.norm(moved.max(axis=0) - moved.min(axis=0))) if moved.shape[0] else 0.0
    if static is not None:
        face = _nearest_face_normal(centroid, *static)
    if spec.bounded and spec.lower is not None and spec.upper is not None and spec.upper > spec.lower:
        values = np.array([spec.lower, spec.upper])
        heights, scores, depth = [], [], []
        for posed in _moved_at(asset, joint, values, rest, points, moved):
            if posed.shape[0] == 0 or static is None:
                break
            protrusion, volume = _closedness(posed, *static)
            scores.append((protrusion, volume))
            heights.append(float(posed[:, 2].mean()))
            depth.append(float((posed.mean(axis=0) - centroid) @ face))
        if static is not None and len(scores) == 2:
            diag = max(float(np.linalg.norm(static[1] - static[0])), 1e-9)
            base_volume = float(np.prod(np.maximum(static[1] - static[0], 1e-9)))
            score = [p / diag + (v / base_volume - 1.0) for p, v in scores]
            if abs(score[0] - score[1]) > OPEN_CLOSED_MIN_GAP:
                closed_index = int(np.argmin(score))
                closed, opened = float(values[closed_index]), float(values[1 - closed_index])
            up, down = float(values[int(np.argmax(heights))]), float(values[int(np.argmin(heights))])
            if abs(heights[0] - heights[1]) < 1e-6:
                up = down = None
            if spec.type == "revolute" and spec.upper - spec.lower > WIDE_SWING_RAD:
                up = _highest(asset, joint, np.linspace(spec.lower, spec.upper, 25), rest, points, moved)  # upright, over the top
            press = float(values[int(np.argmin(depth))]) if abs(depth[0] - depth[1]) > 1e-9 else None
            if press is not None and abs(press - spec.rest) < 1e-9 and category is not None and info(category).press == "into_face" and (
                    spec.type == "prismatic"):
                press, press_outward = float(values[int(np.argmax(depth))]), True  # its only travel leads out of its face
    home_centroid, home_face = centroid, face
    if closed is not None and static is not None:
        home = _moved_at(asset, joint, np.array([closed]), rest, points, moved)[0]
        home_centroid = home.mean(axis=0)
        home_face = _nearest_face_normal(home_centroid, *static)
    return JointGeometry(
        joint=joint,
        type=spec.type,
        child=spec.child,
        category=category,
        moving_links=moving,
        axis_world=axis_world,
        pivot_world=frame[:3, 3],
        lower=spec.lower,
        upper=spec.upper,
        rest=spec.rest,
        centroid=centroid,
        home_centroid=home_centroid,
        home_face=home_face,
        closed_value=closed,
        open_value=opened,
        press_value=press,
        press_outward=press_outward,
        up_value=up,
        down_value=down,
        face_normal=face,
        radius=_radius(asset, points, joint, rest),
        size=size,
        tip=_tip(moved, frame[:3, 3], axis_world, centroid),
    )


def _latches_follow_hosts(asset: ArticulatedAsset, joints: dict[str, JointGeometry]) -> dict[str, JointGeometry]:
    """A latch whose shape does not say which end is shut was modelled in the state of the door or lid it holds:
    with its host modelled open it rests unlatched, with its host modelled shut it rests latched."""
    hosts = [g for g in joints.values() if g.category in HINGED_KINDS and g.closed_value is not None]
    out = dict(joints)
    for name, latch in joints.items():
        kind = latch.category
        if kind is None or not info(kind).latches_host or latch.closed_value is not None or latch.lower is None or latch.upper is None:
            continue
        mine = [h for h in hosts if latch.child in asset.descendants(h.child)] or (hosts if len(hosts) == 1 else [])
        if len(mine) != 1:
            continue
        host = mine[0]
        other = latch.upper if abs(latch.rest - latch.lower) <= abs(latch.rest - latch.upper) else latch.lower
        host_open = abs(host.rest - (host.closed_value or 0.0)) > 1e-3
        closed, opened = (other, latch.rest) if host_open else (latch.rest, other)
        out[name] = replace(latch, closed_value=closed, open_value=opened)
    return out


def _resting_open(joints: dict[str, JointGeometry]) -> dict[str, float]:
    """Doors, lids and drawers resting away from their closed end: joint -> its closed value."""
    return {j: g.closed_value for j, g in joints.items() if g.closed_value is not None and abs(g.closed_value - g.rest) > 1e-9 and (
        g.category is not None and info(g.category).openable)}


def _shut_poses(asset: ArticulatedAsset, shut: dict[str, float]) -> dict[str, FloatArray]:
    """Every link's pose with the parts of ``shut`` (joint -> closed value) at their closed ends, the rest at rest."""
    return link_poses(asset, {j: np.array([v]) for j, v in shut.items()}, frames=1)


def _shut_layout(asset: ArticulatedAsset, shut: dict[str, float], points: dict[str, FloatArray]) -> RestPoints:
    """The object laid out as :func:`_shut_poses` poses it."""
    poses = _shut_poses(asset, shut)
    return RestPoints.of(asset, {n: _posed(points, poses, [n]) for n in asset.visual_links if n in points})


def _body_controls_shut(asset: ArticulatedAsset, joints: dict[str, JointGeometry], points: dict[str, FloatArray],
                        rest: dict[str, FloatArray]) -> dict[str, JointGeometry]:
    """A control on the body (a microwave's door-release button) is read against the body with its doors shut: a door
    resting ajar sticks out past the face the button sits on and would turn its press the wrong way."""
    shut = _resting_open(joints)
    if not shut:
        return joints
    carried = {link for j in shut for link in asset.descendants(joints[j].child)}
    body = [j for j, g in joints.items() if g.child not in carried and g.category is not None and info(g.category).control and not (
        info(g.category).latches_host)]
    if not body:
        return joints
    layout = _shut_layout(asset, shut, points)
    return {**joints, **{j: _joint_geometry(asset, j, points, rest, layout) for j in body}}


def _faces_shut(asset: ArticulatedAsset, joints: dict[str, JointGeometry], points: dict[str, FloatArray]) -> dict[str, JointGeometry]:
    """The face a door closes on, read against the body with the other doors shut: a fridge's two doors resting ajar
    stick out past its front and would each turn the other's face (and so the object's front) sideways."""
    shut = _resting_open(joints)
    if len(shut) < 2:
        return joints
    layout = _shut_layout(asset, shut, points)
    out = dict(joints)
    for name in shut:
        static = layout.box_without(joints[name].child)
        if static is not None:
            out[name] = replace(joints[name], home_face=_nearest_face_normal(joints[name].home_centroid, *static))
    return out


def _closed_layout(asset: ArticulatedAsset, joints: dict[str, JointGeometry], points: dict[str, FloatArray]) -> dict[str, JointGeometry]:
    """Where a part sits is where it sits with the object shut: a knob on a safe door that rests open is placed with the
    door closed (the viewer's left knob stays the left one). Only parts carried by a door, lid or drawer that rests away
    from its closed end change; every other part's closed-state centre is already right."""
    shut = _resting_open(joints)
    carried = {link for j in shut for link in asset.descendants(joints[j].child) if link != joints[j].child}
    riders = [name for name, g in joints.items() if g.child in carried]
    if not riders:
        return joints
    poses = _shut_poses(asset, shut)
    out = dict(joints)
    for name in riders:
        placed = _bounded(_posed(points, poses, joints[name].moving_links))
        if placed.shape[0]:
            out[name] = replace(joints[name], home_centroid=placed.mean(axis=0))
    return out


@lru_cache(maxsize=64)
def _cached(asset: ArticulatedAsset) -> ObjectGeometry:
    points = _local_points(asset)
    rest = link_poses(asset, {}, frames=1)
    laid_out = RestPoints.of(asset, {n: _posed(points, rest, [n]) for n in asset.visual_links if n in points})
    low, high = laid_out.box()
    center = (low + high) / 2.0
    first = {j: _joint_geometry(asset, j, points, rest, laid_out) for j in asset.controllable_joints}
    joints = _closed_layout(asset, _faces_shut(asset, _latches_follow_hosts(asset, _body_controls_shut(asset, first, points, rest)), points), points)
    vote, cue = front_votes(joints, center, asset, points, rest, object_category(asset))
    front = front_of(vote)
    right = np.cross(-front, UP)
    return ObjectGeometry(
        center=center,
        extents=high - low,
        diag=float(np.linalg.norm(high - low)),
        front=front,
        up=UP.copy(),
        right=right / max(float(np.linalg.norm(right)), 1e-9),
        joints=joints,
        category=object_category(asset),
        front_by_convention=by_convention(vote),
        front_cue=cue,
    )


def analyse(asset: ArticulatedAsset) -> ObjectGeometry:
    """Geometric summary of ``asset`` (cached per asset object)."""
    return _cached(asset)


def object_category(asset: ArticulatedAsset) -> str | None:
    """The object's kind from its name or body label ("safe_101593" -> "safe")."""
    name = asset.name.lower()
    stem = "".join(c if c.isalpha() else " " for c in name).split()
    if stem:
        return stem[0] if stem[0] not in ("mobility", "robot", "asset", "model") else None
    for link in asset.links.values():
        label = (link.semantics.label or "").lower()
        if label.endswith("_body") and kind_of_label(label) is None:
            return label[: -len("_body")]
    return None
