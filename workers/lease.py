"""A per-job lease that dies with its holder: exactly one live process runs a job.

Redelivery (worker lost, visibility timeout, recovery sweep) can hand the same job to two
workers; only the lease holder runs it, the other delivery is dropped. The lease is a
PostgreSQL session advisory lock on a dedicated connection, or with SQLite (embedded mode,
one machine) an ``flock`` on ``$ARTIMO_DATA_DIR/locks/<job>.lock``. The database or the
kernel releases it when the holding process dies, even by ``kill -9``.
"""

from __future__ import annotations

import fcntl
import hashlib
import logging
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from sqlalchemy import Connection, Engine, create_engine, text
from sqlalchemy.pool import NullPool

from app.core.config import Settings

logger = logging.getLogger(__name__)

LOCK_NAMESPACE = b"artimo-job-lease:"
SQLITE_BUSY_TIMEOUT_S = 30


def advisory_key(job_id: str) -> int:
    """Signed 64-bit PostgreSQL advisory-lock key of a job id."""
    digest = hashlib.sha256(LOCK_NAMESPACE + job_id.encode()).digest()
    return int.from_bytes(digest[:8], "big", signed=True)


def _is_postgres(settings: Settings) -> bool:
    return settings.sqlalchemy_url.startswith("postgresql")


def lock_dir(settings: Settings) -> Path:
    return settings.data_dir / "locks"


@contextmanager
def _pg_lease(engine: Engine, job_id: str) -> Iterator[bool]:
    key = advisory_key(job_id)
    connection: Connection = engine.connect()
    try:
        held = bool(connection.execute(text("SELECT pg_try_advisory_lock(:key)"), {"key": key}).scalar())
        connection.commit()  # the session-level lock outlives the transaction: no idle-in-transaction
        try:
            yield held
        finally:
            if held:
                connection.execute(text("SELECT pg_advisory_unlock(:key)"), {"key": key})
                connection.commit()
    finally:
        connection.close()


@contextmanager
def _file_lease(folder: Path, job_id: str, *, remove: bool) -> Iterator[bool]:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{job_id}.lock"
    descriptor = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    try:
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            yield False
            return
        try:
            yield True
        finally:
            if remove:
                path.unlink(missing_ok=True)
            fcntl.flock(descriptor, fcntl.LOCK_UN)
    finally:
        os.close(descriptor)


@contextmanager
def job_lease(settings: Settings, job_id: str, *, engine: Engine | None = None, remove: bool = True) -> Iterator[bool]:
    """Hold the lease of ``job_id`` for the ``with`` block; yields whether it was acquired.

    ``remove`` deletes the SQLite lock file on release (the job is finished by then).
    """
    if _is_postgres(settings):
        from app.db.session import get_engine

        with _pg_lease(engine or get_engine(settings.sqlalchemy_url), job_id) as held:
            yield held
    else:
        with _file_lease(lock_dir(settings), job_id, remove=remove) as held:
            yield held


def lease_is_free(settings: Settings, job_id: str, *, engine: Engine) -> bool:
    """Whether no live process holds the job's lease (probe: acquire and release at once)."""
    with job_lease(settings, job_id, engine=engine, remove=False) as held:
        return held


def probe_engine(settings: Settings) -> Engine:
    """An engine without a pool, for the worker's main process (nothing open across forks)."""
    url = settings.sqlalchemy_url
    arguments = {"timeout": SQLITE_BUSY_TIMEOUT_S} if url.startswith("sqlite") else {}
    return create_engine(url, poolclass=NullPool, connect_args=arguments)
