"""The artimo command as a user runs it (in process, through main())."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.cli.main import main


def test_inspect_lists_joints_and_links(capsys: pytest.CaptureFixture[str], examples_dir: Path) -> None:
    assert main(["--no-cache", "inspect", str(examples_dir / "cabinet")]) == 0
    text = capsys.readouterr().out
    assert "door_hinge" in text and "revolute" in text and "drawer_top" in text and "diagonal" in text


def test_inspect_json(capsys: pytest.CaptureFixture[str], examples_dir: Path) -> None:
    assert main(["--no-cache", "inspect", "--json", str(examples_dir / "oven")]) == 0
    data = json.loads(capsys.readouterr().out)
    assert {j["joint_name"] for j in data["joints"]} >= {"door_hinge", "tray_slide"}
    assert data["scale"]["unit_assumption"] == "meters_like_urdf_units"


def test_validate_plan_reports_field_paths(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    plan = json.loads((examples_dir / "oven" / "plan.json").read_text())
    plan["timeline"][0]["controls"][0]["joint"] = "no_such_joint"
    plan["meta"]["fps"] = 25
    bad = tmp_path / "plan.json"
    bad.write_text(json.dumps(plan))
    assert main(["--no-cache", "validate-plan", str(examples_dir / "oven"), "--plan", str(bad)]) == 1
    message = capsys.readouterr().err
    assert "meta.fps" in message


def test_validate_plan_unknown_joint(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    plan = json.loads((examples_dir / "oven" / "plan.json").read_text())
    plan["timeline"][0]["controls"][0]["joint"] = "no_such_joint"
    bad = tmp_path / "plan.json"
    bad.write_text(json.dumps(plan))
    assert main(["--no-cache", "validate-plan", str(examples_dir / "oven"), "--plan", str(bad)]) == 1
    message = capsys.readouterr().err
    assert "timeline[0].controls[0].joint" in message and "no_such_joint" in message


def test_run_plan_writes_outputs(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    assert main(["run-plan", str(examples_dir / "oven"), "--plan", str(examples_dir / "oven" / "plan.json"), "--out", str(tmp_path)]) == 0
    for name in ("plan.json", "trajectory.jsonl", "animation.glb", "report.json"):
        assert (tmp_path / name).is_file()


def test_animate_and_refusal(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    assert main(["--no-cache", "animate", str(examples_dir / "microwave"), "--prompt", "open the microwave", "--out", str(tmp_path / "ok")]) == 0
    assert "animation.glb" in capsys.readouterr().out
    assert main(["--no-cache", "animate", str(examples_dir / "microwave"), "--prompt", "open the trunk", "--out", str(tmp_path / "no")]) == 1
    message = capsys.readouterr().err
    assert "Movable parts" in message and "door" in message


def test_a_misspelt_part_name_suggests_the_closest_part(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    """'medal' is a word of its own (never auto-corrected) a letter away from the bin's 'pedal'."""
    out = tmp_path / "out"
    assert main(["--no-cache", "animate", str(examples_dir / "pedal_bin"), "--prompt", "press the medal to open the bin", "--out", str(out)]) == 1
    message = capsys.readouterr().err
    assert "the prompt mentions 'the medal', but pedal_bin has no such movable part (did you mean 'pedal'?)" in message
    assert not (out / "animation.glb").exists()


def test_missing_asset_is_a_clear_error(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    assert main(["--no-cache", "inspect", str(tmp_path / "nothing")]) == 1
    assert "does not exist" in capsys.readouterr().err


def _two_assets(tmp_path: Path, examples_dir: Path) -> Path:
    """A folder holding two assets (like pointing at a whole PartNet folder)."""
    import shutil

    folder = tmp_path / "many"
    shutil.copytree(examples_dir / "microwave", folder / "microwave")
    shutil.copytree(examples_dir / "pedal_bin", folder / "pedal_bin")
    return folder


def test_a_folder_of_several_assets_is_refused_and_lists_them(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    folder = _two_assets(tmp_path, examples_dir)
    assert main(["--no-cache", "animate", str(folder), "--prompt", "open the door", "--out", str(tmp_path / "out")]) == 1
    message = capsys.readouterr().err
    assert "microwave/microwave.urdf, pedal_bin/pedal_bin.urdf" in message and "--urdf" in message
    assert message.count("pedal_bin.urdf") == 1, message  # before: the list again as the error's element
    assert not (tmp_path / "out" / "animation.glb").exists()


def test_urdf_option_chooses_one_asset(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    folder = _two_assets(tmp_path, examples_dir)
    assert main(["--no-cache", "inspect", str(folder), "--urdf", "pedal_bin/pedal_bin.urdf"]) == 0
    assert "pedal" in capsys.readouterr().out
    out = tmp_path / "out"
    assert main(["--no-cache", "animate", str(folder), "--urdf", "microwave.urdf", "--prompt", "open the door", "--out", str(out)]) == 0
    assert json.loads((out / "report.json").read_text())["asset"]["urdf_file"] == "microwave/microwave.urdf"
    plan = examples_dir / "pedal_bin" / "plan.json"
    assert main(["--no-cache", "run-plan", str(folder), "--urdf", "pedal_bin.urdf", "--plan", str(plan), "--out", str(tmp_path / "rp")]) == 0
    assert main(["--no-cache", "validate-plan", str(folder), "--urdf", "pedal_bin.urdf", "--plan", str(plan)]) == 0


def test_inspect_says_which_end_is_closed_and_where_parts_sit(capsys: pytest.CaptureFixture[str], examples_dir: Path) -> None:
    assert main(["--no-cache", "inspect", str(examples_dir / "cabinet")]) == 0
    text = capsys.readouterr().out
    assert "front faces +X" in text
    lines = text.splitlines()
    bottom = lines.index(next(line for line in lines if line.strip().startswith("drawer_bottom_slide")))
    assert "closed/rest at upper (0), open at lower (-0.35)" in lines[bottom + 1]  # the limit's sign says nothing
    assert any("drawer (upper, drawer_top)" in line and "top, center, middle" in line for line in lines)
    assert any("drawer (lower, drawer_bottom)" in line and "bottom, center, middle" in line for line in lines)
    assert any(line.strip().startswith("door ") and line.endswith("front") for line in lines)


def test_inspect_json_has_the_layout(capsys: pytest.CaptureFixture[str], partnet: Path) -> None:
    assert main(["--no-cache", "inspect", "--json", str(partnet / "refrigerator_11178")]) == 0
    layout = json.loads(capsys.readouterr().out)["layout"]
    assert layout["front"] == [-1.0, 0.0, 0.0]
    names = {p["link"]: p["name"] for p in layout["parts"]}
    assert (names["link_0"], names["link_1"]) == ("door (left, link_0)", "door (right, link_1)")
    ends = {j["joint"]: j for j in layout["joints"]}
    assert (ends["joint_0"]["closed_end"], ends["joint_0"]["open_end"], ends["joint_0"]["rest_end"]) == ("lower", "upper", "lower")
