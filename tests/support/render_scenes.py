"""Primitive scenes and trajectories for the renderer tests (``tests/engine/render``)."""

from __future__ import annotations

import math

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from support.primitive_assets import box, joint, link, robot

DOOR_HINGE = (0.52, 0.4, 0.0)
"""The door's hinge line (world, vertical): the door panel sits just in front of the +X face of the body."""


def door_scene_urdf() -> str:
    """``body`` unit cube at the origin; ``door`` 0.04 x 0.8 x 0.8 panel on a +Z hinge at the body's +X face (q > 0 swings it outward);
    ``core`` a 0.2 cube hidden inside the body (fixed)."""
    return robot(
        link("body", box((1.0, 1.0, 1.0))),
        link("core", box((0.2, 0.2, 0.2))),
        link("door", box((0.04, 0.8, 0.8), xyz=(0.02, -0.4, 0.0))),
        joint("core_fixed", "fixed", "body", "core", axis=None),
        joint(
            "hinge", "revolute", "body", "door", xyz=DOOR_HINGE, axis=(0.0, 0.0, 1.0), limit=(-math.pi / 2, math.pi / 2)
        ),
        name="door_scene",
    )


def joint_sweep(
    asset: ArticulatedAsset, joint_name: str, start: float, end: float, frames: int = 31, fps: int = 30
) -> Trajectory:
    """A trajectory moving ``joint_name`` linearly from ``start`` to ``end``; other joints at rest."""
    names = asset.movable_joints
    q = np.tile(asset.rest_vector(), (frames, 1))
    q[:, names.index(joint_name)] = np.linspace(start, end, frames)
    return Trajectory(
        fps=fps,
        times=np.arange(frames, dtype=np.float64) / fps,
        joint_names=names,
        q=q,
        base_translation=np.zeros((frames, 3)),
        base_rotation_xyzw=np.tile([0.0, 0.0, 0.0, 1.0], (frames, 1)),
    )
