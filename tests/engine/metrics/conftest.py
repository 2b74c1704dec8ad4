"""Fixtures of the metric tests: the primitive cabinet, real PartNet assets, the smoke cases."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from support.primitive_assets import write_cabinet

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.metrics.annotation import Case
from app.engine.metrics.geometry import AssetGeometry, build_geometry

SMOKE_CASES = Path(__file__).resolve().parents[2] / "benchmark" / "data" / "smoke_cases.jsonl"


def make_case(phases: list[dict[str, Any]], constraints: list[dict[str, Any]] | None = None, relations: list[dict[str, Any]] | None = None, **extra: Any) -> Case:
    """A case on the cabinet (or ``asset=...``) from its annotation parts."""
    document = {
        "case_id": "test_case",
        "asset": "cabinet",
        "prompt": "test",
        "motion_type": "independent",
        "phases": phases,
        "constraints": constraints or [],
        "relations": relations or [],
    }
    document.update(extra)
    return Case.model_validate(document)


@pytest.fixture(scope="session")
def cabinet(tmp_path_factory: pytest.TempPathFactory) -> ArticulatedAsset:
    return load_asset(write_cabinet(tmp_path_factory.mktemp("assets") / "cabinet"))


@pytest.fixture(scope="session")
def partnet_assets(partnet: Path) -> dict[str, ArticulatedAsset]:
    names = ("safe_101593", "microwave_7119", "toaster_103477", "storage_19179")
    return {name: load_asset(partnet / name) for name in names}


@pytest.fixture(scope="session")
def geometries(partnet_assets: dict[str, ArticulatedAsset]) -> dict[str, AssetGeometry]:
    return {name: build_geometry(asset) for name, asset in partnet_assets.items()}


@pytest.fixture(scope="session")
def smoke_cases() -> dict[str, Case]:
    from benchmark.cases import read_cases

    return {case.case_id: case for case in read_cases(SMOKE_CASES)}
