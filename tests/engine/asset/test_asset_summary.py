"""``joint_summary`` and ``scale_context`` against the paper's schemas (supplementary §1.3)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
import yourdfpy
from support.primitive_assets import joint, two_link_urdf, write_asset

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import ScaleContext, joint_summary, matrix_to_rpy, scale_context

JOINT_KEYS = {"joint_name", "type", "parent", "child", "axis", "limit", "origin"}
SCALE_KEYS = {
    "asset",
    "unit_assumption",
    "object_bbox_extents_m",
    "object_diag_m",
    "link_bbox_extents_m",
    "joint_child_link_bbox_extents_m",
    "median_revolute_child_radius_m_est",
    "reference_glb_diag_m",
    "glb_to_urdf_scale_ratio",
}
ROUNDING = 1e-6
REAL_ASSETS = ("safe_101593", "laptop_10101", "microwave_7119")


def test_joint_summary_of_the_cabinet(cabinet: ArticulatedAsset) -> None:
    records = {r.joint_name: r.model_dump(mode="json") for r in joint_summary(cabinet)}
    assert list(records) == ["root_fixed", "lid_hinge", "drawer_slide", "knob_spin", "flap_mimic"]
    for record in records.values():
        assert JOINT_KEYS <= set(record) <= JOINT_KEYS | {"mimic"}
        assert set(record["origin"]) == {"xyz", "rpy"}
    assert records["root_fixed"] == {
        "joint_name": "root_fixed", "type": "fixed", "parent": "world", "child": "base", "axis": [0.0, 0.0, 0.0],
        "limit": None, "origin": {"xyz": [0.0, 0.0, 0.0], "rpy": [0.0, 0.0, 0.0]}, "mimic": None,
    }  # fmt: skip
    assert records["lid_hinge"] == {
        "joint_name": "lid_hinge", "type": "revolute", "parent": "base", "child": "lid", "axis": [1.0, 0.0, 0.0],
        "limit": {"lower": 0.0, "upper": 1.570796, "effort": 10.0, "velocity": 2.0},
        "origin": {"xyz": [0.0, -0.5, 0.5], "rpy": [0.0, 0.0, 0.0]}, "mimic": None,
    }  # fmt: skip
    assert records["drawer_slide"]["axis"] == [0.0, 1.0, 0.0]  # written "0 2 0"
    assert records["drawer_slide"]["limit"] == {"lower": 0.0, "upper": 0.6, "effort": 10.0, "velocity": 2.0}
    assert records["knob_spin"]["type"] == "continuous" and records["knob_spin"]["limit"] is None
    assert records["flap_mimic"]["mimic"] == {"joint": "lid_hinge", "multiplier": 0.5, "offset": 0.0}


def test_scale_context_of_the_cabinet(cabinet: ArticulatedAsset) -> None:
    context = scale_context(cabinet)
    dumped = context.model_dump(mode="json")
    assert set(dumped) == SCALE_KEYS
    assert dumped["asset"] == "cabinet" and dumped["unit_assumption"] == "meters_like_urdf_units"
    # base x[-1, 1] y[-.5, .5] z[0, .5]; lid z to .6; knob x to 1.1; flap (on the lid's far edge) y to .8, z to .62
    assert dumped["object_bbox_extents_m"] == pytest.approx([2.1, 1.3, 0.62], abs=ROUNDING)
    diag = math.sqrt(2.1**2 + 1.3**2 + 0.62**2)
    assert dumped["object_diag_m"] == pytest.approx(diag, abs=ROUNDING)
    expected_links = {
        "base": [2.0, 1.0, 0.5],
        "lid": [2.0, 1.0, 0.1],
        "drawer": [1.6, 0.8, 0.2],
        "knob": [0.1, 0.2, 0.2],
        "flap": [2.0, 0.3, 0.02],
    }
    assert set(dumped["link_bbox_extents_m"]) == set(expected_links)  # "world" has no geometry
    for name, extents in expected_links.items():
        assert dumped["link_bbox_extents_m"][name] == pytest.approx(extents, abs=ROUNDING)
    children = {"lid_hinge": "lid", "drawer_slide": "drawer", "knob_spin": "knob", "flap_mimic": "flap"}
    assert set(dumped["joint_child_link_bbox_extents_m"]) == set(children)  # movable joints only
    for joint_name, child in children.items():
        assert dumped["joint_child_link_bbox_extents_m"][joint_name] == pytest.approx(
            expected_links[child], abs=ROUNDING
        )
    # radius per revolute/continuous child: half the middle extent -> lid 0.5, knob 0.1, flap 0.15
    assert dumped["median_revolute_child_radius_m_est"] == pytest.approx(0.15, abs=ROUNDING)
    assert dumped["reference_glb_diag_m"] == pytest.approx(diag, abs=ROUNDING)
    assert dumped["glb_to_urdf_scale_ratio"] == 1.0
    assert ScaleContext.model_validate_json(context.model_dump_json()) == context


def test_scale_context_without_revolute_joints(tmp_path: Path) -> None:
    urdf = two_link_urdf(joint("slide", "prismatic", "base", "part", limit=(0.0, 1.0)))
    context = scale_context(load_asset(write_asset(tmp_path / "slider", urdf)))
    assert context.median_revolute_child_radius_m_est is None
    assert context.object_bbox_extents_m == pytest.approx((1.0, 1.0, 1.0))


@pytest.mark.parametrize(
    "rpy",
    [
        (0.0, 0.0, 0.0),
        (0.3, -0.4, 1.2),
        (math.pi / 2, 0.0, -math.pi / 2),
        (-2.5, 1.1, 3.0),
        (0.7, math.pi / 2, 0.0),
        (0.7, -math.pi / 2, 0.0),
    ],
)
def test_matrix_to_rpy_round_trips(rpy: tuple[float, float, float]) -> None:
    def rotation(r: float, p: float, y: float) -> np.ndarray:
        rx = np.array([[1, 0, 0], [0, math.cos(r), -math.sin(r)], [0, math.sin(r), math.cos(r)]])
        ry = np.array([[math.cos(p), 0, math.sin(p)], [0, 1, 0], [-math.sin(p), 0, math.cos(p)]])
        rz = np.array([[math.cos(y), -math.sin(y), 0], [math.sin(y), math.cos(y), 0], [0, 0, 1]])
        return rz @ ry @ rx

    matrix = np.eye(4)
    matrix[:3, :3] = rotation(*rpy)
    assert np.allclose(rotation(*matrix_to_rpy(matrix)), matrix[:3, :3], atol=1e-9)


@pytest.mark.parametrize("name", REAL_ASSETS)
def test_summary_of_a_real_asset_matches_its_urdf(partnet: Path, name: str) -> None:
    folder = partnet / name
    asset = load_asset(folder)
    xml_joints = {e.get("name"): e for e in ET.parse(folder / "mobility.urdf").getroot().findall("joint")}
    records = joint_summary(asset)
    assert {r.joint_name for r in records} == set(xml_joints)
    for record in records:
        element = xml_joints[record.joint_name]
        assert record.type == element.get("type")
        assert record.parent == element.find("parent").get("link") and record.child == element.find("child").get("link")
        origin = element.find("origin")
        xyz = [float(v) for v in (origin.get("xyz") or "0 0 0").split()]
        rpy = [float(v) for v in (origin.get("rpy") or "0 0 0").split()]
        assert record.origin.xyz == pytest.approx(xyz, abs=ROUNDING) and record.origin.rpy == pytest.approx(
            rpy, abs=ROUNDING
        )
        if record.type != "fixed":
            axis = np.array([float(v) for v in element.find("axis").get("xyz").split()])
            assert record.axis == pytest.approx(axis / np.linalg.norm(axis), abs=ROUNDING)
        limit = element.find("limit")
        if record.type in ("revolute", "prismatic"):
            assert record.limit is not None
            assert record.limit.lower == pytest.approx(float(limit.get("lower")), abs=ROUNDING)
            assert record.limit.upper == pytest.approx(float(limit.get("upper")), abs=ROUNDING)


@pytest.mark.parametrize("name", REAL_ASSETS)
def test_scale_context_of_a_real_asset_matches_yourdfpy(partnet: Path, name: str) -> None:
    folder = partnet / name
    asset = load_asset(folder)
    context = scale_context(asset)
    reference = yourdfpy.URDF.load(
        str(folder / "mobility.urdf"), mesh_dir=str(folder)
    )  # independent FK + meshes at q = 0
    bounds = reference.scene.bounds
    assert all(asset.joints[j].rest == 0.0 for j in asset.movable_joints)  # so q = 0 is our rest pose
    assert context.object_bbox_extents_m == pytest.approx(bounds[1] - bounds[0], abs=1e-5)
    assert context.object_diag_m == pytest.approx(float(np.linalg.norm(bounds[1] - bounds[0])), abs=1e-5)
    assert set(context.link_bbox_extents_m) == set(asset.visual_links)
    radii = []
    for name in asset.movable_joints:
        if asset.joints[name].type in ("revolute", "continuous"):
            middle = sorted(context.joint_child_link_bbox_extents_m[name])[1]
            radii.append(0.5 * middle)
    assert context.median_revolute_child_radius_m_est == pytest.approx(float(np.median(radii)), abs=ROUNDING)
