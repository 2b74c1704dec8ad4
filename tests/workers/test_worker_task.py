"""The task function called directly (no broker): outcomes, status mapping, idempotency, leases."""

from __future__ import annotations

import uuid
from pathlib import Path

import pytest
from celery.exceptions import SoftTimeLimitExceeded, TimeLimitExceeded
from sqlalchemy import update

from app.core.config import Settings
from app.core.storage import LocalStorage
from app.crud import jobs as crud_jobs
from app.db.models import Job, JobStatus
from app.db.session import session_factory
from tests.workers.jobs import PEDAL_BIN, load_job, make_job
from workers import tasks
from workers.lease import job_lease
from workers.observer import JobObserver
from workers.tasks import Outcome, execute_job

EXPECTED_FILES = {"animation.glb", "causal.json", "interaction.json", "plan.json", "report.json", "trajectory.jsonl"}


def _stored_keys(settings: Settings, job_id: uuid.UUID) -> list[str]:
    return list(LocalStorage(settings.storage_dir).iter_keys(f"jobs/{job_id}"))


def test_job_succeeds_with_artifacts_timings_and_events(settings: Settings) -> None:
    job_id = make_job(settings)
    assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.succeeded
    job = load_job(settings, job_id)
    assert job.status == JobStatus.succeeded and job.progress == 100 and job.attempts == 1 and job.worker == "w1"
    assert {a.name for a in job.artifacts} == EXPECTED_FILES
    assert {"load_asset", "perceive", "plan", "refine", "export", "total"} <= set(job.timings)
    glb = next(a for a in job.artifacts if a.name == "animation.glb")
    assert glb.content_type == "model/gltf-binary" and glb.storage_key == f"jobs/{job_id}/animation.glb" and glb.size_bytes > 1000
    stages = [e.stage for e in job.events if e.kind == "stage"]
    assert stages == ["load_asset", "preprocess", "perceive", "plan", "refine", "export", "report"]
    assert [e.message for e in job.events if e.kind == "status"][-1] == "succeeded"


def test_calling_it_twice_leaves_one_set_of_artifacts(settings: Settings) -> None:
    job_id = make_job(settings)
    assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.succeeded
    first = load_job(settings, job_id)
    keys = _stored_keys(settings, job_id)
    assert execute_job(str(job_id), settings=settings, worker="w2") is Outcome.skipped
    second = load_job(settings, job_id)
    assert sorted((a.id, a.sha256) for a in second.artifacts) == sorted((a.id, a.sha256) for a in first.artifacts)
    assert second.attempts == 1 and second.worker == "w1" and len(second.events) == len(first.events)
    assert _stored_keys(settings, job_id) == keys and len(keys) == len(EXPECTED_FILES)


def test_redelivered_running_job_restarts_cleanly(settings: Settings) -> None:
    """A job left 'running' by a dead worker, with partial outputs, is re-run from scratch."""
    job_id = make_job(settings)
    storage = LocalStorage(settings.storage_dir)
    with session_factory(settings.sqlalchemy_url)() as session:
        job = session.get(Job, job_id)
        assert job is not None
        crud_jobs.mark_running(session, job=job, worker="dead-worker")
        stale = storage.put_bytes(f"jobs/{job_id}/stale.partial", b"half a file")
        crud_jobs.add_artifact(session, job=job, name="stale.partial", storage_key=stale.key, sha256=stale.sha256,
                               size_bytes=stale.size, content_type="application/octet-stream")
    assert execute_job(str(job_id), settings=settings, worker="w2") is Outcome.succeeded
    job = load_job(settings, job_id)
    assert job.status == JobStatus.succeeded and job.attempts == 2 and job.worker == "w2"
    assert {a.name for a in job.artifacts} == EXPECTED_FILES
    assert not storage.exists(f"jobs/{job_id}/stale.partial")
    assert len(_stored_keys(settings, job_id)) == len(EXPECTED_FILES)


def test_ungroundable_prompt_fails_with_the_engine_message(settings: Settings) -> None:
    job_id = make_job(settings, prompt="fly to the moon")
    assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.failed
    job = load_job(settings, job_id)
    assert job.status == JobStatus.failed and job.error_kind == "GroundingError"
    assert job.error is not None and "lid_hinge" in job.error and "pedal_pivot" in job.error
    assert [a.name for a in job.artifacts] == ["report.json"]  # the failure report is kept
    assert "perceive" in job.timings


