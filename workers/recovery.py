"""Re-send jobs whose broker message may be lost, when a worker (re)connects and periodically; heartbeats.

Messages are lost when a non-persistent Redis restarts, and kombu's SQLAlchemy transport
never redelivers the message of a worker killed mid-job. The database knows better:

- on (re)connection, a job still ``queued`` after ``requeue_queued_after_s`` is sent again;
- every ``requeue_sweep_s``, when the broker's queue is empty, a job still ``queued`` after
  ``requeue_stuck_after_s`` is sent again (a message can be lost without this worker
  reconnecting: the broker restarted while it was between polls);
- a ``running`` job whose lease is free (its worker died) is sent again.

Duplicates are harmless: a job runs under its lease and finished jobs are skipped
(:mod:`workers.tasks`). The step also records this worker's heartbeat every
``worker_heartbeat_s`` (``/readyz`` is not ready without a live worker) and removes it when
the worker stops. Everything runs in the worker's main process with a pool-less engine, so
nothing database-related is inherited by forked pool processes.
"""

from __future__ import annotations

import logging
import time
import uuid
from datetime import UTC, datetime, timedelta
from typing import Any, ClassVar

from celery import bootsteps
from kombu.exceptions import ChannelError, KombuError
from sqlalchemy import select
from sqlalchemy.exc import SQLAlchemyError
from sqlalchemy.orm import Session

from app.core.config import Settings, get_settings
from app.crud.workers import record_heartbeat, remove_heartbeat
from app.db.models import Job, JobStatus
from workers.broker import EnqueueError, enqueue_job, producer_for
from workers.lease import lease_is_free, probe_engine

logger = logging.getLogger(__name__)

MAX_REQUEUED_PER_SWEEP = 500


SWEEP_ERRORS = (SQLAlchemyError, EnqueueError, KombuError, OSError)
"""What a sweep or heartbeat may meet (database or broker away); logged, retried at the next tick."""


def orphaned_jobs(settings: Settings, *, now: datetime | None = None, queued_after_s: float | None = None) -> list[uuid.UUID]:
    """Ids of jobs that no live worker runs and whose message may be lost (oldest first)."""
    engine = probe_engine(settings)
    age = settings.requeue_queued_after_s if queued_after_s is None else queued_after_s
    cutoff = (now or datetime.now(UTC)) - timedelta(seconds=age)
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


def requeue_orphans(settings: Settings, *, queued_after_s: float | None = None) -> int:
    """Send every orphaned job again; returns how many were sent."""
    sent = 0
    for job_id in orphaned_jobs(settings, queued_after_s=queued_after_s):
        enqueue_job(job_id, settings)
        sent += 1
    if sent:
        logger.warning("recovery: re-sent %d job(s) whose message may have been lost", sent)
    return sent


def broker_queue_size(settings: Settings) -> int:
    """Messages waiting in the job queue on the broker (0 when the queue does not exist)."""
    app = producer_for(settings)
    with app.connection_for_write() as connection, connection.channel() as channel:
        try:
            _, count, _ = channel.queue_declare(queue=settings.celery_queue, passive=True)
        except ChannelError:  # no such queue yet: nothing waits
            return 0
    return int(count)


def periodic_sweep(settings: Settings) -> int:
    """Between reconnections: with nothing waiting on the broker, a job still queued has lost its message."""
    if broker_queue_size(settings) > 0:
        return 0
    return requeue_orphans(settings, queued_after_s=settings.requeue_stuck_after_s)


def beat(settings: Settings, name: str, concurrency: int) -> None:
    engine = probe_engine(settings)
    try:
        with Session(engine) as session:
            record_heartbeat(session, name=name, concurrency=concurrency)
    finally:
        engine.dispose()


def forget(settings: Settings, name: str) -> None:
    engine = probe_engine(settings)
    try:
        with Session(engine) as session:
            remove_heartbeat(session, name=name)
    finally:
        engine.dispose()


class RecoveryStep(bootsteps.StartStopStep):
    """Consumer bootstep: sweep on every (re)connection to the broker, then heartbeat and sweep on a timer."""

    requires: ClassVar[set[str]] = {"celery.worker.consumer.tasks:Tasks"}

    def __init__(self, parent: Any, **kwargs: Any) -> None:
        super().__init__(parent, **kwargs)
        self._timer: Any = None
        self._name = ""
        self._concurrency = 1
        self._last_sweep = 0.0

    def start(self, parent: Any) -> None:
        settings = get_settings()
        self._name = str(getattr(parent, "hostname", None) or "worker")
        self._concurrency = int(getattr(getattr(parent, "pool", None), "num_processes", 1) or 1)
        self._last_sweep = time.monotonic()
        self._guarded("heartbeat", lambda: beat(settings, self._name, self._concurrency))
        self._guarded("recovery sweep", lambda: requeue_orphans(settings))
        self._timer = parent.timer.call_repeatedly(settings.worker_heartbeat_s, self._tick, priority=0)

    def _tick(self) -> None:
        settings = get_settings()
        self._guarded("heartbeat", lambda: beat(settings, self._name, self._concurrency))
        if time.monotonic() - self._last_sweep >= settings.requeue_sweep_s:
            self._last_sweep = time.monotonic()
            self._guarded("periodic recovery sweep", lambda: periodic_sweep(settings))

    def stop(self, parent: Any) -> None:  # noqa: ARG002  (the Consumer; not needed)
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        if self._name:
            self._guarded("heartbeat removal", lambda: forget(get_settings(), self._name))

    shutdown = stop

    @staticmethod
    def _guarded(what: str, action: Any) -> None:
        try:
            action()
        except SWEEP_ERRORS as exc:
            # a sweep that cannot reach the DB or broker must not stop the worker; the next tick retries
            logger.warning("%s failed: %s", what, exc)
