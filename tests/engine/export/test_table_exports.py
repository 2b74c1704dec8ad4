"""joint_trajectory.json (filled into ROS 2 messages with rosbags), trajectory.csv and trajectory.npz read back."""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from rosbags.typesys import Stores, get_typestore

from app.engine.errors import ExportError
from app.engine.export.csv_table import write_csv
from app.engine.export.npz_arrays import write_npz
from app.engine.export.ros import write_ros
from app.engine.export.track import build_track
from tests.support.export_runs import MotionCase

STORE = get_typestore(Stores.ROS2_HUMBLE)
NUMERIC = {"float64": np.float64, "float32": np.float32, "int32": np.int32, "uint32": np.uint32}


def to_message(msgtype: str, value: dict[str, Any]) -> Any:
    """Fill a ROS message from a dict field by field; a missing or extra key is an error."""
    _, fields = STORE.fielddefs[msgtype]
    assert sorted(value) == sorted(name for name, _ in fields), (msgtype, sorted(value))
    return STORE.types[msgtype](**{name: _field(kind, value[name]) for name, kind in fields})


def _field(kind: tuple[Any, Any], value: Any) -> Any:
    node, detail = kind
    if node.name == "NAME":
        return to_message(detail, value)
    if node.name == "BASE":
        return value
    (inner_node, inner), _ = detail
    if inner_node.name == "NAME":
        return [to_message(inner, item) for item in value]
    if inner[0] == "string":
        return list(value)
    return np.asarray(value, dtype=NUMERIC[inner[0]])


@pytest.mark.parametrize("name", ["tiny", "toy_car", "safe_101593"])
def test_ros_fields_fill_trajectory_messages(name: str, motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases[name]
    track = case.track
    document = json.loads((tmp_path / write_ros(track, tmp_path)).read_text())
    base = document.pop("base_pose_track")
    message = to_message("trajectory_msgs/msg/JointTrajectory", document)
    again = STORE.deserialize_cdr(STORE.serialize_cdr(message, message.__msgtype__), message.__msgtype__)
    assert list(again.joint_names) == list(track.moving_joints)
    assert len(again.points) == case.trajectory.frame_count
    for index in (0, len(again.points) // 2, len(again.points) - 1):
        point = again.points[index]
        stamp = point.time_from_start.sec + point.time_from_start.nanosec * 1e-9
        assert stamp == pytest.approx(case.trajectory.times[index], abs=1e-9)
        assert np.array_equal(point.positions, track.joint_matrix()[index])
    base_message = to_message("trajectory_msgs/msg/MultiDOFJointTrajectory", base)
    assert list(base_message.joint_names) == ["base"] and base_message.header.frame_id == "world"
    last = base_message.points[-1].transforms[0]
    assert np.allclose([last.translation.x, last.translation.y, last.translation.z], case.trajectory.base_translation[-1])
    assert np.allclose([last.rotation.x, last.rotation.y, last.rotation.z, last.rotation.w], case.trajectory.base_rotation_xyzw[-1])


def test_ros_velocities_are_finite_differences(motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases["pedal_bin"]
    document = json.loads((tmp_path / write_ros(case.track, tmp_path)).read_text())
    positions = np.array([p["positions"] for p in document["points"]])
    velocities = np.array([p["velocities"] for p in document["points"]])
    fps = case.trajectory.fps
    middle = (positions[2:] - positions[:-2]) * fps / 2
    assert np.allclose(velocities[1:-1], middle)
    spin = json.loads((tmp_path / write_ros(motion_cases["tiny"].track, tmp_path)).read_text())["base_pose_track"]["points"]
    angular = np.array([[p["velocities"][0]["angular"][k] for k in "xyz"] for p in spin])
    axis = np.array([0.3, -0.4, 0.866]) / np.linalg.norm([0.3, -0.4, 0.866])
    assert np.allclose(angular, 1.2 / 0.6 * axis, atol=1e-9)  # 1.2 rad over 0.6 s about the tilted axis


@pytest.mark.parametrize("name", ["tiny", "toy_car", "kitchen_pot_100038"])
def test_csv_reads_back_exactly(name: str, motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases[name]
    track = case.track
    with (tmp_path / write_csv(track, tmp_path)).open(newline="") as handle:
        rows = list(csv.reader(handle))
    header, values = rows[0], np.array(rows[1:], dtype=np.float64)
    assert header == ["time", *track.moving_joints, "base_x", "base_y", "base_z", "base_qx", "base_qy", "base_qz", "base_qw"]
    assert np.array_equal(values[:, 0], case.trajectory.times)
    for column, joint in enumerate(track.moving_joints, start=1):
        assert np.array_equal(values[:, column], track.values[joint])
    assert np.array_equal(values[:, -7:-4], case.trajectory.base_translation)
    assert np.array_equal(values[:, -4:], case.trajectory.base_rotation_xyzw)


@pytest.mark.parametrize("name", ["tiny", "toy_car", "safe_101593"])
def test_npz_loads_without_pickles(name: str, motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases[name]
    track = case.track
    path = tmp_path / write_npz(track, tmp_path)
    with np.load(path, allow_pickle=False) as data:
        assert list(data["joint_names"]) == list(track.moving_joints)
        assert int(data["fps"]) == case.trajectory.fps
        assert np.array_equal(data["time"], case.trajectory.times)
        for joint in track.moving_joints:
            assert np.array_equal(data[joint], track.values[joint])
        assert np.array_equal(data["base_translation"], case.trajectory.base_translation)
        assert np.array_equal(data["base_rotation_xyzw"], case.trajectory.base_rotation_xyzw)
    first = path.read_bytes()
    write_npz(build_track(case.asset, case.trajectory), tmp_path)
    assert path.read_bytes() == first  # fixed zip timestamps: byte-identical


def test_moving_joints_exclude_still_and_mimic_joints(motion_cases: dict[str, MotionCase]) -> None:
    assert motion_cases["tiny"].track.moving_joints == ("hinge", "slide")  # twin_joint mimics hinge
    pedal = motion_cases["pedal_bin"].track
    assert set(pedal.moving_joints) == {"pedal_pivot", "lid_hinge"}


def test_joint_named_like_a_fixed_column_is_refused(motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    import dataclasses

    case = motion_cases["tiny"]
    track = case.track
    clashing = dataclasses.replace(track, moving_joints=("time", "slide"), values={**track.values, "time": track.values["hinge"]})
    with pytest.raises(ExportError, match="time"):
        write_csv(clashing, tmp_path)
    with pytest.raises(ExportError, match="time"):
        write_npz(clashing, tmp_path)
    assert not (tmp_path / "trajectory.csv").exists() and not (tmp_path / "trajectory.npz").exists()