def test_cancel_flag_before_start_cancels(settings: Settings) -> None:
    job_id = make_job(settings)
    with session_factory(settings.sqlalchemy_url)() as session:
        session.execute(update(Job).where(Job.id == job_id).values(cancel_requested=True))
        session.commit()
    assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.cancelled
    assert load_job(settings, job_id).status == JobStatus.cancelled


def test_cancel_during_run_stops_at_next_stage(settings: Settings, monkeypatch: pytest.MonkeyPatch) -> None:
    job_id = make_job(settings)
    original = JobObserver.on_stage

    def cancel_at_plan(self: JobObserver, stage: str, progress: int) -> None:
        original(self, stage, progress)
        if stage == "plan":
            with session_factory(settings.sqlalchemy_url)() as session:
                job = session.get(Job, self.job_id)
                assert job is not None
                crud_jobs.request_cancel(session, job=job)

    monkeypatch.setattr(JobObserver, "on_stage", cancel_at_plan)
    assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.cancelled
    job = load_job(settings, job_id)
    assert job.status == JobStatus.cancelled and job.stage == "plan"
    assert not any(a.name == "animation.glb" for a in job.artifacts)


def test_soft_time_limit_fails_as_timed_out(settings: Settings, monkeypatch: pytest.MonkeyPatch) -> None:
    job_id = make_job(settings)

    def slow(self: JobObserver, stage: str, progress: int) -> None:
        if stage == "refine":
            raise SoftTimeLimitExceeded()

    monkeypatch.setattr(JobObserver, "on_stage", slow)
    assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.failed
    job = load_job(settings, job_id)
    assert job.status == JobStatus.failed and job.error_kind == "TimeLimitExceeded"
    assert job.error == f"timed out after {settings.job_soft_time_limit_s} s"


def test_unexpected_engine_error_fails_the_job(settings: Settings, monkeypatch: pytest.MonkeyPatch) -> None:
    job_id = make_job(settings)

    def broken(*_: object, **__: object) -> None:
        raise ZeroDivisionError("engine bug")

    monkeypatch.setattr(tasks, "_roles", broken)
    assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.failed
    job = load_job(settings, job_id)
    assert job.error_kind == "InternalError" and job.error == "internal error: ZeroDivisionError: engine bug"


