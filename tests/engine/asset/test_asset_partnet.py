"""Every shared PartNet-Mobility asset loads, with counts that match its URDF."""

from __future__ import annotations

import time
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from app.engine.asset.loader import load_asset

PARTNET_ASSET_COUNT = 39
NO_MOVABLE_JOINT = frozenset({"toaster_103498"})
"""Assets whose URDF declares no movable joint at all (the toaster's slider is typed ``fixed``)."""
MOVABLE = ("revolute", "prismatic", "continuous")


def _urdf_counts(urdf: Path) -> tuple[set[str], set[str], set[str], set[str]]:
    """(links, links with a <visual>, joints, movable joints) read straight from the (trusted) XML."""
    root = ET.parse(urdf).getroot()
    links = {e.get("name") for e in root.findall("link")}
    visual = {e.get("name") for e in root.findall("link") if e.find("visual") is not None}
    joints = {e.get("name") for e in root.findall("joint")}
    movable = {e.get("name") for e in root.findall("joint") if e.get("type") in MOVABLE}
    return links, visual, joints, movable  # type: ignore[return-value]


def test_every_partnet_asset_loads(partnet: Path) -> None:
    folders = sorted(p for p in partnet.iterdir() if (p / "mobility.urdf").is_file())
    assert len(folders) == PARTNET_ASSET_COUNT
    started = time.perf_counter()
    for folder in folders:
        asset = load_asset(folder)
        links, visual, joints, movable = _urdf_counts(folder / "mobility.urdf")
        assert asset.name == folder.name
        assert asset.urdf_file == "mobility.urdf"
        assert set(asset.links) == links and set(asset.link_order) == links, folder.name
        assert set(asset.joints) == joints and set(asset.joint_order) == joints, folder.name
        assert set(asset.movable_joints) == movable, folder.name
        if folder.name in NO_MOVABLE_JOINT:
            assert not movable, f"{folder.name} now declares movable joints"
        else:
            assert len(movable) >= 1, folder.name
        assert set(asset.visual_links) == visual, folder.name
        for name in asset.visual_links:
            for part in asset.links[name].parts:
                assert part.faces.shape[0] > 0 and part.faces.shape[1] == 3
                assert part.faces.min() >= 0 and part.faces.max() < part.vertices.shape[0]
                assert np.isfinite(part.vertices).all()
                assert part.normals is not None and np.allclose(np.linalg.norm(part.normals, axis=1), 1.0)
        for name in asset.movable_joints:
            spec = asset.joints[name]
            assert abs(np.linalg.norm(spec.axis) - 1.0) < 1e-12
            if spec.bounded:
                assert spec.lower <= spec.rest <= spec.upper  # type: ignore[operator]
        if (folder / "semantics.txt").is_file():
            labelled = [n for n in asset.links if asset.links[n].semantics.source == "semantics.txt"]
            assert labelled, folder.name
        assert len(asset.content_hash) == 64
    elapsed = time.perf_counter() - started
    print(f"loaded {len(folders)} PartNet assets in {elapsed:.2f} s")
