"""``run_job(job_id)``: one animation job from its DB row to stored artifacts.

load the job -> skip if terminal -> mark running (attempts + 1, worker host) -> clear a
previous partial run -> check the stored asset zip (used in place, not copied) and read its
stored summary -> ``run_pipeline`` in a temporary folder (observer writes progress,
``should_stop`` reads ``cancel_requested``) -> store outputs as ``jobs/<id>/...`` +
Artifact rows -> succeeded with per-stage timings (from the returned report).

This module is the only place that maps an outcome (EngineError subclass, cancellation,
time limit, unexpected error) to a job status. Redelivered messages are safe: a per-job
lease (:mod:`workers.lease`) lets one live process run a job, and a finished job is skipped.
"""

from __future__ import annotations

import logging
import re
import socket
import tempfile
import uuid
from dataclasses import dataclass, field
from enum import StrEnum
from pathlib import Path
from typing import Any

from celery import Task, signals
from celery.exceptions import SoftTimeLimitExceeded, TimeLimitExceeded
from sqlalchemy.exc import OperationalError as DatabaseUnavailable
from sqlalchemy.exc import SQLAlchemyError
from sqlalchemy.orm import Session, sessionmaker

from app.core.asset_summary import read_summary
from app.core.config import Settings, get_settings
from app.core.logging import current_job
from app.core.storage import LocalStorage, Storage, StorageError, intact_local_path
from app.crud import jobs as crud_jobs
from app.db.models import TERMINAL, Job, JobStatus
from app.db.session import session_factory
from app.engine.agents.roles import Roles
from app.engine.asset.stored import StoredAsset
from app.engine.config import EngineConfig
from app.engine.errors import CancelledError, EngineError, ProviderError
from app.engine.providers.names import MODEL_NAME_PATTERN
from app.engine.report import RunReport
from workers.broker import RUN_JOB_TASK
from workers.cancel_watch import CancelWatch
from workers.celery_app import app
from workers.lease import job_lease, probe_engine
from workers.observer import JobObserver
from workers.outputs import asset_name, clear_outputs, publish_outputs
from workers.plan_jobs import is_plan_job, run_plan_job

logger = logging.getLogger(__name__)

DB_RETRIES = 3
DB_RETRY_BACKOFF_S = 5
TIMED_OUT_KIND = "TimeLimitExceeded"
INTERNAL_KIND = "InternalError"
GAVE_UP_KIND = "WorkerLost"
MODEL_ROLES = ("perceiver", "planner", "critic")


class Outcome(StrEnum):
    """What one delivery of ``run_job`` did (the task's return value, for logs and tests)."""

    succeeded = "succeeded"
    failed = "failed"
    cancelled = "cancelled"
    skipped = "skipped"
    """The job is finished, unknown, or another live worker holds its lease."""


@dataclass(frozen=True)
class _AssetFields:
    """The job's asset record, copied while the session is open (an ``AssetRecord``)."""

    filename: str
    urdf: str
    sha256: str
    size_bytes: int
    storage_key: str


@dataclass(frozen=True)
class _Claim:
    """What a run needs from the job row, read while the session is open."""

    job_id: uuid.UUID
    prompt: str
    options: dict[str, Any]
    asset: _AssetFields
    attempts: int


@dataclass
class _Result:
    status: JobStatus
    error: str | None = None
    kind: str | None = None
    timings: dict[str, float] = field(default_factory=dict)


def _timings(report: RunReport | None) -> dict[str, float]:
    """Seconds per pipeline stage (+ ``total``) of a run's report (none when the run ended without one)."""
    if report is None:
        return {}
    timings = {timing.stage: timing.seconds for timing in report.stages}
    timings["total"] = report.total_s
    return timings


def _roles(options: dict[str, Any], settings: Settings, config: EngineConfig) -> Roles:
    """The job's provider with the server's credentials and the job's per-role model names."""
    from app.engine.providers.registry import ProviderConfig, make_roles

    provider = str(options.get("provider") or settings.default_provider)
    if (missing := settings.missing_provider_key(provider)) is not None:  # never an unauthenticated request
        raise ProviderError(missing)
    models = tuple((role, str(options[f"{role}_model"])) for role in MODEL_ROLES if options.get(f"{role}_model"))
    for role, name in models:  # stored options were validated by the API; checked again before any URL is built
        if not re.fullmatch(MODEL_NAME_PATTERN, name):
            raise ProviderError(f"invalid {role} model name {name[:100]!r}")
    base_url = {"openai": settings.openai_base_url, "gemini": settings.gemini_base_url}.get(provider)
    secret = settings.provider_key(provider)
    api_key = None if secret is None else secret.get_secret_value()
    return make_roles(provider, ProviderConfig(api_key=api_key, base_url=base_url, models=models, profile=settings.model_profile), config)


