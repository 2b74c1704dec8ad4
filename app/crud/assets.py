"""Assets: content stored once per hash (:class:`AssetContent`), one record per client over it (:class:`Asset`).

A client sees only its own records: their ids, names and times. Uploading bytes another
client already sent creates a new record for this client (nothing of the other client's
record is shown); only the stored content is shared.
"""

from __future__ import annotations

import re
import uuid

from sqlalchemy import select
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session

from app.db.models import ApiClient, Asset, AssetContent, utcnow

SHA256_PATTERN = re.compile(r"^[0-9a-f]{64}$")


def get_content(session: Session, *, sha256: str) -> AssetContent | None:
    return session.execute(select(AssetContent).where(AssetContent.sha256 == sha256)).scalar_one_or_none()


def get_or_create_content(session: Session, *, sha256: str, size_bytes: int, storage_key: str) -> AssetContent:
    """The content row of ``sha256`` (created if new; race-safe)."""
    content = get_content(session, sha256=sha256)
    if content is not None:
        return content
    content = AssetContent(id=uuid.uuid4(), sha256=sha256, size_bytes=size_bytes, storage_key=storage_key, created_at=utcnow())
    session.add(content)
    try:
        session.commit()
    except IntegrityError:  # the same content uploaded concurrently
        session.rollback()
        return session.execute(select(AssetContent).where(AssetContent.sha256 == sha256)).scalar_one()
    return content


def get_or_create_asset(
    session: Session, *, client: ApiClient, content: AssetContent, filename: str, urdf: str
) -> tuple[Asset, bool]:
    """``client``'s record of ``content`` with ``urdf`` (created if new); ``True`` when the record is new."""
    query = select(Asset).where(Asset.client_id == client.id, Asset.content_id == content.id, Asset.urdf == urdf)
    existing = session.execute(query).scalar_one_or_none()
    if existing is not None:
        return existing, False
    asset = Asset(id=uuid.uuid4(), client_id=client.id, content_id=content.id, filename=filename[:500], urdf=urdf[:500],
                  created_at=utcnow())
    asset.content = content
    session.add(asset)
    try:
        session.commit()
    except IntegrityError:  # this client uploaded it twice at the same moment
        session.rollback()
        return session.execute(query).scalar_one(), False
    return asset, True


def find_assets_for_client(session: Session, *, client: ApiClient, ref: str) -> list[Asset]:
    """``client``'s records named by ``ref``: its id (one), or its content's sha256 (one per chosen URDF)."""
    ref = ref.strip().lower()
    if SHA256_PATTERN.match(ref):
        condition = AssetContent.sha256 == ref
    else:
        try:
            condition = Asset.id == uuid.UUID(ref)
        except ValueError:
            return []
    query = (select(Asset).join(AssetContent, AssetContent.id == Asset.content_id)
             .where(condition, Asset.client_id == client.id).order_by(Asset.created_at, Asset.urdf))
    return list(session.execute(query).unique().scalars().all())
