"""Model providers end to end against a local OpenAI-compatible server replaying recorded replies."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.engine.config import EngineConfig
from app.engine.errors import ProviderResponseError, ProviderTimeout, RoleOutputError
from app.engine.pipeline import PipelineRequest, run_pipeline
from app.engine.providers.registry import ProviderConfig, make_roles
from tests.support.replay_server import recorded, replay_server

PROMPT = "press the pedal to open the bin"


def _run(examples_dir: Path, out: Path, replies: dict, *, provider: str = "openai", config: EngineConfig | None = None, models=()):  # type: ignore[no-untyped-def]
    with replay_server(replies) as (url, script):
        base = url if provider == "openai" else url.removesuffix("/v1")
        roles = make_roles(provider, ProviderConfig(api_key="test-key", base_url=base, models=tuple(models)), config or EngineConfig())
        try:
            result = run_pipeline(PipelineRequest(asset=examples_dir / "pedal_bin", prompt=PROMPT), roles=roles, config=config, out_dir=out)
        finally:
            pass
        return result, script


def test_recorded_replies_drive_the_whole_pipeline(tmp_path: Path, examples_dir: Path) -> None:
    result, script = _run(examples_dir, tmp_path, recorded("pedal_bin"))
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["provider"] == "openai"
    assert {c["role"] for c in report["role_calls"]} == {"perceiver", "planner", "critic"}
    assert all(c["prompt_version"] for c in report["role_calls"])
    assert sum(c["usage"]["input_tokens"] for c in report["role_calls"]) > 0
    assert report["final_state"].startswith("accepted")
    assert script.requests[0]["auth"] == "Bearer test-key"
    assert script.requests[0]["payload"]["response_format"] == {"type": "json_object"}
    last = (tmp_path / "trajectory.jsonl").read_text().splitlines()[-1]
    angles = json.loads(last)["joint_angles"]
    assert angles["lid_hinge"] == pytest.approx(-1.4, abs=1e-6) and angles["pedal_pivot"] == pytest.approx(0.35, abs=1e-6)
    assert json.loads((tmp_path / "causal.json").read_text())["causal"]["action"]["target_link"] == "pedal"
    assert result.outputs["glb"] == "animation.glb"


def test_invalid_reply_goes_back_as_feedback(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    bad = json.loads(replies["perceiver"][0].strip().removeprefix("```json").removesuffix("```"))
    bad["causal"]["effects"]["joint_targets"][1]["joint"] = "lid_joint"  # not a joint of this asset
    replies["perceiver"] = [json.dumps(bad)] + replies["perceiver"]
    _, script = _run(examples_dir, tmp_path, replies)
    perceiver_calls = [r for r in script.requests if r["role"] == "perceiver"]
    assert len(perceiver_calls) == 2
    feedback = perceiver_calls[1]["payload"]["messages"][-1]["content"]
    assert "causal.effects.joint_targets[1].joint" in feedback and "lid_joint" in feedback
    report = json.loads((tmp_path / "report.json").read_text())
    perceiver = [c for c in report["role_calls"] if c["role"] == "perceiver"]
    assert perceiver[0]["error"] and perceiver[1]["attempts"] == 2


def test_persistently_invalid_replies_fail_clearly(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["planner"] = ["this is not JSON"]
    with pytest.raises(RoleOutputError) as info:
        _run(examples_dir, tmp_path, replies)
    assert "planner" in str(info.value)
    assert json.loads((tmp_path / "report.json").read_text())["final_state"].startswith("failed")


def test_rate_limit_is_retried(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"status": 429}] + replies["perceiver"]
    result, script = _run(examples_dir, tmp_path, replies)
    assert [r["role"] for r in script.requests].count("perceiver") == 2
    assert result.report.final_state.startswith("accepted")


def test_server_errors_give_up_with_a_typed_error(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"status": 400}]
    with pytest.raises(ProviderResponseError) as info:
        _run(examples_dir, tmp_path, replies)
    assert "HTTP 400" in str(info.value)


def test_timeouts(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"delay_s": 1.5, "reply": replies["perceiver"][0]}]
    with pytest.raises(ProviderTimeout):
        _run(examples_dir, tmp_path, replies, config=EngineConfig(request_timeout_s=0.3))


def test_critic_diagnosis_is_repaired_by_the_actor(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    plan = json.loads(replies["planner"][0])
    plan["timeline"][2]["controls"][0] = {"mode": "joint_position", "joint": "lid_hinge", "q_target_rad": -0.7, "curve": "ease_out"}
    replies["planner"] = [json.dumps(plan)]
    ok = replies["critic"][0]
    too_small = {**json.loads(ok), "semantic_ok": False,
                 "issues": [{"code": "MOTION_TOO_SMALL", "expected": "open fully (-1.4)", "observed": "-0.7", "segment_index": 2, "phase_type": "effect_motion", "joint": "lid_hinge", "link": "lid"}],
                 "param_fix_hints": [{"type": "adjust_joint_target", "joint": "lid_hinge", "segment_index": 2, "phase_type": "effect_motion", "direction": "increase", "strength": "extra_large", "why": "half open"}]}
    replies["critic"] = [{"match": "joint lid_hinge", "reply": json.dumps(too_small)}, ok]
    _, _ = _run(examples_dir, tmp_path, replies)
    report = json.loads((tmp_path / "report.json").read_text())
    assert len(report["critic_rounds"]) == 2 and report["critic_rounds"][0]["patches"]
    assert report["final_state"].startswith("accepted (best round 1)")
    final = json.loads((tmp_path / "trajectory.jsonl").read_text().splitlines()[-1])["joint_angles"]
    assert final["lid_hinge"] == pytest.approx(-1.4, abs=1e-6)


def test_gemini_wire_format(tmp_path: Path, examples_dir: Path) -> None:
    result, script = _run(examples_dir, tmp_path, recorded("pedal_bin"), provider="gemini", models=(("critic", "geometric"),))
    first = script.requests[0]
    assert ":generateContent" in first["path"] and first["auth"] == "test-key"
    assert first["payload"]["generationConfig"]["responseMimeType"] == "application/json"
    assert result.report.final_state.startswith("accepted")


def test_images_reach_the_vlm_roles(tmp_path: Path, examples_dir: Path) -> None:
    """With rendering on, the perceiver gets reference/overlay views and the critic HEAD/TAIL keyframes."""
    _, script = _run(examples_dir, tmp_path, recorded("pedal_bin"), config=EngineConfig(render_images=True))
    def images(request: dict) -> list[str]:  # type: ignore[type-arg]
        content = request["payload"]["messages"][1]["content"]
        return [p["image_url"]["url"][:22] for p in content if isinstance(p, dict) and p.get("type") == "image_url"] if isinstance(content, list) else []
    perceiver = next(r for r in script.requests if r["role"] == "perceiver")
    assert len(images(perceiver)) == 8 and all(u.startswith("data:image/png;base64") for u in images(perceiver))
    critic = [r for r in script.requests if r["role"] == "critic"]
    assert critic and all(len(images(r)) == 2 for r in critic)
    planner = next(r for r in script.requests if r["role"] == "planner")
    assert images(planner) == []
    assert len(list((tmp_path / "images").glob("*.png"))) == 8
