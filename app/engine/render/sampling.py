"""Deterministic, area-weighted surface points of a link (link frame).

The seed of each link's generator is the first 8 bytes of
``sha256(asset.name + "\\0" + link)``: stable across processes and machines and
independent of where the asset lives on disk. Results are cached per asset object.
"""

from __future__ import annotations

import hashlib
import threading
import weakref

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.types import FloatArray, Points

AREA_EPS = 1e-18

_CACHE: weakref.WeakKeyDictionary[ArticulatedAsset, dict[tuple[str, int], Points]] = weakref.WeakKeyDictionary()
_LOCK = threading.Lock()


def link_seed(asset_name: str, link: str) -> int:
    """The sampling seed of ``link``: sha256 of the asset name and link name."""
    digest = hashlib.sha256(f"{asset_name}\0{link}".encode()).digest()
    return int.from_bytes(digest[:8], "little")


def _triangles(asset: ArticulatedAsset, link: str) -> FloatArray:
    """(m, 3, 3) every triangle of the link in the link frame."""
    parts = asset.links[link].parts
    if not parts:
        raise RenderError(f"link '{link}' has no visual geometry to sample")
    return np.concatenate([p.vertices[p.faces] for p in parts], axis=0)


def sample_link_points(asset: ArticulatedAsset, link: str, count: int) -> Points:
    """(count, 3) points uniformly distributed (by area) on ``link``'s surface, link frame.

    Raises
    ------
    RenderError
        Unknown link, no geometry, or ``count`` < 1.
    """
    if link not in asset.links:
        raise RenderError(f"unknown link '{link}'")
    if count < 1:
        raise RenderError(f"point count must be positive, got {count}")
    with _LOCK:
        cached = _CACHE.setdefault(asset, {}).get((link, count))
    if cached is not None:
        return cached
    triangles = _triangles(asset, link)
    rng = np.random.Generator(np.random.PCG64(link_seed(asset.name, link)))
    areas = 0.5 * np.linalg.norm(np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]), axis=1)
    total = float(areas.sum())
    if total > AREA_EPS:
        chosen = rng.choice(len(triangles), size=count, p=areas / total)
    else:  # degenerate geometry: fall back to uniformly chosen triangles
        chosen = rng.integers(0, len(triangles), size=count)
    r1 = np.sqrt(rng.random(count))
    r2 = rng.random(count)
    tri = triangles[chosen]
    points = (1.0 - r1)[:, None] * tri[:, 0] + (r1 * (1.0 - r2))[:, None] * tri[:, 1] + (r1 * r2)[:, None] * tri[:, 2]
    points.setflags(write=False)
    with _LOCK:
        _CACHE.setdefault(asset, {})[(link, count)] = points
    return points
