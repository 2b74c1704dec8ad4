"""Joint summary and scale context (paper supplementary §1.3)."""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
from pydantic import BaseModel, ConfigDict

from app.engine.asset.kinematics import rest_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.types import FloatArray, Transform

ROUND_DIGITS = 6


class JointLimit(BaseModel):
    model_config = ConfigDict(frozen=True)
    lower: float | None
    upper: float | None
    effort: float | None
    velocity: float | None


class JointOrigin(BaseModel):
    model_config = ConfigDict(frozen=True)
    xyz: tuple[float, float, float]
    rpy: tuple[float, float, float]


class JointMimic(BaseModel):
    model_config = ConfigDict(frozen=True)
    joint: str
    multiplier: float
    offset: float


class JointSummary(BaseModel):
    """One record of the URDF joint summary schema."""

    model_config = ConfigDict(frozen=True)
    joint_name: str
    type: Literal["revolute", "continuous", "prismatic", "fixed"]
    parent: str
    child: str
    axis: tuple[float, float, float]
    limit: JointLimit | None
    origin: JointOrigin
    mimic: JointMimic | None = None


class ScaleContext(BaseModel):
    """The scale context schema: sizes that calibrate motion magnitudes and cameras."""

    model_config = ConfigDict(frozen=True)
    asset: str
    unit_assumption: Literal["meters_like_urdf_units"] = "meters_like_urdf_units"
    object_bbox_extents_m: tuple[float, float, float]
    object_diag_m: float
    link_bbox_extents_m: dict[str, tuple[float, float, float]]
    joint_child_link_bbox_extents_m: dict[str, tuple[float, float, float]]
    median_revolute_child_radius_m_est: float | None
    reference_glb_diag_m: float
    glb_to_urdf_scale_ratio: float


def _r(value: float) -> float:
    return round(float(value), ROUND_DIGITS) + 0.0


def _vec(values: FloatArray) -> tuple[float, float, float]:
    return (_r(values[0]), _r(values[1]), _r(values[2]))


def matrix_to_rpy(matrix: Transform) -> FloatArray:
    """URDF roll, pitch, yaw of a rotation (R = Rz(yaw) Ry(pitch) Rx(roll))."""
    r = matrix[:3, :3]
    pitch = math.asin(-max(-1.0, min(1.0, float(r[2, 0]))))
    if abs(math.cos(pitch)) > 1e-9:
        roll = math.atan2(float(r[2, 1]), float(r[2, 2]))
        yaw = math.atan2(float(r[1, 0]), float(r[0, 0]))
    else:
        roll = math.atan2(-float(r[1, 2]), float(r[1, 1]))
        yaw = 0.0
    return np.array([roll, pitch, yaw])


def joint_summary(asset: ArticulatedAsset) -> list[JointSummary]:
    """Every joint of ``asset`` in ``joint_order`` as the paper's summary records."""
    records = []
    for name in asset.joint_order:
        joint = asset.joints[name]
        limit = None
        if joint.bounded or joint.effort is not None or joint.velocity is not None:
            limit = JointLimit(
                lower=None if joint.lower is None else _r(joint.lower),
                upper=None if joint.upper is None else _r(joint.upper),
                effort=joint.effort,
                velocity=joint.velocity,
            )
        mimic = None
        if joint.mimic is not None:
            mimic = JointMimic(joint=joint.mimic.joint, multiplier=joint.mimic.multiplier, offset=joint.mimic.offset)
        records.append(
            JointSummary(
                joint_name=name,
                type=joint.type,
                parent=joint.parent,
                child=joint.child,
                axis=_vec(joint.axis),
                limit=limit,
                origin=JointOrigin(xyz=_vec(joint.origin[:3, 3]), rpy=_vec(matrix_to_rpy(joint.origin))),
                mimic=mimic,
            )
        )
    return records


def world_bounds(asset: ArticulatedAsset, poses: dict[str, Transform] | None = None) -> dict[str, FloatArray]:
    """{link: (2, 3) world AABB} of every link with geometry (rest pose by default)."""
    poses = poses or rest_poses(asset)
    bounds = {}
    for name in asset.visual_links:
        vertices = asset.links[name].vertices()
        pose = poses[name]
        world = vertices @ pose[:3, :3].T + pose[:3, 3]
        bounds[name] = np.stack([world.min(axis=0), world.max(axis=0)])
    return bounds


def scale_context(asset: ArticulatedAsset) -> ScaleContext:
    """Sizes of the object and its links at rest, in metres (world axes)."""
    bounds = world_bounds(asset)
    stacked = np.concatenate(list(bounds.values()), axis=0)
    extents = stacked.max(axis=0) - stacked.min(axis=0)
    diag = float(np.linalg.norm(extents))
    link_extents = {name: _vec(b[1] - b[0]) for name, b in bounds.items()}
    child_extents = {j: link_extents[asset.joints[j].child] for j in asset.movable_joints if asset.joints[j].child in link_extents}
    radii = []
    for j in asset.movable_joints:
        if asset.joints[j].type in ("revolute", "continuous") and j in child_extents:
            ex, ey, ez = child_extents[j]
            radii.append(0.5 * max(min(ex, ey), min(ex, ez), min(ey, ez)))
    return ScaleContext(
        asset=asset.name,
        object_bbox_extents_m=_vec(extents),
        object_diag_m=_r(diag),
        link_bbox_extents_m=link_extents,
        joint_child_link_bbox_extents_m=child_extents,
        median_revolute_child_radius_m_est=_r(float(np.median(radii))) if radii else None,
        # our GLB is written from these very meshes (only re-oriented to +Y up), so its
        # diagonal equals the URDF one by construction
        reference_glb_diag_m=_r(diag),
        glb_to_urdf_scale_ratio=1.0,
    )
