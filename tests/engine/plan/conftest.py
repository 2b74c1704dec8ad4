"""Fixtures of the plan tests: the primitive cabinet (see ``support.primitive_assets``)."""

from __future__ import annotations

import pytest
from support.primitive_assets import write_cabinet

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset


@pytest.fixture(scope="module")
def cabinet(tmp_path_factory: pytest.TempPathFactory) -> ArticulatedAsset:
    return load_asset(write_cabinet(tmp_path_factory.mktemp("assets") / "cabinet"))
