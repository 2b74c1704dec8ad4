"""The example assets: files, geometry, naming sources and the documented joint conventions."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest
import trimesh
from support.example_runs import EXAMPLE_NAMES, EXAMPLES, MAIN_PLAN, example_asset, plan_files
from support.penetration import surface_points

from app.engine.asset.kinematics import link_poses, rest_poses
from app.engine.asset.loader import find_urdf
from app.engine.asset.meshes import DEFAULT_RGBA
from app.engine.asset.model import ArticulatedAsset

SEMANTICS_EXAMPLES = frozenset({"microwave", "toy_car"})
"""The two examples that ship a PartNet-style ``semantics.txt``."""
SEMANTIC_KINDS = frozenset({"hinge", "slider", "static", "free"})
MAX_CLOSED_GAP_M = 5e-3
"""At rest every moving part sits flush against (or inside) its parent: gap <= 5 mm."""
GAP_SAMPLE_STRIDE = 8
"""Every 8th surface sample is enough to measure the (planar) closed-state gaps."""
MIN_STATE_SHIFT_M = 5e-3
DIRECTION_SHARE = 0.5
"""The documented motion direction must carry at least half of the centroid's displacement."""

X, Z = (1.0, 0.0, 0.0), (0.0, 0.0, 1.0)
MINUS_X, MINUS_Z = (-1.0, 0.0, 0.0), (0.0, 0.0, -1.0)
DOCUMENTED_STATES = {
    # (example, joint): (state name, limit that reaches it, world direction the child's centroid moves)
    ("pedal_bin", "lid_hinge"): ("open", "lower", Z),
    ("pedal_bin", "pedal_pivot"): ("pressed", "upper", MINUS_Z),
    ("microwave", "door_hinge"): ("open", "upper", X),
    ("microwave", "release_button_slide"): ("pressed", "upper", MINUS_X),
    ("cabinet", "drawer_top_slide"): ("out", "upper", X),
    ("cabinet", "drawer_bottom_slide"): ("out", "lower", X),
    ("cabinet", "door_hinge"): ("open", "lower", X),
    ("cabinet", "latch_knob_turn"): ("unlatched", "lower", None),
    ("oven", "door_hinge"): ("open", "upper", X),
    ("oven", "tray_slide"): ("out", "lower", X),
}
CONTINUOUS_JOINTS = {
    "microwave": ("turntable_spin",),
    "toy_car": ("wheel_front_left_axle", "wheel_front_right_axle", "wheel_rear_left_axle", "wheel_rear_right_axle"),
}


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_folder_holds_one_urdf_plans_and_prompts(name: str) -> None:
    folder = EXAMPLES / name
    assert find_urdf(folder).name == f"{name}.urdf"
    assert len(list(folder.glob("*.urdf"))) == 1
    plans = plan_files(name)
    assert plans[0] == MAIN_PLAN
    assert all(re.fullmatch(r"plan(_[a-z0-9_]+)?\.json", p) for p in plans)
    prompts = json.loads((folder / "prompts.json").read_text(encoding="utf-8"))
    assert sorted(prompts) == sorted(plans), "prompts.json must map exactly the plan files"
    assert all(isinstance(p, str) and len(p.split()) >= 3 for p in prompts.values())


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_asset_is_primitive_coloured_and_named(name: str) -> None:
    asset = example_asset(name)
    assert asset.warnings == ()
    assert not any(re.fullmatch(r"(link|joint)_?\d+", n) for n in (*asset.links, *asset.joints)), (
        "names must be descriptive"
    )
    for link in asset.links.values():
        assert link.has_geometry, f"{link.name} has no visual"
        assert len(link.semantics.visual_names) == len(link.parts), f"every visual of {link.name} is named"
        for part in link.parts:
            assert part.source.startswith("primitive:"), f"{link.name} uses a mesh file"
            assert part.material.base_color != DEFAULT_RGBA, f"{link.name} has an uncoloured visual"
    for joint in asset.joints.values():
        assert joint.movable
        if joint.bounded:
            assert joint.lower is not None and joint.upper is not None
            assert joint.lower <= 0.0 <= joint.upper, f"{joint.name}: rest 0 must be the closed state"


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_naming_source(name: str) -> None:
    asset = example_asset(name)
    has_file = (EXAMPLES / name / "semantics.txt").is_file()
    assert has_file == (name in SEMANTICS_EXAMPLES)
    for link in asset.links.values():
        assert link.semantics.source == ("semantics.txt" if has_file else "urdf")
        assert link.semantics.label
        if has_file:
            assert link.semantics.joint_kind in SEMANTIC_KINDS
    if has_file:
        lines = (EXAMPLES / name / "semantics.txt").read_text(encoding="utf-8").splitlines()
        assert sorted(line.split()[0] for line in lines) == sorted(asset.links)


