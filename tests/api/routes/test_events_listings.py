"""GET /v1/animations/{id}/events (server-sent events until the job finishes), GET /v1/assets, GET /v1/batches."""

from __future__ import annotations

import json
import threading
import time
import uuid

from app.crud import jobs as crud_jobs
from app.db.models import Job
from app.db.session import session_factory
from tests.api.routes.test_animations import submit
from tests.support import upload_assets as assets


def _events(text: str) -> list[tuple[str, dict]]:
    events = []
    for block in text.split("\n\n"):
        lines = block.splitlines()
        name = next((line[6:].strip() for line in lines if line.startswith("event:")), None)
        data = "".join(line[5:].strip() for line in lines if line.startswith("data:"))
        if name:
            events.append((name, json.loads(data)))
    return events


def test_events_follow_a_job_until_it_finishes(http, alice, settings) -> None:
    job_id = uuid.UUID(submit(http, alice.headers).json()["id"])

    def work() -> None:
        with session_factory(settings.sqlalchemy_url)() as session:
            time.sleep(0.4)
            job = session.get(Job, job_id)
            crud_jobs.mark_running(session, job=job, worker="w")
            crud_jobs.set_progress(session, job=job, stage="perceive", progress=35)
            time.sleep(0.6)
            crud_jobs.mark_succeeded(session, job=job, timings={"total": 1.0})

    worker = threading.Thread(target=work)
    worker.start()
    began = time.monotonic()
    response = http.get(f"/v1/animations/{job_id}/events", headers=alice.headers)
    worker.join()
    assert response.status_code == 200 and response.headers["content-type"].startswith("text/event-stream")
    assert response.text.startswith("retry: ")
    events = _events(response.text)
    states = [(data["status"], data["stage"]) for name, data in events if name == "job"]
    assert states[0] == ("queued", None) and ("running", "perceive") in states and states[-1][0] == "succeeded"
    assert events[-1] == ("end", {"status": "succeeded"})
    assert time.monotonic() - began < 10


def test_events_of_a_finished_job_end_at_once(http, alice) -> None:
    url = submit(http, alice.headers).json()["url"]
    http.delete(url, headers=alice.headers)
    events = _events(http.get(f"{url}/events", headers=alice.headers).text)
    assert [name for name, _ in events] == ["job", "end"] and events[0][1]["status"] == "cancelled"


def test_events_need_the_owner(http, alice, bob) -> None:
    url = submit(http, alice.headers).json()["url"]
    assert http.get(f"{url}/events", headers=bob.headers).status_code == 404
    assert http.get(f"{url}/events").status_code == 401


def test_assets_and_batches_are_listed_per_client(http, alice, bob) -> None:
    first = http.post("/v1/assets", headers=alice.headers, files=[("asset", assets.hinge_zip("-l1"))]).json()
    second = http.post("/v1/assets", headers=alice.headers, files=[("asset", assets.hinge_zip("-l2"))]).json()
    listed = http.get("/v1/assets", headers=alice.headers).json()["data"]
    assert [a["id"] for a in listed] == [second["id"], first["id"]] and listed[0]["filename"] == "hinge-l2.zip"
    assert http.get("/v1/assets", headers=bob.headers).json()["data"] == []
    batch = http.post("/v1/batches", headers=alice.headers, json={
        "name": "two", "cases": [{"asset": first["id"], "prompt": "open"}, {"asset": second["id"], "prompt": "open", "case_id": "b"}],
    }).json()
    batches = http.get("/v1/batches", headers=alice.headers).json()["data"]
    assert [(b["id"], b["name"], b["count"]) for b in batches] == [(batch["id"], "two", 2)]
    assert http.get("/v1/batches", headers=bob.headers).json()["data"] == []
    assert http.get("/v1/batches", headers={}).status_code == 401
