"""``scene.xml`` loaded with mujoco: bodies, joints, keys applied vs forward kinematics."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import mujoco
import numpy as np
import pytest

from app.engine.errors import ExportError
from app.engine.export.mjcf import key_frames, mjcf_text, write_mjcf
from app.engine.export.track import build_track
from tests.support.export_runs import POSITION_TOLERANCE_M, ROTATION_TOLERANCE, MotionCase, expected_poses

CASES = ["tiny", "safe_101593", "trash_can_102155", "kitchen_pot_100038", "toy_car", "pedal_bin"]
MJ_TYPES = {"revolute": mujoco.mjtJoint.mjJNT_HINGE, "continuous": mujoco.mjtJoint.mjJNT_HINGE, "prismatic": mujoco.mjtJoint.mjJNT_SLIDE}


def _load(case: MotionCase, folder: Path) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_path(str(folder / write_mjcf(case.track, folder, case.phase_ends)))


@pytest.mark.parametrize("name", CASES)
def test_keys_reproduce_forward_kinematics(name: str, motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases[name]
    model = _load(case, tmp_path)
    data = mujoco.MjData(model)
    fps = case.trajectory.fps
    frames = [round(model.key_time[k] * fps) for k in range(model.nkey)]
    last = case.trajectory.frame_count - 1
    phase_frames = {min(max(round(t1 * fps), 0), last) for _, t1 in case.phase_ends}
    assert set(frames) == {0, last} | phase_frames  # one key per phase end, plus first and last frame
    for key, frame in enumerate(frames):
        mujoco.mj_resetDataKeyframe(model, data, key)
        mujoco.mj_kinematics(model, data)
        expected = expected_poses(case, frame)
        for link in case.asset.link_order:
            body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, link)
            assert body >= 0, link
            assert np.abs(data.xpos[body] - expected[link][:3, 3]).max() < POSITION_TOLERANCE_M, (link, frame)
            assert np.abs(data.xmat[body].reshape(3, 3) - expected[link][:3, :3]).max() < ROTATION_TOLERANCE, (link, frame)


@pytest.mark.parametrize("name", CASES)
def test_joints_follow_the_urdf(name: str, motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases[name]
    model = _load(case, tmp_path)
    movable = [j for j in case.asset.joints.values() if j.movable]
    free = case.track.base_moves
    assert model.njnt == len(movable) + int(free)
    if free:
        assert model.jnt_type[0] == mujoco.mjtJoint.mjJNT_FREE
    for joint in movable:
        index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, joint.name)
        assert model.jnt_type[index] == MJ_TYPES[joint.type]
        assert mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, model.jnt_bodyid[index]) == joint.child
        assert np.allclose(model.jnt_axis[index], joint.axis)
        assert bool(model.jnt_limited[index]) == joint.bounded
        if joint.bounded:
            assert np.allclose(model.jnt_range[index], [joint.lower, joint.upper])
    geoms = sum(len(case.asset.links[link].parts) for link in case.asset.link_order)
    assert model.ngeom == geoms and model.nmesh == geoms


def test_mimic_joint_is_tied_and_model_simulates(motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases["tiny"]
    model = _load(case, tmp_path)
    assert model.neq == 1
    assert mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, model.eq_obj1id[0]) == "twin_joint"
    assert np.allclose(model.eq_data[0, :2], [0.1, -0.5])
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    for _ in range(50):
        mujoco.mj_step(model, data)
    assert np.all(np.isfinite(data.qpos))


def test_key_frames_dedupe_and_order(motion_cases: dict[str, MotionCase]) -> None:
    track = motion_cases["pedal_bin"].track
    last = track.frame_count - 1
    keys = key_frames(track, [("b", 1.0), ("a", 0.0), ("c", 1.0), ("d", 99.0)])
    assert keys == [("start", 0), ("b_end", 30), ("d_end", last)]


def test_world_link_only_as_static_root(motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases["pedal_bin"]
    asset = case.asset
    renamed = {("world" if name == asset.root_link else name): dataclasses.replace(link, name="world" if name == asset.root_link else name)
               for name, link in asset.links.items()}
    joints = {name: (dataclasses.replace(j, parent="world") if j.parent == asset.root_link else j) for name, j in asset.joints.items()}
    world_root = dataclasses.replace(asset, root_link="world", links=renamed, joints=joints,
                                     link_order=tuple("world" if n == asset.root_link else n for n in asset.link_order))
    model = mujoco.MjModel.from_xml_string(mjcf_text(build_track(world_root, case.trajectory), case.phase_ends))
    assert model.nbody == len(asset.link_order)  # the root is MuJoCo's world body
    moving = motion_cases["toy_car"]
    wheel = moving.asset.joints["wheel_front_left_axle"].child
    bad = dataclasses.replace(moving.asset, links={**moving.asset.links, "world": moving.asset.links[wheel]},
                              link_order=(*moving.asset.link_order, "world"))
    with pytest.raises(ExportError, match="world"):
        mjcf_text(build_track(bad, moving.trajectory))


def test_output_is_deterministic(motion_cases: dict[str, MotionCase]) -> None:
    case = motion_cases["safe_101593"]
    assert mjcf_text(case.track, case.phase_ends) == mjcf_text(build_track(case.asset, case.trajectory), case.phase_ends)
