"""Motion cases for the exporter tests: asset + trajectory + phase ends, and forward kinematics to compare with."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from app.engine.asset.kinematics import base_transforms, link_poses
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.export.track import ExportTrack, build_track
from app.engine.plan.schema import Plan
from tests.support.glb_cases import SAFE_PLAN, build_tiny_asset, build_tiny_trajectory, move_everything_plan

POSITION_TOLERANCE_M = 1e-5
ROTATION_TOLERANCE = 1e-6


@dataclass(frozen=True)
class MotionCase:
    name: str
    asset: ArticulatedAsset
    trajectory: Trajectory
    phase_ends: tuple[tuple[str, float], ...]

    @property
    def track(self) -> ExportTrack:
        return build_track(self.asset, self.trajectory)


def _planned(name: str, asset: ArticulatedAsset, plan: Plan) -> MotionCase:
    return MotionCase(name, asset, execute(plan, asset), tuple((s.name, s.t1) for s in plan.timeline))


def motion_cases(partnet: Path, examples: Path) -> dict[str, MotionCase]:
    """tiny (mimic, texture, base turning), safe_101593 (the 106-frame plan), trash_can (base push),
    kitchen_pot (decaying diagonal base motion), toy_car (base + wheels), pedal_bin (example plan)."""
    cases = {"tiny": MotionCase("tiny", build_tiny_asset(), build_tiny_trajectory(), (("swing", 0.35),))}
    safe = load_asset(partnet / "safe_101593")
    cases["safe_101593"] = _planned("safe_101593", safe, Plan.model_validate(SAFE_PLAN))
    trash = load_asset(partnet / "trash_can_102155")
    cases["trash_can_102155"] = _planned("trash_can_102155", trash, move_everything_plan(
        trash, fps=24, base={"mode": "base_velocity", "axis_world": [1.0, 0.0, 0.0], "v_mps": 0.2}))
    pot = load_asset(partnet / "kitchen_pot_100038")
    cases["kitchen_pot_100038"] = _planned("kitchen_pot_100038", pot, move_everything_plan(
        pot, fps=30, base={"mode": "base_velocity_decay", "axis_world": [0.0, 1.0, 1.0], "v0_mps": 0.5, "tau_s": 0.7}))
    for example in ("toy_car", "pedal_bin"):
        asset = load_asset(examples / example)
        plan = Plan.model_validate(json.loads((examples / example / "plan.json").read_text()))
        cases[example] = _planned(example, asset, plan)
    return cases


def expected_poses(case: MotionCase, frame: int) -> dict[str, np.ndarray]:
    """(4, 4) world pose of every link at ``frame`` by the engine's forward kinematics."""
    trajectory = case.trajectory
    values = {name: trajectory.q[frame : frame + 1, i] for i, name in enumerate(trajectory.joint_names)}
    base = base_transforms(trajectory.base_translation[frame : frame + 1], trajectory.base_rotation_xyzw[frame : frame + 1])
    return {link: pose[0] for link, pose in link_poses(case.asset, values, base).items()}


def sample_frames(case: MotionCase) -> list[int]:
    """First, last and two frames in between."""
    last = case.trajectory.frame_count - 1
    return sorted({0, last // 3, (2 * last) // 3, last})
