"""Fixtures for the GLB exporter / glTF reader tests (cases live in ``tests.support.glb_cases``)."""

from __future__ import annotations

from pathlib import Path

import pytest

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.export.glb import export_glb
from app.engine.plan.schema import Plan
from tests.support.export_runs import MotionCase
from tests.support.export_runs import motion_cases as build_motion_cases
from tests.support.glb_cases import (
    CASE_SPECS,
    SAFE_PLAN,
    ExportCase,
    build_tiny_asset,
    build_tiny_trajectory,
    move_everything_plan,
)


@pytest.fixture(scope="session")
def assets(partnet: Path) -> dict[str, ArticulatedAsset]:
    names = {"safe_101593", *[spec[0] for spec in CASE_SPECS.values()]}
    return {name: load_asset(partnet / name) for name in sorted(names)}


@pytest.fixture(scope="session")
def export_cases(
    assets: dict[str, ArticulatedAsset], tmp_path_factory: pytest.TempPathFactory
) -> dict[str, ExportCase]:
    """Every real-asset case exported once to a session folder."""
    folder = tmp_path_factory.mktemp("glb_cases")
    cases: dict[str, ExportCase] = {}
    safe = assets["safe_101593"]
    trajectory = execute(Plan.model_validate(SAFE_PLAN), safe)
    cases["safe_101593"] = ExportCase(
        "safe_101593", safe, trajectory, export_glb(safe, trajectory, folder / "safe_101593.glb")
    )
    for case, (asset_name, base, fps) in CASE_SPECS.items():
        asset = assets[asset_name]
        trajectory = execute(move_everything_plan(asset, fps=fps, base=base), asset)
        cases[case] = ExportCase(case, asset, trajectory, export_glb(asset, trajectory, folder / f"{case}.glb"))
    return cases


@pytest.fixture
def tiny_asset() -> ArticulatedAsset:
    return build_tiny_asset()


@pytest.fixture
def tiny_trajectory() -> Trajectory:
    return build_tiny_trajectory()


@pytest.fixture(scope="session")
def motion_cases(partnet: Path, examples_dir: Path) -> dict[str, MotionCase]:
    return build_motion_cases(partnet, examples_dir)
