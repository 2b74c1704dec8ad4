"""Asset upload responses."""

from __future__ import annotations

import uuid

from pydantic import BaseModel

from app.engine.asset.layout import AssetLayout
from app.engine.asset.summary import JointSummary, ScaleContext
from app.schemas.common import UtcDatetime

SUMMARY_VERSION = 2
"""Format of stored summaries; an older one is computed again on first read."""


class AssetPublic(BaseModel):
    id: uuid.UUID
    sha256: str
    """Content hash of the stored zip: reuse the asset by this or by ``id``."""
    filename: str
    urdf: str
    """The URDF file (path inside the asset) this asset animates; "" for an asset stored before it was recorded."""
    size_bytes: int
    created_at: UtcDatetime
    created: bool = False
    """True when this request created the asset; False when you had already uploaded the same content (and URDF)."""
    url: str
    summary_url: str
    """Its joints, link labels and sizes."""


class AssetSummary(BaseModel):
    """What the asset can do: ``GET /v1/assets/{ref}/summary``."""

    version: int = SUMMARY_VERSION
    urdf: str
    """The URDF file the summary describes."""
    joints: list[JointSummary]
    """Every joint, as the paper's joint summary (type, parent/child link, axis, limits, origin, mimic)."""
    scale: ScaleContext
    """Object and link sizes in metres."""
    links: list[str]
    labels: dict[str, str]
    """Link name -> part label (``semantics.txt`` or URDF visual names), where known."""
    layout: AssetLayout
    """Where each part sits as seen from the object's front (same-label parts told apart, e.g.
    "drawer (upper, link_0)"), and which end of each joint's range is closed, open and rest."""