def _stored_asset(claim: _Claim, storage: Storage) -> tuple[Path, StoredAsset]:
    """The stored zip (checked, used in place) and what the upload already computed of it.

    Raises
    ------
    StorageError
        The stored zip is missing or no longer matches its sha256.
    """
    path = intact_local_path(storage, claim.asset.storage_key, claim.asset.sha256, claim.asset.size_bytes)
    summary = read_summary(storage, claim.asset)
    stored = StoredAsset(sha256=claim.asset.sha256, name=asset_name(claim.asset.filename), joints=tuple(summary.joints),
                         scale=summary.scale)
    return path, stored


def _run_engine(claim: _Claim, storage: Storage, out_dir: Path, observer: JobObserver, settings: Settings) -> _Result:
    """Run the pipeline and translate how it ended into a job status."""
    from app.engine.pipeline import PipelineRequest, run_pipeline

    config = settings.engine_config()
    if claim.options.get("preview"):
        config = config.model_copy(update={"preview": True})
    if claim.options.get("exports"):
        config = config.model_copy(update={"exports": tuple(claim.options["exports"])})
    rounds = claim.options.get("max_critic_rounds")
    try:
        path, stored = _stored_asset(claim, storage)
        if is_plan_job(claim.options):  # a submitted plan: executor and exporters only
            report = run_plan_job(claim.options, path, out_dir, observer, settings, urdf=claim.asset.urdf or None)
            return _Result(JobStatus.succeeded, timings=_timings(report))
        fps = claim.options.get("fps")
        request = PipelineRequest(asset=path, prompt=claim.prompt, max_critic_rounds=None if rounds is None else int(rounds),
                                  fps=None if fps is None else int(fps), urdf=claim.asset.urdf or None, stored=stored)
        roles = _roles(claim.options, settings, config)
        watch = CancelWatch(claim.job_id, observer.cancel_requested)
        observer.shield = watch.shield
        with watch.running():  # a cancellation interrupts even a long stage
            result = run_pipeline(request, roles=roles, config=config, out_dir=out_dir, observer=observer, should_stop=observer.should_stop)
    except CancelledError as exc:
        return _Result(JobStatus.cancelled, str(exc), type(exc).__name__, _timings(exc.report))
    except EngineError as exc:
        return _Result(JobStatus.failed, str(exc), type(exc).__name__, _timings(exc.report))
    return _Result(JobStatus.succeeded, timings=_timings(result.report))


def _finish(session: Session, job: Job, result: _Result) -> Outcome:
    if result.status is JobStatus.succeeded:
        crud_jobs.mark_succeeded(session, job=job, timings=result.timings)
        return Outcome.succeeded
    if result.status is JobStatus.cancelled:
        crud_jobs.mark_cancelled(session, job=job, message=result.error)
        return Outcome.cancelled
    crud_jobs.mark_failed(session, job=job, error=result.error or "failed", kind=result.kind or INTERNAL_KIND, timings=result.timings)
    return Outcome.failed


def _start(session: Session, storage: Storage, job_id: uuid.UUID, settings: Settings, worker: str) -> _Claim | Outcome:
    """Claim the job for this run, or say why not (the caller holds the lease)."""
    job = crud_jobs.get_job(session, job_id=job_id)
    if job is None:
        logger.warning("job %s does not exist; message dropped", job_id)
        return Outcome.skipped
    if job.status in TERMINAL:
        logger.info("job %s is already %s; redelivery skipped", job_id, job.status)
        return Outcome.skipped
    if job.cancel_requested:
        crud_jobs.mark_cancelled(session, job=job, message="cancelled before it started")
        return Outcome.cancelled
    if job.attempts >= settings.job_max_attempts:
        message = f"gave up after {job.attempts} attempts (worker lost or killed each time)"
        crud_jobs.mark_failed(session, job=job, error=message, kind=GAVE_UP_KIND)
        return Outcome.failed
    crud_jobs.mark_running(session, job=job, worker=worker)
    if job.status != JobStatus.running:  # cancelled by the API a moment ago (guarded transition refused)
        return Outcome.skipped
    clear_outputs(session, storage, job)
    record = job.asset
    fields = _AssetFields(filename=record.filename, urdf=record.urdf, sha256=record.sha256, size_bytes=record.size_bytes,
                          storage_key=record.storage_key)
    return _Claim(job_id=job.id, prompt=job.prompt, options=dict(job.options or {}), asset=fields, attempts=job.attempts)


