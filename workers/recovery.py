"""Re-send jobs whose broker message may be lost, each time a worker (re)connects.

Messages are lost when a non-persistent Redis restarts, and kombu's SQLAlchemy transport
never redelivers the message of a worker killed mid-job. The database knows better:

- a job still ``queued`` after ``requeue_queued_after_s`` is sent again;
- a ``running`` job whose lease is free (its worker died) is sent again.

Duplicates are harmless: a job runs under its lease and finished jobs are skipped
(:mod:`workers.tasks`). The sweep runs in the worker's main process with a pool-less
engine, so nothing database-related is inherited by forked pool processes.
"""

from __future__ import annotations

import logging
import uuid
from datetime import UTC, datetime, timedelta
from typing import ClassVar

from celery import bootsteps
from kombu.exceptions import KombuError
from sqlalchemy import select
from sqlalchemy.exc import SQLAlchemyError
from sqlalchemy.orm import Session

from app.core.config import Settings, get_settings
from app.db.models import Job, JobStatus
from workers.broker import EnqueueError, enqueue_job
from workers.lease import lease_is_free, probe_engine

logger = logging.getLogger(__name__)

MAX_REQUEUED_PER_SWEEP = 500


def orphaned_jobs(settings: Settings, *, now: datetime | None = None) -> list[uuid.UUID]:
    """Ids of jobs that no live worker runs and whose message may be lost (oldest first)."""
    engine = probe_engine(settings)
    cutoff = (now or datetime.now(UTC)) - timedelta(seconds=settings.requeue_queued_after_s)
    try:
        with Session(engine) as session:
            queued = session.execute(
                select(Job.id)
                .where(Job.status == JobStatus.queued, Job.cancel_requested.is_(False), Job.created_at <= cutoff)
                .order_by(Job.created_at)
                .limit(MAX_REQUEUED_PER_SWEEP)
            ).scalars().all()
            running = session.execute(
                select(Job.id).where(Job.status == JobStatus.running).order_by(Job.created_at).limit(MAX_REQUEUED_PER_SWEEP)
            ).scalars().all()
        dead = [job_id for job_id in running if lease_is_free(settings, str(job_id), engine=engine)]
    finally:
        engine.dispose()
    return [*dead, *queued]


def requeue_orphans(settings: Settings) -> int:
    """Send every orphaned job again; returns how many were sent."""
    sent = 0
    for job_id in orphaned_jobs(settings):
        enqueue_job(job_id, settings)
        sent += 1
    if sent:
        logger.warning("recovery: re-sent %d job(s) whose message may have been lost", sent)
    return sent


class RecoveryStep(bootsteps.StartStopStep):
    """Consumer bootstep: runs :func:`requeue_orphans` on every (re)connection to the broker."""

    requires: ClassVar[set[str]] = {"celery.worker.consumer.tasks:Tasks"}

    def start(self, parent: object) -> None:  # noqa: ARG002  (the Consumer; not needed)
        try:
            requeue_orphans(get_settings())
        except (SQLAlchemyError, EnqueueError, KombuError, OSError) as exc:
            # a sweep that cannot reach the DB must not stop the worker; the next reconnection retries
            logger.warning("recovery sweep failed: %s", exc)
