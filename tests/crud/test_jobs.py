"""Job status transitions: allowed moves, refused moves (terminal jobs never change), events, artifacts."""

from __future__ import annotations

import uuid

import pytest
from sqlalchemy import select
from sqlalchemy.orm import Session

from app.crud import jobs as crud_jobs
from app.crud.assets import find_assets_for_client, get_or_create_asset, get_or_create_content
from app.crud.clients import client_by_key, create_api_client, ensure_client_for_key, hash_key
from app.db.models import Job, JobEvent, JobStatus
from app.db.session import session_factory


@pytest.fixture
def job(db: Session) -> Job:
    client, _ = create_api_client(db, name="crud")
    content = get_or_create_content(db, sha256=uuid.uuid4().hex * 2, size_bytes=1, storage_key="assets/a.zip")
    asset, _ = get_or_create_asset(db, client=client, content=content, filename="a.zip", urdf="mobility.urdf")
    return crud_jobs.create_job(db, client=client, asset=asset, prompt="open", options={"fps": 24})


def _events(db: Session, job: Job) -> list[tuple[str, str | None]]:
    rows = db.execute(select(JobEvent).where(JobEvent.job_id == job.id).order_by(JobEvent.id)).scalars()
    return [(event.kind, event.message or event.stage) for event in rows]


def test_happy_path_records_every_change(db: Session, job: Job) -> None:
    crud_jobs.mark_running(db, job=job, worker="host-1")
    crud_jobs.set_progress(db, job=job, stage="plan", progress=150)
    assert (job.status, job.stage, job.progress, job.attempts, job.worker) == ("running", "plan", 100, 1, "host-1")
    crud_jobs.mark_succeeded(db, job=job, timings={"plan": 1, "total": 2.5})
    assert job.status == JobStatus.succeeded and job.timings == {"plan": 1.0, "total": 2.5} and job.finished_at
    assert _events(db, job) == [("status", "queued"), ("status", "running"), ("stage", "plan"), ("status", "succeeded")]


@pytest.mark.parametrize("end", ["succeeded", "failed", "cancelled"])
def test_terminal_jobs_never_move(db: Session, job: Job, end: str) -> None:
    crud_jobs.mark_running(db, job=job, worker="w")
    {"succeeded": lambda: crud_jobs.mark_succeeded(db, job=job, timings={}),
     "failed": lambda: crud_jobs.mark_failed(db, job=job, error="e", kind="K"),
     "cancelled": lambda: crud_jobs.mark_cancelled(db, job=job)}[end]()
    before = (job.status, job.error, job.finished_at, job.attempts)
    crud_jobs.mark_running(db, job=job, worker="w2")
    crud_jobs.set_progress(db, job=job, stage="export", progress=10)
    crud_jobs.mark_failed(db, job=job, error="late", kind="Late")
    crud_jobs.mark_succeeded(db, job=job, timings={"x": 1})
    crud_jobs.mark_cancelled(db, job=job)
    crud_jobs.request_cancel(db, job=job)
    assert (job.status, job.error, job.finished_at, job.attempts) == before
    assert job.stage != "export"


def test_queued_job_cannot_succeed_without_running(db: Session, job: Job) -> None:
    crud_jobs.mark_succeeded(db, job=job, timings={})
    assert job.status == JobStatus.queued


def test_redelivery_restarts_a_running_job(db: Session, job: Job) -> None:
    crud_jobs.mark_running(db, job=job, worker="dead")
    crud_jobs.set_progress(db, job=job, stage="plan", progress=50)
    crud_jobs.mark_running(db, job=job, worker="alive")
    assert (job.attempts, job.worker, job.stage, job.progress) == (2, "alive", None, 0)


def test_cancel_queued_is_immediate_and_running_is_a_request(db: Session, job: Job) -> None:
    crud_jobs.request_cancel(db, job=job)
    assert job.status == JobStatus.cancelled and job.cancel_requested
    other = crud_jobs.create_job(db, client=_client(db, job), asset=job.asset, prompt="p")
    crud_jobs.mark_running(db, job=other, worker="w")
    crud_jobs.request_cancel(db, job=other)
    assert other.status == JobStatus.running and other.cancel_requested


def _client(db: Session, job: Job):  # type: ignore[no-untyped-def]
    from app.db.models import ApiClient

    return db.get(ApiClient, job.client_id)


def test_a_stale_object_cannot_overwrite_a_newer_state(crud_url: str, db: Session, job: Job) -> None:
    """Two sessions (API and worker): the worker's stale copy cannot un-cancel a job."""
    crud_jobs.mark_running(db, job=job, worker="w")
    with session_factory(crud_url)() as worker_session:
        stale = worker_session.get(Job, job.id)
        crud_jobs.mark_cancelled(db, job=job)
        crud_jobs.mark_succeeded(worker_session, job=stale, timings={})
        assert stale.status == JobStatus.cancelled


def test_add_artifact_upserts_by_name_and_delete_clears(db: Session, job: Job) -> None:
    first = crud_jobs.add_artifact(db, job=job, name="plan.json", storage_key="k1", sha256="a" * 64, size_bytes=1, content_type="application/json")
    second = crud_jobs.add_artifact(db, job=job, name="plan.json", storage_key="k2", sha256="b" * 64, size_bytes=2, content_type="application/json")
    assert first.id == second.id and second.storage_key == "k2"
    db.refresh(job)
    assert [a.name for a in job.artifacts] == ["plan.json"]
    assert crud_jobs.delete_artifacts(db, job=job) == 1
    assert crud_jobs.get_artifact(db, job=job, name="plan.json") is None


def test_keys_are_stored_hashed(db: Session) -> None:
    client, key = create_api_client(db, name="k")
    assert client.key_hash == hash_key(key) and key not in client.key_hash and client.key_prefix == key[:12]
    assert client_by_key(db, key=key).id == client.id
    assert client_by_key(db, key=key + "x") is None
    env_client = ensure_client_for_key(db, key="env-secret")
    assert ensure_client_for_key(db, key="env-secret").id == env_client.id


def test_assets_are_per_client_records_over_shared_content(db: Session) -> None:
    owner, _ = create_api_client(db, name="owner")
    stranger, _ = create_api_client(db, name="stranger")
    sha = uuid.uuid4().hex * 2
    content = get_or_create_content(db, sha256=sha, size_bytes=1, storage_key="k")
    assert get_or_create_content(db, sha256=sha, size_bytes=1, storage_key="k").id == content.id
    asset, created = get_or_create_asset(db, client=owner, content=content, filename="x.zip", urdf="a.urdf")
    again, created_again = get_or_create_asset(db, client=owner, content=content, filename="x.zip", urdf="a.urdf")
    assert created and not created_again and again.id == asset.id
    other_urdf, created_other = get_or_create_asset(db, client=owner, content=content, filename="x.zip", urdf="b.urdf")
    assert created_other and other_urdf.id != asset.id
    assert [a.id for a in find_assets_for_client(db, client=owner, ref=str(asset.id))] == [asset.id]
    assert {a.id for a in find_assets_for_client(db, client=owner, ref=sha)} == {asset.id, other_urdf.id}
    assert find_assets_for_client(db, client=stranger, ref=sha) == []
    assert find_assets_for_client(db, client=owner, ref="nonsense") == []
    theirs, _ = get_or_create_asset(db, client=stranger, content=content, filename="mine.zip", urdf="a.urdf")
    assert theirs.id != asset.id and theirs.filename == "mine.zip" and theirs.sha256 == asset.sha256 == sha