def _run_claimed(sessions: sessionmaker[Session], storage: Storage, claim: _Claim, settings: Settings) -> Outcome:
    observer = JobObserver(sessions, claim.job_id, stage_delay_s=settings.job_stage_delay_s)
    with tempfile.TemporaryDirectory(prefix=f"artimo-job-{claim.job_id}-") as folder:
        work = Path(folder)
        out_dir = work / "out"
        out_dir.mkdir()
        try:
            result = _run_engine(claim, storage, out_dir, observer, settings)
        except SoftTimeLimitExceeded:
            result = _Result(JobStatus.failed, f"timed out after {settings.job_soft_time_limit_s} s", TIMED_OUT_KIND)
        except StorageError as exc:
            result = _Result(JobStatus.failed, f"asset unavailable: {exc} (upload the asset again to restore it)", type(exc).__name__)
        except Exception as exc:  # task boundary: an engine bug must end the job, not leave it running
            logger.exception("job %s: unexpected error", claim.job_id)
            result = _Result(JobStatus.failed, f"internal error: {type(exc).__name__}: {exc}", INTERNAL_KIND)
        with sessions() as session:
            current = session.get(Job, claim.job_id)
            if current is None or current.status in TERMINAL:
                return Outcome.skipped
            publish_outputs(session, storage, current, out_dir)
            return _finish(session, current, result)


def execute_job(job_id: str, *, settings: Settings, worker: str) -> Outcome:
    """Run one job (the body of :func:`run_job`, callable without Celery).

    Idempotent: calling it again for a finished job does nothing; a job left ``running``
    by a dead worker is restarted from scratch (its previous artifacts are removed first).
    """
    try:
        job_uuid = uuid.UUID(str(job_id))
    except ValueError:
        logger.error("run_job got a malformed job id %r; message dropped", job_id)
        return Outcome.skipped
    token = current_job.set(str(job_uuid))
    try:
        return _execute_leased(job_uuid, settings=settings, worker=worker)
    finally:
        current_job.reset(token)


def _execute_leased(job_uuid: uuid.UUID, *, settings: Settings, worker: str) -> Outcome:
    sessions = session_factory(settings.sqlalchemy_url)
    storage = LocalStorage(settings.storage_dir)
    with job_lease(settings, str(job_uuid)) as held:
        if not held:
            logger.info("job %s is being run by another live worker; duplicate delivery dropped", job_uuid)
            return Outcome.skipped
        with sessions() as session:
            claimed = _start(session, storage, job_uuid, settings, worker)
        if isinstance(claimed, Outcome):
            return claimed
        logger.info("job %s: running on %s (attempt %d)", job_uuid, worker, claimed.attempts)
        try:
            return _run_claimed(sessions, storage, claimed, settings)
        except SoftTimeLimitExceeded:
            with sessions() as session:
                current = session.get(Job, job_uuid)
                if current is not None and current.status not in TERMINAL:
                    _finish(session, current, _Result(JobStatus.failed, f"timed out after {settings.job_soft_time_limit_s} s", TIMED_OUT_KIND))
            return Outcome.failed


@app.task(
    name=RUN_JOB_TASK,
    bind=True,
    acks_late=True,
    reject_on_worker_lost=True,
    ignore_result=True,
    autoretry_for=(DatabaseUnavailable,),
    max_retries=DB_RETRIES,
    retry_backoff=DB_RETRY_BACKOFF_S,
)
def run_job(self: Task, job_id: str) -> str:
    """Celery entry point: the payload is the job id only."""
    worker = self.request.hostname or socket.gethostname()
    return execute_job(job_id, settings=get_settings(), worker=worker).value


@signals.task_failure.connect(sender=run_job)
def _hard_time_limit(exception: BaseException | None = None, args: tuple[Any, ...] | None = None, **_: Any) -> None:
    """The pool process was killed at the hard time limit: fail the job (the message is acked, no redelivery).

    Runs in the worker's main process, so it uses a pool-less engine.
    """
    if not isinstance(exception, TimeLimitExceeded) or not args:
        return
    settings = get_settings()
    engine = probe_engine(settings)
    try:
        with Session(engine) as session:
            job = crud_jobs.get_job(session, job_id=uuid.UUID(str(args[0])))
            if job is not None and job.status not in TERMINAL:
                message = f"timed out: killed at the hard time limit of {settings.job_hard_time_limit_s} s"
                crud_jobs.mark_failed(session, job=job, error=message, kind=TIMED_OUT_KIND)
    except (ValueError, SQLAlchemyError) as exc:
        logger.error("could not fail job %s after its hard time limit: %s", args[0], exc)
    finally:
        engine.dispose()
