"""``artimo bench critic``: injections, detection, repair, the JSON names, and a model critic through the local server."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.cli.main import main
from app.engine.asset.loader import load_asset
from app.engine.metrics.compiler import compile_case
from benchmark.cases import read_cases
from benchmark.critic_injection import CLASSES, expectations_from_case, inject
from tests.support.model_server import model_server, recorded

REPO = Path(__file__).resolve().parents[2]
EXAMPLE_CASES = REPO / "benchmark" / "cases" / "dev_examples.jsonl"
PICK = ("cabinet_both_drawers", "microwave_spin_turntable_cw", "pedal_bin_press_hold", "microwave_button_opens_door", "cabinet_knob_pops_door")


def _subset(tmp_path: Path) -> Path:
    lines = [line for line in EXAMPLE_CASES.read_text().splitlines() if json.loads(line)["case_id"] in PICK]
    path = tmp_path / "cases.jsonl"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_each_injection_changes_the_plan_the_way_its_class_says(examples_dir: Path) -> None:
    cases = {c.case_id: c for c in read_cases(EXAMPLE_CASES)}
    case = cases["microwave_button_opens_door"]
    asset = load_asset(examples_dir / case.asset)
    truth = compile_case(case, asset)
    expected = expectations_from_case(case, asset)
    assert any(m.returns_to_rest for m in expected.motions)
    made = {code: inject(code, truth, asset, expected) for code in CLASSES}
    assert made["WRONG_DIRECTION"] is None  # the door rests at a limit: it cannot open the wrong way
    small = made["MOTION_TOO_SMALL"]
    assert small is not None and small.plan != truth.plan and "->" in small.description
    extra = made["UNEXPECTED_EXTRA_MOTION"]
    assert extra is not None and extra.joint not in expected.joints
    assert made["NO_RELEASE_RETURN"] is not None


def test_geometric_critic_table_and_json(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    out = tmp_path / "critic.json"
    assert main(["--no-cache", "bench", "critic", "--cases", str(_subset(tmp_path)), "--assets", str(examples_dir), "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "critic: geometric" in printed and "WRONG_DIRECTION" in printed and "correct plans flagged: 0/5" in printed
    document = json.loads(out.read_text())
    assert document["critic"] == "geometric" and set(document["classes"]) == set(CLASSES)
    for code, row in document["classes"].items():
        assert {"n", "detected", "rate", "repaired"} <= set(row)
        assert isinstance(row["n"], int) and isinstance(row["detected"], int) and isinstance(row["rate"], float) and isinstance(row["repaired"], int)
        if row["n"]:
            assert row["rate"] >= 0.95, code
    assert sum(row["n"] for row in document["classes"].values()) >= 10
    made = [c for c in document["cases"] if c["applicable"]]
    assert all(c["detected"] for c in made) and all(c["score_repaired"] >= c["score_injected"] for c in made)


def test_model_critic_is_run_through_the_provider(capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch, tmp_path: Path,
                                                  examples_dir: Path) -> None:
    """A model that always says "looks fine": nothing detected, and its calls really went out with keyframes."""
    cases = tmp_path / "one.jsonl"
    cases.write_text(next(line for line in EXAMPLE_CASES.read_text().splitlines() if "pedal_bin_press_hold" in line) + "\n")
    with model_server(recorded("pedal_bin")) as (url, script):
        monkeypatch.setenv("OPENAI_API_KEY", "sk-local")
        code = main(["--no-cache", "bench", "critic", "--cases", str(cases), "--assets", str(examples_dir), "--provider", "openai",
                     "--base-url", url, "--model", "critic=gpt-4.1", "--model", "coverage=geometric", "--class", "MOTION_TOO_SMALL",
                     "--out", str(tmp_path / "model.json")])
    assert code == 0
    document = json.loads((tmp_path / "model.json").read_text())
    assert document["critic"] == "openai:gpt-4.1"
    assert document["classes"]["MOTION_TOO_SMALL"]["n"] == 1 and document["classes"]["MOTION_TOO_SMALL"]["detected"] == 0
    critic_calls = script.of("critic")
    assert critic_calls and all("image_url" in json.dumps(r["payload"]) for r in critic_calls)
