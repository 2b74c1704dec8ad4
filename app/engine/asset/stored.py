"""An asset its caller has already validated and summarised (the service's stored upload).

The service validates an upload once (``load_asset`` in the API), keeps the zip under its
sha256 and the joint summary beside it. A job then hands the engine the stored zip's path
with a :class:`StoredAsset`: the asset cache is found by that hash (the zip is not read or
copied when the entry exists), the asset carries the client's name (no renamed copy), and
the roles get the stored summary instead of one computed again.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from app.engine.asset.cache import load_asset_cached
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import JointSummary, ScaleContext, joint_summary, scale_context


@dataclass(frozen=True)
class StoredAsset:
    """What is known of a stored asset file.

    Attributes
    ----------
    sha256
        Content hash of the file (zip) handed to the engine.
    name
        The asset's name in messages, reports and the GLB (the upload's name).
    joints, scale
        Its joint summary and scale context, as computed when it was validated
        (``None``: compute them).
    """

    sha256: str
    name: str
    joints: tuple[JointSummary, ...] | None = None
    scale: ScaleContext | None = None


def load_stored(path: Path, cache_dir: Path | None, urdf: str | None, stored: StoredAsset | None) -> ArticulatedAsset:
    """Load ``path`` through the asset cache, keyed by the stored hash when there is one.

    Raises
    ------
    AssetError
        As :func:`app.engine.asset.loader.load_asset`.
    """
    if stored is None:
        return load_asset_cached(path, cache_dir, urdf=urdf)
    return load_asset_cached(path, cache_dir, urdf=urdf, name=stored.name, content_hash=stored.sha256)


def summaries(asset: ArticulatedAsset, stored: StoredAsset | None) -> tuple[list[JointSummary], ScaleContext]:
    """The joint summary and scale context of ``asset``: the stored ones when known."""
    if stored is not None and stored.joints is not None and stored.scale is not None:
        return list(stored.joints), stored.scale.model_copy(update={"asset": asset.name})
    return joint_summary(asset), scale_context(asset)
