"""Asset upload responses."""

from __future__ import annotations

import uuid

from pydantic import BaseModel

from app.schemas.common import UtcDatetime


class AssetPublic(BaseModel):
    id: uuid.UUID
    sha256: str
    """Content hash of the stored zip: reuse the asset by this or by ``id``."""
    filename: str
    size_bytes: int
    created_at: UtcDatetime
    created: bool = False
    """True when this request stored the asset; False when identical content was already there."""
    url: str
