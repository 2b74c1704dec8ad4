"""The worker's Celery app (``celery -A workers.celery_app worker``).

Configured lazily from :func:`get_settings` when first used (nothing is read at import):
broker = ``settings.broker_url`` (Redis when ``REDIS_URL`` is set, else kombu's SQLAlchemy
transport on SQLite), no result backend (job status lives in the database), late acks,
requeue on a lost worker, prefetch 1, soft/hard time limits. Logging is configured through
Celery's ``setup_logging`` signal; pool processes drop database connections inherited
from their parent; the :class:`~workers.recovery.RecoveryStep` re-sends orphaned jobs on
every broker (re)connection.

The producer side (:func:`enqueue_job`, :func:`broker_ping`) is re-exported from
:mod:`workers.broker` so the API does not import the engine.
"""

from __future__ import annotations

import logging
from typing import Any

from celery import Celery, signals

from app.core.config import get_settings
from app.core.logging import configure_logging
from workers.broker import EnqueueError, broker_ping, celery_config, enqueue_job
from workers.recovery import RecoveryStep

__all__ = ["EnqueueError", "app", "broker_ping", "enqueue_job"]

logger = logging.getLogger(__name__)

app = Celery("artimo", include=["workers.tasks"], set_as_current=True)
app.add_defaults(lambda: celery_config(get_settings()))
app.steps["consumer"].add(RecoveryStep)


@signals.setup_logging.connect
def _setup_logging(**_: Any) -> None:
    """Connected, so Celery leaves the root logger to :func:`configure_logging`."""
    configure_logging(get_settings())


@signals.worker_process_init.connect
def _fresh_connections(**_: Any) -> None:
    """A forked pool process must not share its parent's pooled database connections.

    The main process only uses pool-less engines (:mod:`workers.recovery`), so the cache
    is normally empty here; if not, forget the inherited engines (and their sessionmakers).
    """
    from app.db import session as db_session

    if db_session.get_engine.cache_info().currsize:
        logger.warning("pool process inherited database engines; creating fresh ones")
        db_session.get_engine.cache_clear()
        db_session._factory.cache_clear()
