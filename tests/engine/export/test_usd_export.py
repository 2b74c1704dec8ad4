"""``animation.usda`` read back with pxr (usd-core): stage metadata, prim tree, world transforms vs FK."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from pxr import Sdf, Usd, UsdGeom, UsdShade

from app.engine.export.usd import prim_names, write_usd
from tests.support.export_runs import (
    POSITION_TOLERANCE_M,
    ROTATION_TOLERANCE,
    MotionCase,
    expected_poses,
    sample_frames,
)

CASES = ["tiny", "safe_101593", "trash_can_102155", "kitchen_pot_100038", "toy_car", "pedal_bin"]


def _open(case: MotionCase, folder: Path) -> Usd.Stage:
    name = write_usd(case.track, folder)
    stage = Usd.Stage.Open(str(folder / name))
    assert stage is not None
    return stage


def _link_prims(stage: Usd.Stage) -> dict[str, Usd.Prim]:
    top = stage.GetDefaultPrim()
    return {prim.GetDisplayName() or prim.GetName(): prim for prim in Usd.PrimRange(top) if prim.GetTypeName() == "Xform" and prim != top}


@pytest.mark.parametrize("name", CASES)
def test_world_transforms_match_forward_kinematics(name: str, motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases[name]
    stage = _open(case, tmp_path)
    prims = _link_prims(stage)
    assert set(prims) == set(case.asset.link_order)
    cache = UsdGeom.XformCache()
    for frame in sample_frames(case):
        cache.SetTime(Usd.TimeCode(frame))
        expected = expected_poses(case, frame)
        for link, prim in prims.items():
            world = np.array(cache.GetLocalToWorldTransform(prim)).T  # USD row-vector matrix -> column convention
            assert np.abs(world[:3, 3] - expected[link][:3, 3]).max() < POSITION_TOLERANCE_M, (link, frame)
            assert np.abs(world[:3, :3] - expected[link][:3, :3]).max() < ROTATION_TOLERANCE, (link, frame)


@pytest.mark.parametrize("name", ["tiny", "safe_101593"])
def test_stage_metadata_and_tree(name: str, motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases[name]
    stage = _open(case, tmp_path)
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert stage.GetTimeCodesPerSecond() == case.trajectory.fps
    assert stage.GetStartTimeCode() == 0 and stage.GetEndTimeCode() == case.trajectory.frame_count - 1
    prims = _link_prims(stage)
    for joint in case.asset.joints.values():  # nested as the kinematic tree
        assert prims[joint.child].GetParent() == prims[joint.parent]
    track = case.track
    for link, prim in prims.items():
        attribute = prim.GetAttribute("xformOp:transform")
        assert attribute.GetNumTimeSamples() == (case.trajectory.frame_count if link in track.moving_links else 0)


def test_meshes_and_materials_are_embedded(motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases["tiny"]
    stage = _open(case, tmp_path)
    prims = _link_prims(stage)
    for link, prim in prims.items():
        meshes = [UsdGeom.Mesh(child) for child in prim.GetChildren() if child.GetTypeName() == "Mesh"]
        parts = case.asset.links[link].parts
        assert len(meshes) == len(parts)
        for mesh, part in zip(meshes, parts, strict=True):
            points = np.array(mesh.GetPointsAttr().Get())
            assert np.abs(points - part.vertices).max() < 1e-6
            assert list(mesh.GetFaceVertexIndicesAttr().Get()) == part.faces.reshape(-1).tolist()
            material, _ = UsdShade.MaterialBindingAPI(mesh.GetPrim()).ComputeBoundMaterial()
            assert material, f"{link}: no material bound"
    textures = sorted((tmp_path / "usd_textures").glob("*.png"))
    assert len(textures) == 1 and textures[0].read_bytes() == case.asset.links["arm"].parts[0].material.image_png


def test_prim_names_are_valid_and_unique() -> None:
    names = prim_names(["door-1", "door_1", "1st link", "base"])
    assert names["base"] == "base"
    assert len(set(names.values())) == 4
    assert all(Sdf.Path.IsValidIdentifier(name) for name in names.values())


def test_output_is_deterministic(motion_cases: dict[str, MotionCase], tmp_path: Path) -> None:
    case = motion_cases["tiny"]
    first, second = tmp_path / "a", tmp_path / "b"
    write_usd(case.track, first)
    write_usd(case.track, second)
    assert (first / "animation.usda").read_bytes() == (second / "animation.usda").read_bytes()
