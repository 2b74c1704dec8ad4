"""Contact points per motion type: on the link's surface (1 mm) and moving with it exactly (FK)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
import trimesh

from app.engine.asset.kinematics import base_transforms, link_poses
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.export.rotations import quaternion_to_matrix
from app.engine.interaction.model import ActuatedPhase, Interaction, InteractionDocument
from app.engine.interaction.phases import actuated_phases
from app.engine.interaction.targets import interaction_targets
from app.engine.plan.schema import Plan

SURFACE_TOLERANCE_M = 1e-3
FK_TOLERANCE = 1e-9


def _poses(asset: ArticulatedAsset, trajectory: Trajectory, frame: int) -> dict[str, np.ndarray]:
    values = {name: trajectory.q[frame : frame + 1, i] for i, name in enumerate(trajectory.joint_names)}
    base = base_transforms(trajectory.base_translation[frame : frame + 1], trajectory.base_rotation_xyzw[frame : frame + 1])
    return {link: pose[0] for link, pose in link_poses(asset, values, base).items()}


def _fixed_group(asset: ArticulatedAsset, link: str) -> set[str]:
    group, grown = {link}, True
    while grown:
        grown = False
        for joint in asset.joints.values():
            if joint.type == "fixed" and len({joint.parent, joint.child} & group) == 1:
                group |= {joint.parent, joint.child}
                grown = True
    return group


def surface_distance(asset: ArticulatedAsset, links: set[str], poses: dict[str, np.ndarray], point: np.ndarray) -> float:
    """Distance from a world point to the posed surface of ``links`` (trimesh's closest point)."""
    meshes = []
    for name in links:
        for part in asset.links[name].parts:
            vertices = part.vertices @ poses[name][:3, :3].T + poses[name][:3, 3]
            meshes.append(trimesh.Trimesh(vertices=vertices, faces=part.faces, process=False))
    _, distance, _ = trimesh.proximity.closest_point(trimesh.util.concatenate(meshes), point[None])
    return float(distance[0])


def check_record(asset: ArticulatedAsset, trajectory: Trajectory, record: Interaction) -> np.ndarray:
    """On the surface at the first frame, and every path sample = FK(link) @ the same local point. Returns it (link frame)."""
    frames = [round(sample.time_s * trajectory.fps) for sample in record.path]
    assert frames == list(range(frames[0], frames[-1] + 1))
    assert record.path[0].time_s <= record.t0 + 1e-9
    assert record.path[-1].time_s >= min(record.t1, trajectory.times[-1]) - 1e-9
    start = _poses(asset, trajectory, frames[0])
    point = np.array(record.contact_point)
    assert surface_distance(asset, _fixed_group(asset, record.link), start, point) < SURFACE_TOLERANCE_M
    local = np.linalg.inv(start[record.link]) @ np.append(point, 1.0)
    normal = np.array(record.contact_normal)
    assert abs(np.linalg.norm(normal) - 1.0) < 1e-9
    for frame, sample in zip(frames, record.path, strict=True):
        pose = _poses(asset, trajectory, frame)[record.link]
        assert np.abs(np.array(sample.position) - (pose @ local)[:3]).max() < FK_TOLERANCE
        assert np.abs(quaternion_to_matrix(np.array(sample.orientation_xyzw)) - pose[:3, :3]).max() < FK_TOLERANCE
    return np.asarray(local[:3])


def _far(asset: ArticulatedAsset, joint: str) -> str:
    """The limit farther from the rest value (the opening direction of a closed part)."""
    spec = asset.joints[joint]
    return "upper_limit" if abs((spec.upper or 0.0) - spec.rest) >= abs((spec.lower or 0.0) - spec.rest) else "lower_limit"


def _plan(joint: str, target: str, *, fps: int = 30, phase: str = "effect_motion") -> Plan:
    return Plan.model_validate({"meta": {"fps": fps, "duration_s": 2.0}, "timeline": [
        {"name": "move", "phase_type": phase, "t0": 0.2, "t1": 1.7,
         "controls": [{"mode": "joint_position", "joint": joint, "q_target_expr": target, "curve": "ease_in_out"}]}]})


def _run(asset: ArticulatedAsset, plan: Plan) -> tuple[Trajectory, InteractionDocument]:
    trajectory = execute(plan, asset)
    return trajectory, interaction_targets(asset, trajectory, actuated_phases(asset, plan))


def test_revolute_door_without_handle_is_touched_at_its_free_edge(partnet: Path) -> None:
    asset = load_asset(partnet / "door_8877")
    trajectory, document = _run(asset, _plan("joint_1", _far(asset, "joint_1")))
    (record,) = document.interactions
    assert (record.link, record.joint, record.kind, record.feature) == ("link_1", "joint_1", "direct_manipulation", "free_edge")
    assert (record.t0, record.t1) == (0.2, 1.7)
    local = check_record(asset, trajectory, record)
    joint = asset.joints["joint_1"]
    radial = np.linalg.norm(np.cross(local, joint.axis))  # distance from the hinge axis (through the link origin)
    vertices = asset.links["link_1"].vertices()
    reach = np.linalg.norm(np.cross(vertices, joint.axis), axis=1).max()
    assert radial > 0.85 * reach
    normal, direction = np.array(record.contact_normal), np.array(record.direction)
    assert abs(normal @ (_poses(asset, trajectory, 6)["link_1"][:3, :3] @ joint.axis)) < 0.1  # a face, not the hinge side
    assert (record.action == "pull") == (normal @ direction > 0)


def test_revolute_door_with_handle_is_touched_on_the_handle(partnet: Path) -> None:
    asset = load_asset(partnet / "dishwasher_11700")
    trajectory, document = _run(asset, _plan("joint_0", _far(asset, "joint_0")))
    (record,) = document.interactions
    assert record.feature == "handle" and record.action == "pull"
    check_record(asset, trajectory, record)
    start = _poses(asset, trajectory, round(record.t0 * trajectory.fps))
    handle = [p for p in asset.links["link_0"].parts if "handle" in p.visual]
    meshes = [trimesh.Trimesh(p.vertices @ start["link_0"][:3, :3].T + start["link_0"][:3, 3], p.faces, process=False) for p in handle]
    _, distance, _ = trimesh.proximity.closest_point(trimesh.util.concatenate(meshes), np.array([record.contact_point]))
    assert distance[0] < SURFACE_TOLERANCE_M


def test_prismatic_drawer_is_pulled_by_its_handle(partnet: Path) -> None:
    asset = load_asset(partnet / "storage_19179")
    trajectory, document = _run(asset, _plan("joint_1", _far(asset, "joint_1")))
    (record,) = document.interactions
    assert (record.feature, record.action, record.kind) == ("handle", "pull", "direct_manipulation")
    check_record(asset, trajectory, record)
    assert np.array(record.contact_normal) @ np.array(record.direction) > 0.9
    travel = np.array(record.path[-1].position) - np.array(record.path[0].position)
    assert np.linalg.norm(travel) == pytest.approx(abs(trajectory.joint("joint_1")[-1] - trajectory.joint("joint_1")[0]), abs=1e-9)


def test_button_is_pressed_at_its_face_centre(examples_dir: Path) -> None:
    asset = load_asset(examples_dir / "microwave")
    plan = Plan.model_validate(json.loads((examples_dir / "microwave" / "plan.json").read_text()))
    trajectory, document = _run(asset, plan)
    (record,) = document.interactions  # the door swings open as an effect: no record
    assert (record.link, record.kind, record.feature, record.action) == ("release_button", "control_actuation", "face_centre", "push")
    local = check_record(asset, trajectory, record)
    assert np.array(record.contact_normal) @ np.array(record.direction) < -0.9
    vertices = asset.links["release_button"].vertices()
    centre = (vertices.min(axis=0) + vertices.max(axis=0)) / 2
    normal_local = np.linalg.inv(_poses(asset, trajectory, 0)["release_button"][:3, :3]) @ np.array(record.contact_normal)
    across = (local - centre) - ((local - centre) @ normal_local) * normal_local
    assert np.linalg.norm(across) < 1e-3
    assert (local - centre) @ normal_local == pytest.approx(np.abs(vertices - centre) @ np.abs(normal_local), abs=1e-3)


def test_whole_object_push_touches_the_rear_face(examples_dir: Path) -> None:
    asset = load_asset(examples_dir / "toy_car")
    plan = Plan.model_validate(json.loads((examples_dir / "toy_car" / "plan.json").read_text()))
    trajectory, document = _run(asset, plan)
    (record,) = document.interactions  # the wheels roll as an effect: no record
    assert (record.link, record.joint, record.kind, record.feature, record.action) == ("chassis", None, "whole_object_push", "rear_face", "push")
    check_record(asset, trajectory, record)
    assert np.allclose(record.direction, [1.0, 0.0, 0.0]) and np.allclose(record.contact_normal, [-1.0, 0.0, 0.0])
    body = asset.links["chassis"].vertices()
    assert record.contact_point[0] == pytest.approx(body[:, 0].min(), abs=3e-3)  # the rear face (taillights stand 2 mm proud)
    first, last = (round(s.time_s * trajectory.fps) for s in (record.path[0], record.path[-1]))
    moved = np.array(record.path[-1].position) - np.array(record.path[0].position)
    assert np.allclose(moved, trajectory.base_translation[last] - trajectory.base_translation[first], atol=1e-12)


def test_pedal_is_stepped_on_at_its_tread(examples_dir: Path) -> None:
    asset = load_asset(examples_dir / "pedal_bin")
    plan = Plan.model_validate(json.loads((examples_dir / "pedal_bin" / "plan.json").read_text()))
    trajectory, document = _run(asset, plan)
    (record,) = document.interactions
    assert (record.link, record.feature, record.action) == ("pedal", "tread", "push")
    check_record(asset, trajectory, record)
    assert record.contact_normal[2] > 0.9 and record.direction[2] < -0.9


def test_knob_is_turned_at_its_face(examples_dir: Path) -> None:
    asset = load_asset(examples_dir / "cabinet")
    plan = Plan.model_validate(json.loads((examples_dir / "cabinet" / "plan_open_door.json").read_text()))
    trajectory, document = _run(asset, plan)
    (record,) = document.interactions
    assert (record.link, record.action, record.feature) == ("latch_knob", "turn", "face_centre")
    check_record(asset, trajectory, record)
    assert record.contact_normal[0] > 0.9  # the cabinet's front faces +X


def test_phase_without_motion_or_geometry_is_noted_not_invented(examples_dir: Path) -> None:
    asset = load_asset(examples_dir / "pedal_bin")
    plan = Plan.model_validate(json.loads((examples_dir / "pedal_bin" / "plan.json").read_text()))
    trajectory = execute(plan, asset)
    still = ActuatedPhase(link="lid", joint="lid_hinge", t0=1.5, t1=2.0, kind="direct_manipulation")
    unknown = ActuatedPhase(link="handle", joint="handle_joint", t0=0.0, t1=1.0, kind="direct_manipulation")
    unrelated = ActuatedPhase(link="lid", joint="pedal_pivot", t0=0.0, t1=0.35, kind="direct_manipulation")
    document = interaction_targets(asset, trajectory, [still, unknown, unrelated])
    assert document.interactions == []
    assert [n.split(": ", 1)[1] for n in document.notes] == [
        "joint lid_hinge does not move in [1.5, 2.0] s", "unknown link", "joint pedal_pivot does not move it"]


def test_document_is_deterministic(partnet: Path) -> None:
    asset = load_asset(partnet / "storage_19179")
    plan = _plan("joint_0", _far(asset, "joint_0"))
    _, first = _run(asset, plan)
    _, second = _run(load_asset(partnet / "storage_19179"), plan)
    assert first.dumps() == second.dumps() and len(first.interactions) == 1


def test_phase_window_is_validated() -> None:
    with pytest.raises(ValueError, match="t1"):
        ActuatedPhase(link="a", joint="j", t0=1.0, t1=1.0, kind="direct_manipulation")
    with pytest.raises(ValueError, match="whole_object_push"):
        ActuatedPhase(link="a", joint=None, t0=0.0, t1=1.0, kind="direct_manipulation")
    assert math.isclose(ActuatedPhase(link="a", joint=None, t0=0.0, t1=0.5, kind="whole_object_push").t1, 0.5)
