"""Forward kinematics against poses computed by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation
from support.primitive_assets import box, joint, link, robot, write_asset

from app.engine.asset.kinematics import (
    axis_angle_matrices,
    base_transforms,
    link_poses,
    quaternion_matrices,
    rest_poses,
)
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset

SMALL = box((0.1, 0.1, 0.1))


@pytest.fixture(scope="module")
def chain(tmp_path_factory: pytest.TempPathFactory) -> ArticulatedAsset:
    """base -swing (revolute z at (1,0,0))-> arm -slide (prismatic x at (0,1,0), yaw 90°)-> slider -spin (continuous y at (0,0,.5))-> wheel."""
    urdf = robot(
        link("base", SMALL),
        link("arm", SMALL),
        link("slider", SMALL),
        link("wheel", SMALL),
        joint("swing", "revolute", "base", "arm", xyz=(1.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), limit=(-math.pi, math.pi)),
        joint(
            "slide",
            "prismatic",
            "arm",
            "slider",
            xyz=(0.0, 1.0, 0.0),
            rpy=(0.0, 0.0, math.pi / 2),
            axis=(1.0, 0.0, 0.0),
            limit=(-1.0, 1.0),
        ),
        joint("spin", "continuous", "slider", "wheel", xyz=(0.0, 0.0, 0.5), axis=(0.0, 1.0, 0.0)),
    )
    return load_asset(write_asset(tmp_path_factory.mktemp("fk") / "chain", urdf))


def rz(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def one(asset: ArticulatedAsset, **values: float) -> dict[str, np.ndarray]:
    return {name: pose[0] for name, pose in link_poses(asset, {k: np.array([v]) for k, v in values.items()}).items()}


def test_rest_pose(chain: ArticulatedAsset) -> None:
    poses = rest_poses(chain)
    assert np.allclose(poses["base"], np.eye(4))
    assert np.allclose(poses["arm"][:3, 3], [1, 0, 0]) and np.allclose(poses["arm"][:3, :3], np.eye(3))
    assert np.allclose(poses["slider"][:3, 3], [1, 1, 0]) and np.allclose(poses["slider"][:3, :3], rz(math.pi / 2))
    assert np.allclose(poses["wheel"][:3, 3], [1, 1, 0.5])


def test_revolute(chain: ArticulatedAsset) -> None:
    poses = one(chain, swing=math.pi / 2)
    assert np.allclose(poses["arm"][:3, 3], [1, 0, 0]) and np.allclose(poses["arm"][:3, :3], rz(math.pi / 2))
    # the slider's origin (0, 1, 0) in the arm frame swings to (-1, 0, 0): world (0, 0, 0), facing -x
    assert np.allclose(poses["slider"][:3, 3], [0, 0, 0]) and np.allclose(poses["slider"][:3, :3], rz(math.pi))


def test_prismatic_nested_under_revolute(chain: ArticulatedAsset) -> None:
    poses = one(chain, swing=math.pi / 2, slide=0.3)
    assert np.allclose(poses["slider"][:3, 3], [-0.3, 0, 0])  # local +x is world -x
    poses = one(chain, slide=0.3)
    assert np.allclose(poses["slider"][:3, 3], [1, 1.3, 0])  # local +x is world +y at rest


def test_continuous_nested_three_deep(chain: ArticulatedAsset) -> None:
    poses = one(chain, swing=math.pi / 2, slide=0.3, spin=math.pi / 2)
    wheel = poses["wheel"]
    assert np.allclose(wheel[:3, 3], [-0.3, 0, 0.5])
    # the wheel's local +x: turned onto -z by the spin about +y, then unchanged by the 180° yaw
    assert np.allclose(wheel[:3, :3] @ [1, 0, 0], [0, 0, -1])
    assert np.allclose(wheel[:3, :3] @ [0, 1, 0], [0, -1, 0])


def test_continuous_winds_without_wrapping_issues(chain: ArticulatedAsset) -> None:
    a = one(chain, spin=0.1)["wheel"]
    b = one(chain, spin=0.1 + 4 * math.pi)["wheel"]
    assert np.allclose(a, b)


def test_vectorised_over_frames(chain: ArticulatedAsset) -> None:
    swing = np.array([0.0, math.pi / 2, math.pi])
    poses = link_poses(chain, {"swing": swing})
    assert poses["slider"].shape == (3, 4, 4)
    expected = np.stack([1 - np.sin(swing), np.cos(swing), np.zeros(3)], axis=1)
    assert np.allclose(poses["slider"][:, :3, 3], expected)
    for i, q in enumerate(swing):
        assert np.allclose(poses["arm"][i, :3, :3], rz(float(q)))


def test_base_pose_moves_every_link(chain: ArticulatedAsset) -> None:
    quarter = [0.0, 0.0, math.sin(math.pi / 4), math.cos(math.pi / 4)]  # 90° about +z
    base = base_transforms(np.array([[0.0, 0.0, 1.0]]), np.array([quarter]))
    poses = link_poses(chain, {}, base=base)
    assert np.allclose(poses["base"][0], base[0])
    assert np.allclose(poses["arm"][0, :3, 3], [0, 1, 1])  # (1, 0, 0) turned 90° then lifted 1 m
    assert np.allclose(poses["slider"][0, :3, 3], [-1, 1, 1])
    assert np.allclose(poses["arm"][0, :3, :3], rz(math.pi / 2))


def test_axis_angle_and_quaternion_match_scipy() -> None:
    generator = np.random.default_rng(7)
    axis = generator.normal(size=3)
    axis /= np.linalg.norm(axis)
    angles = np.linspace(-7.0, 7.0, 9)
    expected = Rotation.from_rotvec(angles[:, None] * axis[None]).as_matrix()
    assert np.allclose(axis_angle_matrices(axis, angles), expected)
    quaternions = Rotation.from_rotvec(angles[:, None] * axis[None]).as_quat()  # x, y, z, w
    assert np.allclose(quaternion_matrices(quaternions), expected)
