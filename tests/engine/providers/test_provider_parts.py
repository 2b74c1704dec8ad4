"""Provider pieces on their own: profiles, schemas for structured output, key hygiene, transport records."""

from __future__ import annotations

import asyncio
import json

import pytest

from app.engine.agents.critique import Critique
from app.engine.contracts.causal import CausalDocument
from app.engine.errors import ProviderError, ProviderRateLimited
from app.engine.plan.schema import Plan
from app.engine.providers.http import Exchange, Timeouts, is_quota, make_client, post_json
from app.engine.providers.keys import clean_key, mask
from app.engine.providers.profiles import profile_for
from app.engine.providers.schemas import gemini_schema, json_schema
from tests.support.model_server import model_server


def test_profiles_by_family_and_overrides() -> None:
    assert profile_for("openai", "gpt-5-mini-2025-08-07").token_param == "max_completion_tokens"
    assert profile_for("openai", "gpt-5").temperature is None and profile_for("openai", "o3").temperature is None
    assert profile_for("openai", "gpt-4.1").token_param == "max_tokens" and profile_for("openai", "gpt-4.1").temperature == 0.0
    assert profile_for("openai", "org/gpt-4o-mini").price_in_per_mtok == 0.15
    assert profile_for("openai", "llama-3.1-8b").price_in_per_mtok is None
    assert profile_for("gemini", "gemini-2.5-pro").thinking_budget == 2048
    custom = profile_for("openai", "gpt-5", {"temperature": "0.2", "output_mode": "text", "max_output_tokens": "1000"})
    assert (custom.temperature, custom.output_mode, custom.max_output_tokens) == (0.2, "text", 1000)
    with pytest.raises(ProviderError, match="output_mode must be one of"):
        profile_for("openai", "gpt-5", {"output_mode": "xml"})
    assert profile_for("openai", "gpt-4.1").cost(1_000_000, 1_000_000) == 10.0


@pytest.mark.parametrize("model", [CausalDocument, Plan, Critique])
def test_gemini_schema_is_in_the_openapi_subset(model: type) -> None:
    text = json.dumps(gemini_schema(model))
    for word in ("$ref", "$defs", "additionalProperties", "prefixItems", "const", '"null"', "title"):
        assert word not in text, word
    assert json_schema(model)["type"] == "object"


def test_keys_are_stripped_checked_and_masked() -> None:
    assert clean_key(" sk-abc\r\n", "openai") == "sk-abc" and clean_key("  ", "openai") is None
    with pytest.raises(ProviderError, match="space or control character at position 5 of 7"):
        clean_key("sk-a bc", "openai")
    masked = mask("bad key sk-abcdef\r (sk-abcdef)", "sk-abcdef\r")
    assert "sk-abcdef" not in masked and masked.count("[redacted key]") == 2


def test_quota_bodies() -> None:
    assert is_quota({"code": "insufficient_quota"}) and is_quota({"type": "insufficient_quota"})
    assert is_quota({"details": [{"@type": "type.googleapis.com/google.rpc.QuotaFailure", "violations": [{"quotaId": "GenerateRequestsPerDayPerProjectPerModel"}]}]})
    assert not is_quota({"code": "rate_limit_exceeded"})


def test_transport_attempts_and_the_retry_budget() -> None:
    async def call(url: str) -> Exchange:
        exchange = Exchange(url=url + "/chat/completions", headers={}, provider="openai")
        client = make_client(Timeouts())
        try:
            with pytest.raises(ProviderRateLimited):
                await post_json(client, exchange, {"messages": [{"role": "system", "content": "You are the planner"}]}, attempts=3)
        finally:
            await client.aclose()
        return exchange

    with model_server({"planner": [{"status": 429}]}) as (url, script):
        exchange = asyncio.run(call(url))
    assert [a.outcome for a in exchange.attempts] == ["rate_limited"] * 3 and len(script.requests) == 3
    assert all(a.status == 429 for a in exchange.attempts)


@pytest.mark.parametrize("name", ["../../admin/delete?confirm=1#", "gemini pro", "models/../x", "a%2Fb", ""])
def test_a_gemini_model_name_cannot_change_the_url(name: str) -> None:
    """The name goes into the URL path: anything but plain segments is refused before a request is built."""
    from app.engine.providers.gemini import GeminiModel

    with pytest.raises(ProviderError, match="invalid Gemini model name"):
        GeminiModel(name, api_key="k", base_url="http://127.0.0.1:9")


@pytest.mark.parametrize("name", ["gemini-2.5-pro", "tunedModels/my-model-1", "gemini-1.5-flash-001"])
def test_ordinary_gemini_model_names_are_accepted(name: str) -> None:
    from app.engine.providers.gemini import GeminiModel

    assert GeminiModel(name, api_key="k", base_url="http://127.0.0.1:9").model == name


@pytest.mark.parametrize(("name", "segment"), [("gemini-2.5-pro", "gemini-2.5-pro"),
                                               ("../../admin/delete?confirm=1#", "..%2F..%2Fadmin%2Fdelete%3Fconfirm%3D1%23")])
def test_the_gemini_url_escapes_the_model_name_even_past_the_name_check(name: str, segment: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Defence in depth: were the name check ever loosened, the name is still one escaped segment under models/
    (before: pasted as is, '../../admin/delete?confirm=1#' posted to /admin/delete with the server's key)."""
    from app.engine.providers import gemini
    from app.engine.providers.base import Message, ModelRequest

    monkeypatch.setattr(gemini, "valid_model_name", lambda _name: True)

    async def call(base: str) -> None:
        model = gemini.GeminiModel(name, api_key="k", base_url=base, attempts=1)
        await model.complete(ModelRequest(system="You are the planner", messages=(Message(role="user", text="hi"),)))

    with model_server({"planner": ["plain text"]}) as (url, script):
        asyncio.run(call(url.removesuffix("/v1") + "/v1beta"))
    assert [r["path"] for r in script.requests] == [f"/v1beta/models/{segment}:generateContent"]
