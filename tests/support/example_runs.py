"""The example assets of ``examples/``: loading, executing their plans, timing helpers.

Loading and executing are cached per process: assets and trajectories are immutable.
"""

from __future__ import annotations

import functools
import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.asset.kinematics import base_transforms, link_poses
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.checks import validate_plan
from app.engine.plan.schema import Plan

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
EXAMPLE_NAMES = ("pedal_bin", "microwave", "cabinet", "oven", "toy_car")
MAIN_PLAN = "plan.json"
MOTION_EPS = 1e-9
"""A joint has moved once it differs from its first value by more than this (rad or m)."""


@dataclass(frozen=True, eq=False)
class Run:
    """One executed example plan.

    Attributes
    ----------
    poses : {link: (f, 4, 4) world transforms}, base motion included
    warnings : validation warnings of the plan
    """

    asset: ArticulatedAsset
    plan: Plan
    raw: dict[str, Any]
    trajectory: Trajectory
    poses: dict[str, np.ndarray]
    warnings: tuple[str, ...]

    @property
    def times(self) -> np.ndarray:
        return self.trajectory.times

    def q(self, joint: str) -> np.ndarray:
        return self.trajectory.joint(joint)


def plan_files(name: str) -> list[str]:
    """Plan file names of one example, ``plan.json`` first."""
    files = sorted(p.name for p in (EXAMPLES / name).glob("plan*.json"))
    return sorted(files, key=lambda f: (f != MAIN_PLAN, f))


def all_plans() -> list[tuple[str, str]]:
    """(example, plan file) for every plan of every example."""
    return [(name, plan) for name in EXAMPLE_NAMES for plan in plan_files(name)]


@functools.cache
def example_asset(name: str) -> ArticulatedAsset:
    return load_asset(EXAMPLES / name)


@functools.cache
def run_example(name: str, plan_file: str) -> Run:
    """Validate and execute one example plan; FK for every frame."""
    asset = example_asset(name)
    raw = json.loads((EXAMPLES / name / plan_file).read_text(encoding="utf-8"))
    checked = validate_plan(raw, asset)
    trajectory = execute(checked.document, asset)
    base = base_transforms(trajectory.base_translation, trajectory.base_rotation_xyzw)
    poses = link_poses(asset, trajectory.joint_values(), base=base)
    return Run(
        asset=asset, plan=checked.document, raw=raw, trajectory=trajectory, poses=poses, warnings=checked.warnings
    )


def first_motion_time(run: Run, joint: str, eps: float = MOTION_EPS) -> float:
    """Onset of ``joint``'s motion: time (s) of the last frame before it first leaves its frame-0 value.

    The joint starts moving within one frame after this time; inf if it never moves.
    """
    values = run.q(joint)
    moved = np.flatnonzero(np.abs(values - values[0]) > eps)
    return float(run.times[moved[0] - 1]) if moved.size else float("inf")


def last_motion_time(run: Run, joint: str, eps: float = MOTION_EPS) -> float:
    """Time (s) of the first frame from which ``joint`` no longer changes."""
    values = run.q(joint)
    changed = np.flatnonzero(np.abs(np.diff(values)) > eps)
    return float(run.times[changed[-1] + 1]) if changed.size else 0.0


def first_time_at(run: Run, joint: str, value: float, tol: float = 1e-6, after: float = -np.inf) -> float:
    """Time (s) of the first frame later than ``after`` where ``joint`` is within ``tol`` of ``value``; inf if never."""
    hits = np.flatnonzero((np.abs(run.q(joint) - value) <= tol) & (run.times > after))
    return float(run.times[hits[0]]) if hits.size else float("inf")


def world_vertices(run_or_asset: Run | ArticulatedAsset, link: str, pose: np.ndarray) -> np.ndarray:
    """(n, 3) vertices of ``link`` carried to the world by ``pose`` (4, 4)."""
    asset = run_or_asset.asset if isinstance(run_or_asset, Run) else run_or_asset
    vertices = asset.links[link].vertices()
    return vertices @ pose[:3, :3].T + pose[:3, 3]
