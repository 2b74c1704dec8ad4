"""Celery configuration from :class:`Settings`, and the producer side (enqueue, broker health).

The API never imports :mod:`workers.tasks` (the engine): it sends the task by name through
a small producer app cached per broker URL, so whatever environment was current when a
module was imported, a job goes to the broker of the ``settings`` passed in.
"""

from __future__ import annotations

import json
import logging
import uuid
from functools import lru_cache
from typing import Any

from celery import Celery
from kombu.exceptions import KombuError, OperationalError

from app.core.config import Settings

logger = logging.getLogger(__name__)

RUN_JOB_TASK = "workers.tasks.run_job"
SQLITE_BUSY_TIMEOUT_S = 30
SQLA_PREFIX = "sqla+"
SQLITE_TRANSPORT = "workers.sqlite_transport:Transport"
REDIS_SOCKET_TIMEOUT_S = 5
PUBLISH_RETRIES = 2
"""Publish attempts after the first (0.2 s, 0.7 s apart) before :class:`EnqueueError`."""
PING_TIMEOUT_S = 2.0
MAX_RESTORE_INTERVAL_S = 60


class EnqueueError(Exception):
    """The broker did not accept the job (unreachable); the job row stays ``queued``."""


def uses_redis(settings: Settings) -> bool:
    return settings.broker_url.startswith(("redis://", "rediss://"))


def _transport_options(settings: Settings) -> dict[str, Any]:
    if uses_redis(settings):
        visibility = settings.visibility_timeout_s
        return {
            "visibility_timeout": visibility,
            # sweep for messages of dead workers often enough to honour the visibility timeout
            "unacked_restore_interval": max(1, min(MAX_RESTORE_INTERVAL_S, visibility // 4)),
            "unacked_restore_throttle": 1,
            "socket_connect_timeout": REDIS_SOCKET_TIMEOUT_S,
            "socket_keepalive": True,
        }
    # kombu's SQLAlchemy transport passes these to create_engine (SQLite shared with the API)
    return {"connect_args": {"timeout": SQLITE_BUSY_TIMEOUT_S}}


def celery_config(settings: Settings) -> dict[str, Any]:
    """Every Celery setting ArtiMo uses (status lives in the DB: no result backend)."""
    redis = uses_redis(settings)
    broker: dict[str, Any] = {"broker_url": settings.broker_url}
    if not redis and settings.broker_url.startswith(SQLA_PREFIX):  # same database URL, faster-polling transport
        broker = {"broker_url": settings.broker_url.removeprefix(SQLA_PREFIX), "broker_transport": SQLITE_TRANSPORT}
    return {
        **broker,
        "broker_transport_options": _transport_options(settings),
        "broker_connection_retry_on_startup": True,
        "broker_connection_max_retries": None,
        "task_default_queue": settings.celery_queue,
        "task_serializer": "json",
        "accept_content": ["json"],
        "task_ignore_result": True,
        "result_backend": None,
        "task_acks_late": True,
        "task_reject_on_worker_lost": True,
        "worker_prefetch_multiplier": 1,
        "task_soft_time_limit": settings.job_soft_time_limit_s,
        "task_time_limit": settings.job_hard_time_limit_s,
        "worker_hijack_root_logger": False,
        "worker_cancel_long_running_tasks_on_connection_loss": False,
        # broadcast (remote control, events) needs fanout, which the SQLAlchemy transport lacks
        "worker_enable_remote_control": redis,
        "worker_send_task_events": redis,
        "task_send_sent_event": redis,
        "broker_connection_timeout": REDIS_SOCKET_TIMEOUT_S,
    }


@lru_cache(maxsize=8)
def _producer(config_json: str) -> Celery:
    app = Celery("artimo-producer", set_as_current=False)
    app.conf.update(json.loads(config_json))
    return app


def producer_for(settings: Settings) -> Celery:
    """A Celery app that only sends, cached per configuration (broker URL, queue, options)."""
    return _producer(json.dumps(celery_config(settings), sort_keys=True))


def enqueue_job(job_id: uuid.UUID | str, settings: Settings) -> None:
    """Send ``run_job(job_id)`` to ``settings.celery_queue``.

    Raises
    ------
    EnqueueError
        The broker is unreachable after a short retry.
    """
    app = producer_for(settings)
    try:
        app.send_task(
            RUN_JOB_TASK,
            args=[str(job_id)],
            queue=settings.celery_queue,
            task_id=f"{job_id}-{uuid.uuid4().hex[:8]}",
            retry=True,
            retry_policy={"max_retries": PUBLISH_RETRIES, "interval_start": 0.2, "interval_step": 0.5, "interval_max": 1.0},
        )
    except (OperationalError, KombuError, OSError) as exc:
        raise EnqueueError(f"broker unreachable: {exc}") from exc
    logger.info("enqueued job %s on %s", job_id, settings.celery_queue)


def broker_ping(settings: Settings) -> bool:
    """True when the broker accepts a connection within :data:`PING_TIMEOUT_S`."""
    app = producer_for(settings)
    try:
        with app.connection_for_write() as connection:
            connection.ensure_connection(max_retries=1, timeout=PING_TIMEOUT_S)
            if uses_redis(settings):
                connection.default_channel.client.ping()
    except (OperationalError, KombuError, OSError) as exc:
        logger.warning("broker ping failed: %s", exc)
        return False
    return True
