"""Geometric critic and actor: injected failures are detected with the right code and repaired."""

from __future__ import annotations

import asyncio
import copy
from typing import Any

import pytest

from app.engine.agents.actor import repair
from app.engine.agents.critique import Critique, FixHint
from app.engine.agents.expectations import Expectations, expectations_from_intent, expectations_of
from app.engine.agents.loop import refine
from app.engine.agents.roles import Context
from app.engine.asset.summary import joint_summary, scale_context
from app.engine.config import EngineConfig
from app.engine.execute.executor import execute
from app.engine.offline.critic import critique
from app.engine.offline.perceiver import read_prompt
from app.engine.offline.planner import plan_intent
from app.engine.offline.roles import GeometricCritic, OfflinePerceiver
from app.engine.plan.schema import Plan
from tests.engine.offline.conftest import asset


def _setup(name: str, prompt: str) -> tuple[Any, Any, dict[str, Any]]:
    model = asset(name)
    intent = read_prompt(prompt, model).intent
    return model, intent, plan_intent(intent, model).model_dump(exclude_none=True)


def _control(plan: dict[str, Any], joint: str, mode: str = "joint_position") -> dict[str, Any]:
    for segment in plan["timeline"]:
        for control in segment["controls"]:
            if control.get("joint") == joint and control["mode"] == mode:
                return control
    raise AssertionError(f"no {mode} control for {joint}")


def _codes(model: Any, intent: Any, plan: dict[str, Any]) -> list[tuple[str, str]]:
    checked = Plan.model_validate(plan)
    return [(i.code, i.joint) for i in critique(model, checked, execute(checked, model), expectations_from_intent(intent)).issues]


def test_correct_plans_pass() -> None:
    for name, prompt in [("examples/pedal_bin", "press the pedal to open the bin"), ("examples/oven", "pull out the tray"),
                         ("safe_101593", "open the safe door"), ("storage_19179", "open both drawers"), ("examples/toy_car", "push the car 0.5 m along +x")]:
        model, intent, plan = _setup(name, prompt)
        assert _codes(model, intent, plan) == [], f"{name}: {prompt}"


def test_wrong_direction_detected_and_flipped() -> None:
    model, intent, plan = _setup("examples/cabinet", "open the door")
    door = _control(plan, "door_hinge")
    door.pop("q_target_expr", None)
    door["q_target_rad"] = 0.0  # closed side: nothing happens -> too small; use a mirrored door instead
    bad = copy.deepcopy(plan)
    _control(bad, "door_hinge")["q_target_rad"] = 0.0
    assert ("MOTION_TOO_SMALL", "door_hinge") in _codes(model, intent, bad)
    model, intent, plan = _setup("safe_101593", "rotate the left knob 90 degrees clockwise")
    knob = _control(plan, "joint_1")
    knob.pop("q_target_expr", None)
    knob["q_target_rad"] = -knob["q_target_rad"]
    assert _codes(model, intent, plan) == [("WRONG_DIRECTION", "joint_1")]


def test_magnitude_and_extra_motion_and_return() -> None:
    model, intent, plan = _setup("storage_19179", "open the bottom drawer halfway")
    drawer = _control(plan, "joint_0")
    drawer.pop("q_target_expr", None)
    drawer["q_target_rad"] = 0.9
    assert _codes(model, intent, plan) == [("EXCESSIVE_MOTION", "joint_0")]
    drawer["q_target_rad"] = 0.2
    assert _codes(model, intent, plan) == [("MOTION_TOO_SMALL", "joint_0")]
    drawer["q_target_rad"] = 0.5
    plan["timeline"][0]["controls"].append({"mode": "joint_position", "joint": "joint_1", "q_target_rad": 0.3, "curve": "linear"})
    assert _codes(model, intent, plan) == [("UNEXPECTED_EXTRA_MOTION", "joint_1")]
    model, intent, plan = _setup("examples/microwave", "press the door release button")
    plan["timeline"] = [s for s in plan["timeline"] if s["phase_type"] != "control_release"]
    assert ("NO_RELEASE_RETURN", "release_button_slide") in _codes(model, intent, plan)


def test_collision_is_flagged() -> None:
    model, intent, plan = _setup("examples/oven", "open the oven door, then slide the tray out")
    door_segment = next(s for s in plan["timeline"] if any(c.get("joint") == "door_hinge" for c in s["controls"]))
    plan["timeline"].remove(door_segment)  # the tray now slides through the closed door
    codes = _codes(model, intent, plan)
    assert codes == [("MOTION_TOO_SMALL", "door_hinge")]  # the cause; the tray hitting the closed door is not blamed on the tray
    checked = Plan.model_validate(plan)
    expected = expectations_from_intent(intent)
    without_door = Expectations(motions=tuple(m for m in expected.motions if m.joint != "door_hinge"))
    issues = critique(model, checked, execute(checked, model), without_door).issues
    assert [(i.code, i.joint) for i in issues] == [("EXCESSIVE_MOTION", "tray_slide")] and "inside" in issues[0].observed


@pytest.mark.parametrize("direction,expected", [("increase", 0.6), ("decrease", 0.5 / 1.2), ("zero", 0.0)])
def test_actor_target_hints(direction: str, expected: float) -> None:
    model, _, plan = _setup("storage_19179", "open the bottom drawer halfway")
    checked = Plan.model_validate(plan)
    index = next(i for i, s in enumerate(checked.timeline) if any(getattr(c, "joint", None) == "joint_0" for c in s.controls))
    hint = FixHint(type="adjust_joint_target", joint="joint_0", segment_index=index, phase_type=checked.timeline[index].phase_type, direction=direction, strength="medium")  # type: ignore[arg-type]
    repaired, patches = repair(checked, Critique(param_fix_hints=[hint]), model, execute(checked, model))
    assert patches
    assert execute(repaired, model).joint("joint_0")[-1] == pytest.approx(expected, abs=1e-6)


def test_actor_timing_shifts_later_segments() -> None:
    model, _, plan = _setup("examples/oven", "open the oven door, then slide the tray out")
    checked = Plan.model_validate(plan)
    hint = FixHint(type="adjust_timing", joint="door_hinge", segment_index=0, phase_type=checked.timeline[0].phase_type, direction="increase", strength="extra_large")
    repaired, _ = repair(checked, Critique(param_fix_hints=[hint]), model)
    assert repaired.timeline[0].t1 == pytest.approx(2 * checked.timeline[0].t1)
    shift = repaired.timeline[0].t1 - checked.timeline[0].t1
    assert repaired.timeline[1].t0 == pytest.approx(checked.timeline[1].t0 + shift)


def test_loop_repairs_and_keeps_the_best() -> None:
    model = asset("storage_19179")
    prompt = "open the bottom drawer halfway"
    config = EngineConfig()
    context = Context(asset=model, prompt=prompt, joint_summary=joint_summary(model), scale=scale_context(model), config=config)
    perception = asyncio.run(OfflinePerceiver().perceive(context))
    plan = plan_intent(perception.intent, model).model_dump(exclude_none=True)
    drawer = _control(plan, "joint_0")
    drawer.pop("q_target_expr", None)
    drawer["q_target_rad"] = 0.25
    refined = asyncio.run(refine(context, expectations_of(perception), Plan.model_validate(plan), GeometricCritic(), max_rounds=3))
    assert refined.state == "accepted" and refined.best_round >= 1
    assert refined.trajectory.joint("joint_0")[-1] == pytest.approx(0.5, abs=0.025)
    assert refined.rounds[0].issues and refined.rounds[0].patches
