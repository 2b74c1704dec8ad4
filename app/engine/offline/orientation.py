"""Joint values that put a part in a stated orientation ("lid vertical", "handle upright", "screen flat").

A panel-like part (one thin dimension) is vertical when its thin axis is horizontal; a
rod-like part (a handle) is upright when its long axis is vertical. The joint's range is
sampled; among the best-matching values the planner takes the one nearest to the closed
(or rest) state, except for "flat" when opening, where it takes the farthest (a screen
folded all the way back).
"""

from __future__ import annotations

import math

import numpy as np

from app.engine.asset.kinematics import link_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.offline.geometry import WIDE_SWING_RAD, JointGeometry
from app.engine.types import FloatArray

SAMPLES = 721
PANEL_RATIO = 0.35
"""Thinnest / middle extent below this: the part is a panel (door, lid, screen)."""
PEAK_TOLERANCE = 0.08
"""Local best matches this close to the global best count as candidates (about 20 degrees)."""
UP = np.array([0.0, 0.0, 1.0])
SNAP_RAD = math.radians(4.0)
LIMIT_SNAP_RAD = math.radians(8.0)
"""A limit this close to the best match is where the designer put "flat" (an oven door's stop)."""


def _principal_axes(points: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    """(axes (3, 3) rows sorted by extent ascending, extents (3,), centre (3,)) in the link frame."""
    centre = points.mean(axis=0)
    _, _, rows = np.linalg.svd(points - centre, full_matrices=False)
    extents = np.ptp((points - centre) @ rows.T, axis=0)
    order = np.argsort(extents)
    return rows[order], extents[order], centre


def _range(geometry: JointGeometry) -> FloatArray:
    if geometry.lower is not None and geometry.upper is not None:
        return np.linspace(geometry.lower, geometry.upper, SAMPLES)
    return np.linspace(geometry.rest - math.pi, geometry.rest + math.pi, SAMPLES)


def orientation_value(asset: ArticulatedAsset, geometry: JointGeometry, orientation: str, opening: bool, way: float | None = None,
                      start: float | None = None) -> float | None:
    """Joint value that makes ``geometry.child`` vertical or flat (None if the part cannot tell); ``way`` (+1 / -1):
    only values reached moving that way from ``start`` (else the rest value), when there are any."""
    points = asset.links[geometry.child].vertices()
    if points.shape[0] < 4 or geometry.type not in ("revolute", "continuous"):
        return None
    rows, extents, _ = _principal_axes(points)
    panel = extents[0] < PANEL_RATIO * max(extents[1], 1e-9)
    axis = rows[0] if panel else rows[2]
    values = _range(geometry)
    poses = link_poses(asset, {geometry.joint: values}, frames=values.shape[0])[geometry.child]
    alignment = np.abs(np.einsum("tij,j->ti", poses[:, :3, :3], axis) @ UP)
    wants_aligned = (orientation == "flat") == panel  # flat panel / upright rod: its axis along up
    score = alignment if wants_aligned else 1.0 - alignment
    peaks = [i for i in range(values.shape[0])
             if (i == 0 or score[i] >= score[i - 1]) and (i == values.shape[0] - 1 or score[i] > score[i + 1])]
    clusters = [i for i in peaks if score[i] >= score.max() - PEAK_TOLERANCE]
    reference = geometry.closed_value if geometry.closed_value is not None else geometry.rest
    if way is not None:
        origin = start if start is not None else geometry.rest
        clusters = [i for i in clusters if (float(values[i]) - origin) * way > SNAP_RAD] or clusters
    distance = [abs(float(values[i]) - reference) for i in clusters]
    farthest = orientation == "flat" and opening
    chosen = float(values[clusters[int(np.argmax(distance) if farthest else np.argmin(distance))]])
    return _snap(geometry, chosen, reference)


def _snap(geometry: JointGeometry, value: float, reference: float) -> float:
    """The joint's limit when within LIMIT_SNAP_RAD, else a whole quarter turn from the closed state when within
    SNAP_RAD (meshes are not perfectly flat)."""
    limits = [v for v in (geometry.lower, geometry.upper) if v is not None and abs(v - reference) > 1e-6]
    near = [v for v in limits if abs(v - value) <= LIMIT_SNAP_RAD]
    if near:
        return float(min(near, key=lambda v: abs(v - value)))
    quarters = round((value - reference) / (math.pi / 2))
    snapped = reference + quarters * math.pi / 2
    inside = geometry.lower is None or geometry.upper is None or geometry.lower - 1e-9 <= snapped <= geometry.upper + 1e-9
    return snapped if abs(snapped - value) <= SNAP_RAD and inside else value


def directional_sign(geometry: JointGeometry, direction: FloatArray) -> float:
    """+1 or -1: the joint direction that moves the part's centre along ``direction``."""
    if geometry.type == "prismatic":
        along = float(geometry.axis_world @ direction)
    elif geometry.span is not None and geometry.span > WIDE_SWING_RAD:
        # a handle that swings over the top: where it ends, not where it starts to go (hanging down the front,
        # it first moves forward and up, yet its far end hangs down the back)
        along = float((_swung(geometry, geometry.upper) - _swung(geometry, geometry.lower)) @ direction)
    else:
        along = float(np.cross(geometry.axis_world, geometry.tip - geometry.pivot_world) @ direction)
    return 1.0 if along >= 0 else -1.0


def _swung(geometry: JointGeometry, value: float | None) -> FloatArray:
    """Where the part's tip is with the joint at ``value`` (a rotation about its axis from rest)."""
    angle = (value if value is not None else geometry.rest) - geometry.rest
    axis, arm = geometry.axis_world, geometry.tip - geometry.pivot_world
    turned = arm * math.cos(angle) + np.cross(axis, arm) * math.sin(angle) + axis * float(axis @ arm) * (1 - math.cos(angle))
    return geometry.pivot_world + turned
