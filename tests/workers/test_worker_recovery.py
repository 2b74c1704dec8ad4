"""Jobs never wait forever while the service says it is healthy.

Before the fix: a job whose message was lost between two broker connections stayed ``queued``
with an empty queue and an idle worker (the sweep ran only on reconnection, for jobs older
than two minutes); and ``/readyz`` said ready with no worker at all.
"""

from __future__ import annotations

from pathlib import Path

import httpx

from app.core.config import Settings
from tests.workers import stack
from tests.workers.jobs import load_job, make_job

HEARTBEAT_S = "0.5"
QUICK_RECOVERY = {"REQUEUE_SWEEP_S": "1", "REQUEUE_STUCK_AFTER_S": "1", "WORKER_HEARTBEAT_S": HEARTBEAT_S,
                  "REQUEUE_QUEUED_AFTER_S": "3600"}  # the sweep on (re)connection would not catch these jobs
JOB_TIMEOUT_S = 60.0


def test_jobs_whose_message_was_lost_are_sent_again_without_a_reconnection(
    service_env: dict[str, str], settings: Settings, log_dir: Path, workers: list[stack.Service]
) -> None:
    workers.append(stack.start_worker("w-sweep", {**service_env, **QUICK_RECOVERY}, log_dir))
    lost = [make_job(settings) for _ in range(3)]  # queued in the database, never sent: like a Redis restart loses them
    for job_id in lost:
        done = stack.wait_until(lambda job_id=job_id: load_job(settings, job_id).status == "succeeded" or None,
                                JOB_TIMEOUT_S, 0.2, f"lost job {job_id} to run")
        assert done
    assert "periodic" in workers[0].text() or "re-sent" in workers[0].text()


def test_readyz_says_not_ready_without_a_live_worker(service_env: dict[str, str], log_dir: Path, workers: list[stack.Service]) -> None:
    server, api = stack.start_api({**service_env, **QUICK_RECOVERY}, log_dir, name="api-ready")
    workers.append(server)  # stopped with the workers

    def workers_check() -> str:
        return str(httpx.get(f"{api}/readyz", timeout=5).json()["checks"]["workers"])

    first = stack.start_worker("w-ready", {**service_env, **QUICK_RECOVERY}, log_dir)
    workers.append(first)
    stack.wait_until(lambda: workers_check() == "ok", 10, 0.2, "a worker heartbeat")
    assert httpx.get(f"{api}/readyz", timeout=5).status_code == 200
    first.stop()  # a clean stop removes its heartbeat at once
    stack.wait_until(lambda: workers_check().startswith("no live worker"), 10, 0.2, "readyz to notice the stop")
    assert httpx.get(f"{api}/readyz", timeout=5).status_code == 503
    second = stack.start_worker("w-ready2", {**service_env, **QUICK_RECOVERY}, log_dir)
    workers.append(second)
    stack.wait_until(lambda: workers_check() == "ok", 10, 0.2, "the second worker's heartbeat")
    second.kill9()  # no goodbye: its heartbeat goes stale within three intervals
    stack.wait_until(lambda: workers_check().startswith("no live worker (last seen"), 10, 0.2, "readyz to notice the kill")
