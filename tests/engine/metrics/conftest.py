"""Fixtures of the metric tests: the primitive cabinet, real PartNet assets, the smoke cases."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.metric_cases import SMOKE_CASES
from support.primitive_assets import write_cabinet

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.metrics.annotation import Case
from app.engine.metrics.geometry import AssetGeometry, build_geometry


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
