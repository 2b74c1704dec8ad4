"""Replies the way real models send them: wrapped JSON, reasoning models, endpoints that reject parameters, truncation."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.engine.errors import RoleOutputError
from tests.engine.providers.conftest import NO_RENDER, run_model
from tests.support.model_server import recorded

GEOMETRIC = (("critic", "geometric"),)


def _plain(text: str) -> str:
    return json.dumps(json.loads(text.strip().removeprefix("```json").removesuffix("```")))


@pytest.mark.parametrize("shape", ["fenced", "prose", "think", "comments", "list", "tool"])
def test_wrapped_json_is_read(shape: str, tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"text": _plain(replies["perceiver"][0]), "shape": shape}]
    replies["planner"] = [{"text": _plain(replies["planner"][0]), "shape": shape}]
    run = run_model(examples_dir, tmp_path, replies, config=NO_RENDER, models=GEOMETRIC)
    assert run.report["final_state"].startswith("accepted")
    assert [c["attempts"] for c in run.report["role_calls"] if c["role"] in ("perceiver", "planner")] == [1, 1]
    if shape == "tool":
        assert run.calls("planner")[0]["finish_reason"] == "tool_calls"


@pytest.mark.parametrize("provider", ["openai", "gemini"])
def test_reasoning_model_profile_sends_what_it_accepts(provider: str, tmp_path: Path, examples_dir: Path) -> None:
    model = "gpt-5" if provider == "openai" else "gemini-2.5-flash"
    models = (("perceiver", model), ("planner", model), ("critic", "geometric"))
    run = run_model(examples_dir, tmp_path, recorded("pedal_bin"), provider=provider, models=models, config=NO_RENDER,
                    reasoning_models=frozenset({"gpt-5"}))
    payload = run.script.requests[0]["payload"]
    if provider == "openai":
        assert payload["max_completion_tokens"] == 16384 and "max_tokens" not in payload and "temperature" not in payload
    else:
        assert payload["generationConfig"]["thinkingConfig"] == {"thinkingBudget": 1024}
    assert len(run.script.requests) == 2  # no rejected request


def test_unknown_reasoning_model_is_adapted_to_after_its_400s(tmp_path: Path, examples_dir: Path) -> None:
    models = (("perceiver", "acme-reasoner"), ("planner", "acme-reasoner"), ("critic", "geometric"))
    run = run_model(examples_dir, tmp_path, recorded("pedal_bin"), models=models, config=NO_RENDER, reasoning_models=frozenset({"acme-reasoner"}))
    first, second = run.calls("perceiver")[0], run.calls("planner")[0]
    assert [a["outcome"] for a in first["transport"]] == ["client_error", "client_error", "ok"]
    assert "max_completion_tokens" in first["transport"][0]["error"]
    assert [a["outcome"] for a in second["transport"]] == ["ok"]  # the model keeps what worked
    last = run.script.of("planner")[-1]["payload"]
    assert "max_completion_tokens" in last and "temperature" not in last


def test_endpoint_that_rejects_json_object_gets_json_schema(tmp_path: Path, examples_dir: Path) -> None:
    run = run_model(examples_dir, tmp_path, recorded("pedal_bin"), models=GEOMETRIC, config=NO_RENDER,
                    profile=(("output_mode", "json_object"),), rejects_json_object=True)
    call = run.calls("perceiver")[0]
    assert [a["outcome"] for a in call["transport"]] == ["client_error", "ok"] and call["output_mode"] == "json_schema"
    assert run.report["final_state"].startswith("accepted")


def test_truncated_reply_is_asked_again_with_more_room(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["planner"] = [{"text": _plain(replies["planner"][0]), "needs_tokens": 12000}]
    run = run_model(examples_dir, tmp_path, replies, models=GEOMETRIC, config=NO_RENDER)
    calls = run.calls("planner")
    assert calls[0]["finish_reason"] == "length" and "output limit of 8192" in calls[0]["error"] and calls[0]["usage"]["output_tokens"] > 0
    assert calls[1]["error"] is None
    limits = [r["payload"]["max_tokens"] for r in run.script.of("planner")]
    assert limits == [8192, 16384]


def test_truncation_at_the_cap_says_so(tmp_path: Path, examples_dir: Path) -> None:
    replies = recorded("pedal_bin")
    replies["planner"] = [{"text": _plain(replies["planner"][0]), "needs_tokens": 12000}]
    run = run_model(examples_dir, tmp_path, replies, models=GEOMETRIC, config=NO_RENDER, profile=(("max_output_tokens_cap", "8192"),),
                    expect=RoleOutputError)
    assert "cut at the output limit of 8192" in str(run.error) and "max_output_tokens_cap" in str(run.error)
    assert len(run.script.of("planner")) == 1


def test_gemini_thinking_that_uses_up_the_limit_is_retried(tmp_path: Path, examples_dir: Path) -> None:
    models = (("perceiver", "gemini-2.5-flash"), ("planner", "gemini-2.5-flash"), ("critic", "geometric"))
    run = run_model(examples_dir, tmp_path, recorded("pedal_bin"), provider="gemini", models=models, config=NO_RENDER,
                    profile=(("max_output_tokens", "2048"),), thinking_tokens=3000)
    first = run.calls("perceiver")[0]
    assert first["finish_reason"] == "length" and "thinking used all of it" in first["error"]
    assert [r["payload"]["generationConfig"]["maxOutputTokens"] for r in run.script.of("perceiver")] == [2048, 4096]
    assert run.report["final_state"].startswith("accepted")
