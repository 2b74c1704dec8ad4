"""POST /v1/batches and GET /v1/batches/{id}."""

from __future__ import annotations

import uuid

from fastapi.testclient import TestClient

from app.crud import jobs as crud_jobs
from app.db.models import Job
from app.main import create_app
from tests.support import upload_assets as assets


def _asset(http: TestClient, headers: dict[str, str], variant: str) -> dict:  # type: ignore[type-arg]
    return http.post("/v1/assets", headers=headers, files=[("asset", assets.hinge_zip(variant))]).json()


def test_batch_queues_one_job_per_case(http, alice, db, sent) -> None:
    first, second = _asset(http, alice.headers, "-b1"), _asset(http, alice.headers, "-b2")
    body = {
        "name": "nightly",
        "options": {"fps": 24},
        "cases": [
            {"asset": first["id"], "prompt": "open the lid", "case_id": "a"},
            {"asset": second["sha256"], "prompt": "close it", "case_id": "b", "options": {"fps": 30, "max_critic_rounds": 0}},
        ],
    }
    response = http.post("/v1/batches", headers=alice.headers, json=body)
    assert response.status_code == 202, response.text
    batch = response.json()
    assert batch["count"] == 2 and batch["done"] is False and batch["status_counts"]["queued"] == 2
    assert [case["case_id"] for case in batch["cases"]] == ["a", "b"]
    assert sorted(sent) == sorted(uuid.UUID(case["job_id"]) for case in batch["cases"])
    jobs = {case["case_id"]: http.get(case["url"], headers=alice.headers).json() for case in batch["cases"]}
    assert jobs["a"]["options"] == {"fps": 24} and jobs["b"]["options"] == {"fps": 30, "max_critic_rounds": 0}
    assert jobs["a"]["batch_id"] == batch["id"]
    for case in batch["cases"]:
        job = db.get(Job, uuid.UUID(case["job_id"]))
        crud_jobs.mark_running(db, job=job, worker="w")
        crud_jobs.mark_failed(db, job=job, error="boom", kind="ExecutionError")
    done = http.get(batch["url"], headers=alice.headers).json()
    assert done["done"] is True and done["status_counts"]["failed"] == 2


def test_unknown_asset_in_a_case_is_422_and_creates_nothing(http, alice, sent) -> None:
    known = _asset(http, alice.headers, "-b3")
    body = {"cases": [{"asset": known["id"], "prompt": "x"}, {"asset": "f" * 64, "prompt": "y"}]}
    response = http.post("/v1/batches", headers=alice.headers, json=body)
    assert response.status_code == 422 and "case 1" in response.json()["detail"]
    assert sent == [] and http.get("/v1/animations", headers=alice.headers).json()["count"] == 0


def test_batch_validation(http, alice) -> None:
    for body in ({"cases": []}, {"cases": [{"asset": "x"}]}, {"cases": [{"asset": "x", "prompt": " "}]}, {"x": 1},
                 {"cases": [{"asset": "x", "prompt": "p", "options": {"fps": 12}}]}):
        assert http.post("/v1/batches", headers=alice.headers, json=body).status_code == 422, body


def test_too_many_cases_is_413(settings, alice) -> None:
    with TestClient(create_app(settings.model_copy(update={"max_batch_cases": 2}))) as http:
        cases = [{"asset": "x", "prompt": "p"}] * 3
        assert http.post("/v1/batches", headers=alice.headers, json={"cases": cases}).status_code == 413


def test_another_clients_batch_is_404(http, alice, bob) -> None:
    asset = _asset(http, alice.headers, "-b4")
    url = http.post("/v1/batches", headers=alice.headers, json={"cases": [{"asset": asset["id"], "prompt": "x"}]}).json()["url"]
    assert http.get(url, headers=bob.headers).status_code == 404
    assert http.get(f"/v1/batches/{uuid.uuid4()}", headers=alice.headers).status_code == 404


def test_lone_surrogates_in_json_are_422_not_500(http, alice) -> None:
    body = '{"cases": [{"asset": "x", "prompt": "p\\ud800", "case_id": "c\\udfff"}], "name": "\\ud800"}'
    response = http.post("/v1/batches", headers={**alice.headers, "content-type": "application/json"}, content=body.encode())
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"][0] == "body"
