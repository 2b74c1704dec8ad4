"""Vertex normals of a triangle mesh whose file gives none: face normals weighted by corner angle.

The arithmetic follows the one trimesh does for ``Trimesh.vertex_normals`` (Thürrner & Wüthrich
1998: each face adds its unit normal times the angle of its corner at the vertex), operation for
operation, so a mesh read by the built-in OBJ reader gets the same normals, bit for bit, as the
same mesh read by trimesh.
"""

from __future__ import annotations

import numpy as np

from app.engine.types import FloatArray, IntArray

ZERO_LENGTH = float(np.finfo(np.float64).resolution * 100)
"""Vectors no longer than this have no direction (trimesh's ``TOL_ZERO``, 1e-13)."""
SMALLEST_ANGLE = 1e-8
"""A face with a corner smaller than this (radians) is a sliver: all its corner weights are zero."""


def _unit_rows(vectors: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Rows scaled to unit length (rows too short to have a direction are left scaled by their own
    tiny length) and the mask of the rows that had a direction."""
    length = np.sqrt(np.dot(vectors * vectors, [1.0] * vectors.shape[1]))
    valid = length > ZERO_LENGTH
    length[valid] **= -1
    return vectors * length.reshape((-1, 1)), valid


def _row_dots(a: FloatArray, b: FloatArray) -> FloatArray:
    return np.dot(a * b, [1.0] * a.shape[1])


def face_normals(triangles: FloatArray) -> FloatArray:
    """(m, 3) unit normals of (m, 3, 3) triangles; zero rows for degenerate triangles."""
    edges = triangles[:, 1:, :] - triangles[:, :2, :]  # v1 - v0 and v2 - v1
    unit, valid = _unit_rows(np.cross(edges[:, 0], edges[:, 1]))
    if valid.all():
        return unit
    normals = np.zeros((len(triangles), 3), dtype=np.float64)
    normals[valid] = unit[valid]
    return normals


def corner_angles(triangles: FloatArray) -> FloatArray:
    """(m, 3) angle of every triangle corner, radians; all zero for a triangle with a sliver corner."""
    first, _ = _unit_rows(triangles[:, 1] - triangles[:, 0])
    second, _ = _unit_rows(triangles[:, 2] - triangles[:, 0])
    third, _ = _unit_rows(triangles[:, 2] - triangles[:, 1])
    angles = np.zeros((len(triangles), 3), dtype=np.float64)
    angles[:, 0] = np.arccos(np.clip(_row_dots(first, second), -1, 1))
    angles[:, 1] = np.arccos(np.clip(_row_dots(-first, third), -1, 1))
    angles[:, 2] = np.pi - angles[:, 0] - angles[:, 1]
    angles[(angles < SMALLEST_ANGLE).any(axis=1), :] = 0.0
    return angles


def angle_weighted_normals(vertices: FloatArray, faces: IntArray) -> FloatArray:
    """(n, 3) unit vertex normals of a triangle mesh (zero for vertices no valid face uses).

    Each vertex sums ``angle x normal`` over its faces in face order (degenerate faces skipped),
    then the sums are scaled to unit length.
    """
    if len(faces) == 0:
        return np.zeros((len(vertices), 3), dtype=np.float64)
    triangles = vertices.view(np.ndarray)[faces]
    normals = face_normals(triangles)
    angles = corner_angles(triangles)
    usable = (normals**2).sum(axis=1) > 0.5
    corners = faces[usable].reshape(-1)
    weights = angles[usable].reshape(-1)
    per_corner = np.repeat(normals[usable], 3, axis=0)
    summed = np.zeros((len(vertices), 3), dtype=np.float64)
    for axis in range(3):
        summed[:, axis] = np.bincount(corners, weights=weights * per_corner[:, axis], minlength=len(vertices))
    unit, _ = _unit_rows(summed)
    return unit
