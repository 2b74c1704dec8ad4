"""Hand a job to the workers; a FastAPI dependency so API tests can replace it.

The producer lives in :mod:`workers.broker` (imported lazily: it sends the task by name,
so the API never imports the engine-running :mod:`workers.tasks`).
"""

from __future__ import annotations

import logging
import uuid
from collections.abc import Callable, Sequence
from functools import partial

from sqlalchemy.orm import Session

from app.api.errors import ServiceUnavailable, TooManyJobs
from app.core.config import Settings
from app.crud import jobs as crud_jobs
from app.db.models import ApiClient, Job

logger = logging.getLogger(__name__)

BROKER_DOWN_KIND = "BrokerUnavailable"

Enqueuer = Callable[[uuid.UUID], None]
"""Sends one job id to the workers; raises :class:`QueueUnavailable` when it cannot."""


class QueueUnavailable(Exception):
    """The broker did not take the job."""


def enqueue_job(job_id: uuid.UUID, *, settings: Settings) -> None:
    """Send ``workers.tasks.run_job(job_id)`` on the broker of ``settings``.

    Raises
    ------
    QueueUnavailable
        The broker is unreachable.
    """
    from workers.broker import EnqueueError
    from workers.broker import enqueue_job as send

    try:
        send(job_id, settings)
    except EnqueueError as exc:
        raise QueueUnavailable(str(exc)) from exc


def celery_enqueuer(settings: Settings) -> Enqueuer:
    return partial(enqueue_job, settings=settings)


def broker_reachable(settings: Settings) -> bool:
    from workers.broker import broker_ping

    return broker_ping(settings)


def check_job_quota(session: Session, *, client: ApiClient, adding: int, limit: int) -> None:
    """Refuse ``adding`` more jobs when the client would have more than ``limit`` queued or running.

    Raises
    ------
    TooManyJobs
        429 with ``Retry-After``.
    """
    active = crud_jobs.count_active_jobs(session, client=client)
    if active + adding > limit:
        raise TooManyJobs(active, adding, limit)


def dispatch_jobs(session: Session, jobs: Sequence[Job], enqueue: Enqueuer) -> int:
    """Send every job; returns how many were sent.

    If none could be sent they all fail at once (kind ``BrokerUnavailable``) and
    :class:`ServiceUnavailable` (503) tells the caller to retry: nothing is left behind.
    Jobs left unsent after at least one was sent stay ``queued``: the workers' recovery
    sweep re-sends queued jobs on their next connection to the broker.

    Raises
    ------
    ServiceUnavailable
        Not one job reached the broker.
    """
    sent, problem = 0, None
    for job in jobs:
        try:
            enqueue(job.id)
            sent += 1
        except QueueUnavailable as exc:
            problem = exc
            if sent == 0:
                break
    if problem is None:
        return sent
    if sent == 0:
        for job in jobs:
            crud_jobs.mark_failed(session, job=job, error=f"not queued: {problem}", kind=BROKER_DOWN_KIND)
        raise ServiceUnavailable(f"the job queue is unavailable ({problem}); retry later")
    logger.warning("%d of %d jobs not sent (%s); the recovery sweep will send them", len(jobs) - sent, len(jobs), problem)
    return sent
