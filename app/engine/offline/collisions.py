"""Do parts pass through each other along a trajectory?

Each link is approximated by the convex hulls of its mesh parts (the largest ones),
moving links by sample points. A pair interpenetrates at a frame when more of the moving
link's points sit deeper than a margin inside the other link's hulls than at rest — the
comparison with rest tolerates assets whose parts already overlap when closed.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy.spatial import ConvexHull, QhullError

from app.engine.asset.kinematics import base_transforms, link_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.types import FloatArray

MAX_HULLS_PER_LINK = 48
POINTS_PER_LINK = 240
MAX_FRAMES = 24
DEPTH_MARGIN_FRACTION = 0.02
"""Points must be this fraction of the other link's size inside a hull to count ..."""
THIN_MARGIN_FRACTION = 0.2
"""... or, for a thin part (a door slab), this fraction of its thinnest extent."""
NEW_PENETRATION = 0.03
"""Fraction of a link's points newly inside another link that counts as a collision."""
BLOCKING_PENETRATION = 0.02
"""The same for a deliberate sweep through a closed part (:func:`blocking_joints`): a tray sliding out through its
closed door leaves only the strip inside the door slab, minus the thin-part margin (2.8-3.1% of its points on
oven_7179's top tray, counted with 240 to 4000 samples), so the collision threshold would decide it by sampling
noise."""


@dataclass(frozen=True)
class Collision:
    moving_link: str
    other_link: str
    frame: int
    time_s: float
    fraction: float


@dataclass(frozen=True, eq=False)
class _LinkShape:
    hulls: tuple[tuple[FloatArray, FloatArray, FloatArray, float], ...]
    """(equations (f, 4), box low (3,), box high (3,), depth margin) per hull, link frame."""
    points: FloatArray
    size: float

    @property
    def hull_box(self) -> FloatArray:
        """(2, 3) low and high corner of every hull's box, link frame (no point outside it counts as inside)."""
        return np.array([np.min([h[1] for h in self.hulls], axis=0), np.max([h[2] for h in self.hulls], axis=0)])

    @property
    def point_box(self) -> FloatArray:
        return np.array([self.points.min(axis=0), self.points.max(axis=0)])


_CORNERS = np.array([[i, j, k] for i in (0, 1) for j in (0, 1) for k in (0, 1)], dtype=np.float64)


def _swept_box(box: FloatArray, poses: FloatArray) -> FloatArray:
    """(2, 3) world box holding the link-frame ``box`` at every pose of ``poses`` (f, 4, 4): the corners moved, so a
    box that holds the moved box. Two parts whose swept boxes are apart never overlap at any of those frames."""
    corners = box[0] + _CORNERS * (box[1] - box[0])
    world = np.einsum("fij,cj->fci", poses[:, :3, :3], corners) + poses[:, None, :3, 3]
    return np.array([world.min(axis=(0, 1)), world.max(axis=(0, 1))])


def _hull(vertices: FloatArray, link_size: float) -> tuple[FloatArray, FloatArray, FloatArray, float] | None:
    if vertices.shape[0] < 4 or np.linalg.matrix_rank(vertices - vertices.mean(axis=0), tol=1e-9) < 3:
        return None
    try:
        hull = ConvexHull(vertices)
    except QhullError:
        return None
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    margin = min(DEPTH_MARGIN_FRACTION * link_size, THIN_MARGIN_FRACTION * float(np.min(high - low)))
    return hull.equations, low, high, margin


def _surface_points(asset: ArticulatedAsset, link: str) -> FloatArray:
    """(n, 3) area-weighted surface samples of a link, seeded by its triangles' areas: deterministic, and the same
    points of the shape whatever the link is called and wherever its frame is."""
    parts = asset.links[link].parts
    triangles = np.concatenate([p.vertices[p.faces] for p in parts])
    areas = 0.5 * np.linalg.norm(np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]), axis=1)
    if areas.sum() <= 0:
        return asset.links[link].vertices()[:POINTS_PER_LINK]
    seed = int.from_bytes(hashlib.sha256(np.round(areas, 8).tobytes()).digest()[:8], "little")  # areas: the same in any frame
    generator = np.random.default_rng(seed)
    chosen = generator.choice(triangles.shape[0], size=POINTS_PER_LINK, p=areas / areas.sum())
    u, v = generator.random(POINTS_PER_LINK), generator.random(POINTS_PER_LINK)
    flip = u + v > 1.0
    u[flip], v[flip] = 1.0 - u[flip], 1.0 - v[flip]
    corner = triangles[chosen]
    return corner[:, 0] + u[:, None] * (corner[:, 1] - corner[:, 0]) + v[:, None] * (corner[:, 2] - corner[:, 0])


@lru_cache(maxsize=32)
def _shapes(asset: ArticulatedAsset) -> dict[str, _LinkShape]:
    shapes = {}
    for name in asset.visual_links:
        parts = sorted(asset.links[name].parts, key=lambda p: -float(np.prod(np.ptp(p.vertices, axis=0) + 1e-9)))
        vertices = asset.links[name].vertices()
        size = float(np.linalg.norm(np.ptp(vertices, axis=0)))
        hulls = tuple(h for h in (_hull(p.vertices, size) for p in parts[:MAX_HULLS_PER_LINK]) if h is not None)
        shapes[name] = _LinkShape(hulls=hulls, points=_surface_points(asset, name), size=size)
    return shapes


