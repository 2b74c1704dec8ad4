"""Actuated phases derived from Causal.json actions and Plan.json segments (effects get none)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.causal import CausalDocument
from app.engine.interaction.model import ActuatedPhase
from app.engine.interaction.phases import actuated_phases, driving_joint
from app.engine.plan.schema import Plan


def _example(examples_dir: Path, name: str, plan_file: str = "plan.json") -> tuple[ArticulatedAsset, Plan]:
    folder = examples_dir / name
    return load_asset(folder), Plan.model_validate(json.loads((folder / plan_file).read_text()))


def _causal(*actions: dict[str, Any], effects: tuple[str, ...] | list[str] = ()) -> CausalDocument:
    first, *rest = actions
    segments = [{"segment_id": f"S{i}", "time_hint": {"order_index": i}, "action": a} for i, a in enumerate(actions)] if rest else None
    return CausalDocument.model_validate({
        "causal": {"has_causal": True, "action": first, "effects": {"effect_links": list(effects)}},
        "causal_segments": segments,
    })


def _action(primitive: str, link: str, role: str, links: list[str] | None = None) -> dict[str, Any]:
    return {"primitive": primitive, "target_link": link, "target_links": links or [link], "target_role": role}


def _brief(phases: list[ActuatedPhase]) -> list[tuple[str, str | None, float, float, str, str | None]]:
    return [(p.link, p.joint, p.t0, p.t1, p.kind, p.action) for p in phases]


def test_control_gets_a_phase_and_its_effect_none(examples_dir: Path) -> None:
    asset, plan = _example(examples_dir, "pedal_bin")
    causal = _causal(_action("press", "pedal", "control"), effects=["lid"])
    assert _brief(actuated_phases(asset, plan, causal)) == [("pedal", "pedal_pivot", 0.0, 0.35, "control_actuation", "push")]
    assert _brief(actuated_phases(asset, plan)) == [("pedal", "pedal_pivot", 0.0, 0.35, "control_actuation", None)]


def test_parts_moved_by_hand_in_order(examples_dir: Path) -> None:
    asset, plan = _example(examples_dir, "oven")
    expected = [("door", "door_hinge", 0.0, 1.2, "direct_manipulation"), ("tray", "tray_slide", 1.4, 2.6, "direct_manipulation")]
    assert [b[:5] for b in _brief(actuated_phases(asset, plan))] == expected
    causal = _causal(_action("open", "door", "direct_object"), _action("pull", "tray", "direct_object"))
    assert _brief(actuated_phases(asset, plan, causal)) == [(*expected[0], None), (*expected[1], "pull")]


def test_whole_object_push_and_rolling_wheels(examples_dir: Path) -> None:
    asset, plan = _example(examples_dir, "toy_car")
    causal = _causal(_action("push", "chassis", "direct_object"), effects=["wheel_front_left"])
    expected = [("chassis", None, 0.0, 2.0, "whole_object_push", "push")]
    assert _brief(actuated_phases(asset, plan, causal)) == expected
    assert _brief(actuated_phases(asset, plan)) == [(*expected[0][:5], None)]


def test_state_dependent_plan_has_only_the_control(examples_dir: Path) -> None:
    asset, plan = _example(examples_dir, "cabinet", "plan_open_door.json")
    assert _brief(actuated_phases(asset, plan)) == [("latch_knob", "latch_knob_turn", 0.0, 0.5, "control_actuation", None)]


def test_touching_segments_merge(examples_dir: Path) -> None:
    asset, plan = _example(examples_dir, "microwave", "plan_spin_turntable.json")
    causal = _causal(_action("spin", "turntable", "direct_object"))
    assert _brief(actuated_phases(asset, plan, causal)) == [("turntable", "turntable_spin", 0.0, 5.0, "direct_manipulation", "turn")]


def test_several_target_links_and_unknown_ones(partnet: Path) -> None:
    asset = load_asset(partnet / "refrigerator_11178")
    doors = [j.child for j in asset.joints.values() if j.movable]
    plan = Plan.model_validate({"meta": {"fps": 30, "duration_s": 2.0}, "timeline": [
        {"name": f"open_{i}", "phase_type": "effect_motion", "t0": 0.5 * i, "t1": 0.5 * i + 1.0,
         "controls": [{"mode": "joint_position", "joint": driving_joint(asset, door), "q_target_expr": "0.5*upper_limit"}]}
        for i, door in enumerate(doors)]})
    causal = _causal(_action("open", doors[0], "direct_object", [*doors, "no_such_link"]))
    phases = actuated_phases(asset, plan, causal)
    assert [p.link for p in phases] == doors and all(p.kind == "direct_manipulation" for p in phases)


def test_driving_joint_walks_through_fixed_joints(examples_dir: Path) -> None:
    asset, _ = _example(examples_dir, "pedal_bin")
    assert driving_joint(asset, "pedal") == "pedal_pivot"
    assert driving_joint(asset, asset.root_link) is None


@pytest.mark.parametrize("example", ["pedal_bin", "oven", "toy_car", "microwave", "cabinet"])
def test_every_example_plan_derives_valid_phases(examples_dir: Path, example: str) -> None:
    asset, plan = _example(examples_dir, example)
    for phase in actuated_phases(asset, plan):
        assert phase.link in asset.links and plan.duration_s >= phase.t1 > phase.t0
