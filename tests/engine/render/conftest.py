"""Fixtures of the renderer tests: tiny primitive scenes in tmp folders and a few PartNet assets.

Every test here renders for real through EGL (Mesa llvmpipe on CPU); nothing skips.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from support.primitive_assets import box, joint, link, robot, write_asset

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory

DOOR_HINGE = (0.52, -0.4, 0.0)
"""The door's hinge line (world, vertical): the door panel sits just in front of the +X face of the body."""


def door_scene_urdf() -> str:
    """``body`` unit cube at the origin; ``door`` 0.04 x 0.8 x 0.8 panel on a +Z hinge at the body's +X face;
    ``core`` a 0.2 cube hidden inside the body (fixed)."""
    return robot(
        link("body", box((1.0, 1.0, 1.0))),
        link("core", box((0.2, 0.2, 0.2))),
        link("door", box((0.04, 0.8, 0.8), xyz=(0.02, 0.4, 0.0))),
        joint("core_fixed", "fixed", "body", "core", axis=None),
        joint("hinge", "revolute", "body", "door", xyz=DOOR_HINGE, axis=(0.0, 0.0, 1.0), limit=(-math.pi / 2, math.pi / 2)),
        name="door_scene",
    )


@pytest.fixture(scope="module")
def door_scene(tmp_path_factory: pytest.TempPathFactory) -> ArticulatedAsset:
    return load_asset(write_asset(tmp_path_factory.mktemp("render") / "door_scene", door_scene_urdf()))


@pytest.fixture(scope="module")
def unit_box(tmp_path_factory: pytest.TempPathFactory) -> ArticulatedAsset:
    """One link: a 1 m cube centred at the origin."""
    return load_asset(write_asset(tmp_path_factory.mktemp("render") / "unit_box", robot(link("cube", box((1.0, 1.0, 1.0))), name="unit_box")))


_PARTNET_CACHE: dict[str, ArticulatedAsset] = {}


@pytest.fixture(scope="session")
def load_partnet(partnet: Path):  # type: ignore[no-untyped-def]
    """``load_partnet(name)`` -> the loaded PartNet asset (cached for the session)."""

    def load(name: str) -> ArticulatedAsset:
        if name not in _PARTNET_CACHE:
            _PARTNET_CACHE[name] = load_asset(partnet / name)
        return _PARTNET_CACHE[name]

    return load


def joint_sweep(asset: ArticulatedAsset, joint_name: str, start: float, end: float, frames: int = 31, fps: int = 30) -> Trajectory:
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
