"""POST/GET/DELETE /v1/animations: submit, read, list, cancel, isolation between clients."""

from __future__ import annotations

import uuid

import pytest
from fastapi.testclient import TestClient

from app.api.queue import QueueUnavailable
from app.crud import jobs as crud_jobs
from app.db.models import Job, JobStatus
from tests.support import upload_assets as assets


def submit(http: TestClient, headers: dict[str, str], prompt: str = "open the lid", upload=None, **fields):  # type: ignore[no-untyped-def]
    name, data = upload or assets.hinge_zip()
    return http.post("/v1/animations", headers=headers, data={"prompt": prompt, **fields}, files=[("asset", (name, data))])


def test_submit_returns_202_with_a_pollable_url(http, alice, sent) -> None:
    response = submit(http, alice.headers, fps="30", max_critic_rounds="1", provider="offline")
    assert response.status_code == 202, response.text
    body = response.json()
    assert body["status"] == "queued" and response.headers["location"] == body["url"]
    assert sent == [uuid.UUID(body["id"])]
    job = http.get(body["url"], headers=alice.headers).json()
    assert job["prompt"] == "open the lid" and job["progress"] == 0 and job["artifacts"] == []
    assert job["options"] == {"fps": 30, "max_critic_rounds": 1, "provider": "offline"}
    assert job["created_at"].endswith("Z") or job["created_at"].endswith("+00:00")


def test_submit_by_asset_reference(http, alice, sent) -> None:
    asset = http.post("/v1/assets", headers=alice.headers, files=[("asset", assets.hinge_zip("-ref"))]).json()
    for ref in (asset["id"], asset["sha256"]):
        response = http.post("/v1/animations", headers=alice.headers, files=[("prompt", (None, "open it")), ("asset_ref", (None, ref))])
        assert response.status_code == 202, response.text
        assert http.get(response.json()["url"], headers=alice.headers).json()["asset_id"] == asset["id"]
    assert len(sent) == 2


def test_asset_reference_of_another_client_is_404(http, alice, bob) -> None:
    asset = http.post("/v1/assets", headers=alice.headers, files=[("asset", assets.hinge_zip("-private"))]).json()
    response = http.post("/v1/animations", headers=bob.headers, files=[("prompt", (None, "x")), ("asset_ref", (None, asset["sha256"]))])
    assert response.status_code == 404


def test_files_and_reference_together_are_422(http, alice) -> None:
    response = submit(http, alice.headers, asset_ref="0" * 64)
    assert response.status_code == 422 and "not both" in response.json()["detail"]


@pytest.mark.parametrize(
    ("fields", "where"),
    [
        ({"prompt": "   "}, "prompt"),
        ({"fps": "25"}, "fps"),
        ({"fps": "abc"}, "fps"),
        ({"max_critic_rounds": "9"}, "max_critic_rounds"),
        ({"provider": "nonsense"}, "provider"),
        ({"exports": "usd,gltf"}, "exports"),
        ({"prompt": "x" * 5000}, "prompt"),
    ],
)
def test_invalid_fields_are_422_naming_the_field(http, alice, sent, fields, where) -> None:
    response = submit(http, alice.headers, **{"prompt": "open", **fields})
    assert response.status_code == 422, response.text
    assert any(error["loc"] == ["body", where] for error in response.json()["detail"])
    assert sent == []


def test_exports_are_stored_as_known_names(http, alice, sent) -> None:
    response = submit(http, alice.headers, exports=" NPZ, usd ,usd")
    assert response.status_code == 202, response.text
    job = http.get(response.json()["url"], headers=alice.headers).json()
    assert job["options"]["exports"] == ["usd", "npz"]


def test_missing_prompt_is_422(http, alice) -> None:
    response = http.post("/v1/animations", headers=alice.headers, files=[("asset", assets.hinge_zip())])
    assert response.status_code == 422


def test_bad_asset_creates_no_job(http, alice, db, sent) -> None:
    response = submit(http, alice.headers, upload=assets.missing_mesh())
    assert response.status_code == 422 and "missing.obj" in response.json()["detail"]
    assert http.get("/v1/animations", headers=alice.headers).json()["count"] == 0
    assert sent == []


def test_another_clients_job_is_404(http, alice, bob) -> None:
    url = submit(http, alice.headers).json()["url"]
    assert http.get(url, headers=bob.headers).status_code == 404
    assert http.delete(url, headers=bob.headers).status_code == 404
    assert http.get(url + "/report.json", headers=bob.headers).status_code == 404
    assert http.get(url, headers=alice.headers).status_code == 200


