"""Exact interpenetration tests between the convex primitive parts of posed links.

Every visual of the example assets is a URDF box, cylinder (a 48-sided prism once
meshed) or sphere (an icosphere): closed convex polyhedra. A point lies inside such
a part exactly when it is behind every face plane, so the test needs no ray casting.
Surface samples (vertices, points along every edge, area samples) of one link are
carried to another link's frame and tested against that link's parts.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import trimesh

from app.engine.asset.model import ArticulatedAsset

CLEARANCE_M = 5e-4
"""Points closer than this to the inside of another link's part count as touching it.

The examples leave gaps of at least 1 mm, so every contact or overlap fails the test."""
EDGE_STEP_M = 4e-3
"""Spacing of the sample points placed along every mesh edge."""
AREA_PER_SAMPLE_M2 = 1e-4
"""One area sample per square centimetre of surface (faces away from edges are probed here)."""
MAX_AREA_SAMPLES = 4000
PLANE_DECIMALS = 9
SAMPLE_SEED = 20240607


@dataclass(frozen=True)
class ConvexPart:
    """A convex part as half-spaces ``normals @ p <= offsets`` plus its box, link frame.

    Attributes
    ----------
    normals : (k, 3) float, unit outward face normals
    offsets : (k,) float, metres
    lower, upper : (3,) float, metres, axis-aligned bounds
    name : material name of the part (identifies the visual in messages)
    """

    normals: np.ndarray
    offsets: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    name: str


@dataclass(frozen=True)
class Contact:
    """One offending point: ``point_link``'s surface point inside ``part_link``'s part."""

    point_link: str
    part_link: str
    part: str
    depth_m: float
    point_world: tuple[float, float, float]


def convex_parts(asset: ArticulatedAsset, link: str) -> list[ConvexPart]:
    """Half-space form of every part of ``link`` (each must be a closed convex mesh)."""
    out = []
    for part in asset.links[link].parts:
        mesh = trimesh.Trimesh(vertices=part.vertices, faces=part.faces, process=True)
        if not (mesh.is_watertight and mesh.is_convex):
            raise ValueError(f"link {link} part {part.material.name} is not a closed convex primitive")
        normals = np.asarray(mesh.face_normals, dtype=np.float64)
        offsets = np.einsum("ij,ij->i", normals, mesh.vertices[mesh.faces[:, 0]])
        planes = np.unique(np.round(np.column_stack([normals, offsets]), PLANE_DECIMALS), axis=0)
        out.append(
            ConvexPart(
                normals=planes[:, :3],
                offsets=planes[:, 3],
                lower=mesh.vertices.min(axis=0),
                upper=mesh.vertices.max(axis=0),
                name=part.material.name,
            )
        )
    return out


def surface_points(asset: ArticulatedAsset, link: str) -> np.ndarray:
    """(n, 3) surface samples of ``link`` in its own frame: vertices, edge points, area samples."""
    chunks = []
    for index, part in enumerate(asset.links[link].parts):
        mesh = trimesh.Trimesh(vertices=part.vertices, faces=part.faces, process=True)
        chunks.append(mesh.vertices)
        for a, b in mesh.vertices[mesh.edges_unique]:
            steps = max(1, int(np.ceil(np.linalg.norm(b - a) / EDGE_STEP_M)))
            s = (np.arange(1, steps) / steps)[:, None]
            chunks.append(a + s * (b - a))
        count = int(min(MAX_AREA_SAMPLES, max(64, mesh.area / AREA_PER_SAMPLE_M2)))
        samples, _ = trimesh.sample.sample_surface(mesh, count, seed=SAMPLE_SEED + index)
        chunks.append(samples)
    return np.concatenate(chunks, axis=0)


def _depths(points: np.ndarray, part: ConvexPart, clearance: float) -> tuple[np.ndarray, np.ndarray]:
    """Indices of ``points`` (n, 3) within ``clearance`` of the inside of ``part`` and their depth."""
    near = np.all((points >= part.lower - clearance) & (points <= part.upper + clearance), axis=1)
    index = np.flatnonzero(near)
    if index.size == 0:
        return index, np.zeros(0)
    signed = points[index] @ part.normals.T - part.offsets[None, :]
    outside = signed.max(axis=1)
    hit = outside < clearance
    return index[hit], -outside[hit]


class PenetrationChecker:
    """Pairwise contact test of all links of one asset at given link poses."""

    def __init__(self, asset: ArticulatedAsset) -> None:
        self.asset = asset
        self.links = asset.visual_links
        self.parts = {link: convex_parts(asset, link) for link in self.links}
        self.points = {link: surface_points(asset, link) for link in self.links}
        self.bounds = {
            link: (np.min([p.lower for p in parts], axis=0), np.max([p.upper for p in parts], axis=0))
            for link, parts in self.parts.items()
        }

    def contacts(self, poses: Mapping[str, np.ndarray], clearance: float = CLEARANCE_M) -> list[Contact]:
        """Every link's samples that come within ``clearance`` of another link's parts.

        Parameters
        ----------
        poses
            {link: (4, 4) world pose} for one frame.
        clearance
            Metres; 0 reports only true overlaps.

        Returns
        -------
        The deepest offending point per (point link, part link, part), deepest first.
        """
        found: list[Contact] = []
        world = {link: self._to_world(self.points[link], poses[link]) for link in self.links}
        for part_link in self.links:
            inverse = np.linalg.inv(poses[part_link])
            for point_link in self.links:
                if point_link == part_link:
                    continue
                local = world[point_link] @ inverse[:3, :3].T + inverse[:3, 3]
                lower, upper = self.bounds[part_link]
                near = np.flatnonzero(np.all((local >= lower - clearance) & (local <= upper + clearance), axis=1))
                for part in self.parts[part_link] if near.size else ():
                    index, depth = _depths(local[near], part, clearance)
                    if index.size:
                        worst = int(np.argmax(depth))
                        point = world[point_link][near[index[worst]]]
                        found.append(
                            Contact(point_link, part_link, part.name, float(depth[worst]), tuple(map(float, point)))
                        )
        return sorted(found, key=lambda c: -c.depth_m)

    @staticmethod
    def _to_world(points: np.ndarray, pose: np.ndarray) -> np.ndarray:
        return points @ pose[:3, :3].T + pose[:3, 3]
