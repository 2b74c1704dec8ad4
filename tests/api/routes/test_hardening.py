"""The service under attack from a client with a valid key: quotas, model names, provider keys, leaks.

Each test here failed before its fix (issue "First hour of a new user, and the service under attack").
"""

from __future__ import annotations

import uuid

import pytest
from fastapi.testclient import TestClient

from app.core.config import Settings
from app.main import create_app
from tests.api.routes.test_animations import submit
from tests.support import upload_assets as assets


def _app(settings: Settings, sent: list[uuid.UUID], **changes: object) -> TestClient:
    from app.api.deps import get_enqueuer

    application = create_app(settings.model_copy(update=changes))
    application.dependency_overrides[get_enqueuer] = lambda: sent.append
    return TestClient(application)


# --- 2. a per-client cap on queued jobs and on batches ---------------------------------------------
def test_a_client_cannot_queue_more_than_its_share_of_jobs(settings, alice, bob, sent) -> None:
    with _app(settings, sent, max_active_jobs_per_client=2) as http:
        for _ in range(2):
            assert submit(http, alice.headers, upload=assets.hinge_zip("-quota")).status_code == 202
        refused = submit(http, alice.headers, upload=assets.hinge_zip("-quota"))
        assert refused.status_code == 429 and refused.headers["Retry-After"]
        assert "2 jobs queued or running" in refused.json()["detail"]
        assert submit(http, bob.headers, upload=assets.hinge_zip("-quota")).status_code == 202  # others are not blocked
        first = http.get("/v1/animations", headers=alice.headers).json()["data"][0]
        assert http.delete(first["url"], headers=alice.headers).status_code == 200
        assert submit(http, alice.headers, upload=assets.hinge_zip("-quota")).status_code == 202


def test_a_batch_counts_against_the_cap(settings, alice, sent) -> None:
    with _app(settings, sent, max_active_jobs_per_client=3) as http:
        asset = http.post("/v1/assets", headers=alice.headers, files=[("asset", assets.hinge_zip("-bq"))]).json()
        cases = [{"asset": asset["id"], "prompt": "open"} for _ in range(4)]
        refused = http.post("/v1/batches", headers=alice.headers, json={"cases": cases})
        assert refused.status_code == 429, refused.text
        assert http.post("/v1/batches", headers=alice.headers, json={"cases": cases[:3]}).status_code == 202
        assert sent and len(sent) == 3


# --- 3. a job field must never reach the provider URL; no request without the server's key ---------
EVIL_MODEL = "../../../admin/delete?confirm=1#"


@pytest.mark.parametrize("name", [EVIL_MODEL, "gemini pro", "a/../b", "model%2F..", "x?y=1", "/abs", "a//b"])
def test_model_names_follow_a_strict_pattern(http, alice, sent, name) -> None:
    response = submit(http, alice.headers, provider="offline", perceiver_model=name)
    assert response.status_code == 422, response.text
    assert "perceiver_model" in str(response.json()["detail"]) and sent == []


@pytest.mark.parametrize("name", ["gpt-4.1", "gemini-2.5-pro", "meta-llama/Llama-3.1-8B-Instruct", "qwen2.5:7b", "geometric"])
def test_real_model_names_pass(http, alice, sent, name) -> None:
    assert submit(http, alice.headers, provider="offline", critic_model=name).status_code == 202


def test_batch_options_follow_the_same_pattern(http, alice, sent) -> None:
    asset = http.post("/v1/assets", headers=alice.headers, files=[("asset", assets.hinge_zip("-evil"))]).json()
    body = {"options": {"planner_model": EVIL_MODEL}, "cases": [{"asset": asset["id"], "prompt": "open"}]}
    assert http.post("/v1/batches", headers=alice.headers, json=body).status_code == 422 and sent == []


@pytest.mark.parametrize("provider", ["openai", "gemini"])
def test_a_provider_without_a_server_key_is_refused(http, alice, sent, provider) -> None:
    response = submit(http, alice.headers, provider=provider)
    assert response.status_code == 422, response.text
    assert f"{provider.upper()}_API_KEY" in response.json()["detail"] and sent == []
    asset = http.post("/v1/assets", headers=alice.headers, files=[("asset", assets.hinge_zip("-nokey"))]).json()
    body = {"options": {"provider": provider}, "cases": [{"asset": asset["id"], "prompt": "open"}]}
    assert http.post("/v1/batches", headers=alice.headers, json=body).status_code == 422
