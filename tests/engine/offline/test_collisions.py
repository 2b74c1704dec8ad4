"""The collision check tests only pairs whose swept boxes meet, and finds exactly what testing every pair finds."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from support.primitive_assets import box, joint, link, robot, write_asset

from app.engine.asset.kinematics import base_transforms, link_poses
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.offline import collisions
from app.engine.offline.collisions import Collision, blocking_joints, find_collisions
from tests.engine.offline.conftest import asset


def _every_pair(model: ArticulatedAsset, trajectory: Trajectory, moving: set[str]) -> list[Collision]:
    """The check without the box filter: every moving link against every other visual link."""
    shapes = collisions._shapes(model)
    checked = np.unique(np.linspace(0, trajectory.frame_count - 1, min(collisions.MAX_FRAMES, trajectory.frame_count)).round().astype(np.int64))
    poses = link_poses(model, {n: trajectory.joint(n)[checked] for n in trajectory.joint_names}, base_transforms(trajectory.base_translation[checked]))
    found: dict[tuple[str, str], Collision] = {}
    for mover in sorted(moving & set(shapes)):
        for other in model.visual_links:
            if other == mover or collisions._neighbours(model, mover, other):
                continue
            relative = np.linalg.inv(poses[other]) @ poses[mover]
            points = shapes[mover].points
            baseline = collisions._inside_fraction(points @ relative[0, :3, :3].T + relative[0, :3, 3], shapes[other])
            for index in range(1, checked.shape[0]):
                fraction = collisions._inside_fraction(points @ relative[index, :3, :3].T + relative[index, :3, 3], shapes[other]) - baseline
                key = (min(mover, other), max(mover, other))
                if fraction > collisions.NEW_PENETRATION and (key not in found or fraction > found[key].fraction):
                    found[key] = Collision(mover, other, int(checked[index]), float(trajectory.times[int(checked[index])]), round(fraction, 4))
    return sorted(found.values(), key=lambda c: (-c.fraction, c.moving_link, c.other_link))


def _sweep(model: ArticulatedAsset, joint_name: str, target: float) -> Trajectory:
    names = model.movable_joints
    q = np.array([[model.joints[n].rest for n in names]] * 9, dtype=np.float64)
    q[:, names.index(joint_name)] = np.linspace(model.joints[joint_name].rest, target, 9)
    return Trajectory(fps=1, times=np.arange(9, dtype=np.float64), joint_names=names, q=q, base_translation=np.zeros((9, 3)),
                      base_rotation_xyzw=np.tile([0.0, 0.0, 0.0, 1.0], (9, 1)))


@pytest.mark.parametrize(("name", "joint_name"), [("extra/oven_7179", "joint_1"), ("extra/oven_7179", "joint_0"), ("dishwasher_12553", "joint_0"),
                                                  ("refrigerator_11178", "joint_0"), ("extra/storage_25308", "joint_1"), ("washing_machine_103508", "joint_0")])
def test_the_box_filter_finds_what_every_pair_finds(name: str, joint_name: str) -> None:
    model = asset(name)
    spec = model.joints[joint_name]
    for target in (spec.lower, spec.upper):
        assert target is not None
        trajectory = _sweep(model, joint_name, target)
        moving = set(model.moving_links(joint_name))
        assert find_collisions(model, trajectory, moving) == _every_pair(model, trajectory, moving)


def test_a_rack_behind_a_shut_door_is_still_blocked() -> None:
    """The case the check exists for: pulling an oven rack out through its closed door."""
    model = asset("extra/oven_7179")
    assert blocking_joints(model, "joint_1", 0.528, {"joint_3": 0.0}) == ["joint_3"]


def _row(tmp_path: Path, count: int) -> ArticulatedAsset:
    """``count`` boxes side by side on sliders, far apart: no box is near another."""
    links = [link("base", box((0.05, 0.05, 0.05)))] + [link(f"b{i}", box((0.05, 0.05, 0.05))) for i in range(count)]
    joints = [joint(f"j{i}", "prismatic", "base", f"b{i}", xyz=(0.0, 0.3 * (i + 1), 0.0), axis=(1.0, 0.0, 0.0), limit=(0.0, 0.1)) for i in range(count)]
    return load_asset(write_asset(tmp_path / f"row{count}", robot(*links, *joints, name=f"row{count}")))


def test_pairs_tested_grow_with_the_parts_that_meet_not_with_every_pair(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Before: every moving link against every other link (a 40-box row tested 40 x 40 pairs per frame set)."""
    calls: list[int] = []
    original = collisions._inside_fraction

    def counted(points, shape):  # type: ignore[no-untyped-def]
        calls.append(1)
        return original(points, shape)

    monkeypatch.setattr(collisions, "_inside_fraction", counted)
    for count in (20, 40):
        model = _row(tmp_path, count)
        names = model.movable_joints
        q = np.linspace(0.0, 0.1, 5)[:, None] * np.ones((1, len(names)))
        trajectory = Trajectory(fps=1, times=np.arange(5, dtype=np.float64), joint_names=names, q=q, base_translation=np.zeros((5, 3)),
                                base_rotation_xyzw=np.tile([0.0, 0.0, 0.0, 1.0], (5, 1)))
        calls.clear()
        assert find_collisions(model, trajectory, set(model.visual_links)) == []
        assert len(calls) == 0, count  # no two boxes come near each other: no point is ever tested
