"""Fixtures of the executor tests: the rig of ``support.executor_rig``."""

from __future__ import annotations

import pytest
from support.executor_rig import rig_urdf
from support.primitive_assets import write_asset

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset


@pytest.fixture(scope="session")
def rig(tmp_path_factory: pytest.TempPathFactory) -> ArticulatedAsset:
    return load_asset(write_asset(tmp_path_factory.mktemp("assets") / "rig", rig_urdf()))
