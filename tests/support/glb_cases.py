"""Cases for the GLB exporter / glTF reader tests: plans for real PartNet assets that drive
revolute, continuous and prismatic joints and the base, plus a tiny hand-built asset
(box parts, a texture, a transparent material, a mimic joint, a link without geometry)."""

from __future__ import annotations

import math
import struct
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.asset.model import ArticulatedAsset, JointSpec, LinkSpec, Material, MeshPart, Mimic
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.schema import Plan

SAFE_PLAN: dict[str, Any] = {
    "meta": {"fps": 30, "duration_s": 3.5},
    "timeline": [
        {
            "name": "spin dial",
            "phase_type": "control_actuation",
            "t0": 0.0,
            "t1": 1.0,
            "controls": [{"mode": "joint_velocity", "joint": "joint_1", "omega_radps": -math.pi / 2}],
        },
        {
            "name": "turn handle",
            "phase_type": "control_actuation",
            "t0": 1.0,
            "t1": 1.5,
            "controls": [
                {"mode": "joint_position", "joint": "joint_2", "q_target_rad": -math.pi / 2, "curve": "ease_in_out"}
            ],
        },
        {
            "name": "open door",
            "phase_type": "effect_motion",
            "t0": 1.5,
            "t1": 3.5,
            "controls": [
                {"mode": "joint_position", "joint": "joint_0", "q_target_expr": "upper_limit", "curve": "linear"}
            ],
        },
    ],
}
"""The measurement plan of the brief: 30 fps, 3.5 s, 106 frames on safe_101593."""


def move_everything_plan(asset: ArticulatedAsset, *, fps: int = 24, base: dict[str, Any] | None = None) -> Plan:
    """A 2 s plan: continuous joints spin, bounded joints go to the far limit, optional base control."""
    controls: list[dict[str, Any]] = []
    for name in asset.controllable_joints:
        joint = asset.joints[name]
        if joint.type == "continuous":
            controls.append({"mode": "joint_velocity", "joint": name, "omega_radps": 2.0})
        else:
            target = "upper_limit" if abs(joint.upper or 0.0) >= abs(joint.lower or 0.0) else "lower_limit"
            controls.append({"mode": "joint_position", "joint": name, "q_target_expr": target, "curve": "ease_in_out"})
    if base is not None:
        controls.append(base)
    segment = {"name": "move", "phase_type": "effect_motion", "t0": 0.0, "t1": 2.0, "controls": controls}
    return Plan.model_validate({"meta": {"fps": fps, "duration_s": 2.0}, "timeline": [segment]})


@dataclass(frozen=True)
class ExportCase:
    name: str
    asset: ArticulatedAsset
    trajectory: Trajectory
    path: Path


CASE_SPECS: dict[str, tuple[str, dict[str, Any] | None, int]] = {
    "trash_can_102155": (
        "trash_can_102155",
        {"mode": "base_velocity", "axis_world": [1.0, 0.0, 0.0], "v_mps": 0.2},
        24,
    ),
    "kitchen_pot_100038": (
        "kitchen_pot_100038",
        {"mode": "base_velocity_decay", "axis_world": [0.0, 1.0, 1.0], "v0_mps": 0.5, "tau_s": 0.7},
        30,
    ),
    "laptop_10101": ("laptop_10101", None, 24),
    "coffee_machine_103030": (
        "coffee_machine_103030",
        {"mode": "base_velocity", "axis_world": [0.0, 0.0, 1.0], "v_mps": -0.1},
        30,
    ),
    "safe_102387": ("safe_102387", None, 30),
    "oven_7138": ("oven_7138", None, 24),
    "safe_101564": ("safe_101564", None, 24),
}


def _png_chunk(kind: bytes, body: bytes) -> bytes:
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def tiny_png(extra_chunks: tuple[tuple[bytes, bytes], ...] = ()) -> bytes:
    """A 2x2 RGB PNG built byte by byte (stored deflate: identical on every platform)."""
    rows = b"".join(b"\x00" + bytes(row) for row in ([255, 0, 0, 0, 255, 0], [0, 0, 255, 255, 255, 255]))
    header = _png_chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0))
    extra = b"".join(_png_chunk(kind, body) for kind, body in extra_chunks)
    return (
        b"\x89PNG\r\n\x1a\n" + header + extra + _png_chunk(b"IDAT", zlib.compress(rows, 0)) + _png_chunk(b"IEND", b"")
    )


def _box(size: tuple[float, float, float], offset: tuple[float, float, float]) -> tuple[np.ndarray, np.ndarray]:
    corners = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]) * size + offset
    faces = np.array(
        [
            [0, 1, 3],
            [0, 3, 2],
            [4, 6, 7],
            [4, 7, 5],
            [0, 4, 5],
            [0, 5, 1],
            [2, 3, 7],
            [2, 7, 6],
            [0, 2, 6],
            [0, 6, 4],
            [1, 5, 7],
            [1, 7, 3],
        ],
        dtype=np.int64,
    )
    return corners, faces


