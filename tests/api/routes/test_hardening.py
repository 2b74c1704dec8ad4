"""The service under attack from a client with a valid key: quotas, model names, provider keys, leaks.

Each test here failed before its fix (issue "First hour of a new user, and the service under attack").
"""

from __future__ import annotations

import uuid

import pytest
from fastapi.testclient import TestClient
from pydantic import SecretStr

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


# --- 6. smaller leaks -----------------------------------------------------------------------------
def test_metrics_are_not_open_to_everyone(app, settings, sent) -> None:
    """Every client's activity: loopback only without METRICS_TOKEN, else the token is required."""
    with TestClient(app, client=("203.0.113.7", 40000)) as remote:
        assert remote.get("/metrics").status_code == 403
    with TestClient(app, client=("127.0.0.1", 40000)) as local:
        assert local.get("/metrics").status_code == 200
    with _app(settings, sent, metrics_token=SecretStr("scrape-me")) as protected:
        assert protected.get("/metrics").status_code == 401
        assert protected.get("/metrics", headers={"Authorization": "Bearer wrong"}).status_code == 401
        assert protected.get("/metrics", headers={"Authorization": "Bearer scrape-me"}).status_code == 200


def test_validation_errors_do_not_echo_the_input(http, alice) -> None:
    secret_prompt = "confidential " * 200  # too long: 2600 characters
    response = submit(http, alice.headers, prompt=secret_prompt)
    assert response.status_code == 422 and "confidential" not in response.text
    huge_key = "k" * 5000
    body = {"cases": [{"asset": "x", "prompt": "open", huge_key: 1}]}
    response = http.post("/v1/batches", headers=alice.headers, json=body)
    assert response.status_code == 422 and huge_key not in response.text and len(response.text) < 2000


def test_a_malformed_job_id_is_a_422_saying_it_must_be_a_uuid(http, alice) -> None:
    for url in ("/v1/animations/not-a-uuid", "/v1/animations/not-a-uuid/plan.json", "/v1/batches/123"):
        response = http.get(url, headers=alice.headers)
        assert response.status_code == 422, url
        assert "must be a UUID such as 123e4567-e89b-12d3-a456-426614174000" in response.json()["detail"][0]["msg"], response.text


def test_batches_have_a_body_size_cap(settings, alice, sent) -> None:
    with _app(settings, sent, max_json_body_bytes=10_000) as http:
        body = {"cases": [{"asset": "a" * 64, "prompt": "p" * 1000} for _ in range(20)]}
        response = http.post("/v1/batches", headers=alice.headers, json=body)
        assert response.status_code == 413 and response.json()["kind"] == "PayloadTooLarge", response.text

        def chunks():  # no Content-Length: counted while it streams
            yield b'{"cases": ['
            for _ in range(40):
                yield b'{"asset": "' + b"a" * 64 + b'", "prompt": "' + b"p" * 500 + b'"},'
            yield b'{"asset": "x", "prompt": "y"}]}'

        streamed = http.post("/v1/batches", headers={**alice.headers, "Content-Type": "application/json"}, content=chunks())
        assert streamed.status_code == 413, streamed.text


def test_a_key_in_the_url_is_refused_and_never_logged(http, alice, caplog) -> None:
    import logging

    from app.core.logging import _RedactFilter

    for parameter in ("api_key", "token", "key"):
        response = http.get(f"/v1/animations?{parameter}={alice.key}")
        assert response.status_code == 400 and response.json()["kind"] == "CredentialInUrl"
        assert alice.key not in response.text
    record = logging.LogRecord("uvicorn.access", logging.INFO, __file__, 1, '%s - "%s %s HTTP/%s" %d',
                               ("127.0.0.1:5000", "GET", f"/v1/animations?limit=5&api_key={alice.key}", "1.1", 400), None)
    assert _RedactFilter().filter(record) and alice.key not in record.getMessage() and "api_key=[redacted]" in record.getMessage()


def test_a_damaged_output_is_not_served_under_its_old_etag(http, alice, db, settings) -> None:
    from app.crud import jobs as crud_jobs
    from app.db.models import Job

    url = submit(http, alice.headers).json()["url"]
    job = db.get(Job, uuid.UUID(url.rsplit("/", 1)[-1]))
    crud_jobs.mark_running(db, job=job, worker="w1")
    from app.core.storage import LocalStorage

    stored = LocalStorage(settings.storage_dir).put_bytes(f"jobs/{job.id}/plan.json", b'{"plan": 1}')
    crud_jobs.add_artifact(db, job=job, name="plan.json", storage_key=stored.key, sha256=stored.sha256, size_bytes=stored.size,
                           content_type="application/json")
    crud_jobs.mark_succeeded(db, job=job, timings={})
    good = http.get(f"{url}/plan.json", headers=alice.headers)
    assert good.status_code == 200 and good.headers["etag"] == f'"{stored.sha256}"'
    (settings.storage_dir / stored.key).write_bytes(b'{"plan": 2}')  # same size, other bytes
    damaged = http.get(f"{url}/plan.json", headers=alice.headers)
    assert damaged.status_code == 500 and damaged.json()["kind"] == "DamagedData" and "submit the job again" in damaged.text
