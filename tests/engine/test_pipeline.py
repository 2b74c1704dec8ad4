"""run_pipeline end to end with the offline roles: files, report, progress, cancellation, failure."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from PIL import Image

from app.engine.config import EngineConfig
from app.engine.errors import CancelledError, GroundingError
from app.engine.pipeline import STAGES, PipelineRequest, run_pipeline
from app.engine.providers.registry import make_roles
from tests.support.gltf_validator import assert_valid


class Recorder:
    def __init__(self) -> None:
        self.stages: list[tuple[str, int]] = []

    def on_stage(self, stage: str, progress: int) -> None:
        self.stages.append((stage, progress))

    def on_message(self, message: str) -> None:
        pass


def test_pipeline_writes_every_output(tmp_path: Path, examples_dir: Path) -> None:
    recorder = Recorder()
    result = run_pipeline(PipelineRequest(asset=examples_dir / "pedal_bin", prompt="press the pedal to open the bin"),
                          roles=make_roles("offline"), out_dir=tmp_path, observer=recorder)
    for name in ("causal.json", "plan.json", "trajectory.jsonl", "animation.glb", "report.json"):
        assert (tmp_path / name).is_file(), name
    assert recorder.stages == [stage for stage in STAGES if stage[0] != "preview"]  # not asked for
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["provider"] == "offline"
    assert report["final_state"].startswith("accepted")
    assert {c["role"] for c in report["role_calls"]} == {"perceiver", "planner", "critic"}
    assert [s["stage"] for s in report["stages"]] == [name for name, _ in STAGES if name not in ("report", "preview")]  # its own write is not timed
    assert report["outputs"]["glb"] == "animation.glb"
    assert result.report.asset.name == "pedal_bin"
    assert_valid([tmp_path / "animation.glb"])


def test_pipeline_is_deterministic(tmp_path: Path, examples_dir: Path) -> None:
    outputs = []
    for run in ("a", "b"):
        run_pipeline(PipelineRequest(asset=examples_dir / "oven", prompt="pull out the tray"), roles=make_roles("offline"), out_dir=tmp_path / run)
        outputs.append([(tmp_path / run / f).read_bytes() for f in ("causal.json", "plan.json", "trajectory.jsonl", "animation.glb")])
    assert outputs[0] == outputs[1]


def test_cancellation_between_stages(tmp_path: Path, examples_dir: Path) -> None:
    calls = iter([False, False, True])
    with pytest.raises(CancelledError):
        run_pipeline(PipelineRequest(asset=examples_dir / "oven", prompt="open the door"), roles=make_roles("offline"), out_dir=tmp_path,
                     should_stop=lambda: next(calls, True))
    assert not (tmp_path / "animation.glb").exists()


def test_refusal_writes_a_report_and_no_animation(tmp_path: Path, examples_dir: Path) -> None:
    with pytest.raises(GroundingError) as info:
        run_pipeline(PipelineRequest(asset=examples_dir / "oven", prompt="open the trunk"), roles=make_roles("offline"), out_dir=tmp_path)
    assert "tray" in str(info.value)
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["final_state"].startswith("failed")
    assert not (tmp_path / "animation.glb").exists()


def test_requested_fps_is_used(tmp_path: Path, examples_dir: Path) -> None:
    run_pipeline(PipelineRequest(asset=examples_dir / "oven", prompt="open the door", fps=24), roles=make_roles("offline"), out_dir=tmp_path)
    plan = json.loads((tmp_path / "plan.json").read_text())
    assert plan["meta"]["fps"] == 24
    frames = [json.loads(line) for line in (tmp_path / "trajectory.jsonl").read_text().splitlines()]
    assert frames[1]["time_s"] == pytest.approx(1 / 24)


def test_preview_gif_is_written_when_asked(tmp_path: Path, examples_dir: Path) -> None:
    recorder = Recorder()
    result = run_pipeline(PipelineRequest(asset=examples_dir / "pedal_bin", prompt="press the pedal to open the bin"),
                          roles=make_roles("offline"), config=EngineConfig(preview=True), out_dir=tmp_path, observer=recorder)
    assert result.outputs["preview"] == "preview.gif" and recorder.stages == list(STAGES)
    with Image.open(tmp_path / "preview.gif") as gif:
        assert gif.format == "GIF" and gif.n_frames > 10
    assert json.loads((tmp_path / "report.json").read_text())["outputs"]["preview"] == "preview.gif"
