"""``joint_trajectory.json``: the motion as ROS ``trajectory_msgs`` message fields.

The top level holds the fields of ``trajectory_msgs/msg/JointTrajectory`` (``header``,
``joint_names``, ``points[]`` with ``positions``, ``velocities``, ``accelerations``,
``effort`` and ``time_from_start`` as ``{sec, nanosec}``) for the joints that move
(mimic joints are left to the URDF, as ``robot_state_publisher`` does). The key
``base_pose_track`` holds the fields of ``trajectory_msgs/msg/MultiDOFJointTrajectory``
for one virtual joint ``base`` that places the URDF root link in the ``world`` frame
(``transforms[0]``: translation in metres, rotation as a unit quaternion x, y, z, w;
``velocities[0]``: linear m/s and angular rad/s). A ROS tool fills the messages from
these dictionaries field by field (see ``tests/engine/export/test_ros.py``).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.export.track import ExportTrack
from app.engine.files import atomic_write_text
from app.engine.types import FloatArray

ROS_FILE = "joint_trajectory.json"
BASE_JOINT = "base"
WORLD_FRAME = "world"


def _stamp(sec: int, nanosec: int) -> dict[str, int]:
    return {"sec": sec, "nanosec": nanosec}


def _angular_velocity(rotation_xyzw: FloatArray, fps: int) -> FloatArray:
    """(f, 3) world angular velocity (rad/s) of a quaternion track: the rotation from the previous to
    the next frame (one-sided at the ends) as a rotation vector over its time (exact for constant spin)."""
    q = np.asarray(rotation_xyzw, dtype=np.float64)
    count = q.shape[0]
    if count < 2:
        return np.zeros((count, 3))
    index = np.arange(count)
    before, after = np.maximum(index - 1, 0), np.minimum(index + 1, count - 1)
    a, b = q[after], q[before] * np.array([-1.0, -1.0, -1.0, 1.0])  # after * conj(before)
    vector = a[:, 3:] * b[:, :3] + b[:, 3:] * a[:, :3] + np.cross(a[:, :3], b[:, :3])
    scalar = a[:, 3] * b[:, 3] - np.einsum("ij,ij->i", a[:, :3], b[:, :3])
    flip = np.where(scalar < 0, -1.0, 1.0)
    vector, scalar = vector * flip[:, None], scalar * flip
    length = np.linalg.norm(vector, axis=1)
    angle = 2.0 * np.arctan2(length, scalar)
    axis = np.divide(vector, length[:, None], out=np.zeros_like(vector), where=length[:, None] > 0)
    return np.asarray(axis * (angle * fps / (after - before))[:, None], dtype=np.float64)


def ros_document(track: ExportTrack) -> dict[str, Any]:
    """The ``joint_trajectory.json`` content as plain data (see the module docstring)."""
    stamps = track.time_from_start()
    positions = track.joint_matrix().tolist()
    velocities = track.joint_velocities().tolist()
    points = [
        {"positions": positions[i], "velocities": velocities[i], "accelerations": [], "effort": [], "time_from_start": _stamp(*stamps[i])}
        for i in range(track.frame_count)
    ]
    trajectory = track.trajectory
    translation = np.asarray(trajectory.base_translation, dtype=np.float64)
    rotation = np.asarray(trajectory.base_rotation_xyzw, dtype=np.float64)
    linear: list[list[float]] = (np.gradient(translation, 1.0 / track.fps, axis=0) if track.frame_count > 1 else np.zeros_like(translation)).tolist()
    angular: list[list[float]] = _angular_velocity(rotation, track.fps).tolist()
    base_points = [
        {
            "transforms": [{"translation": dict(zip("xyz", translation[i].tolist(), strict=True)),
                            "rotation": dict(zip("xyzw", rotation[i].tolist(), strict=True))}],
            "velocities": [{"linear": dict(zip("xyz", linear[i], strict=True)), "angular": dict(zip("xyz", angular[i], strict=True))}],
            "accelerations": [],
            "time_from_start": _stamp(*stamps[i]),
        }
        for i in range(track.frame_count)
    ]
    return {
        "header": {"stamp": _stamp(0, 0), "frame_id": track.asset.root_link},
        "joint_names": list(track.moving_joints),
        "points": points,
        "base_pose_track": {
            "header": {"stamp": _stamp(0, 0), "frame_id": WORLD_FRAME},
            "joint_names": [BASE_JOINT],
            "points": base_points,
        },
    }


def write_ros(track: ExportTrack, out_dir: Path) -> str:
    """Write ``joint_trajectory.json`` into ``out_dir``; returns its file name."""
    atomic_write_text(out_dir / ROS_FILE, json.dumps(ros_document(track), separators=(",", ":")) + "\n")
    return ROS_FILE
