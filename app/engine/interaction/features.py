"""Mesh features a contact point is taken from: a face's centre, a handle's grip, a door's
free edge, and which side of a part is exposed (free space in front of it).

All points and directions are in one link's frame unless a name says ``world``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.engine.interaction.surface import nearest_on_surface, ray_distances, triangle_normals
from app.engine.types import FloatArray

PARALLEL_COS = 0.7
"""A triangle belongs to a face looking along ``e`` when ``|normal . e|`` is at least this."""
FREE_EDGE_INSET_M = 0.02
FREE_EDGE_INSET_FRACTION = 0.1
"""The free-edge point sits this far (the smaller of the two) in from the edge, on the face."""
RAY_GRID = (0.25, 0.5, 0.75)
"""Ray origins for exposure: this grid over the part's cross-section, 1 mm in front of it."""
RAY_OFFSET_M = 1e-3
EXPOSURE_TIE_M = 1e-6


@dataclass(frozen=True)
class SurfacePoint:
    point: FloatArray
    normal: FloatArray


def unit(vector: FloatArray) -> FloatArray:
    length = float(np.linalg.norm(vector))
    return vector / length if length > 0 else vector


def basis(e: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Two unit vectors completing ``e`` to a right-handed orthonormal basis (deterministic)."""
    helper = np.eye(3)[int(np.argmin(np.abs(e)))]
    first = unit(np.cross(e, helper))
    return first, np.cross(e, first)


def snap(triangles: FloatArray, target: FloatArray, e: FloatArray) -> SurfacePoint:
    """The surface point nearest ``target`` on the face looking along ``e`` (any face if there is none).

    The normal is the triangle's, turned to agree with ``e`` (meshes are not oriented).
    """
    normals = triangle_normals(triangles)
    facing = np.abs(normals @ e) >= PARALLEL_COS
    pool = np.flatnonzero(facing) if facing.any() else np.arange(triangles.shape[0])
    point, index = nearest_on_surface(triangles[pool], target)
    normal = normals[pool[index]]
    if float(normal @ e) < 0:
        normal = -normal
    if not np.any(normal):
        normal = e
    return SurfacePoint(point=point, normal=unit(normal))


def face_target(vertices: FloatArray, e: FloatArray) -> FloatArray:
    """Centre of the vertices' box across ``e``, at their outermost extent along ``e``."""
    first, second = basis(e)
    coordinates = vertices @ np.column_stack([first, second, e])
    low, high = coordinates.min(axis=0), coordinates.max(axis=0)
    centre = (low + high) / 2.0
    return np.asarray(centre[0] * first + centre[1] * second + high[2] * e, dtype=np.float64)


def end_target(vertices: FloatArray, e: FloatArray, toward: FloatArray) -> FloatArray:
    """On the ``e`` face, just in from its end along ``toward`` (unit, across ``e``), centred the other way."""
    third = np.cross(e, toward)
    coordinates = vertices @ np.column_stack([toward, third, e])
    low, high = coordinates.min(axis=0), coordinates.max(axis=0)
    inset = min(FREE_EDGE_INSET_M, FREE_EDGE_INSET_FRACTION * float(high[0] - low[0]))
    return np.asarray((high[0] - inset) * toward + (low[1] + high[1]) / 2.0 * third + high[2] * e, dtype=np.float64)


def free_edge_target(vertices: FloatArray, axis: FloatArray, anchor: FloatArray, e: FloatArray) -> FloatArray:
    """Mid-way along the hinge axis, just in from the edge farthest from it, on the ``e`` face."""
    relative = vertices - anchor
    along = relative @ axis
    radial = relative - np.outer(along, axis)
    u = unit(radial.mean(axis=0) - (radial.mean(axis=0) @ e) * e)
    reach = radial @ u
    inset = min(FREE_EDGE_INSET_M, FREE_EDGE_INSET_FRACTION * float(reach.max() - reach.min()))
    height = (float(along.min()) + float(along.max())) / 2.0
    return np.asarray(anchor + height * axis + (float(reach.max()) - inset) * u + float((relative @ e).max()) * e, dtype=np.float64)


def exposure(vertices_world: FloatArray, others_world: FloatArray, direction_world: FloatArray, limit: float) -> float:
    """Mean free distance (m, capped at ``limit``) in front of the part's side facing ``direction_world``.

    Rays start on a 3x3 grid over the part's cross-section, 1 mm beyond its extent, and are
    tested against the other (non-moving) geometry ``others_world`` (t, 3, 3).
    """
    first, second = basis(direction_world)
    coordinates = vertices_world @ np.column_stack([first, second, direction_world])
    low, high = coordinates.min(axis=0), coordinates.max(axis=0)
    origins = np.array([
        (low[0] + a * (high[0] - low[0])) * first + (low[1] + b * (high[1] - low[1])) * second + (high[2] + RAY_OFFSET_M) * direction_world
        for a in RAY_GRID for b in RAY_GRID
    ])
    return float(ray_distances(others_world, origins, direction_world, limit).mean())


def more_exposed(candidates: list[FloatArray], vertices_world: FloatArray, others_world: FloatArray, limit: float) -> int:
    """Index of the world direction with the most free space in front (the first on ties)."""
    scores = [exposure(vertices_world, others_world, unit(c), limit) for c in candidates]
    best = 0
    for index, score in enumerate(scores):
        if score > scores[best] + EXPOSURE_TIE_M:
            best = index
    return best