def _inside_fraction(points: FloatArray, shape: _LinkShape) -> float:
    """Fraction of ``points`` (other link's frame) deeper than the margin inside any hull."""
    if not shape.hulls or points.shape[0] == 0:
        return 0.0
    inside = np.zeros(points.shape[0], dtype=bool)
    for equations, low, high, margin in shape.hulls:
        near = np.all((points >= low + margin) & (points <= high - margin), axis=1) & ~inside
        if not near.any():
            continue
        distance = points[near] @ equations[:, :3].T + equations[:, 3]
        inside[np.flatnonzero(near)[np.all(distance < -margin, axis=1)]] = True
    return float(inside.mean())


def _neighbours(asset: ArticulatedAsset, a: str, b: str) -> bool:
    """Links joined directly by a joint (they meet at the hinge by design)."""
    joint_a, joint_b = asset.parent_joint(a), asset.parent_joint(b)
    return (joint_a is not None and joint_a.parent == b) or (joint_b is not None and joint_b.parent == a) or (
        joint_a is not None and joint_b is not None and joint_a.parent == joint_b.parent and not (joint_a.movable or joint_b.movable)
    )


def find_collisions(asset: ArticulatedAsset, trajectory: Trajectory, moving: set[str], frames: list[int] | None = None,
                    threshold: float = NEW_PENETRATION) -> list[Collision]:
    """New interpenetrations of ``moving`` links with the rest, worst first (one per pair).

    ``frames`` restricts the check to those frame indices (frame 0, the reference, is always
    added); by default up to ``MAX_FRAMES`` evenly spaced frames are checked. ``threshold``: the
    fraction of a link's points newly inside another that counts.
    """
    shapes = _shapes(asset)
    if frames is None:
        checked = np.unique(np.linspace(0, trajectory.frame_count - 1, min(MAX_FRAMES, trajectory.frame_count)).round().astype(np.int64))
    else:
        checked = np.unique(np.clip(np.array([0, *frames], dtype=np.int64), 0, trajectory.frame_count - 1))
    poses = link_poses(asset, {n: trajectory.joint(n)[checked] for n in trajectory.joint_names}, base_transforms(trajectory.base_translation[checked]))
    solid = [n for n in asset.visual_links if n in shapes and shapes[n].hulls]
    if not solid:
        return []
    hull_boxes = np.array([_swept_box(shapes[n].hull_box, poses[n]) for n in solid])  # (n, 2, 3)
    found: dict[tuple[str, str], Collision] = {}
    for mover in sorted(n for n in moving & set(shapes) if shapes[n].points.shape[0]):
        low, high = _swept_box(shapes[mover].point_box, poses[mover])
        near = np.all(hull_boxes[:, 0] <= high, axis=1) & np.all(hull_boxes[:, 1] >= low, axis=1)
        for other in (solid[k] for k in np.flatnonzero(near)):  # a part whose swept box misses this one's can hold none of its points
            if other == mover or _neighbours(asset, mover, other):
                continue
            relative = np.linalg.inv(poses[other]) @ poses[mover]
            points = shapes[mover].points
            baseline = _inside_fraction(points @ relative[0, :3, :3].T + relative[0, :3, 3], shapes[other])
            for index in range(1, checked.shape[0]):
                local = points @ relative[index, :3, :3].T + relative[index, :3, 3]
                fraction = _inside_fraction(local, shapes[other]) - baseline
                key = (min(mover, other), max(mover, other))
                if fraction > threshold and (key not in found or fraction > found[key].fraction):
                    frame = int(checked[index])
                    found[key] = Collision(mover, other, frame, float(trajectory.times[frame]), round(fraction, 4))
    return sorted(found.values(), key=lambda c: (-c.fraction, c.moving_link, c.other_link))


PATH_SAMPLES = 8


def blocking_joints(asset: ArticulatedAsset, joint: str, target: float, state: dict[str, float]) -> list[str]:
    """Movable joints whose parts (at ``state``) stand in the way of moving ``joint`` to ``target``.

    The joint is swept from its value in ``state`` to ``target`` with everything else
    still; a part of another joint that the sweep newly penetrates blocks it (an oven
    tray behind a closed door).
    """
    names = asset.movable_joints
    start = state.get(joint, asset.joints[joint].rest)
    sweep = np.linspace(start, target, PATH_SAMPLES + 1)
    q = np.array([[state.get(n, asset.joints[n].rest) for n in names]] * sweep.shape[0], dtype=np.float64)
    q[:, names.index(joint)] = sweep
    times = np.arange(sweep.shape[0], dtype=np.float64)
    rotation = np.tile([0.0, 0.0, 0.0, 1.0], (sweep.shape[0], 1))
    path = Trajectory(fps=1, times=times, joint_names=names, q=q, base_translation=np.zeros((sweep.shape[0], 3)), base_rotation_xyzw=rotation)
    moving = set(asset.moving_links(joint))
    owners: dict[str, str] = {}
    for other in asset.movable_joints:
        if other != joint and asset.joints[joint].child not in asset.moving_links(other):
            for link in asset.moving_links(other):
                if link not in moving:
                    owners.setdefault(link, other)
    blockers = []
    for hit in find_collisions(asset, path, moving, threshold=BLOCKING_PENETRATION):
        owner = owners.get(hit.other_link)
        if owner is not None and owner not in blockers:
            blockers.append(owner)
    return blockers
