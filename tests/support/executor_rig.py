"""A rig asset with one joint of every kind, and terse plan builders, for the executor tests."""

from __future__ import annotations

from typing import Any

from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.checks import parse_document
from app.engine.plan.schema import Plan
from support.primitive_assets import box, joint, link, robot

WIDE = (-10.0, 10.0)
"""Limits wide enough that closed-form checks never touch them."""


def rig_urdf() -> str:
    """One joint of every kind on a fixed root: hinge (wide), door [0, 1.5], slide [0, 0.5], wheel, follower, shifted [0.3, 2]."""
    small = box((0.1, 0.1, 0.1))
    names = ("base", "hinge_l", "door_l", "slide_l", "wheel_l", "follower_l", "shifted_l")
    return robot(
        link("world"),
        *(link(n, small) for n in names),
        joint("root", "fixed", "world", "base", axis=None),
        joint("hinge", "revolute", "base", "hinge_l", axis=(0.0, 0.0, 1.0), limit=WIDE),
        joint("door", "revolute", "base", "door_l", xyz=(0.5, 0.0, 0.0), axis=(0.0, 0.0, 1.0), limit=(0.0, 1.5)),
        joint("slide", "prismatic", "base", "slide_l", axis=(2.0, 0.0, 0.0), limit=(0.0, 0.5)),
        joint("wheel", "continuous", "base", "wheel_l", axis=(0.0, 1.0, 0.0)),
        joint(
            "follower",
            "revolute",
            "hinge_l",
            "follower_l",
            axis=(1.0, 0.0, 0.0),
            limit=WIDE,
            mimic=("hinge", -0.5, 0.2),
        ),
        joint("shifted", "revolute", "base", "shifted_l", axis=(0.0, 0.0, 1.0), limit=(0.3, 2.0)),
        name="rig",
    )


def seg(
    t0: float, t1: float, *controls: dict[str, Any], name: str = "phase", phase_type: str = "effect_motion"
) -> dict[str, Any]:
    return {"name": name, "phase_type": phase_type, "t0": t0, "t1": t1, "controls": list(controls)}


def plan(
    *segments: dict[str, Any], duration: float = 2.0, fps: int = 30, physics: dict[str, Any] | None = None
) -> Plan:
    raw: dict[str, Any] = {"meta": {"fps": fps, "duration_s": duration}, "timeline": list(segments)}
    if physics is not None:
        raw["physics"] = physics
    return parse_document(Plan, raw, "plan")


def run(asset: ArticulatedAsset, *segments: dict[str, Any], **meta: Any) -> Trajectory:
    return execute(plan(*segments, **meta), asset)


def position(joint: str, target: float | str, **extra: Any) -> dict[str, Any]:
    key = "q_target_expr" if isinstance(target, str) else "q_target_rad"
    return {"mode": "joint_position", "joint": joint, key: target, **extra}


def velocity(joint: str, omega: float, **extra: Any) -> dict[str, Any]:
    return {"mode": "joint_velocity", "joint": joint, "omega_radps": omega, **extra}
