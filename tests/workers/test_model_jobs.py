"""Model-backed jobs through the service: the task function, and ``artimo serve`` with a real worker process.

The model is the local model server (tests/support/model_server.py) on an imperfect but
recoverable day; the worker renders images for the vision roles by default.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from app.client import ArtimoClient
from app.core.config import Settings, get_settings
from app.core.storage import LocalStorage
from app.db.models import JobStatus
from tests.support.model_server import model_server, recorded
from tests.workers import stack
from tests.workers.jobs import PEDAL_BIN, PEDAL_PROMPT, load_job, make_job
from tests.workers.test_embedded_serve import KEY_LINE, SERVE_TIMEOUT_S, _embedded_env, _ready
from workers.tasks import Outcome, execute_job


def _imperfect() -> dict:  # type: ignore[type-arg]
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"status": 500}, {"text": replies["perceiver"][0], "shape": "prose"}]
    replies["critic"] = [{"text": replies["critic"][0], "shape": "think"}]
    return replies


def _use_model(monkeypatch: pytest.MonkeyPatch, url: str) -> Settings:
    monkeypatch.setenv("OPENAI_API_KEY", "sk-service-key")
    monkeypatch.setenv("OPENAI_BASE_URL", url)
    get_settings.cache_clear()
    return get_settings()


def test_model_job_renders_for_the_vision_roles_and_succeeds(settings: Settings, monkeypatch: pytest.MonkeyPatch) -> None:
    with model_server(_imperfect()) as (url, script):
        configured = _use_model(monkeypatch, url)
        job_id = make_job(configured, options={"provider": "openai"})
        assert execute_job(str(job_id), settings=configured, worker="w1") is Outcome.succeeded
    job = load_job(configured, job_id)
    names = {a.name for a in job.artifacts}
    assert {"animation.glb", "report.json", "causal.json", "plan.json", "trajectory.jsonl"} <= names
    assert len([n for n in names if n.startswith("images/")]) == 8 and not any(".artimo-partial" in n for n in names)
    for role in ("perceiver", "coverage", "critic"):
        assert script.of(role) and all("image_url" in json.dumps(r["payload"]) for r in script.of(role)), role
    report = json.loads(LocalStorage(configured.storage_dir).get_bytes(f"jobs/{job_id}/report.json"))
    assert report["images"] is True and report["final_state"].startswith("accepted")
    assert "sk-service-key" not in json.dumps(report)


def test_model_job_out_of_quota_fails_with_only_its_report(settings: Settings, monkeypatch: pytest.MonkeyPatch) -> None:
    replies = recorded("pedal_bin")
    replies["perceiver"] = [{"status": 429, "quota": True}]
    with model_server(replies) as (url, _):
        configured = _use_model(monkeypatch, url)
        job_id = make_job(configured, options={"provider": "openai"})
        assert execute_job(str(job_id), settings=configured, worker="w1") is Outcome.failed
    job = load_job(configured, job_id)
    assert job.status == JobStatus.failed and job.error_kind == "ProviderQuotaExceeded" and "quota" in (job.error or "")
    assert {a.name for a in job.artifacts} == {"report.json"}


def test_model_job_through_artimo_serve(tmp_path: Path) -> None:
    data_dir, port = tmp_path / "data", stack.free_port()
    with model_server(_imperfect()) as (model_url, script):
        env = {**_embedded_env(data_dir), "OPENAI_API_KEY": "sk-service-key", "OPENAI_BASE_URL": model_url}
        server = subprocess.Popen([sys.executable, "-m", "app.cli.main", "serve", "--host", "127.0.0.1", "--port", str(port), "--workers", "1"],
                                  cwd=stack.REPO, env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, start_new_session=True)
        url = f"http://127.0.0.1:{port}"
        try:
            assert server.stdout is not None
            match = KEY_LINE.search(server.stdout.readline() + server.stdout.readline())
            assert match
            stack.wait_until(lambda: _ready(url), SERVE_TIMEOUT_S, 0.1, "artimo serve /readyz")
            with ArtimoClient(url, match.group(1)) as client:
                job = client.submit(PEDAL_BIN, PEDAL_PROMPT, provider="openai")
                done = client.wait(job["id"], timeout=120, poll=0.2)
                assert done["status"] == "succeeded", done
                client.download(job["id"], tmp_path / "out", ["report.json"])
                report = json.loads((tmp_path / "out" / "report.json").read_text())
        finally:
            server.terminate()
            server.wait(SERVE_TIMEOUT_S)
    assert report["images"] is True and {c["role"] for c in report["role_calls"]} == {"perceiver", "planner", "critic", "coverage"}
    assert all("image_url" in json.dumps(r["payload"]) for r in script.of("perceiver") + script.of("critic"))
