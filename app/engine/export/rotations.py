"""Quaternion helpers shared by the GLB writer and the glTF reader (vectorised).

Quaternions are ``(..., 4)`` arrays in glTF order ``x, y, z, w``. Frames: URDF world is
+Z up, glTF is +Y up; :data:`Z_UP_TO_Y_UP` maps URDF world points to glTF world points.
"""

from __future__ import annotations

import numpy as np

from app.engine.types import FloatArray

QUAT_NORM_EPS = 1e-12
"""Quaternions shorter than this cannot be normalised."""
SLERP_LINEAR_DOT = 0.9995
"""Above this |cos(angle)| slerp falls back to a normalised lerp (avoids 0/0)."""

Z_UP_TO_Y_UP: FloatArray = np.array(
    [[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, -1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
)
"""(4, 4) rotation of -90 deg about X: URDF world (+Z up) -> glTF world (+Y up)."""
Z_UP_TO_Y_UP.setflags(write=False)


def matrix_to_quaternion(matrices: FloatArray) -> FloatArray:
    """Unit quaternions of rotation matrices.

    Parameters
    ----------
    matrices : (..., 3, 3) float
        Orthonormal rotation matrices (right-handed).

    Returns
    -------
    (..., 4) float
        Unit quaternions ``x, y, z, w`` with an arbitrary (but deterministic) sign.
    """
    stack = np.asarray(matrices, dtype=np.float64)
    shape = stack.shape[:-2]
    m = stack.reshape(-1, 3, 3)
    diagonal = np.stack([m[:, 0, 0], m[:, 1, 1], m[:, 2, 2]], axis=1)
    trace = diagonal.sum(axis=1)
    choice = np.argmax(np.column_stack([diagonal, trace]), axis=1)
    out = np.zeros((m.shape[0], 4))
    use_w = choice == 3
    w_rows = m[use_w]
    out[use_w, 0] = w_rows[:, 2, 1] - w_rows[:, 1, 2]
    out[use_w, 1] = w_rows[:, 0, 2] - w_rows[:, 2, 0]
    out[use_w, 2] = w_rows[:, 1, 0] - w_rows[:, 0, 1]
    out[use_w, 3] = 1.0 + trace[use_w]
    for i in range(3):
        rows = np.flatnonzero(choice == i)
        if rows.size == 0:
            continue
        j, k = (i + 1) % 3, (i + 2) % 3
        sub = m[rows]
        out[rows, i] = 1.0 - trace[rows] + 2.0 * sub[:, i, i]
        out[rows, j] = sub[:, j, i] + sub[:, i, j]
        out[rows, k] = sub[:, k, i] + sub[:, i, k]
        out[rows, 3] = sub[:, k, j] - sub[:, j, k]
    out /= np.linalg.norm(out, axis=1, keepdims=True)
    return out.reshape((*shape, 4))


def quaternion_to_matrix(quaternions: FloatArray) -> FloatArray:
    """(..., 3, 3) rotation matrices of quaternions (..., 4) ``x, y, z, w`` (normalised first).

    Raises
    ------
    ValueError
        If a quaternion has (near) zero length.
    """
    q = np.asarray(quaternions, dtype=np.float64)
    norm = np.linalg.norm(q, axis=-1, keepdims=True)
    if np.any(~(norm > QUAT_NORM_EPS)):
        raise ValueError("a rotation quaternion has zero length")
    q = q / norm
    x, y, z, w = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    rows = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def continuous_signs(quaternions: FloatArray) -> FloatArray:
    """Flip signs so consecutive quaternions have a non-negative dot product.

    Parameters
    ----------
    quaternions : (t, 4) float

    Returns
    -------
    (t, 4) float
        The same rotations; the first one has ``w >= 0`` (ties: first non-zero
        component positive), so the output is canonical for identical input.
    """
    q = np.array(quaternions, dtype=np.float64, copy=True)
    if q.shape[0] == 0:
        return q
    nonzero = np.flatnonzero(q[0][[3, 0, 1, 2]])
    lead = q[0][[3, 0, 1, 2]][nonzero[0]] if nonzero.size else 1.0
    signs = np.ones(q.shape[0])
    if lead < 0:
        signs[0] = -1.0
    if q.shape[0] > 1:
        flips = np.where(np.einsum("ij,ij->i", q[1:], q[:-1]) < 0.0, -1.0, 1.0)
        signs[1:] = signs[0] * np.cumprod(flips)
    return q * signs[:, None]


def slerp(a: FloatArray, b: FloatArray, s: FloatArray) -> FloatArray:
    """Spherical interpolation along the shorter arc.

    Parameters
    ----------
    a, b : (k, 4) float
        Unit quaternions ``x, y, z, w``.
    s : (k,) float
        Interpolation parameters in [0, 1].

    Returns
    -------
    (k, 4) float
        Unit quaternions.
    """
    a = np.asarray(a, dtype=np.float64)
    b = np.array(b, dtype=np.float64, copy=True)
    s = np.asarray(s, dtype=np.float64)[:, None]
    dot = np.einsum("ij,ij->i", a, b)
    b[dot < 0] *= -1.0
    dot = np.abs(dot)[:, None]
    near = dot > SLERP_LINEAR_DOT
    angle = np.arccos(np.clip(dot, -1.0, 1.0))
    sin_angle = np.where(near, 1.0, np.sin(angle))
    wa = np.where(near, 1.0 - s, np.sin((1.0 - s) * angle) / sin_angle)
    wb = np.where(near, s, np.sin(s * angle) / sin_angle)
    out = wa * a + wb * b
    result: FloatArray = out / np.linalg.norm(out, axis=1, keepdims=True)
    return result


def compose_trs(translation: FloatArray, rotation: FloatArray, scale: FloatArray) -> FloatArray:
    """(k, 4, 4) matrices ``T @ R @ S`` from (k, 3) translations, (k, 4) quaternions, (k, 3) scales."""
    count = translation.shape[0]
    out = np.zeros((count, 4, 4))
    out[:, :3, :3] = quaternion_to_matrix(rotation) * scale[:, None, :]
    out[:, :3, 3] = translation
    out[:, 3, 3] = 1.0
    return out
