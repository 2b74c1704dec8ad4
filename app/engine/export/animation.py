"""Per-node translation/rotation tracks of a trajectory and their glTF animation.

A link node's local transform is ``joint.origin @ motion(q)`` (joint frame in the
parent link frame); the root link's node is the identity under ``artimo_root``, whose
transform is ``Z_UP_TO_Y_UP @ base(t)``. Tracks are sampled at the trajectory's frame
times and written as LINEAR samplers, one per moving path.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from app.engine.asset.kinematics import joint_motion, resolve_joint_values
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import ExportError
from app.engine.execute.trajectory import Trajectory
from app.engine.export.gltf_builder import GltfBuilder
from app.engine.export.rotations import Z_UP_TO_Y_UP, continuous_signs, matrix_to_quaternion, quaternion_to_matrix
from app.engine.types import FloatArray

logger = logging.getLogger(__name__)

MOTION_EPS = 1e-9
"""A path is animated when some key differs from frame 0 by more than this (m or quaternion units)."""
ANIMATION_NAME = "action"


@dataclass(frozen=True, eq=False)
class NodeTrack:
    """Local TRS of one node per frame.

    Attributes
    ----------
    translation : (f, 3) float, metres, parent node frame
    rotation : (f, 4) float, unit quaternions x, y, z, w with sign continuity
    """

    translation: FloatArray
    rotation: FloatArray

    @property
    def moves_translation(self) -> bool:
        return bool(np.abs(self.translation - self.translation[:1]).max(initial=0.0) > MOTION_EPS)

    @property
    def moves_rotation(self) -> bool:
        return bool(np.abs(self.rotation - self.rotation[:1]).max(initial=0.0) > MOTION_EPS)


def track_of(matrices: FloatArray, count: int) -> NodeTrack:
    """Track of (f, 4, 4) or (1, 4, 4) rigid transforms (a single one is held for ``count`` frames)."""
    rotation = continuous_signs(matrix_to_quaternion(matrices[:, :3, :3]))
    translation = np.array(matrices[:, :3, 3], dtype=np.float64)
    if matrices.shape[0] == 1 and count != 1:
        rotation = np.repeat(rotation, count, axis=0)
        translation = np.repeat(translation, count, axis=0)
    return NodeTrack(translation=translation, rotation=rotation)


def link_tracks(asset: ArticulatedAsset, trajectory: Trajectory) -> dict[str, NodeTrack]:
    """Local tracks of every link node (root link: identity), keyed by link name."""
    count = trajectory.frame_count
    values = resolve_joint_values(asset, trajectory.joint_values(), count)
    tracks = {asset.root_link: track_of(np.eye(4)[None], count)}
    for name in asset.joint_order:
        joint = asset.joints[name]
        if not joint.movable:
            tracks[joint.child] = track_of(joint.origin[None], count)
            continue
        q = values[name]
        if joint.type != "prismatic" and count > 1 and float(np.abs(np.diff(q)).max()) >= math.pi:
            logger.warning("joint %s turns by pi or more between two frames; LINEAR keys take the shorter way", name)
        tracks[joint.child] = track_of(joint.origin[None] @ joint_motion(joint, q), count)
    return tracks


def root_track(trajectory: Trajectory) -> NodeTrack:
    """Track of ``artimo_root``: Y-up conversion composed with the base pose."""
    turn = Z_UP_TO_Y_UP[:3, :3]
    count = trajectory.frame_count
    matrices = np.zeros((count, 4, 4))
    matrices[:, :3, :3] = turn[None] @ quaternion_to_matrix(trajectory.base_rotation_xyzw)
    matrices[:, :3, 3] = trajectory.base_translation @ turn.T
    matrices[:, 3, 3] = 1.0
    return track_of(matrices, count)


def check_trajectory(asset: ArticulatedAsset, trajectory: Trajectory) -> None:
    """Reject trajectories the GLB cannot represent.

    Raises
    ------
    ExportError
        No frames, times not finite / negative / strictly increasing (in float32),
        arrays of the wrong shape, non-finite values, or joints the asset lacks.
    """
    count = trajectory.frame_count
    if count == 0:
        raise ExportError("the trajectory has no frames")
    times = np.asarray(trajectory.times, dtype=np.float64)
    if not np.all(np.isfinite(times)) or times[0] < 0.0:
        raise ExportError("trajectory times must be finite and non-negative")
    if count > 1 and not np.all(np.diff(times.astype(np.float32)) > 0):
        raise ExportError("trajectory times must be strictly increasing (as float32)")
    unknown = [n for n in trajectory.joint_names if n not in asset.joints or not asset.joints[n].movable]
    if unknown:
        raise ExportError(f"trajectory names joints that are not movable joints of {asset.name}: {', '.join(unknown)}")
    shapes = {
        "q": (trajectory.q, (count, len(trajectory.joint_names))),
        "base_translation": (trajectory.base_translation, (count, 3)),
        "base_rotation_xyzw": (trajectory.base_rotation_xyzw, (count, 4)),
    }
    for label, (array, shape) in shapes.items():
        if array.shape != shape:
            raise ExportError(f"trajectory {label} has shape {array.shape}, expected {shape}")
        if not np.all(np.isfinite(array)):
            raise ExportError(f"trajectory {label} holds a non-finite value")
    if np.any(np.linalg.norm(trajectory.base_rotation_xyzw, axis=1) < 1e-9):
        raise ExportError("trajectory base_rotation_xyzw holds a zero quaternion")


def add_animation(builder: GltfBuilder, times: FloatArray, targets: list[tuple[int, NodeTrack]]) -> dict[str, Any]:
    """Write the ``action`` animation: one shared time accessor, a LINEAR sampler per moving path.

    ``targets`` is (node index, track) in node order. When nothing moves, the first
    target's rotation is written as a constant channel so the animation stays valid
    (glTF requires at least one channel) and still spans the trajectory's duration.
    """
    time_accessor = builder.add_accessor(np.asarray(times, dtype=np.float32), bounds=True)
    samplers: list[dict[str, Any]] = []
    channels: list[dict[str, Any]] = []

    def add(node: int, path: str, values: FloatArray) -> None:
        output = builder.add_accessor(np.ascontiguousarray(values, dtype=np.float32))
        samplers.append({"input": time_accessor, "interpolation": "LINEAR", "output": output})
        channels.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": path}})

    for node, track in targets:
        if track.moves_translation:
            add(node, "translation", track.translation)
        if track.moves_rotation:
            add(node, "rotation", normalised(track.rotation))
    if not channels:
        node, track = targets[0]
        add(node, "rotation", normalised(track.rotation))
    return {"name": ANIMATION_NAME, "channels": channels, "samplers": samplers}


def normalised(quaternions: FloatArray) -> FloatArray:
    """(k, 4) quaternions scaled to unit length."""
    result: FloatArray = quaternions / np.linalg.norm(quaternions, axis=1, keepdims=True)
    return result
