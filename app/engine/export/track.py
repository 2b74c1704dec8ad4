"""What every motion exporter reads: one trajectory on one asset, sampled per frame.

Built once per run and shared by the ROS, CSV, NPZ, USD and MJCF writers, so they all
describe exactly the same motion. Frames: world = the URDF root frame (+Z up, metres);
a link's *local* transform maps its frame to its parent link's frame
(``joint.origin @ motion(q)``); the root link's local transform is the base pose.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.engine.asset.kinematics import base_transforms, joint_motion, resolve_joint_values
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.types import FloatArray, Transforms

MOTION_EPS = 1e-12
"""A joint or transform whose values differ by less than this over the run does not move."""
NANOSECONDS = 1_000_000_000


@dataclass(frozen=True, eq=False)
class ExportTrack:
    """A trajectory resolved against its asset.

    Attributes
    ----------
    asset, trajectory : the inputs
    moving_joints : controllable (non-mimic) joints whose value changes, in ``asset.joint_order``
    values : {movable joint: (f,) value}, mimic joints resolved from their leader
    local : {link: (f, 4, 4)} link frame -> parent link frame; root link: base pose in the world
    world : {link: (f, 4, 4)} link frame -> world
    moving_links : links whose ``local`` transform changes over the run
    """

    asset: ArticulatedAsset
    trajectory: Trajectory
    moving_joints: tuple[str, ...]
    values: dict[str, FloatArray]
    local: dict[str, Transforms]
    world: dict[str, Transforms]
    moving_links: frozenset[str]

    @property
    def fps(self) -> int:
        return self.trajectory.fps

    @property
    def frame_count(self) -> int:
        return self.trajectory.frame_count

    @property
    def base_moves(self) -> bool:
        return self.asset.root_link in self.moving_links

    def joint_matrix(self) -> FloatArray:
        """(f, m) values of ``moving_joints`` (radians or metres)."""
        count = self.frame_count
        if not self.moving_joints:
            return np.zeros((count, 0))
        return np.column_stack([self.values[name] for name in self.moving_joints])

    def joint_velocities(self) -> FloatArray:
        """(f, m) finite-difference velocities of ``moving_joints`` (rad/s or m/s; central inside, one-sided at the ends)."""
        matrix = self.joint_matrix()
        if self.frame_count < 2 or matrix.shape[1] == 0:
            return np.zeros_like(matrix)
        return np.asarray(np.gradient(matrix, 1.0 / self.fps, axis=0), dtype=np.float64)

    def time_from_start(self) -> list[tuple[int, int]]:
        """(sec, nanosec) of every frame, rounded to the nanosecond from ``i / fps`` in integers."""
        stamps = []
        for index in range(self.frame_count):
            total = (2 * index * NANOSECONDS + self.fps) // (2 * self.fps)
            stamps.append((total // NANOSECONDS, total % NANOSECONDS))
        return stamps


def build_track(asset: ArticulatedAsset, trajectory: Trajectory) -> ExportTrack:
    """Resolve ``trajectory`` on ``asset`` (forward kinematics of every frame, vectorised)."""
    count = trajectory.frame_count
    given = {name: trajectory.q[:, i] for i, name in enumerate(trajectory.joint_names) if name in asset.joints}
    values = resolve_joint_values(asset, given, count)
    base = base_transforms(np.asarray(trajectory.base_translation, dtype=np.float64), np.asarray(trajectory.base_rotation_xyzw, dtype=np.float64))
    local: dict[str, Transforms] = {asset.root_link: base}
    world: dict[str, Transforms] = {asset.root_link: base}
    for name in asset.joint_order:
        joint = asset.joints[name]
        if joint.movable:
            local[joint.child] = joint.origin[None] @ joint_motion(joint, values[name])
        else:
            local[joint.child] = np.broadcast_to(joint.origin, (count, 4, 4))
        world[joint.child] = world[joint.parent] @ local[joint.child]
    moving = frozenset(link for link, stack in local.items() if _changes(stack))
    moving_joints = tuple(
        name for name in asset.controllable_joints if name in values and _changes(values[name])
    )
    return ExportTrack(asset=asset, trajectory=trajectory, moving_joints=moving_joints, values=values, local=local, world=world,
                       moving_links=moving)


def _changes(stack: FloatArray) -> bool:
    if stack.shape[0] < 2:
        return False
    return bool(np.abs(stack - stack[:1]).max(initial=0.0) > MOTION_EPS)
