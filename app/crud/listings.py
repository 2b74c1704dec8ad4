"""Read-only listings for the page: a client's assets and batches, newest first."""

from __future__ import annotations

from sqlalchemy import func, select
from sqlalchemy.orm import Session

from app.db.models import ApiClient, Asset, Batch, Job

MAX_LISTED = 200


def list_client_assets(session: Session, *, client: ApiClient, limit: int = 50) -> list[Asset]:
    """``client``'s asset records (one per uploaded content and chosen URDF), newest first."""
    return list(session.execute(
        select(Asset).where(Asset.client_id == client.id)
        .order_by(Asset.created_at.desc(), Asset.id).limit(min(max(limit, 1), MAX_LISTED))
    ).unique().scalars().all())


def list_client_batches(session: Session, *, client: ApiClient, limit: int = 50) -> list[tuple[Batch, int]]:
    """``client``'s batches with their job counts, newest first."""
    counts = select(Job.batch_id, func.count(Job.id).label("jobs")).group_by(Job.batch_id).subquery()
    rows = session.execute(
        select(Batch, func.coalesce(counts.c.jobs, 0)).outerjoin(counts, counts.c.batch_id == Batch.id)
        .where(Batch.client_id == client.id)
        .order_by(Batch.created_at.desc(), Batch.id).limit(min(max(limit, 1), MAX_LISTED))
    ).all()
    return [(batch, int(count)) for batch, count in rows]
