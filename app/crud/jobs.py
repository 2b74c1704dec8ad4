"""Jobs: creation, listing, cancellation and the guarded status transitions the worker drives.

Every function takes the session first and keyword-only arguments, and commits. Status
changes are conditional ``UPDATE ... WHERE status IN (...)`` statements, so two processes
racing (the API cancelling while a worker finishes) cannot move a job out of a terminal
state: the losing call changes nothing, logs it and returns the job as stored.
"""

from __future__ import annotations

import logging
import uuid
from collections.abc import Iterable, Mapping
from typing import Any

from sqlalchemy import delete, func, select, update
from sqlalchemy.orm import Session, joinedload, selectinload

from app.db.models import TERMINAL, ApiClient, Artifact, Asset, Job, JobEvent, JobStatus, utcnow

logger = logging.getLogger(__name__)

MAX_PAGE_SIZE = 200
MAX_EVENT_MESSAGE_CHARS = 4000
_ACTIVE = (JobStatus.queued, JobStatus.running)


def create_job(
    session: Session,
    *,
    client: ApiClient,
    asset: Asset,
    prompt: str,
    options: Mapping[str, Any] | None = None,
    batch_id: uuid.UUID | None = None,
    case_id: str | None = None,
    commit: bool = True,
) -> Job:
    """A new ``queued`` job (plus its first event); ``commit=False`` lets a batch add many at once."""
    job = Job(
        id=uuid.uuid4(), client_id=client.id, asset_id=asset.id, prompt=prompt, options=dict(options or {}),
        batch_id=batch_id, case_id=case_id, status=JobStatus.queued, progress=0, timings={}, attempts=0,
        cancel_requested=False, created_at=utcnow(),
    )
    session.add(job)
    session.add(JobEvent(job_id=job.id, kind="status", message=JobStatus.queued.value, progress=0, created_at=utcnow()))
    if commit:
        session.commit()
    return job


def get_job(session: Session, *, job_id: uuid.UUID) -> Job | None:
    return session.get(Job, job_id)


def get_job_for_client(session: Session, *, job_id: uuid.UUID, client: ApiClient) -> Job | None:
    """The job if it exists and belongs to ``client`` (another client's job is ``None``, like a missing one)."""
    query = select(Job).where(Job.id == job_id, Job.client_id == client.id).options(joinedload(Job.artifacts))
    return session.execute(query).unique().scalar_one_or_none()


def list_jobs(
    session: Session, *, client: ApiClient, limit: int = 50, offset: int = 0, status: JobStatus | None = None
) -> tuple[list[Job], int]:
    """The client's jobs, newest first, and how many there are in total (with the same filter)."""
    conditions = [Job.client_id == client.id]
    if status is not None:
        conditions.append(Job.status == status)
    count = session.execute(select(func.count()).select_from(Job).where(*conditions)).scalar_one()
    rows = session.execute(
        select(Job).where(*conditions).options(selectinload(Job.artifacts))
        .order_by(Job.created_at.desc(), Job.id.desc()).limit(min(max(limit, 1), MAX_PAGE_SIZE)).offset(max(offset, 0))
    ).scalars().all()
    return list(rows), int(count)


def count_active_jobs(session: Session, *, client: ApiClient) -> int:
    """The client's jobs that are queued or running."""
    query = select(func.count()).select_from(Job).where(Job.client_id == client.id, Job.status.in_([s.value for s in _ACTIVE]))
    return int(session.execute(query).scalar_one())


def count_jobs_by_status(session: Session) -> dict[str, int]:
    """Jobs per status over all clients (every status present, zero when none)."""
    counts = {status.value: 0 for status in JobStatus}
    for status, count in session.execute(select(Job.status, func.count()).group_by(Job.status)).all():
        counts[str(status)] = int(count)
    return counts


def record_event(
    session: Session,
    *,
    job_id: uuid.UUID,
    kind: str,
    message: str | None = None,
    stage: str | None = None,
    progress: int | None = None,
) -> JobEvent:
    """Append one event (``status``, ``stage`` or ``message``) to the job's history."""
    event = JobEvent(
        job_id=job_id, kind=kind, message=None if message is None else message[:MAX_EVENT_MESSAGE_CHARS],
        stage=stage, progress=progress, created_at=utcnow(),
    )
    session.add(event)
    session.commit()
    return event


def _transition(
    session: Session, job: Job, *, allowed: Iterable[JobStatus], values: dict[str, Any], event: str | None
) -> bool:
    """Apply ``values`` iff the job's stored status is in ``allowed``; refresh ``job`` either way."""
    allowed = tuple(allowed)
    result = session.execute(
        update(Job).where(Job.id == job.id, Job.status.in_([s.value for s in allowed])).values(**values)
        .execution_options(synchronize_session=False)
    )
    applied = bool(result.rowcount == 1)  # type: ignore[attr-defined]
    if applied and event is not None:
        session.add(JobEvent(
            job_id=job.id, kind="status", message=event, stage=values.get("stage"),
            progress=values.get("progress"), created_at=utcnow(),
        ))
    session.commit()
    session.refresh(job)
    if not applied:
        logger.warning("job %s: refused transition to %s from %s", job.id, values.get("status", "(same)"), job.status)
    return applied


