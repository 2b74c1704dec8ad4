"""Assets: stored once per content hash, visible to the clients that uploaded them."""

from __future__ import annotations

import re
import uuid

from sqlalchemy import select
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session

from app.db.models import ApiClient, Asset, ClientAsset, utcnow

SHA256_PATTERN = re.compile(r"^[0-9a-f]{64}$")


def get_or_create_asset(
    session: Session, *, client: ApiClient, sha256: str, filename: str, size_bytes: int, storage_key: str
) -> tuple[Asset, bool]:
    """The asset with ``sha256`` (created if new) granted to ``client``; ``True`` when the row is new."""
    asset = session.execute(select(Asset).where(Asset.sha256 == sha256)).scalar_one_or_none()
    created = False
    if asset is None:
        asset = Asset(id=uuid.uuid4(), sha256=sha256, filename=filename[:500], size_bytes=size_bytes,
                      storage_key=storage_key, created_at=utcnow())
        session.add(asset)
        try:
            session.commit()
            created = True
        except IntegrityError:  # the same content uploaded concurrently
            session.rollback()
            asset = session.execute(select(Asset).where(Asset.sha256 == sha256)).scalar_one()
    grant_asset(session, client=client, asset=asset)
    return asset, created


def grant_asset(session: Session, *, client: ApiClient, asset: Asset) -> None:
    """Let ``client`` use ``asset`` (idempotent)."""
    if session.get(ClientAsset, (client.id, asset.id)) is not None:
        return
    session.add(ClientAsset(client_id=client.id, asset_id=asset.id, created_at=utcnow()))
    try:
        session.commit()
    except IntegrityError:
        session.rollback()


def get_asset_for_client(session: Session, *, client: ApiClient, ref: str) -> Asset | None:
    """The asset named by ``ref`` (its id or sha256) if ``client`` may use it, else ``None``."""
    ref = ref.strip().lower()
    if SHA256_PATTERN.match(ref):
        condition = Asset.sha256 == ref
    else:
        try:
            condition = Asset.id == uuid.UUID(ref)
        except ValueError:
            return None
    return session.execute(
        select(Asset).join(ClientAsset, ClientAsset.asset_id == Asset.id)
        .where(condition, ClientAsset.client_id == client.id)
    ).scalar_one_or_none()
