"""What an uploaded asset can do: its joints (the paper's joint summary) and its sizes.

Computed from the stored zip with the engine's loader when the asset is first validated,
and kept beside it in storage (``assets/<sha256>.summary.json``) so later reads cost one
file read. Assets stored before summaries existed get theirs on first request.
"""

from __future__ import annotations

import json
from pathlib import PurePosixPath

from app.core.storage import Storage
from app.db.models import Asset
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import joint_summary, scale_context
from app.schemas.assets import AssetSummary


def summary_key(sha256: str) -> str:
    return f"assets/{sha256}.summary.json"


def summarise(asset: ArticulatedAsset, name: str) -> AssetSummary:
    """``name``: the asset as the client named it (its upload's file name without ``.zip``)."""
    return AssetSummary(
        joints=joint_summary(asset), scale=scale_context(asset).model_copy(update={"asset": name}),
        links=sorted(asset.links),
        labels={name: link.semantics.label for name, link in sorted(asset.links.items()) if link.semantics.label},
    )


def store_summary(storage: Storage, sha256: str, asset: ArticulatedAsset, name: str) -> AssetSummary:
    summary = summarise(asset, name)
    storage.put_bytes(summary_key(sha256), summary.model_dump_json().encode())
    return summary


def read_summary(storage: Storage, asset: Asset) -> AssetSummary:
    """The stored summary, or one computed (and stored) from the asset's zip."""
    key = summary_key(asset.sha256)
    if storage.exists(key):
        return AssetSummary.model_validate(json.loads(storage.get_bytes(key)))
    name = PurePosixPath(asset.filename).stem
    return store_summary(storage, asset.sha256, load_asset(storage.local_path(asset.storage_key)), name)
