"""A job end to end: API submit -> the worker's task function (run inline) -> API status and downloads.

No Celery process: the fake enqueuer records the id and the test calls
``workers.tasks.execute_job`` itself, on the same database and storage as the API.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.api.routes.test_animations import submit
from tests.support import upload_assets as assets

tasks = pytest.importorskip("workers.tasks", reason="the worker package is built by the workers helper")


def test_submit_run_download(http, alice, settings, sent) -> None:
    response = submit(http, alice.headers, prompt="open the lid", upload=assets.hinge_zip("-life"))
    assert response.status_code == 202, response.text
    url = response.json()["url"]
    outcome = tasks.execute_job(str(sent[0]), settings=settings, worker="inline-test")
    job = http.get(url, headers=alice.headers).json()
    assert outcome.value == "succeeded", job
    assert job["status"] == "succeeded" and job["progress"] == 100 and job["attempts"] == 1
    assert job["timings"]["total"] > 0
    names = {a["name"] for a in job["artifacts"]}
    assert {"animation.glb", "trajectory.jsonl", "plan.json", "report.json"} <= names
    glb = http.get(f"{url}/animation.glb", headers=alice.headers)
    assert glb.headers["content-type"] == "model/gltf-binary" and glb.content[:4] == b"glTF"
    lines = http.get(f"{url}/trajectory.jsonl", headers=alice.headers).text.splitlines()
    assert len(lines) > 1 and json.loads(lines[0])
    report = http.get(f"{url}/report.json", headers=alice.headers).json()
    assert report
    again = tasks.execute_job(str(sent[0]), settings=settings, worker="inline-test")
    assert again.value == "skipped"


def test_engine_failure_reaches_the_client(http, alice, settings, sent) -> None:
    """An asset without movable joints cannot be animated: the engine's message becomes the job's error."""
    upload = ("welded.zip", assets.zip_bytes({"welded/mobility.urdf": assets.welded_urdf()}))
    url = submit(http, alice.headers, prompt="open the lid", upload=upload).json()["url"]
    assert tasks.execute_job(str(sent[0]), settings=settings, worker="inline-test").value == "failed"
    job = http.get(url, headers=alice.headers).json()
    assert job["status"] == "failed" and job["error_kind"] == "GroundingError", job
    assert "no movable parts" in job["error"]
    assert http.get(f"{url}/animation.glb", headers=alice.headers).status_code == 404
    assert http.get(f"{url}/report.json", headers=alice.headers).status_code == 200


def test_cancelled_before_the_worker_starts(http, alice, settings, sent) -> None:
    url = submit(http, alice.headers, upload=assets.hinge_zip("-cancel")).json()["url"]
    assert http.delete(url, headers=alice.headers).json()["status"] == "cancelled"
    outcome = tasks.execute_job(str(sent[0]), settings=settings, worker="inline-test")
    assert outcome.value == "skipped"
    assert http.get(url, headers=alice.headers).json()["status"] == "cancelled"


def test_client_library_against_the_app(http, alice, settings, sent, tmp_path) -> None:
    from app.client import ArtimoClient, ClientError
    from tests.support.app_transport import TestClientTransport

    folder = tmp_path / "hinge"
    folder.mkdir()
    (folder / "mobility.urdf").write_text(assets.hinge_urdf(name="hinge-client"))
    with ArtimoClient("http://testserver", alice.key, transport=TestClientTransport(http)) as client:
        job = client.submit(folder, "open the lid", fps=24)
        tasks.execute_job(str(sent[-1]), settings=settings, worker="inline-test")
        final = client.wait(job["id"], timeout=5, poll=0.05)
        assert final["status"] == "succeeded"
        written = client.download(job["id"], tmp_path / "out")
        assert (tmp_path / "out" / "animation.glb") in written
        by_ref = client.submit(final["asset_id"], "open the lid")
        assert by_ref["status"] == "queued"
        batch = client.submit_batch([{"asset": final["asset_id"], "prompt": "open", "case_id": "c1"}], name="b")
        assert client.get_batch(batch["id"])["cases"][0]["case_id"] == "c1"
        with pytest.raises(ClientError) as error:
            client.submit(_bad_asset(tmp_path), "open")
        assert error.value.status == 422 and "missing.obj" in error.value.message
        with pytest.raises(ClientError) as missing:
            client.get("00000000-0000-0000-0000-000000000000")
        assert missing.value.status == 404


def _bad_asset(tmp_path: Path) -> Path:
    name, data = assets.missing_mesh()
    path = tmp_path / name
    path.write_bytes(data)
    return path


def test_a_job_uses_what_the_upload_computed_and_the_returned_report(http, alice, settings, sent, monkeypatch) -> None:
    """The worker neither loads nor summarises the uploaded asset again, and takes its timings from
    run_pipeline's result (report.json is not read back)."""
    response = submit(http, alice.headers, prompt="open the lid", upload=assets.hinge_zip("-once"))
    assert response.status_code == 202, response.text

    def refuse(*_args: object, **_kwargs: object) -> None:
        raise AssertionError("computed a second time")

    import app.engine.asset.loader
    import app.engine.asset.stored
    import app.engine.pipeline

    monkeypatch.setattr(app.engine.asset.loader, "load_asset", refuse)
    monkeypatch.setattr(app.engine.asset.stored, "joint_summary", refuse)
    monkeypatch.setattr(app.engine.asset.stored, "scale_context", refuse)
    monkeypatch.setattr(app.engine.pipeline, "write_report", lambda *_args: None)  # no report.json on disk
    outcome = tasks.execute_job(str(sent[0]), settings=settings, worker="inline-test")
    job = http.get(response.json()["url"], headers=alice.headers).json()
    assert outcome.value == "succeeded", job
    assert job["timings"]["total"] > 0 and {"load_asset", "perceive", "export"} <= set(job["timings"])
