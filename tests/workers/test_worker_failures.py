"""Infrastructure failures on the real stack: a worker killed mid-job, Redis restarted, a time limit."""

from __future__ import annotations

import uuid
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from app.client import ArtimoClient, ClientError
from app.core.config import Settings
from app.core.storage import LocalStorage
from tests.support.gltf_validator import assert_valid
from tests.workers import stack
from tests.workers.conftest import TEST_API_KEY
from tests.workers.jobs import PEDAL_BIN, PEDAL_PROMPT, load_job

JOB_TIMEOUT_S = 60.0
REDELIVERY_TIMEOUT_S = 40.0
POLL_S = 0.05
OUTPUT_NAMES = ["animation.glb", "causal.json", "interaction.json", "plan.json", "report.json", "trajectory.jsonl"]


@pytest.fixture()
def client(api: str) -> Iterator[ArtimoClient]:
    with ArtimoClient(api, TEST_API_KEY) as http:
        yield http


def _wait_for(client: ArtimoClient, job_id: str, predicate: Any, what: str, timeout: float = JOB_TIMEOUT_S) -> dict[str, Any]:
    def check() -> dict[str, Any] | None:
        job = client.get(job_id)
        return job if predicate(job) else None

    return stack.wait_until(check, timeout, POLL_S, what)  # type: ignore[no-any-return]


def test_worker_killed_mid_job_is_redelivered_and_completes_once(
    client: ArtimoClient, workers: list[stack.Service], service_env: dict[str, str], log_dir: Path, settings: Settings, tmp_path: Path
) -> None:
    for name in ("w-one", "w-two"):
        workers.append(stack.start_worker(name, service_env, log_dir))
    accepted = client.submit(PEDAL_BIN, PEDAL_PROMPT)
    _wait_for(client, accepted["id"], lambda j: j["status"] == "running" and j["progress"] >= 35, "running past perceive")
    job_id = uuid.UUID(accepted["id"])
    holder = load_job(settings, job_id).worker or ""
    doomed = next(w for w in workers if holder.startswith(f"{w.name}@"))
    survivor = next(w for w in workers if w is not doomed)
    doomed.kill9()  # main process and pool process, no warning, no ack
    assert client.get(accepted["id"])["status"] == "running"  # the dead worker left it running

    done = _wait_for(client, accepted["id"], lambda j: j["status"] in ("succeeded", "failed"), "redelivery", REDELIVERY_TIMEOUT_S)
    assert done["status"] == "succeeded" and done["attempts"] == 2
    job = load_job(settings, job_id)
    assert job.worker is not None and job.worker.startswith(f"{survivor.name}@")
    assert sorted(a.name for a in job.artifacts) == OUTPUT_NAMES  # one set, no duplicates
    assert sorted(LocalStorage(settings.storage_dir).iter_keys(f"jobs/{job_id}")) == [f"jobs/{job_id}/{n}" for n in OUTPUT_NAMES]
    statuses = [e.message for e in job.events if e.kind == "status"]
    assert statuses.count("running") == 2 and statuses.count("succeeded") == 1
    assert survivor.text().count(f"job {job_id}: running on {survivor.name}@") == 1
    client.download(accepted["id"], tmp_path, names=["animation.glb"])
    assert_valid([tmp_path / "animation.glb"])


def test_redis_restart_mid_run(client: ArtimoClient, workers: list[stack.Service], service_env: dict[str, str], log_dir: Path) -> None:
    """The running job finishes, the queued one (its message lost with Redis' memory) is re-sent, new jobs work."""
    workers.append(stack.start_worker("w-redis", service_env, log_dir))
    running = client.submit(PEDAL_BIN, PEDAL_PROMPT)
    queued = client.submit(PEDAL_BIN, PEDAL_PROMPT)
    _wait_for(client, running["id"], lambda j: j["status"] == "running" and j["progress"] >= 15, "first job running")
    try:
        stack.restart_redis()
    finally:
        stack.start_redis()  # whatever happened, leave the machine's Redis up
    for job in (running, queued):
        done = client.wait(job["id"], timeout=REDELIVERY_TIMEOUT_S, poll=POLL_S)
        assert done["status"] == "succeeded", done
    assert "recovery: re-sent" in workers[0].text()

    def accepted_again() -> dict[str, Any] | None:
        try:
            return client.submit(PEDAL_BIN, PEDAL_PROMPT)
        except ClientError:  # the API's broker connection may need a moment after the restart
            return None

    after = stack.wait_until(accepted_again, 20, 0.5, "a submission after the restart")
    assert client.wait(after["id"], timeout=JOB_TIMEOUT_S, poll=POLL_S)["status"] == "succeeded"


def test_soft_time_limit_fails_the_job_as_timed_out(
    client: ArtimoClient, workers: list[stack.Service], service_env: dict[str, str], log_dir: Path
) -> None:
    limited = {**service_env, "JOB_SOFT_TIME_LIMIT_S": "1", "JOB_HARD_TIME_LIMIT_S": "10"}
    workers.append(stack.start_worker("w-limited", limited, log_dir))
    accepted = client.submit(PEDAL_BIN, PEDAL_PROMPT)  # 7 stages x 0.3 s > 1 s
    done = client.wait(accepted["id"], timeout=JOB_TIMEOUT_S, poll=POLL_S)
    assert done["status"] == "failed" and done["error_kind"] == "TimeLimitExceeded"
    assert done["error"] == "timed out after 1 s" and done["attempts"] == 1

