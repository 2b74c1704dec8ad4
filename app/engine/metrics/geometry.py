"""Per-link reference geometry for the 3D metrics (SPEC §6), built once per asset.

For every link with visual geometry, in the link's own frame:

- ``samples`` (N, 3): N area-weighted surface points drawn with a
  ``numpy.random.Generator`` seeded from ``sha256(f"{asset_name}:{link_name}:{N}")``
  (no global RNG, no trimesh sampler), shared by ground truth and prediction;
- ``hull`` (h, 3): the convex-hull vertices of the link's vertices; the world AABB of
  the posed vertices equals the AABB of the posed hull vertices under any affine map;
- ``local_diagonal``: diagonal of the link's vertex box in its own frame;
- ``tree``: a KD-tree of ``samples`` (nearest-neighbour queries in the link frame).

``object_diagonal`` is the diagonal of the world AABB of all visual vertices at the rest
pose.
"""

from __future__ import annotations

import hashlib
import logging
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from scipy.spatial import ConvexHull, QhullError, cKDTree

from app.engine.asset.kinematics import rest_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import MetricError
from app.engine.types import FloatArray, IntArray, Points

logger = logging.getLogger(__name__)

POINTS_PER_LINK = 2048
GIOU_EXTENT_FLOOR = 1e-4
"""Box extents are floored at this fraction of the object diagonal."""
PC_SCALE_FLOOR = 0.05
"""Link scales are floored at this fraction of the object diagonal."""
MIN_HULL_POINTS = 5
AREA_EPS = 1e-18


@dataclass(frozen=True, eq=False)
class LinkGeometry:
    """Reference geometry of one link, in the link frame (metres)."""

    name: str
    samples: Points
    hull: Points
    local_diagonal: float
    tree: cKDTree


@dataclass(frozen=True, eq=False)
class AssetGeometry:
    """Reference geometry of every visual link of an asset (``links`` in link order)."""

    asset_name: str
    links: tuple[str, ...]
    geometry: Mapping[str, LinkGeometry]
    object_diagonal: float
    point_count: int

    @property
    def extent_floor(self) -> float:
        """Smallest box extent (metres) used by gIoU."""
        return GIOU_EXTENT_FLOOR * self.object_diagonal

    def link_scale(self, link: str) -> float:
        """PC scale of ``link``: its local box diagonal, floored at 5 % of the object diagonal."""
        return max(self.geometry[link].local_diagonal, PC_SCALE_FLOOR * self.object_diagonal)


def seed_of(text: str) -> int:
    """64-bit seed from the SHA-256 of ``text`` (first 8 bytes, little endian)."""
    return int.from_bytes(hashlib.sha256(text.encode("utf-8")).digest()[:8], "little")


def sample_surface(vertices: Points, faces: IntArray, count: int, seed_text: str) -> Points:
    """``count`` area-weighted points on a triangle mesh.

    Parameters
    ----------
    vertices : (n, 3) float, metres
    faces : (m, 3) int
    seed_text : str
        Seeds the private generator (same text -> same points).

    Returns
    -------
    (count, 3) float. A mesh with no area gives points drawn from its vertices.
    """
    generator = np.random.default_rng(seed_of(seed_text))
    if faces.shape[0] == 0:
        return vertices[generator.integers(0, vertices.shape[0], size=count)].copy()
    a, b, c = (vertices[faces[:, i]] for i in range(3))
    areas = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    total = float(areas.sum())
    if total <= AREA_EPS:
        return vertices[generator.integers(0, vertices.shape[0], size=count)].copy()
    cumulative = np.cumsum(areas)
    picks = np.searchsorted(cumulative, generator.random(count) * cumulative[-1], side="right")
    picks = np.minimum(picks, faces.shape[0] - 1)
    uv = generator.random((count, 2))
    flip = uv.sum(axis=1) > 1.0
    uv[flip] = 1.0 - uv[flip]
    points: Points = a[picks] + uv[:, :1] * (b[picks] - a[picks]) + uv[:, 1:] * (c[picks] - a[picks])
    return points


def hull_vertices(vertices: Points) -> Points:
    """(h, 3) the convex-hull vertices of ``vertices`` (all unique vertices when flat or tiny)."""
    unique = np.unique(vertices, axis=0)
    if unique.shape[0] < MIN_HULL_POINTS:
        return unique
    try:
        hull = ConvexHull(unique)
    except QhullError:
        return unique  # flat or degenerate: every vertex is kept, the box stays exact
    return np.asarray(unique[np.sort(hull.vertices)], dtype=np.float64)


def _link_mesh(asset: ArticulatedAsset, link: str) -> tuple[FloatArray, IntArray]:
    parts = asset.links[link].parts
    offsets = np.cumsum([0] + [p.vertices.shape[0] for p in parts[:-1]])
    vertices = np.concatenate([p.vertices for p in parts], axis=0).astype(np.float64)
    faces = np.concatenate([p.faces.astype(np.int64) + o for p, o in zip(parts, offsets, strict=True)], axis=0)
    return vertices, faces


def build_geometry(asset: ArticulatedAsset, point_count: int = POINTS_PER_LINK) -> AssetGeometry:
    """Sample and summarise every visual link of ``asset``.

    Raises
    ------
    MetricError
        The asset has no visual geometry or a link's vertices are not finite.
    """
    links = asset.visual_links
    if not links:
        raise MetricError(f"asset {asset.name} has no link with visual geometry")
    rest = rest_poses(asset)
    geometry: dict[str, LinkGeometry] = {}
    corners = []
    for link in links:
        vertices, faces = _link_mesh(asset, link)
        if not np.all(np.isfinite(vertices)):
            raise MetricError(f"asset {asset.name}: link {link} has non-finite vertices")
        samples = sample_surface(vertices, faces, point_count, f"{asset.name}:{link}:{point_count}")
        hull = hull_vertices(vertices)
        extent = vertices.max(axis=0) - vertices.min(axis=0)
        geometry[link] = LinkGeometry(
            name=link, samples=samples, hull=hull, local_diagonal=float(np.linalg.norm(extent)), tree=cKDTree(samples)
        )
        posed = hull @ rest[link][:3, :3].T + rest[link][:3, 3]
        corners.append(posed.min(axis=0))
        corners.append(posed.max(axis=0))
    stacked = np.stack(corners)
    diagonal = float(np.linalg.norm(stacked.max(axis=0) - stacked.min(axis=0)))
    if diagonal <= 0.0:
        raise MetricError(f"asset {asset.name}: the visual geometry has zero size")
    return AssetGeometry(
        asset_name=asset.name, links=links, geometry=geometry, object_diagonal=diagonal, point_count=point_count
    )
