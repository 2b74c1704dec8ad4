"""``--export`` on ``artimo run-plan`` and ``artimo animate``: files written, bad names and missing extras refused up front."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from app.cli.main import main
from app.engine.errors import ExportError
from app.engine.export.outputs import parse_exports, require_exports

ALL = "usd,mjcf,ros,csv,npz"
FILES = {"usd": "animation.usda", "mjcf": "scene.xml", "ros": "joint_trajectory.json", "csv": "trajectory.csv", "npz": "trajectory.npz"}


def test_run_plan_writes_every_export(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    folder = examples_dir / "oven"
    assert main(["--no-cache", "run-plan", str(folder), "--plan", str(folder / "plan.json"), "--out", str(tmp_path), "--export", ALL]) == 0
    printed = capsys.readouterr().out
    report = json.loads((tmp_path / "report.json").read_text())
    for kind, name in {**FILES, "interaction": "interaction.json"}.items():
        assert (tmp_path / name).is_file() and report["outputs"][kind] == name and name in printed
    interactions = json.loads((tmp_path / "interaction.json").read_text())["interactions"]
    assert [(i["link"], i["kind"]) for i in interactions] == [("door", "direct_manipulation"), ("tray", "direct_manipulation")]


def test_animate_writes_the_asked_exports_only(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    code = main(["--no-cache", "animate", str(examples_dir / "pedal_bin"), "--prompt", "press the pedal to open the bin",
                 "--out", str(tmp_path), "--export", "csv, NPZ"])
    assert code == 0, capsys.readouterr().err
    assert (tmp_path / "trajectory.csv").is_file() and (tmp_path / "trajectory.npz").is_file()
    assert not (tmp_path / "animation.usda").exists() and not (tmp_path / "scene.xml").exists()
    (record,) = json.loads((tmp_path / "interaction.json").read_text())["interactions"]
    assert (record["link"], record["action"], record["feature"]) == ("pedal", "push", "tread")


def test_unknown_export_is_refused_before_any_work(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    folder = examples_dir / "oven"
    out = tmp_path / "out"
    assert main(["--no-cache", "run-plan", str(folder), "--plan", str(folder / "plan.json"), "--out", str(out), "--export", "usd,gltf"]) == 1
    assert "unknown export(s) gltf: choose from usd, mjcf, ros, csv, npz" in capsys.readouterr().err
    assert not out.exists()


def test_missing_usd_package_names_the_extra(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], tmp_path: Path,
                                             examples_dir: Path) -> None:
    for name in [m for m in sys.modules if m == "pxr" or m.startswith("pxr.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "pxr", None)  # import pxr -> ImportError, as without usd-core
    with pytest.raises(ExportError, match=r"pip install 'artimo\[usd\]' \(or pip install usd-core\)"):
        require_exports(["usd"])
    require_exports(["mjcf", "ros", "csv", "npz"])  # these need no optional package to be written
    folder = examples_dir / "oven"
    out = tmp_path / "out"
    assert main(["--no-cache", "run-plan", str(folder), "--plan", str(folder / "plan.json"), "--out", str(out), "--export", "usd"]) == 1
    assert "the 'usd' export needs the optional package usd-core" in capsys.readouterr().err
    assert not out.exists()


def test_parse_exports_orders_and_dedupes() -> None:
    assert parse_exports(" npz,USD,usd ,") == ("usd", "npz")
    assert parse_exports(["ros", "csv"]) == ("ros", "csv")
    assert parse_exports(None) == () and parse_exports("") == ()


def test_engine_config_checks_export_names() -> None:
    from pydantic import ValidationError

    from app.engine.config import EngineConfig

    assert EngineConfig(exports="npz,usd").exports == ("usd", "npz")
    with pytest.raises(ValidationError, match="exports"):
        EngineConfig(exports=["usd", "fbx"])
