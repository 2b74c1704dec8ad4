"""Asset upload responses."""

from __future__ import annotations

import uuid

from pydantic import BaseModel

from app.engine.asset.summary import JointSummary, ScaleContext
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
    summary_url: str
    """Its joints, link labels and sizes."""


class AssetSummary(BaseModel):
    """What the asset can do: ``GET /v1/assets/{ref}/summary``."""

    joints: list[JointSummary]
    """Every joint, as the paper's joint summary (type, parent/child link, axis, limits, origin, mimic)."""
    scale: ScaleContext
    """Object and link sizes in metres."""
    links: list[str]
    labels: dict[str, str]
    """Link name -> part label (``semantics.txt`` or URDF visual names), where known."""
