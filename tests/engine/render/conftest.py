"""Fixtures of the renderer tests: tiny primitive scenes in tmp folders and a few PartNet assets.

Every test here renders for real through EGL (Mesa llvmpipe on CPU); nothing skips.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from support.primitive_assets import box, link, robot, write_asset, write_cabinet
from support.render_scenes import door_scene_urdf

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset


@pytest.fixture(scope="module")
def door_scene(tmp_path_factory: pytest.TempPathFactory) -> ArticulatedAsset:
    return load_asset(write_asset(tmp_path_factory.mktemp("render") / "door_scene", door_scene_urdf()))


@pytest.fixture(scope="module")
def unit_box(tmp_path_factory: pytest.TempPathFactory) -> ArticulatedAsset:
    """One link: a 1 m cube centred at the origin."""
    return load_asset(
        write_asset(
            tmp_path_factory.mktemp("render") / "unit_box", robot(link("cube", box((1.0, 1.0, 1.0))), name="unit_box")
        )
    )


@pytest.fixture(scope="module")
def cabinet(tmp_path_factory: pytest.TempPathFactory) -> ArticulatedAsset:
    return load_asset(write_cabinet(tmp_path_factory.mktemp("render") / "cabinet"))


_PARTNET_CACHE: dict[str, ArticulatedAsset] = {}


@pytest.fixture(scope="session")
def load_partnet(partnet: Path) -> Callable[[str], ArticulatedAsset]:
    """``load_partnet(name)`` -> the loaded PartNet asset (cached for the session)."""

    def load(name: str) -> ArticulatedAsset:
        if name not in _PARTNET_CACHE:
            _PARTNET_CACHE[name] = load_asset(partnet / name)
        return _PARTNET_CACHE[name]

    return load
