"""Job progress and outputs as the API shows them, with the worker's writes simulated through CRUD."""

from __future__ import annotations

import uuid

from app.core.storage import LocalStorage
from app.crud import jobs as crud_jobs
from app.db.models import Job
from tests.api.routes.test_animations import submit

FILES = {
    "animation.glb": (b"glTF\x02\x00\x00\x00fake", "model/gltf-binary"),
    "trajectory.jsonl": (b'{"t": 0}\n', "application/jsonl"),
    "plan.json": (b"{}", "application/json"),
    "causal.json": (b"{}", "application/json"),
    "report.json": (b'{"ok": true}', "application/json"),
    "images/front.png": (b"\x89PNG fake", "image/png"),
}


def _publish(db, settings, job: Job, names=tuple(FILES)) -> None:  # type: ignore[no-untyped-def]
    storage = LocalStorage(settings.storage_dir)
    for name in names:
        data, kind = FILES[name]
        stored = storage.put_bytes(f"jobs/{job.id}/{name}", data)
        crud_jobs.add_artifact(db, job=job, name=name, storage_key=stored.key, sha256=stored.sha256,
                               size_bytes=stored.size, content_type=kind)


def test_progress_timings_and_outputs_of_a_successful_job(http, alice, db, settings) -> None:
    url = submit(http, alice.headers).json()["url"]
    job = db.get(Job, uuid.UUID(url.rsplit("/", 1)[-1]))
    for name in ("animation.glb", "report.json"):
        assert http.get(f"{url}/{name}", headers=alice.headers).status_code == 404
    crud_jobs.mark_running(db, job=job, worker="w1")
    crud_jobs.set_progress(db, job=job, stage="plan", progress=50)
    running = http.get(url, headers=alice.headers).json()
    assert (running["status"], running["stage"], running["progress"], running["attempts"]) == ("running", "plan", 50, 1)
    _publish(db, settings, job)
    assert http.get(f"{url}/animation.glb", headers=alice.headers).status_code == 404  # not before it has finished
    crud_jobs.mark_succeeded(db, job=job, timings={"plan": 0.25, "total": 1.5})
    done = http.get(url, headers=alice.headers).json()
    assert done["status"] == "succeeded" and done["progress"] == 100 and done["timings"] == {"plan": 0.25, "total": 1.5}
    assert done["finished_at"] is not None and done["started_at"] is not None
    links = {a["name"]: a["url"] for a in done["artifacts"]}
    assert links["animation.glb"] == f"{url}/animation.glb"
    assert links["images/front.png"] == f"{url}/keyframes/front.png"
    for name, (data, kind) in FILES.items():
        response = http.get(links[name], headers=alice.headers)
        assert response.status_code == 200 and response.content == data
        assert response.headers["content-type"].startswith(kind)
        assert response.headers["etag"].strip('"') == next(a for a in done["artifacts"] if a["name"] == name)["sha256"]
    assert http.get(f"{url}/files/images/front.png", headers=alice.headers).content == FILES["images/front.png"][0]


def test_failed_job_shows_the_engine_message_and_keeps_its_report(http, alice, db, settings) -> None:
    url = submit(http, alice.headers).json()["url"]
    job = db.get(Job, uuid.UUID(url.rsplit("/", 1)[-1]))
    crud_jobs.mark_running(db, job=job, worker="w1")
    _publish(db, settings, job, names=("report.json",))
    crud_jobs.mark_failed(db, job=job, error="no movable part matches 'wheel' (movable parts: lid)", kind="GroundingError")
    body = http.get(url, headers=alice.headers).json()
    assert body["status"] == "failed" and body["error_kind"] == "GroundingError" and "movable parts: lid" in body["error"]
    assert http.get(f"{url}/report.json", headers=alice.headers).status_code == 200
    missing = http.get(f"{url}/animation.glb", headers=alice.headers)
    assert missing.status_code == 404 and "no such output" in missing.json()["detail"]


def test_unknown_artifact_names_and_traversal_are_rejected(http, alice) -> None:
    url = submit(http, alice.headers).json()["url"]
    assert http.get(f"{url}/secret.txt", headers=alice.headers).status_code == 422
    assert http.get(f"{url}/keyframes/..%2F..%2Fetc", headers=alice.headers).status_code in (404, 422)
    assert http.get(f"{url}/files/%2E%2E/%2E%2E/etc/passwd", headers=alice.headers).status_code == 404


def test_artifact_missing_from_storage_is_404_not_500(http, alice, db, settings) -> None:
    url = submit(http, alice.headers).json()["url"]
    job = db.get(Job, uuid.UUID(url.rsplit("/", 1)[-1]))
    crud_jobs.mark_running(db, job=job, worker="w1")
    crud_jobs.add_artifact(db, job=job, name="plan.json", storage_key=f"jobs/{job.id}/plan.json", sha256="0" * 64,
                           size_bytes=2, content_type="application/json")
    crud_jobs.mark_succeeded(db, job=job, timings={})
    assert http.get(f"{url}/plan.json", headers=alice.headers).status_code == 404
