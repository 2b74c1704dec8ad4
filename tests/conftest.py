"""Shared fixtures: where the PartNet-Mobility assets and the examples live."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = REPO / "examples"


def partnet_root() -> Path:
    """The shared PartNet-Mobility folder: $ARTIMO_PARTNET_ROOT, ../shared/assets/partnet, /work/shared/assets/partnet."""
    candidates = [os.environ.get("ARTIMO_PARTNET_ROOT"), REPO.parent / "shared/assets/partnet", "/work/shared/assets/partnet"]
    for candidate in candidates:
        if candidate and (Path(candidate) / "safe_101593" / "mobility.urdf").is_file():
            return Path(candidate)
    raise RuntimeError("PartNet-Mobility assets not found; set ARTIMO_PARTNET_ROOT to the folder holding safe_101593/")


@pytest.fixture(scope="session")
def partnet() -> Path:
    return partnet_root()


@pytest.fixture(scope="session")
def examples_dir() -> Path:
    return EXAMPLES