def _closest_gap(name: str, child: str, parent: str) -> float:
    asset = example_asset(name)
    poses = rest_poses(asset)
    meshes = [trimesh.Trimesh(p.vertices, p.faces) for p in asset.links[parent].parts]
    parent_mesh = trimesh.util.concatenate(meshes)
    parent_mesh.apply_transform(poses[parent])
    pose = poses[child]
    points = surface_points(asset, child)[::GAP_SAMPLE_STRIDE] @ pose[:3, :3].T + pose[:3, 3]
    _, distance, _ = trimesh.proximity.closest_point(parent_mesh, points)
    return float(distance.min())


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_closed_parts_sit_flush_against_their_parent(name: str) -> None:
    asset = example_asset(name)
    for joint in asset.movable_joints:
        spec = asset.joints[joint]
        gap = _closest_gap(name, spec.child, spec.parent)
        assert 0.0 < gap <= MAX_CLOSED_GAP_M, f"{spec.child} is {gap * 1000:.2f} mm from {spec.parent}"


def _centroid(asset: ArticulatedAsset, link: str, pose: np.ndarray) -> np.ndarray:
    """(3,) volume centroid of ``link``'s primitives in the world, for the (4, 4) ``pose``."""
    meshes = [trimesh.Trimesh(p.vertices, p.faces) for p in asset.links[link].parts]
    volumes = np.array([m.volume for m in meshes])
    local = (volumes[:, None] * np.array([m.center_mass for m in meshes])).sum(axis=0) / volumes.sum()
    return pose[:3, :3] @ local + pose[:3, 3]


@pytest.mark.parametrize(("name", "joint"), sorted(DOCUMENTED_STATES))
def test_documented_joint_states_match_the_geometry(name: str, joint: str) -> None:
    asset = example_asset(name)
    spec = asset.joints[joint]
    state, side, direction = DOCUMENTED_STATES[(name, joint)]
    value = spec.lower if side == "lower" else spec.upper
    assert value is not None and value != 0.0
    poses = link_poses(asset, {joint: np.array([spec.rest, value])})
    child = poses[spec.child]
    if direction is None:
        # the knob: its grip bar turns from horizontal (world Y) to vertical, clockwise seen from the front
        grip_axis = child[1, :3, 1]
        np.testing.assert_allclose(grip_axis, [0.0, 0.0, -1.0], atol=1e-4)
        return
    centroids = [_centroid(asset, spec.child, child[i]) for i in range(2)]
    shift = centroids[1] - centroids[0]
    along = float(np.dot(shift, direction))
    assert np.linalg.norm(shift) >= MIN_STATE_SHIFT_M, f"{joint} barely moves at its {state} limit"
    assert along >= DIRECTION_SHARE * np.linalg.norm(shift), f"{joint} at {side} limit is not '{state}': shift {shift}"


def test_sign_conventions_are_mixed_on_purpose() -> None:
    for kind in ("revolute", "prismatic"):
        sides = {
            side
            for (name, joint), (_, side, _) in DOCUMENTED_STATES.items()
            if example_asset(name).joints[joint].type == kind
        }
        assert sides == {"lower", "upper"}, f"{kind} joints should reach their active state at both signs"


def test_every_movable_joint_is_documented() -> None:
    for name in EXAMPLE_NAMES:
        asset = example_asset(name)
        documented = {j for (n, j) in DOCUMENTED_STATES if n == name} | set(CONTINUOUS_JOINTS.get(name, ()))
        assert documented == set(asset.movable_joints)


def test_readme_documents_every_asset_joint_and_plan() -> None:
    readme = (EXAMPLES / "README.md").read_text(encoding="utf-8")
    for name in EXAMPLE_NAMES:
        assert f"`{name}/`" in readme
        for joint in example_asset(name).movable_joints:
            assert f"`{joint}`" in readme, f"README does not document {name}/{joint}"
        for plan in plan_files(name):
            assert f"`{plan}`" in readme, f"README does not describe {name}/{plan}"
    for (name, joint), (state, _, _) in DOCUMENTED_STATES.items():
        assert state in readme, f"README does not use the state word '{state}' of {name}/{joint}"
