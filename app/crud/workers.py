"""Worker heartbeats: each Celery worker's main process says it is alive every few seconds."""

from __future__ import annotations

from datetime import datetime, timedelta

from sqlalchemy import delete, select, update
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session

from app.db.models import WorkerHeartbeat, utcnow


def record_heartbeat(session: Session, *, name: str, concurrency: int, now: datetime | None = None) -> None:
    """Insert or refresh the heartbeat of worker ``name``."""
    now = now or utcnow()
    refreshed = session.execute(
        update(WorkerHeartbeat).where(WorkerHeartbeat.name == name[:200]).values(last_seen=now, concurrency=concurrency)
        .execution_options(synchronize_session=False)
    )
    if refreshed.rowcount == 0:  # type: ignore[attr-defined]
        session.add(WorkerHeartbeat(name=name[:200], concurrency=concurrency, started_at=now, last_seen=now))
        try:
            session.commit()
        except IntegrityError:  # recorded by a concurrent call a moment ago
            session.rollback()
        return
    session.commit()


def remove_heartbeat(session: Session, *, name: str) -> None:
    """A worker stopping cleanly: no longer counted as alive."""
    session.execute(delete(WorkerHeartbeat).where(WorkerHeartbeat.name == name[:200]))
    session.commit()


def live_workers(session: Session, *, stale_after_s: float, now: datetime | None = None) -> list[WorkerHeartbeat]:
    """Workers whose last heartbeat is more recent than ``stale_after_s`` seconds."""
    cutoff = (now or utcnow()) - timedelta(seconds=stale_after_s)
    return list(session.execute(select(WorkerHeartbeat).where(WorkerHeartbeat.last_seen >= cutoff)
                                .order_by(WorkerHeartbeat.name)).scalars().all())


def last_heartbeat(session: Session) -> datetime | None:
    """When any worker was last heard from (None: never)."""
    return session.execute(select(WorkerHeartbeat.last_seen).order_by(WorkerHeartbeat.last_seen.desc()).limit(1)).scalar_one_or_none()