@pytest.mark.parametrize("damage", ["delete", "truncate", "alter"])
def test_a_missing_or_damaged_stored_asset_fails_the_job_as_a_storage_error(settings: Settings, tmp_path: Path, damage: str) -> None:
    """Not the user's AssetError: the server lost the bytes (and says how to restore them)."""
    import hashlib
    import shutil

    from tests.workers import stack

    folder = tmp_path / "bin"
    shutil.copytree(PEDAL_BIN, folder)
    (folder / "note.txt").write_text(f"{damage} {uuid.uuid4()}")  # content of its own: nothing shared with other tests
    job_id = make_job(settings, folder=folder)
    stored = settings.storage_dir / "assets" / f"{hashlib.sha256(stack.zip_folder(folder)).hexdigest()}.zip"
    data = stored.read_bytes()
    if damage == "delete":
        stored.unlink()
    elif damage == "truncate":
        stored.write_bytes(data[: len(data) // 2])
    else:
        stored.write_bytes(data[:-40] + bytes(40))  # same size, other bytes
    assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.failed
    failed = load_job(settings, job_id)
    assert failed.error_kind == "StorageError", failed.error
    assert "upload the asset again" in (failed.error or "")


def test_duplicate_delivery_while_leased_is_dropped(settings: Settings) -> None:
    job_id = make_job(settings)
    with job_lease(settings, str(job_id)) as held:
        assert held
        assert execute_job(str(job_id), settings=settings, worker="w2") is Outcome.skipped
    job = load_job(settings, job_id)
    assert job.status == JobStatus.queued and job.attempts == 0


def test_gives_up_after_max_attempts(settings: Settings) -> None:
    job_id = make_job(settings)
    with session_factory(settings.sqlalchemy_url)() as session:
        session.execute(update(Job).where(Job.id == job_id).values(status=JobStatus.running, attempts=settings.job_max_attempts))
        session.commit()
    assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.failed
    job = load_job(settings, job_id)
    assert job.error_kind == "WorkerLost" and f"after {settings.job_max_attempts} attempts" in (job.error or "")


@pytest.mark.parametrize("job_id", ["not-a-uuid", "3f2b8c1e-5d4a-4e7b-9c0d-1a2b3c4d5e6f"])
def test_malformed_or_unknown_id_is_dropped(settings: Settings, job_id: str) -> None:
    assert execute_job(job_id, settings=settings, worker="w1") is Outcome.skipped


def test_hard_time_limit_kill_fails_the_job(settings: Settings) -> None:
    """The worker's main process gets Celery's task_failure signal after killing the pool process."""
    job_id = make_job(settings)
    with session_factory(settings.sqlalchemy_url)() as session:
        job = session.get(Job, job_id)
        assert job is not None
        crud_jobs.mark_running(session, job=job, worker="w-killed")  # the killed process left it running
    tasks._hard_time_limit(exception=TimeLimitExceeded(settings.job_hard_time_limit_s), args=(str(job_id),))
    job = load_job(settings, job_id)
    assert job.status == JobStatus.failed and job.error_kind == "TimeLimitExceeded"
    assert job.error == f"timed out: killed at the hard time limit of {settings.job_hard_time_limit_s} s"
    tasks._hard_time_limit(exception=ValueError("another failure"), args=(str(job_id),))  # ignored


@pytest.mark.parametrize(
    ("provider", "options", "says"),
    [
        ("openai", {"provider": "openai"}, "no API key for provider 'openai'"),
        ("gemini", {"provider": "gemini", "perceiver_model": "../../../admin/delete?confirm=1#"}, "invalid perceiver model name"),
    ],
)
def test_the_worker_sends_nothing_to_a_provider_for_a_bad_job(settings: Settings, monkeypatch: pytest.MonkeyPatch, provider: str,
                                                              options: dict[str, str], says: str) -> None:
    """Jobs stored before the API checked them (or written to the database directly) fail without a request."""
    from app.core.config import get_settings
    from tests.support.model_server import model_server

    with model_server({}) as (base_url, script):
        monkeypatch.setenv("OPENAI_BASE_URL", base_url)
        monkeypatch.setenv("GEMINI_BASE_URL", base_url)
        if provider == "gemini":
            monkeypatch.setenv("GEMINI_API_KEY", "server-secret")
        get_settings.cache_clear()
        job_id = make_job(settings, options=options)
        assert execute_job(str(job_id), settings=get_settings(), worker="w1") is Outcome.failed
        failed = load_job(settings, job_id)
        assert failed.error_kind == "ProviderError" and says in (failed.error or "")
        assert script.requests == []
    get_settings.cache_clear()


def test_a_cancel_interrupts_a_stage_that_would_never_end(settings: Settings, monkeypatch: pytest.MonkeyPatch) -> None:
    """Before: a DELETE during a long stage answered 202 and changed nothing until the stage ended."""
    import threading
    import time

    import app.engine.pipeline
    from workers import cancel_watch

    monkeypatch.setattr(cancel_watch, "POLL_S", 0.1)
    endless = threading.Event()

    async def stuck_refine(*_args: object, **_kwargs: object) -> None:
        deadline = time.monotonic() + 20
        while not endless.is_set():  # a stage stuck in long work (an oversized asset, a slow model)
            time.sleep(0.02)
            if time.monotonic() > deadline:
                raise RuntimeError("the stage was not interrupted")

    monkeypatch.setattr(app.engine.pipeline, "refine", stuck_refine)
    job_id = make_job(settings)

    def cancel_when_refining() -> None:
        stack_deadline = time.monotonic() + 30
        while time.monotonic() < stack_deadline:
            with session_factory(settings.sqlalchemy_url)() as session:
                job = session.get(Job, job_id)
                if job is not None and job.stage == "refine":
                    crud_jobs.request_cancel(session, job=job)
                    return
            time.sleep(0.05)

    canceller = threading.Thread(target=cancel_when_refining)
    canceller.start()
    try:
        assert execute_job(str(job_id), settings=settings, worker="w1") is Outcome.cancelled
    finally:
        endless.set()
        canceller.join()
    done = load_job(settings, job_id)
    assert done.status == JobStatus.cancelled and "cancelled while running" in (done.events[-1].message or "")
    assert "animation.glb" not in {a.name for a in done.artifacts}