def _origin(xyz: tuple[float, float, float], rpy: tuple[float, float, float]) -> np.ndarray:
    roll, pitch, yaw = rpy
    rx = np.array([[1, 0, 0], [0, math.cos(roll), -math.sin(roll)], [0, math.sin(roll), math.cos(roll)]])
    ry = np.array([[math.cos(pitch), 0, math.sin(pitch)], [0, 1, 0], [-math.sin(pitch), 0, math.cos(pitch)]])
    rz = np.array([[math.cos(yaw), -math.sin(yaw), 0], [math.sin(yaw), math.cos(yaw), 0], [0, 0, 1]])
    out = np.eye(4)
    out[:3, :3] = rz @ ry @ rx
    out[:3, 3] = xyz
    return out


def _tiny_joints() -> dict[str, JointSpec]:
    z_axis, x_axis = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0])
    joints = {
        "hinge": JointSpec(
            "hinge", "revolute", "base", "arm", _origin((0.1, 0.0, 0.1), (0.3, -0.2, 0.5)), z_axis, -1.0, 2.0
        ),
        "slide": JointSpec(
            "slide", "prismatic", "arm", "slider", _origin((0.3, 0.0, 0.0), (0.0, 0.0, 0.0)), x_axis, 0.0, 0.2
        ),
        "twin_joint": JointSpec(
            "twin_joint",
            "revolute",
            "arm",
            "twin",
            _origin((0.0, 0.1, 0.0), (0.0, 0.0, 0.0)),
            z_axis,
            -3.0,
            3.0,
            mimic=Mimic("hinge", -0.5, 0.1),
        ),
        "mount_joint": JointSpec(
            "mount_joint", "fixed", "base", "mount", _origin((0.0, 0.0, 0.3), (0.0, 0.0, 1.0)), np.zeros(3)
        ),
    }
    return joints


def build_tiny_asset() -> ArticulatedAsset:
    """base (box) -> arm (revolute, rpy origin, textured box) -> slider (prismatic) ; arm -> twin (mimic) ;
    base -> mount (fixed, no geometry)."""
    plain = Material(name="grey", base_color=(0.5, 0.5, 0.5, 1.0), metallic=0.1, roughness=0.7)
    glass = Material(name="glass", base_color=(0.2, 0.4, 0.9, 0.5), double_sided=False)
    textured = Material(name="checker", image_png=tiny_png())

    def part(
        size: tuple[float, float, float], offset: tuple[float, float, float], material: Material, *, uv: bool = False
    ) -> MeshPart:
        vertices, faces = _box(size, offset)
        coords = (vertices[:, :2] - vertices[:, :2].min(axis=0)) / np.ptp(vertices[:, :2], axis=0) if uv else None
        return MeshPart(vertices=vertices, faces=faces, normals=None, uv=coords, material=material, source="tiny")

    links = {
        "base": LinkSpec("base", (part((0.4, 0.4, 0.1), (0.0, 0.0, 0.05), plain),)),
        "arm": LinkSpec(
            "arm",
            (
                part((0.3, 0.05, 0.05), (0.15, 0.0, 0.0), textured, uv=True),
                part((0.05, 0.05, 0.05), (0.0, 0.0, 0.0), plain),
            ),
        ),
        "slider": LinkSpec("slider", (part((0.05, 0.05, 0.2), (0.0, 0.0, 0.1), glass),)),
        "twin": LinkSpec("twin", (part((0.1, 0.02, 0.02), (0.05, 0.0, 0.0), plain),)),
        "mount": LinkSpec("mount"),
    }
    joints = _tiny_joints()
    return ArticulatedAsset(
        name="tiny",
        urdf_file="tiny.urdf",
        root_link="base",
        links=links,
        joints=joints,
        joint_order=("hinge", "mount_joint", "slide", "twin_joint"),
        link_order=("base", "arm", "mount", "slider", "twin"),
    )


def build_tiny_trajectory(frames: int = 7, fps: int = 10) -> Trajectory:
    """Hinge swings, slider slides, base translates and turns about a tilted axis."""
    times = np.arange(frames, dtype=np.float64) / fps
    s = times / times[-1]
    hinge = -0.5 + 2.0 * s
    slide = 0.2 * s * s
    twin = -0.5 * hinge + 0.1
    angle = 1.2 * s
    axis = np.array([0.3, -0.4, 0.866])
    axis /= np.linalg.norm(axis)
    rotation = np.column_stack([np.sin(angle / 2)[:, None] * axis[None], np.cos(angle / 2)])
    return Trajectory(
        fps=fps,
        times=times,
        joint_names=("hinge", "slide", "twin_joint"),
        q=np.column_stack([hinge, slide, twin]),
        base_translation=np.column_stack([0.3 * s, -0.1 * s, 0.05 * s]),
        base_rotation_xyzw=rotation,
    )
