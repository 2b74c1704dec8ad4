"""Triangle-soup geometry for contact points: closest points and ray hits (vectorised numpy).

Triangles are ``(t, 3, 3)`` arrays of vertex positions in one frame (metres).
"""

from __future__ import annotations

import numpy as np

from app.engine.types import FloatArray

RAY_EPS = 1e-9
DEGENERATE_AREA = 1e-18


def triangle_normals(triangles: FloatArray) -> FloatArray:
    """(t, 3) unit geometric normals (winding order; zero for degenerate triangles)."""
    cross = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    length = np.linalg.norm(cross, axis=1, keepdims=True)
    return np.divide(cross, length, out=np.zeros_like(cross), where=length > DEGENERATE_AREA)


def closest_points(triangles: FloatArray, point: FloatArray) -> FloatArray:
    """(t, 3) the closest point of each triangle to ``point`` (3,) (Ericson's region tests)."""
    a, b, c = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    p = np.broadcast_to(point, a.shape)
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = np.einsum("ij,ij->i", ab, ap), np.einsum("ij,ij->i", ac, ap)
    bp = p - b
    d3, d4 = np.einsum("ij,ij->i", ab, bp), np.einsum("ij,ij->i", ac, bp)
    cp = p - c
    d5, d6 = np.einsum("ij,ij->i", ab, cp), np.einsum("ij,ij->i", ac, cp)
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    denominator = va + vb + vc
    safe = np.where(np.abs(denominator) > DEGENERATE_AREA, denominator, 1.0)
    v, w = vb / safe, vc / safe
    result = a + ab * v[:, None] + ac * w[:, None]  # inside the face
    # edges and vertices, most specific last so they override the face case
    edge_bc = (va <= 0) & (d4 - d3 >= 0) & (d5 - d6 >= 0)
    t_bc = np.divide(d4 - d3, (d4 - d3) + (d5 - d6), out=np.zeros_like(d4), where=edge_bc)
    result = np.where(edge_bc[:, None], b + (c - b) * t_bc[:, None], result)
    edge_ac = (vb <= 0) & (d2 >= 0) & (d6 <= 0)
    t_ac = np.divide(d2, d2 - d6, out=np.zeros_like(d2), where=edge_ac)
    result = np.where(edge_ac[:, None], a + ac * t_ac[:, None], result)
    edge_ab = (vc <= 0) & (d1 >= 0) & (d3 <= 0)
    t_ab = np.divide(d1, d1 - d3, out=np.zeros_like(d1), where=edge_ab)
    result = np.where(edge_ab[:, None], a + ab * t_ab[:, None], result)
    result = np.where(((d6 >= 0) & (d5 <= d6))[:, None], c, result)
    result = np.where(((d3 >= 0) & (d4 <= d3))[:, None], b, result)
    result = np.where(((d1 <= 0) & (d2 <= 0))[:, None], a, result)
    return np.asarray(result, dtype=np.float64)


def nearest_on_surface(triangles: FloatArray, point: FloatArray) -> tuple[FloatArray, int]:
    """The point of the triangle soup nearest to ``point`` and the index of its triangle (first on ties)."""
    candidates = closest_points(triangles, point)
    index = int(np.argmin(np.linalg.norm(candidates - point, axis=1)))
    return candidates[index], index


def ray_distances(triangles: FloatArray, origins: FloatArray, direction: FloatArray, limit: float) -> FloatArray:
    """(r,) distance along ``direction`` (3,) unit from each origin (r, 3) to the first hit, capped at ``limit``.

    Möller-Trumbore against every triangle; both faces count (meshes are not oriented).
    """
    if triangles.shape[0] == 0:
        return np.full(origins.shape[0], limit)
    a = triangles[:, 0]
    e1, e2 = triangles[:, 1] - a, triangles[:, 2] - a
    h = np.cross(direction, e2)
    det = np.einsum("ij,ij->i", e1, h)
    usable = np.abs(det) > RAY_EPS
    inverse = np.divide(1.0, det, out=np.zeros_like(det), where=usable)
    s = origins[:, None, :] - a[None]
    u = np.einsum("rij,ij->ri", s, h) * inverse
    q = np.cross(s, e1[None])
    v = (q @ direction) * inverse
    t = np.einsum("rij,ij->ri", q, e2) * inverse
    hit = usable & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > RAY_EPS)
    return np.asarray(np.where(hit, t, limit).min(axis=1, initial=limit), dtype=np.float64)
