"""Batches: many jobs created in one transaction, read back with their jobs."""

from __future__ import annotations

import uuid
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from sqlalchemy import select
from sqlalchemy.orm import Session, selectinload

from app.crud.jobs import create_job
from app.db.models import ApiClient, Asset, Batch, Job, utcnow


@dataclass(frozen=True)
class BatchCase:
    """One case of a batch, its asset already resolved."""

    asset: Asset
    prompt: str
    case_id: str | None = None
    options: Mapping[str, Any] = field(default_factory=dict)


def create_batch(session: Session, *, client: ApiClient, cases: Sequence[BatchCase], name: str | None = None) -> Batch:
    """A batch and one queued job per case (all or nothing)."""
    batch = Batch(id=uuid.uuid4(), client_id=client.id, name=name, created_at=utcnow())
    session.add(batch)
    session.flush()
    for case in cases:
        create_job(session, client=client, asset=case.asset, prompt=case.prompt, options=case.options,
                   batch_id=batch.id, case_id=case.case_id, commit=False)
    session.commit()
    session.refresh(batch)
    return batch


def get_batch_for_client(session: Session, *, batch_id: uuid.UUID, client: ApiClient) -> Batch | None:
    """The batch (jobs loaded) if it belongs to ``client``."""
    return session.execute(
        select(Batch).where(Batch.id == batch_id, Batch.client_id == client.id)
        .options(selectinload(Batch.jobs).selectinload(Job.artifacts))
    ).scalar_one_or_none()