@pytest.mark.parametrize("path", ["/v1/animations/not-a-uuid", "/v1/animations/123", "/v1/batches/zzz"])
def test_malformed_ids_are_422(http, alice, path) -> None:
    assert http.get(path, headers=alice.headers).status_code == 422


def test_unknown_job_is_404(http, alice) -> None:
    assert http.get(f"/v1/animations/{uuid.uuid4()}", headers=alice.headers).status_code == 404


def test_list_is_paginated_newest_first(http, alice, bob) -> None:
    ids = [submit(http, alice.headers, prompt=f"open {i}").json()["id"] for i in range(5)]
    submit(http, bob.headers)
    page = http.get("/v1/animations", headers=alice.headers, params={"limit": 2}).json()
    assert page["count"] == 5 and [job["id"] for job in page["data"]] == ids[::-1][:2]
    rest = http.get("/v1/animations", headers=alice.headers, params={"limit": 2, "offset": 4}).json()
    assert [job["id"] for job in rest["data"]] == [ids[0]]
    assert http.get("/v1/animations", headers=alice.headers, params={"status": "succeeded"}).json()["count"] == 0


@pytest.mark.parametrize("params", [{"limit": 0}, {"limit": 1000}, {"offset": -1}, {"status": "bogus"}, {"limit": "x"}])
def test_bad_query_parameters_are_422(http, alice, params) -> None:
    assert http.get("/v1/animations", headers=alice.headers, params=params).status_code == 422


def test_cancel_a_queued_job_at_once(http, alice) -> None:
    url = submit(http, alice.headers).json()["url"]
    response = http.delete(url, headers=alice.headers)
    assert response.status_code == 200 and response.json()["status"] == "cancelled"
    again = http.delete(url, headers=alice.headers)
    assert again.status_code == 200 and again.json()["status"] == "cancelled"


def test_cancel_a_running_job_sets_the_flag(http, alice, db) -> None:
    job_id = uuid.UUID(submit(http, alice.headers).json()["id"])
    crud_jobs.mark_running(db, job=db.get(Job, job_id), worker="w1")
    response = http.delete(f"/v1/animations/{job_id}", headers=alice.headers)
    assert response.status_code == 202
    assert response.json()["status"] == "running" and response.json()["cancel_requested"] is True


def test_cancel_a_finished_job_is_409(http, alice, db) -> None:
    job_id = uuid.UUID(submit(http, alice.headers).json()["id"])
    job = db.get(Job, job_id)
    crud_jobs.mark_running(db, job=job, worker="w1")
    crud_jobs.mark_succeeded(db, job=job, timings={"total": 1.0})
    response = http.delete(f"/v1/animations/{job_id}", headers=alice.headers)
    assert response.status_code == 409
    db.refresh(job)
    assert job.status == JobStatus.succeeded


def test_broker_down_is_503_and_leaves_no_queued_job(app, http, alice) -> None:
    from app.api.deps import get_enqueuer

    def refuse(_job_id: uuid.UUID) -> None:
        raise QueueUnavailable("connection refused")

    app.dependency_overrides[get_enqueuer] = lambda: refuse
    response = submit(http, alice.headers)
    assert response.status_code == 503 and response.headers["retry-after"]
    jobs = http.get("/v1/animations", headers=alice.headers).json()["data"]
    assert [(job["status"], job["error_kind"]) for job in jobs] == [("failed", "BrokerUnavailable")]


@pytest.mark.parametrize("fields", [{"prompt": "a\x00b"}, {"planner_model": "m\x00"}, {"critic_model": "tab\there"}])
def test_nul_and_control_characters_are_422_not_500(http, alice, fields) -> None:
    response = submit(http, alice.headers, **{"prompt": "open", **fields})
    assert response.status_code == 422, response.text


def test_nul_in_names_and_refs_is_404(http, alice) -> None:
    url = submit(http, alice.headers).json()["url"]
    for path in (f"{url}/files/a%00b", f"{url}/keyframes/a%00b", "/v1/assets/a%00b"):
        assert http.get(path, headers=alice.headers).status_code == 404, path
    batch = {"name": "n\x00", "cases": [{"asset": "x", "prompt": "p\x00", "case_id": "c\x00"}]}
    assert http.post("/v1/batches", headers=alice.headers, json=batch).status_code == 422
