"""Model providers end to end against the local model server: recorded replies, feedback, transport."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.engine.config import EngineConfig
from app.engine.errors import ProviderQuotaExceeded, ProviderResponseError, ProviderTimeout, RoleOutputError
from tests.engine.providers.conftest import NO_RENDER, run_model
from tests.support.model_server import recorded


def _images(request: dict) -> list[str]:  # type: ignore[type-arg]
    content = request["payload"]["messages"][1]["content"]
    return [p["image_url"]["url"][:22] for p in content if isinstance(p, dict) and p.get("type") == "image_url"] if isinstance(content, list) else []


def test_recorded_replies_drive_the_whole_pipeline_with_images_by_default(tmp_path: Path, examples_dir: Path) -> None:
    run = run_model(examples_dir, tmp_path, recorded("pedal_bin"))
    report = run.report
    assert report["provider"] == "openai" and report["images"] is True
    assert {c["role"] for c in report["role_calls"]} == {"perceiver", "planner", "critic", "coverage"}
    assert set(report["prompt_versions"]) == {"perceiver", "planner", "critic", "coverage"}
    assert report["usage_by_role"]["perceiver"]["input_tokens"] > 0 and report["usage_by_role"]["critic"]["est_cost_usd"] > 0
    assert report["final_state"].startswith("accepted")
    first = run.script.requests[0]
    assert first["auth"] == "Bearer test-key"
    assert first["payload"]["response_format"]["type"] == "json_schema"
    assert first["payload"]["response_format"]["json_schema"]["name"] == "CausalDocument"
    assert first["payload"]["max_tokens"] == 8192 and first["payload"]["temperature"] == 0.0
    # images reach every VLM role: 8 views for the perceiver, 4 for coverage, HEAD/TAIL per critic case; none for the planner
    assert len(_images(run.script.of("perceiver")[0])) == 8
    assert len(_images(run.script.of("coverage")[0])) == 4
    assert run.script.of("critic") and all(len(_images(r)) == 2 for r in run.script.of("critic"))
    assert _images(run.script.of("planner")[0]) == []
    assert {c["link"]: c["source"] for c in report["coverage"]} == {"pedal": "model", "lid": "model"}
    angles = json.loads((tmp_path / "trajectory.jsonl").read_text().splitlines()[-1])["joint_angles"]
    assert angles["lid_hinge"] == pytest.approx(-1.4, abs=1e-6) and angles["pedal_pivot"] == pytest.approx(0.35, abs=1e-6)
    assert run.result is not None and run.result.outputs["glb"] == "animation.glb"
    assert len(list((tmp_path / "images").glob("*.png"))) == 8
    keyframes = sorted(p.name for p in (tmp_path / "keyframes").glob("*.png"))
    assert keyframes and all(name.startswith("round_00_TIMELINE_SAMPLE_") for name in keyframes) and len(keyframes) == 2 * len(run.script.of("critic"))


def test_no_render_is_a_warning(tmp_path: Path, examples_dir: Path) -> None:
    run = run_model(examples_dir, tmp_path, recorded("pedal_bin"), config=NO_RENDER)
    assert run.report["images"] is False
    assert any("rendering is off" in w and "perceiver and critic" in w for w in run.report["warnings"])
    assert all(_images(r) == [] for r in run.script.requests) and not run.script.of("coverage")


def test_invalid_reply_goes_back_as_feedback(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    bad = json.loads(replies["perceiver"][0].strip().removeprefix("```json").removesuffix("```"))
    bad["causal"]["effects"]["joint_targets"][1]["joint"] = "lid_joint"  # not a joint of this asset
    replies["perceiver"] = [json.dumps(bad), *replies["perceiver"]]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER)
    perceiver = run.script.of("perceiver")
    assert len(perceiver) == 2
    feedback = perceiver[1]["payload"]["messages"][-1]["content"]
    assert "causal.effects.joint_targets[1].joint" in feedback and "lid_joint" in feedback
    calls = run.calls("perceiver")
    assert calls[0]["error"] and calls[1]["attempts"] == 2 and calls[1]["error"] is None


def test_persistently_invalid_replies_fail_clearly_and_leave_no_stale_outputs(tmp_path: Path, examples_dir: Path) -> None:
    (tmp_path / "animation.glb").write_bytes(b"glTF from an earlier run")
    (tmp_path / "notes.txt").write_text("mine")
    replies = recorded("pedal_bin")
    replies["planner"] = ["this is not JSON"]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER, expect=RoleOutputError)
    assert "planner" in str(run.error) and "no JSON object" in str(run.error)
    report = run.report
    assert report["final_state"] == "failed: RoleOutputError" and report["error_kind"] == "RoleOutputError"
    assert [c["attempts"] for c in run.calls("planner")] == [1, 2, 3] and all(c["error"] for c in run.calls("planner"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.txt", "report.json"]


def test_rate_limit_is_retried_and_recorded(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"status": 429}, *replies["perceiver"]]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER)
    assert len(run.script.of("perceiver")) == 2
    call = run.calls("perceiver")[0]
    assert [a["outcome"] for a in call["transport"]] == ["rate_limited", "ok"] and call["transport"][0]["status"] == 429
    assert run.report["usage_by_role"]["perceiver"]["transport_retries"] == 1


def test_quota_error_fails_fast_with_the_providers_message(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"status": 429, "quota": True}]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER, expect=ProviderQuotaExceeded)
    assert len(run.script.of("perceiver")) == 1
    assert "exceeded your current quota" in str(run.error)
    assert run.calls("perceiver")[0]["transport"][0]["outcome"] == "quota"
    assert not (tmp_path / "animation.glb").exists()


def test_client_errors_give_up_with_a_typed_error(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"status": 400, "body": {"error": {"message": "Invalid image data", "type": "invalid_request_error", "param": "messages"}}}]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER, expect=ProviderResponseError)
    assert "HTTP 400" in str(run.error) and "Invalid image data" in str(run.error)


def test_a_stalled_server_times_out(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"stall_s": 1.5, "reply": replies["perceiver"][0]}]
    config = EngineConfig(render_images=False, request_timeout_s=0.3, call_timeout_s=1.0)
    run = run_model(examples_dir, tmp_path, replies, config=config, expect=ProviderTimeout)
    outcomes = [a["outcome"] for a in run.calls("perceiver")[0]["transport"]]
    assert outcomes and set(outcomes) == {"timeout"}
    assert "1 s" in str(run.error) or "in time" in str(run.error)


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
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER)
    report = run.report
    assert len(report["critic_rounds"]) == 2 and report["critic_rounds"][0]["patches"]
    patch = report["critic_rounds"][0]["patches"][0]
    assert patch["change"] == "target" and patch["value_before"] == pytest.approx(-0.7) and patch["value_after"] == pytest.approx(-1.4)
    assert report["critic_rounds"][0]["issues"][0]["code"] == "MOTION_TOO_SMALL"
    assert report["final_state"].startswith("accepted (best round 1)")
    final = json.loads((tmp_path / "trajectory.jsonl").read_text().splitlines()[-1])["joint_angles"]
    assert final["lid_hinge"] == pytest.approx(-1.4, abs=1e-6)


def test_gemini_wire_format(tmp_path: Path, examples_dir: Path) -> None:
    run = run_model(examples_dir, tmp_path, recorded("pedal_bin"), provider="gemini", models=(("critic", "geometric"),), config=NO_RENDER)
    first = run.script.requests[0]
    assert ":generateContent" in first["path"] and "gemini-2.5-pro" in first["path"] and first["auth"] == "test-key"
    config = first["payload"]["generationConfig"]
    assert config["responseMimeType"] == "application/json" and config["responseSchema"]["type"] == "object"
    assert "$ref" not in json.dumps(config["responseSchema"]) and "additionalProperties" not in json.dumps(config["responseSchema"])
    assert config["thinkingConfig"] == {"thinkingBudget": 2048} and config["maxOutputTokens"] == 16384
    assert run.report["final_state"].startswith("accepted")
    assert run.report["role_calls"][0]["est_cost_usd"] is not None
