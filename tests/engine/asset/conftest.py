"""Fixtures of the asset tests: the primitive cabinet (see ``support.primitive_assets``)."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.primitive_assets import write_cabinet

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset


@pytest.fixture(scope="module")
def cabinet_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return write_cabinet(tmp_path_factory.mktemp("assets") / "cabinet")


@pytest.fixture(scope="module")
def cabinet(cabinet_dir: Path) -> ArticulatedAsset:
    return load_asset(cabinet_dir)
