"""A model's bad days: blocks, failures per role (fallback or fail), keys, critic replies that do not fit, oscillation."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.engine.config import EngineConfig, FallbackPolicy
from app.engine.errors import ProviderBlocked, ProviderError, ProviderResponseError
from app.engine.providers.registry import ProviderConfig, make_roles
from tests.engine.providers.conftest import NO_RENDER, run_model
from tests.support.model_server import recorded

GEOMETRIC = (("critic", "geometric"),)
ISSUE = {"code": "MOTION_TOO_SMALL", "expected": "open fully", "observed": "-0.7", "segment_index": 2, "phase_type": "effect_motion",
         "joint": "lid_hinge", "link": "lid"}


def _verdict(ok_text: str, issue: dict, hint: dict | None = None) -> str:  # type: ignore[type-arg]
    hints = [hint] if hint else []
    return json.dumps({**json.loads(ok_text), "semantic_ok": False, "issues": [issue], "param_fix_hints": hints})


def test_gemini_prompt_block_names_the_reason(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"block": "PROHIBITED_CONTENT"}]
    run = run_model(examples_dir, tmp_path, replies, provider="gemini", models=GEOMETRIC, config=NO_RENDER, expect=ProviderBlocked)
    assert "PROHIBITED_CONTENT" in str(run.error) and run.report["error_kind"] == "ProviderBlocked"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.json"]


def test_refusal_is_a_block(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["planner"] = [{"refusal": "I can't help with that."}]
    run = run_model(examples_dir, tmp_path, replies, models=GEOMETRIC, config=NO_RENDER, expect=ProviderBlocked)
    assert "refused: I can't help with that." in str(run.error)


def test_critic_content_filter_falls_back_to_the_geometric_critic(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["critic"] = [{"block": "content_filter"}]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER)
    report = run.report
    assert report["final_state"].startswith("accepted") and "critic" in report["fallbacks"]
    assert any("critic: the model gave no usable answer (ProviderBlocked" in w for w in report["warnings"])
    assert report["critic_rounds"][0]["critic"] == "offline:offline-rules-2 (fallback)"
    assert (tmp_path / "animation.glb").is_file()
    assert len(run.script.of("critic")) >= 1 and all(c["error"] for c in run.calls("critic") if c["provider"] == "openai")


def test_critic_failure_with_fallback_fail_keeps_the_plan_and_writes_everything(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["critic"] = ["I think the lid looks fine."]
    config = EngineConfig(render_images=False, fallback=FallbackPolicy(critic="fail"))
    run = run_model(examples_dir, tmp_path, replies, config=config)
    report = run.report
    assert report["final_state"] == "critic_failed (best round 0)"
    assert report["critic_rounds"][0]["error"].startswith("critic: no valid reply after 3 attempts")
    for name in ("causal.json", "plan.json", "trajectory.jsonl", "animation.glb", "report.json"):
        assert (tmp_path / name).is_file(), name
    assert report["usage_by_role"]["critic"]["failed_calls"] >= 3


def test_perceiver_quota_with_fallback_offline_uses_the_offline_perceiver(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"status": 429, "quota": True}]
    config = EngineConfig(render_images=False, fallback=FallbackPolicy(perceiver="offline"))
    run = run_model(examples_dir, tmp_path, replies, config=config, models=GEOMETRIC)
    report = run.report
    assert "perceiver" in report["fallbacks"] and "ProviderQuotaExceeded" in report["fallbacks"]["perceiver"]
    assert [c["provider"] for c in run.calls("perceiver")] == ["openai", "offline"]
    assert report["final_state"].startswith("accepted")


def test_critic_reply_that_does_not_fit_the_asset_goes_back(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    ok = replies["critic"][0]
    wrong = _verdict(ok, {**ISSUE, "joint": "lid_joint"}, {"type": "adjust_joint_target", "joint": "pedal_pivot", "segment_index": 2,
                                                           "phase_type": "effect_motion", "direction": "increase", "strength": "large"})
    replies["critic"] = [{"match": "joint lid_hinge", "reply": wrong}, ok]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER)
    lid_calls = [r for r in run.script.of("critic") if "joint lid_hinge" in json.dumps(r["payload"]["messages"][1])]
    feedback = lid_calls[1]["payload"]["messages"][-1]["content"]
    assert "issues[0].joint: unknown joint 'lid_joint'" in feedback
    assert "param_fix_hints[0].joint: segment 2 has no control of 'pedal_pivot'" not in feedback  # pedal is held in segment 2
    assert run.report["final_state"].startswith("accepted")


def test_critic_hint_on_an_uncontrolled_joint_is_refused(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    ok = replies["critic"][0]
    wrong = _verdict(ok, ISSUE, {"type": "adjust_joint_target", "joint": "lid_hinge", "segment_index": 0, "phase_type": "control_actuation",
                                 "direction": "increase", "strength": "large"})
    replies["critic"] = [{"match": "joint lid_hinge", "reply": wrong}, ok]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER)
    lid_calls = [r for r in run.script.of("critic") if "joint lid_hinge" in json.dumps(r["payload"]["messages"][1])]
    assert "param_fix_hints[0].joint: segment 0 has no control of 'lid_hinge' (it controls: pedal_pivot)" in lid_calls[1]["payload"]["messages"][-1]["content"]


def test_a_patch_that_undoes_an_earlier_one_stops_the_loop(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    ok = replies["critic"][0]
    hint = {"type": "adjust_joint_target", "joint": "lid_hinge", "segment_index": 2, "phase_type": "effect_motion", "strength": "medium"}
    up = _verdict(ok, ISSUE, {**hint, "direction": "increase"})
    down = _verdict(ok, {**ISSUE, "code": "EXCESSIVE_MOTION"}, {**hint, "direction": "decrease"})
    replies["critic"] = [{"match": "joint lid_hinge", "reply": up}, {"match": "joint lid_hinge", "reply": down}, ok]
    plan = json.loads(replies["planner"][0])
    plan["timeline"][2]["controls"][0] = {"mode": "joint_position", "joint": "lid_hinge", "q_target_rad": -1.0, "curve": "ease_out"}
    replies["planner"] = [json.dumps(plan)]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER)
    report = run.report
    assert report["final_state"].startswith("oscillation")
    assert report["critic_rounds"][0]["patches"] and report["critic_rounds"][1]["rejected_patches"]
    assert any("would undo an earlier patch" in w for w in report["warnings"])


def test_key_with_a_carriage_return_is_stripped_and_never_shown(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    secret = "sk-test-0123456789abcdef"
    replies["perceiver"] = [{"status": 401, "body": {"error": {"message": f"Incorrect API key provided: {secret}.", "type": "invalid_request_error"}}}]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER, models=GEOMETRIC, api_key=secret + "\r", expect=ProviderResponseError)
    assert run.script.requests[0]["auth"] == f"Bearer {secret}"
    assert secret not in str(run.error) and "[redacted key]" in str(run.error)
    assert secret not in (tmp_path / "report.json").read_text()


def test_non_ascii_key_is_a_clear_error() -> None:
    with pytest.raises(ProviderError) as info:
        make_roles("openai", ProviderConfig(api_key="sk-abc\u2013def", base_url="http://127.0.0.1:9/v1"))
    message = str(info.value)
    assert "non-ASCII character at position 7 of 10" in message and "abc" not in message


def test_coverage_reply_is_checked_against_links_and_the_camera_bank(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    good = json.loads(replies["coverage"][0])
    bad = {**good, "selected_views_by_link": {**good["selected_views_by_link"], "lid_panel": good["selected_views_by_link"]["lid"]},
           "proposed_views": [{"azimuth_deg": 15, "elevation_deg": 20, "distance_scale": 1.0, "fov_deg": 35}]}
    replies["coverage"] = [json.dumps(bad), json.dumps(good)]
    run = run_model(examples_dir, tmp_path, replies)
    feedback = run.script.of("coverage")[1]["payload"]["messages"][-1]["content"]
    assert "selected_views_by_link.lid_panel: not a required link" in feedback and "proposed_views[0]: values must come from" in feedback
    assert {c["source"] for c in run.report["coverage"]} == {"model"}


def test_failed_coverage_falls_back_to_the_geometric_choice(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["coverage"] = ["no idea"]
    run = run_model(examples_dir, tmp_path, replies)
    assert {c["source"] for c in run.report["coverage"]} == {"geometric"}
    assert any("coverage selection failed" in w for w in run.report["warnings"]) and run.report["final_state"].startswith("accepted")
