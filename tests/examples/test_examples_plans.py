"""Every example plan follows the planner contract (paper supp. §2.2), validates and executes cleanly."""

from __future__ import annotations

import numpy as np
import pytest
from support.example_runs import EXAMPLE_NAMES, all_plans, first_motion_time, plan_files, run_example

from app.engine.execute.executor import execute

PHASE_TYPES = frozenset({"control_actuation", "causal_latency", "control_release", "effect_motion", "settle", "hold"})
CONTROL_FIELDS = {
    "base_velocity": {"mode", "axis_world", "v_mps"},
    "base_velocity_decay": {"mode", "axis_world", "v0_mps", "tau_s"},
    "joint_velocity": {"mode", "joint", "omega_radps", "ramp_to_omega_radps", "decay"},
    "joint_position": {"mode", "joint", "q_target_expr", "q_target_rad", "q_start_rad", "curve"},
    "hold_position": {"mode", "joint"},
    "spring_return": {"mode", "joint", "spring_k", "damping_c", "rest_position"},
    "mode_set": {"mode", "name", "set"},
}
TIMING_FIELDS = {"control_onset_time", "control_peak_time", "effect_start_time", "enforced_delay_s"}
MOTION_TYPES = {
    ("pedal_bin", "plan.json"): "mechanically_coupled",
    ("microwave", "plan.json"): "mechanically_coupled",
    ("microwave", "plan_spin_turntable.json"): "independent",
    ("cabinet", "plan.json"): "independent",
    ("cabinet", "plan_open_top_drawer.json"): "independent",
    ("cabinet", "plan_open_door.json"): "state_dependent",
    ("oven", "plan.json"): "state_dependent",
    ("toy_car", "plan.json"): "environment_mediated",
    ("toy_car", "plan_roll_to_stop.json"): "environment_mediated",
}
CAUSAL_DELAY_S = {"pedal_bin": 0.10, "microwave": 0.05, "cabinet": 0.05}
"""Contract minimum from control onset to effect start: spring-loaded lid 0.10 s, button/latch 0.05 s."""
TIME_EPS = 1e-9
MOVING_MODES = frozenset({"joint_position", "joint_velocity", "spring_return"})
PLANS = all_plans()


def test_every_example_has_plans_and_all_motion_types_are_covered() -> None:
    assert set(PLANS) == set(MOTION_TYPES)
    assert all(plan_files(name) for name in EXAMPLE_NAMES)
    assert set(MOTION_TYPES.values()) == {
        "independent",
        "mechanically_coupled",
        "state_dependent",
        "environment_mediated",
    }


@pytest.mark.parametrize(("name", "plan_file"), PLANS)
def test_plan_follows_the_contract_literally(name: str, plan_file: str) -> None:
    raw = run_example(name, plan_file).raw
    assert set(raw) <= {"meta", "physics", "timeline", "timing_checks"}
    assert raw["meta"]["fps"] == 30 and set(raw["meta"]) == {"fps", "duration_s"}
    duration = raw["meta"]["duration_s"]
    assert 1.0 <= duration <= 8.0
    for segment in raw["timeline"]:
        assert set(segment) == {"name", "phase_type", "t0", "t1", "controls"}
        assert segment["phase_type"] in PHASE_TYPES
        assert 0.0 <= segment["t0"] < segment["t1"] <= duration
        for control in segment["controls"]:
            assert set(control) <= CONTROL_FIELDS[control["mode"]], f"{segment['name']}: unlisted field"
            assert "joints" not in control
            if control["mode"] == "joint_position":
                assert "q_target_expr" in control or "q_target_rad" in control
    assert set(raw.get("timing_checks", {})) <= TIMING_FIELDS


@pytest.mark.parametrize(("name", "plan_file"), PLANS)
def test_plan_validates_and_executes_without_warnings(name: str, plan_file: str) -> None:
    run = run_example(name, plan_file)
    assert run.warnings == ()
    assert run.trajectory.events == (), "no overlaps, clamps, jumps or limit stops expected"
    assert run.trajectory.fps == 30
    assert run.trajectory.frame_count == round(run.plan.duration_s * 30) + 1
    for joint in run.asset.movable_joints:
        spec = run.asset.joints[joint]
        values = run.q(joint)
        assert values[0] == spec.rest
        if spec.bounded:
            assert spec.lower is not None and spec.upper is not None
            assert values.min() >= spec.lower - 1e-12 and values.max() <= spec.upper + 1e-12


@pytest.mark.parametrize(("name", "plan_file"), PLANS)
def test_execution_is_deterministic(name: str, plan_file: str) -> None:
    run = run_example(name, plan_file)
    again = execute(run.plan, run.asset)
    assert again.q.tobytes() == run.trajectory.q.tobytes()
    assert again.base_translation.tobytes() == run.trajectory.base_translation.tobytes()


def _moved_joints(segment: dict) -> set[str]:
    return {c["joint"] for c in segment["controls"] if c["mode"] in MOVING_MODES}


def _direct_timing(segments: list[dict]) -> dict[str, float]:
    """timing_checks of a plan without a control: the first motion, then any motion that waits for it."""
    effects = [s for s in segments if s["phase_type"] == "effect_motion"]
    first = effects[0]
    dependents = [s for s in effects if not _moved_joints(s) & _moved_joints(first)]
    start = min(s["t0"] for s in dependents) if dependents else first["t0"]
    return {
        "control_onset_time": first["t0"],
        "control_peak_time": first["t1"],
        "effect_start_time": start,
        "enforced_delay_s": round(start - first["t1"], 9) if dependents else 0.0,
    }


@pytest.mark.parametrize(("name", "plan_file"), PLANS)
def test_timing_checks_agree_with_the_timeline_and_the_motion(name: str, plan_file: str) -> None:
    run = run_example(name, plan_file)
    checks = run.raw["timing_checks"]
    segments = run.raw["timeline"]
    actuation = [s for s in segments if s["phase_type"] == "control_actuation"]
    effects = [s for s in segments if s["phase_type"] == "effect_motion"]
    assert effects, "every example plan moves something in an effect_motion phase"
    if not actuation:
        assert checks == _direct_timing(segments)
        return
    onset = min(s["t0"] for s in actuation)
    effect_start = min(s["t0"] for s in effects)
    assert checks["control_onset_time"] == onset
    assert checks["control_peak_time"] == max(s["t1"] for s in actuation)
    assert checks["effect_start_time"] == effect_start
    assert checks["enforced_delay_s"] == CAUSAL_DELAY_S[name]
    assert effect_start >= onset + CAUSAL_DELAY_S[name] - TIME_EPS
    control_joints = {c["joint"] for s in actuation for c in s["controls"]}
    effect_joints = set().union(*(_moved_joints(s) for s in effects)) - control_joints
    control_moves = min(first_motion_time(run, j) for j in control_joints)
    effect_moves = min(first_motion_time(run, j) for j in effect_joints)
    assert effect_moves >= control_moves + CAUSAL_DELAY_S[name] - TIME_EPS


@pytest.mark.parametrize(("name", "plan_file"), PLANS)
def test_exactly_the_driven_joints_move(name: str, plan_file: str) -> None:
    run = run_example(name, plan_file)
    driven = set().union(*(_moved_joints(s) for s in run.raw["timeline"]))
    for joint in run.asset.movable_joints:
        assert bool(np.ptp(run.q(joint)) > 0.0) == (joint in driven), joint
