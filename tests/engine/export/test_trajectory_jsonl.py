"""trajectory.jsonl (SPEC §4) round trip, and reading files written by other tools."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import MetricError
from app.engine.execute.executor import execute
from app.engine.export.glb import glb_bytes
from app.engine.export.jsonl import read_trajectory_jsonl, write_trajectory_jsonl
from app.engine.plan.schema import Plan
from tests.support.glb_cases import SAFE_PLAN, ExportCase


def test_round_trip_is_exact(export_cases: dict[str, ExportCase], tmp_path: Path) -> None:
    for name in ("safe_101593", "kitchen_pot_100038", "trash_can_102155"):
        case = export_cases[name]
        path = write_trajectory_jsonl(case.trajectory, tmp_path / f"{name}.jsonl")
        back, notes = read_trajectory_jsonl(path, case.asset, fps=case.trajectory.fps)
        assert notes == []
        assert back.joint_names == case.trajectory.joint_names and back.fps == case.trajectory.fps
        for field in ("times", "q", "base_translation", "base_rotation_xyzw"):
            np.testing.assert_array_equal(getattr(back, field), getattr(case.trajectory, field))
        assert glb_bytes(case.asset, back) == case.path.read_bytes()


def test_records_use_the_authors_field_names(export_cases: dict[str, ExportCase], tmp_path: Path) -> None:
    case = export_cases["safe_101593"]
    lines = write_trajectory_jsonl(case.trajectory, tmp_path / "t.jsonl").read_text().splitlines()
    assert len(lines) == case.trajectory.frame_count == 106
    record = json.loads(lines[30])
    assert set(record) == {"frame_idx", "time_s", "joint_angles", "base_pose", "modes"}
    assert record["frame_idx"] == 30 and record["time_s"] == 1.0
    assert set(record["joint_angles"]) == set(case.asset.movable_joints)
    assert record["base_pose"] == {"translation": [0.0, 0.0, 0.0], "rotation_xyzw": [0.0, 0.0, 0.0, 1.0]}


def test_modes_survive_the_round_trip(assets: dict[str, ArticulatedAsset], tmp_path: Path) -> None:
    plan = json.loads(json.dumps(SAFE_PLAN))
    plan["timeline"][2]["controls"].append({"mode": "mode_set", "name": "door_unlocked", "set": True})
    trajectory = execute(Plan.model_validate(plan), assets["safe_101593"])
    assert trajectory.modes[-1] == {"door_unlocked": True} and trajectory.modes[0] == {}
    back, _ = read_trajectory_jsonl(
        write_trajectory_jsonl(trajectory, tmp_path / "m.jsonl"), assets["safe_101593"], fps=30
    )
    assert back.modes == trajectory.modes


def test_foreign_files_estimate_fps_and_report_unknown_joints(
    assets: dict[str, ArticulatedAsset], tmp_path: Path
) -> None:
    asset = assets["safe_101593"]
    rows = [
        {"frame_idx": i, "time_s": i / 24, "joint_angles": {"joint_0": 0.1 * i, "joint_3": 0.0, "ghost": 1.0}}
        for i in range(5)
    ]
    path = tmp_path / "foreign.jsonl"
    path.write_text("\n".join(json.dumps(r) for r in rows) + "\n")
    back, notes = read_trajectory_jsonl(path, asset)
    assert back.fps == 24 and notes == ["foreign.jsonl: unknown joints ignored: ghost"]
    np.testing.assert_allclose(back.joint("joint_0"), 0.1 * np.arange(5))
    np.testing.assert_array_equal(back.joint("joint_1"), np.zeros(5))
    np.testing.assert_array_equal(back.base_rotation_xyzw[:, 3], np.ones(5))
    assert back.modes == ({},) * 5


@pytest.mark.parametrize(
    ("line", "message"),
    [
        ('{"frame_idx": 0, "time_s": NaN, "joint_angles": {}}', "time_s"),
        ('{"frame_idx": "zero", "joint_angles": {}}', "frame_idx"),
        ('{"time_s": 0, "joint_angles": {"joint_0": true}}', "joint_0"),
        ('{"time_s": 0, "base_pose": [0, 0, 0]}', "base_pose must be an object"),
        ('{"time_s": 0, "modes": {"x": 1}}', "modes"),
        ("[1, 2]", "expected an object"),
        ("{oops", "not JSON"),
    ],
)
def test_malformed_lines_are_metric_errors(
    assets: dict[str, ArticulatedAsset], tmp_path: Path, line: str, message: str
) -> None:
    path = tmp_path / "bad.jsonl"
    path.write_text(line + "\n")
    with pytest.raises(MetricError, match=message):
        read_trajectory_jsonl(path, assets["safe_101593"])