def mark_running(session: Session, *, job: Job, worker: str) -> Job:
    """queued|running -> running: one more attempt, fresh start time, progress/stage/error cleared."""
    _transition(session, job, allowed=_ACTIVE, event=JobStatus.running.value, values={
        "status": JobStatus.running.value, "attempts": Job.attempts + 1, "worker": worker[:200],
        "started_at": utcnow(), "finished_at": None, "stage": None, "progress": 0,
        "error": None, "error_kind": None, "timings": {},
    })
    return job


def set_progress(session: Session, *, job: Job, stage: str, progress: int) -> Job:
    """Stage and progress (clamped to 0..100) of a running job, plus a ``stage`` event."""
    progress = min(max(int(progress), 0), 100)
    applied = _transition(session, job, allowed=(JobStatus.running,), event=None,
                          values={"stage": stage[:32], "progress": progress})
    if applied:
        record_event(session, job_id=job.id, kind="stage", stage=stage[:32], progress=progress)
    return job


def mark_succeeded(session: Session, *, job: Job, timings: Mapping[str, float]) -> Job:
    """running -> succeeded with per-stage timings (seconds)."""
    _transition(session, job, allowed=(JobStatus.running,), event=JobStatus.succeeded.value, values={
        "status": JobStatus.succeeded.value, "progress": 100, "finished_at": utcnow(),
        "timings": {str(k): float(v) for k, v in timings.items()},
    })
    return job


def mark_failed(session: Session, *, job: Job, error: str, kind: str, timings: Mapping[str, float] | None = None) -> Job:
    """queued|running -> failed with the engine's message and error class name."""
    values: dict[str, Any] = {
        "status": JobStatus.failed.value, "finished_at": utcnow(), "error": error, "error_kind": kind[:64],
    }
    if timings is not None:
        values["timings"] = {str(k): float(v) for k, v in timings.items()}
    _transition(session, job, allowed=_ACTIVE, event=f"{JobStatus.failed.value}: {kind}", values=values)
    return job


def mark_cancelled(session: Session, *, job: Job, message: str | None = None) -> Job:
    """queued|running -> cancelled."""
    _transition(session, job, allowed=_ACTIVE, event=message or JobStatus.cancelled.value, values={
        "status": JobStatus.cancelled.value, "cancel_requested": True, "finished_at": utcnow(),
    })
    return job


def request_cancel(session: Session, *, job: Job) -> Job:
    """Cancel a job: a queued one at once, a running one at its next stage (the worker checks the flag).

    A finished job is returned unchanged (the caller decides what that means).
    """
    if job.status == JobStatus.queued and mark_cancelled(session, job=job, message="cancelled while queued").status == JobStatus.cancelled:
        return job
    if _transition(session, job, allowed=(JobStatus.running,), event=None, values={"cancel_requested": True}):
        record_event(session, job_id=job.id, kind="message", message="cancellation requested")
    return job


def add_artifact(
    session: Session, *, job: Job, name: str, storage_key: str, sha256: str, size_bytes: int, content_type: str
) -> Artifact:
    """Record an output file of ``job``; a second call with the same name replaces the first row's data."""
    artifact = session.execute(
        select(Artifact).where(Artifact.job_id == job.id, Artifact.name == name)
    ).scalar_one_or_none()
    if artifact is None:
        artifact = Artifact(id=uuid.uuid4(), job_id=job.id, name=name, created_at=utcnow(),
                            storage_key=storage_key, sha256=sha256, size_bytes=size_bytes, content_type=content_type)
        session.add(artifact)
    else:
        artifact.storage_key, artifact.sha256 = storage_key, sha256
        artifact.size_bytes, artifact.content_type = size_bytes, content_type
    session.commit()
    return artifact


def delete_artifacts(session: Session, *, job: Job) -> int:
    """Remove every Artifact row of ``job`` (a restarted run); returns how many there were."""
    result = session.execute(delete(Artifact).where(Artifact.job_id == job.id).execution_options(synchronize_session=False))
    session.commit()
    session.expire(job, ["artifacts"])
    return int(result.rowcount)  # type: ignore[attr-defined]


def get_artifact(session: Session, *, job: Job, name: str) -> Artifact | None:
    return session.execute(select(Artifact).where(Artifact.job_id == job.id, Artifact.name == name)).scalar_one_or_none()


def is_terminal(job: Job) -> bool:
    return JobStatus(job.status) in TERMINAL
