"""What an uploaded asset can do: its joints (the paper's joint summary), sizes, and where its parts sit.

Computed with the engine's loader when a content hash and URDF are first validated, and kept
beside the content in storage (``assets/<sha256>.<urdf digest>.summary.json``) so later
reads cost one file read. The client's own name for the asset is filled in on read (the
stored summary is shared by every client with the same content). A summary of an older
format, or a missing one, is computed again from the stored zip.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import PurePosixPath
from typing import Protocol

from pydantic import ValidationError

from app.core.storage import Storage, intact_local_path
from app.engine.asset.layout import asset_layout
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import joint_summary, scale_context
from app.schemas.assets import SUMMARY_VERSION, AssetSummary


class AssetRecord(Protocol):
    """What a summary read needs of a client's asset (an ``Asset`` row, or a worker's copy of its fields)."""

    @property
    def filename(self) -> str: ...

    @property
    def urdf(self) -> str: ...

    @property
    def sha256(self) -> str: ...

    @property
    def size_bytes(self) -> int: ...

    @property
    def storage_key(self) -> str: ...


def summary_key(sha256: str, urdf: str) -> str:
    """Storage key of the summary of content ``sha256`` loaded with ``urdf`` ("" = its only URDF)."""
    return f"assets/{sha256}.{hashlib.sha256(urdf.encode()).hexdigest()[:16]}.summary.json"


def summarise(asset: ArticulatedAsset, name: str = "") -> AssetSummary:
    """``name``: the asset as the client named it (its upload's file name without ``.zip``)."""
    return AssetSummary(
        version=SUMMARY_VERSION, urdf=asset.urdf_file,
        joints=joint_summary(asset), scale=scale_context(asset).model_copy(update={"asset": name}),
        links=sorted(asset.links),
        labels={name: link.semantics.label for name, link in sorted(asset.links.items()) if link.semantics.label},
        layout=asset_layout(asset),
    )


def store_summary(storage: Storage, sha256: str, urdf: str, asset: ArticulatedAsset) -> AssetSummary:
    summary = summarise(asset)
    storage.put_bytes(summary_key(sha256, urdf), summary.model_dump_json().encode())
    return summary


def _stored(storage: Storage, key: str) -> AssetSummary | None:
    if not storage.exists(key):
        return None
    try:
        summary = AssetSummary.model_validate(json.loads(storage.get_bytes(key)))
    except (ValueError, ValidationError):  # an older format: computed again
        return None
    return summary if summary.version == SUMMARY_VERSION else None


def has_summary(storage: Storage, sha256: str, urdf: str) -> bool:
    """Whether this content and URDF were validated and summarised in the current format."""
    return _stored(storage, summary_key(sha256, urdf)) is not None


def read_summary(storage: Storage, asset: AssetRecord) -> AssetSummary:
    """The client's summary of ``asset``: the stored one under its name, or one computed (and stored) now.

    Raises
    ------
    StorageError
        The summary has to be computed and the stored zip is missing or damaged.
    """
    name = PurePosixPath(asset.filename).stem
    summary = _stored(storage, summary_key(asset.sha256, asset.urdf))
    if summary is None:
        path = intact_local_path(storage, asset.storage_key, asset.sha256, asset.size_bytes)
        summary = store_summary(storage, asset.sha256, asset.urdf, load_asset(path, name=name, urdf=asset.urdf or None))
    return summary.model_copy(update={"scale": summary.scale.model_copy(update={"asset": name})})
