"""``artimo animate`` / ``run-plan`` with model roles and bad runs, as a user runs them (main(), environment)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.cli.main import main
from tests.support.model_server import model_server, recorded


def _imperfect() -> dict:  # type: ignore[type-arg]
    """A recoverable bad day: prose around the JSON, a rate limit, a cut reply, list content, a <think> block."""
    replies = recorded("pedal_bin")
    perceiver = json.dumps(json.loads(replies["perceiver"][0].strip().removeprefix("```json").removesuffix("```")))
    replies["perceiver"] = [{"status": 429}, {"text": perceiver, "shape": "prose"}]
    replies["planner"] = [{"text": replies["planner"][0], "needs_tokens": 9000, "shape": "list"}]
    replies["critic"] = [{"text": replies["critic"][0], "shape": "think"}]
    return replies


def test_animate_with_an_imperfect_model_succeeds_and_images_reach_every_vlm_role(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch, tmp_path: Path, examples_dir: Path,
) -> None:
    with model_server(_imperfect()) as (url, script):
        monkeypatch.setenv("OPENAI_API_KEY", "sk-local\r")
        monkeypatch.setenv("OPENAI_BASE_URL", url)
        code = main(["--no-cache", "animate", str(examples_dir / "pedal_bin"), "--prompt", "press the pedal to open the bin",
                     "--out", str(tmp_path), "--provider", "openai"])
    printed = capsys.readouterr()
    assert code == 0, printed.err
    assert "sk-local" not in printed.out + printed.err
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["images"] is True and report["final_state"].startswith("accepted")
    for role in ("perceiver", "coverage", "critic"):
        assert all(isinstance(r["payload"]["messages"][1]["content"], list) for r in script.of(role)), role
    assert "perceiver   1 calls (0 failed, 1 retries)" in printed.out and "~$" in printed.out
    assert (tmp_path / "animation.glb").is_file() and len(list((tmp_path / "images").glob("*.png"))) == 8


def test_no_render_fallback_and_timeouts_from_flags_and_environment(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch, tmp_path: Path, examples_dir: Path,
) -> None:
    replies = recorded("pedal_bin")
    replies["critic"] = [{"stall_s": 1.2, "reply": replies["critic"][0]}]
    with model_server(replies) as (url, script):
        monkeypatch.setenv("OPENAI_API_KEY", "sk-local")
        monkeypatch.setenv("ARTIMO_CALL_TIMEOUT_S", "0.6")
        code = main(["--no-cache", "animate", str(examples_dir / "pedal_bin"), "--prompt", "press the pedal to open the bin",
                     "--out", str(tmp_path), "--provider", "openai", "--base-url", url, "--no-render", "--timeout", "0.4",
                     "--fallback", "critic=offline"])
    printed = capsys.readouterr().out
    assert code == 0
    assert "rendering is off (--no-render)" in printed and "the offline critic was used instead" in printed
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["fallbacks"]["critic"].startswith("critic: the model gave no usable answer (ProviderTimeout")
    assert all("image_url" not in json.dumps(r["payload"]) for r in script.requests)


def test_bad_flags_are_clear_errors(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    base = ["--no-cache", "animate", str(examples_dir / "pedal_bin"), "--prompt", "open it", "--out", str(tmp_path), "--provider", "openai",
            "--base-url", "http://127.0.0.1:9/v1"]
    assert main([*base, "--fallback", "critic=maybe"]) == 1
    assert "--fallback" in capsys.readouterr().err
    assert main([*base, "--profile", "temprature=0"]) == 1
    assert "unknown model profile field 'temprature'" in capsys.readouterr().err
    assert main([*base, "--model", "actor=gpt-4.1"]) == 1
    assert "ROLE one of perceiver, planner, critic, coverage" in capsys.readouterr().err


def test_failed_run_plan_replaces_the_previous_outputs_with_its_report(capsys: pytest.CaptureFixture[str], tmp_path: Path, examples_dir: Path) -> None:
    plan = examples_dir / "oven" / "plan.json"
    assert main(["run-plan", str(examples_dir / "oven"), "--plan", str(plan), "--out", str(tmp_path)]) == 0
    assert (tmp_path / "animation.glb").is_file()
    bad = json.loads(plan.read_text())
    bad["timeline"][0]["controls"][0]["joint"] = "no_such_joint"
    broken = tmp_path.parent / f"{tmp_path.name}-broken-plan.json"
    broken.write_text(json.dumps(bad))
    assert main(["run-plan", str(examples_dir / "oven"), "--plan", str(broken), "--out", str(tmp_path)]) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.json"]
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["final_state"] == "failed: PlanValidationError" and "no_such_joint" in report["error"]
