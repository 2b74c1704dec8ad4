"""Plan.json: schema, contract ranges and checks against an asset; every error names its field."""

from __future__ import annotations

import copy
import json
from typing import Any

import pytest

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import PlanValidationError
from app.engine.plan.checks import parse_document, validate_plan
from app.engine.plan.schema import JointPosition, JointVelocity, Plan


def paper_plan() -> dict[str, Any]:
    """The paper's Plan.json schema example (supplementary §2.2), filled in for the cabinet."""
    return {
        "meta": {"fps": 30, "duration_s": 3.0},
        "physics": {},
        "timeline": [
            {
                "name": "open lid",
                "phase_type": "effect_motion",
                "t0": 0.0,
                "t1": 1.5,
                "controls": [
                    {
                        "mode": "joint_position",
                        "joint": "lid_hinge",
                        "q_start_rad": 0.0,
                        "q_target_expr": "upper_limit",
                        "q_target_rad": 1.5707963267948966,
                        "curve": "ease_out",
                    }
                ],
            },
            {
                "name": "hold",
                "phase_type": "hold",
                "t0": 1.5,
                "t1": 3.0,
                "controls": [{"mode": "hold_position", "joint": "lid_hinge"}],
            },
        ],
        "timing_checks": {
            "control_onset_time": 0.0,
            "control_peak_time": 0.0,
            "effect_start_time": 0.0,
            "enforced_delay_s": 0.0,
        },
    }


def issues_of(raw: dict[str, Any], asset: ArticulatedAsset) -> list[str]:
    with pytest.raises(PlanValidationError) as caught:
        validate_plan(raw, asset)
    assert caught.value.issues
    for issue in caught.value.issues:  # each line is "<field path>: <message>"
        path, _, message = issue.partition(": ")
        assert path and message and " " not in path, issue
    return caught.value.issues


def with_control(control: dict[str, Any], **segment: Any) -> dict[str, Any]:
    raw = paper_plan()
    raw["timeline"][1]["controls"] = [control]
    raw["timeline"][1].update(segment)
    return raw


def only_issue(raw: dict[str, Any], asset: ArticulatedAsset, path: str, says: str) -> None:
    issues = issues_of(raw, asset)
    assert len(issues) == 1, issues
    assert issues[0].startswith(path + ": "), issues
    assert says in issues[0], issues


def test_paper_example_validates(cabinet: ArticulatedAsset) -> None:
    checked = validate_plan(paper_plan(), cabinet)
    plan = checked.document
    assert isinstance(plan, Plan) and checked.warnings == ()
    assert plan.duration_s == 3.0
    assert isinstance(plan.timeline[0].controls[0], JointPosition)
    assert validate_plan(json.dumps(paper_plan()), cabinet).document == plan  # JSON text too
    assert Plan.model_validate_json(plan.dumps()) == plan  # canonical text round-trips


def test_all_seven_modes_validate(cabinet: ArticulatedAsset) -> None:
    raw = paper_plan()
    raw["timeline"][1]["controls"] = [
        {"mode": "base_velocity", "axis_world": [0, 2, 0], "v_mps": 0.5},
        {"mode": "base_velocity_decay", "axis_world": [1, 0, 0], "v0_mps": 1.0, "tau_s": 0.5},
        {
            "mode": "joint_velocity",
            "joint": "knob_spin",
            "omega_radps": 2.0,
            "ramp_to_omega_radps": -2.0,
            "decay": {"type": "exponential", "tau_s": 1.0, "min_omega_radps": 0.5},
        },
        {"mode": "spring_return", "joint": "drawer_slide", "spring_k": 20, "damping_c": 5, "rest_position": 0.0},
        {"mode": "mode_set", "name": "latched", "set": True},
    ]
    validate_plan(raw, cabinet)


@pytest.mark.parametrize(
    ("joint", "says"),
    [
        ("ghost", "unknown joint 'ghost'"),
        ("root_fixed", "joint 'root_fixed' is fixed"),
        ("flap_mimic", "mimics 'lid_hinge'"),
    ],
)
@pytest.mark.parametrize("mode", ["hold_position", "joint_velocity", "spring_return", "joint_position"])
def test_joints_a_plan_may_not_drive(cabinet: ArticulatedAsset, joint: str, says: str, mode: str) -> None:
    control: dict[str, Any] = {"mode": mode, "joint": joint}
    if mode == "joint_velocity":
        control["omega_radps"] = 1.0
    if mode == "joint_position":
        control["q_target_rad"] = 0.1
    only_issue(with_control(control), cabinet, "timeline[1].controls[0].joint", says)


def test_unknown_joint_in_joint_dynamics(cabinet: ArticulatedAsset) -> None:
    raw = paper_plan()
    raw["physics"] = {"joint_dynamics": [{"joint": "lid_hinge", "spring_k": 3}, {"joint": "ghost", "spring_k": 3}]}
    only_issue(raw, cabinet, "physics.joint_dynamics[1].joint", "unknown joint 'ghost'")


@pytest.mark.parametrize(
    ("patch", "path", "says"),
    [
        ({"meta": {"fps": 25, "duration_s": 3.0}}, "meta.fps", "24 or 30"),
        ({"meta": {"fps": 60, "duration_s": 3.0}}, "meta.fps", "24 or 30"),
        ({"meta": {"fps": 30, "duration_s": 0.5}}, "meta.duration_s", "greater than or equal to 1"),
        ({"meta": {"fps": 30, "duration_s": 8.5}}, "meta.duration_s", "less than or equal to 8"),
    ],
)
def test_meta_out_of_contract(cabinet: ArticulatedAsset, patch: dict[str, Any], path: str, says: str) -> None:
    raw = paper_plan()
    raw.update(patch)
    only_issue(raw, cabinet, path, says)


@pytest.mark.parametrize(
    ("control", "path", "says"),
    [
        (
            {"mode": "joint_velocity", "joint": "knob_spin", "omega_radps": 20.5},
            "omega_radps",
            "less than or equal to 20",
        ),
        (
            {"mode": "joint_velocity", "joint": "knob_spin", "omega_radps": -21},
            "omega_radps",
            "greater than or equal to -20",
        ),
        (
            {"mode": "joint_velocity", "joint": "knob_spin", "omega_radps": 1, "ramp_to_omega_radps": 25},
            "ramp_to_omega_radps",
            "less than or equal to 20",
        ),
        (
            {"mode": "joint_velocity", "joint": "knob_spin", "omega_radps": 1, "decay": {"tau_s": 0}},
            "decay.tau_s",
            "greater than 0",
        ),
        (
            {
                "mode": "joint_velocity",
                "joint": "knob_spin",
                "omega_radps": 1,
                "decay": {"tau_s": 1, "min_omega_radps": -1},
            },
            "decay.min_omega_radps",
            "greater than or equal to 0",
        ),
        ({"mode": "spring_return", "joint": "lid_hinge", "spring_k": 20.01}, "spring_k", "less than or equal to 20"),
        ({"mode": "spring_return", "joint": "lid_hinge", "spring_k": -1}, "spring_k", "greater than or equal to 0"),
        ({"mode": "spring_return", "joint": "lid_hinge", "damping_c": 5.5}, "damping_c", "less than or equal to 5"),
        (
            {"mode": "joint_position", "joint": "lid_hinge", "q_target_rad": 1, "curve": "cubic"},
            "curve",
            "'linear', 'ease_in', 'ease_out' or 'ease_in_out'",
        ),
        (
            {"mode": "joint_position", "joint": "lid_hinge", "q_target_expr": "__import__('os')"},
            "q_target_expr",
            "unknown name '__import__'",
        ),
        (
            {"mode": "joint_position", "joint": "lid_hinge", "q_target_expr": "upper_limit +"},
            "q_target_expr",
            "unexpected end",
        ),
        ({"mode": "joint_position", "joint": "lid_hinge", "q_target_expr": ""}, "q_target_expr", "empty"),
        (
            {"mode": "joint_position", "joint": "lid_hinge", "q_target_expr": "velocity:fast"},
            "q_target_expr",
            "unknown name 'velocity'",
        ),
        (
            {"mode": "joint_position", "joint": "lid_hinge", "q_target_expr": "velocity:30"},
            "omega_radps",
            "less than or equal to 20",
        ),
        (
            {"mode": "hold_position", "joint": "lid_hinge", "joints": ["lid_hinge"]},
            "joints",
            "Extra inputs are not permitted",
        ),
        (
            {"mode": "joint_velocity", "joint": "knob_spin", "omega_radps": 1, "speed": 3},
            "speed",
            "Extra inputs are not permitted",
        ),
        ({"mode": "base_velocity", "axis_world": [0, 0, 0], "v_mps": 1}, "axis_world", "zero vector"),
        ({"mode": "base_velocity", "axis_world": [1, 0], "v_mps": 1}, "axis_world[2]", "Field required"),
        ({"mode": "base_velocity_decay", "axis_world": [1, 0, 0], "v0_mps": 1, "tau_s": -1}, "tau_s", "greater than 0"),
        ({"mode": "mode_set", "name": "latched"}, "set", "Field required"),
    ],
)
def test_control_fields_out_of_contract(
    cabinet: ArticulatedAsset, control: dict[str, Any], path: str, says: str
) -> None:
    only_issue(with_control(control), cabinet, f"timeline[1].controls[0].{path}", says)


def test_position_without_target(cabinet: ArticulatedAsset) -> None:
    only_issue(
        with_control({"mode": "joint_position", "joint": "lid_hinge"}),
        cabinet,
        "timeline[1].controls[0]",
        "needs q_target_expr or q_target_rad",
    )


def test_unknown_mode(cabinet: ArticulatedAsset) -> None:
    only_issue(
        with_control({"mode": "teleport", "joint": "lid_hinge"}), cabinet, "timeline[1].controls[0]", "'teleport'"
    )


def test_unknown_phase_type(cabinet: ArticulatedAsset) -> None:
    raw = paper_plan()
    raw["timeline"][1]["phase_type"] = "wiggle"
    only_issue(raw, cabinet, "timeline[1].phase_type", "control_actuation")


@pytest.mark.parametrize(("t0", "t1"), [(2.0, 2.0), (2.5, 2.0)])
def test_phase_with_t0_not_before_t1(cabinet: ArticulatedAsset, t0: float, t1: float) -> None:
    raw = paper_plan()
    raw["timeline"][1].update(t0=t0, t1=t1)
    only_issue(raw, cabinet, "timeline[1].t1", "must be greater than t0")


def test_negative_t0(cabinet: ArticulatedAsset) -> None:
    raw = paper_plan()
    raw["timeline"][0]["t0"] = -0.1
    only_issue(raw, cabinet, "timeline[0].t0", "greater than or equal to 0")


def test_every_problem_is_listed_at_once(cabinet: ArticulatedAsset) -> None:
    raw = paper_plan()
    raw["meta"]["fps"] = 25
    raw["timeline"][0]["controls"][0]["q_target_expr"] = "import os"
    raw["timeline"][1]["controls"] = [{"mode": "joint_velocity", "joint": "knob_spin", "omega_radps": 99}]
    raw["timeline"][1]["t1"] = 1.0
    issues = issues_of(raw, cabinet)
    paths = sorted(issue.partition(": ")[0] for issue in issues)
    assert paths == [
        "meta.fps",
        "timeline[0].controls[0].q_target_expr",
        "timeline[1].controls[0].omega_radps",
        "timeline[1].t1",
    ]


def test_velocity_target_becomes_joint_velocity(cabinet: ArticulatedAsset) -> None:
    raw = with_control(
        {"mode": "joint_position", "joint": "knob_spin", "q_target_expr": "velocity:-2.5", "curve": "linear"}
    )
    control = validate_plan(raw, cabinet).document.timeline[1].controls[0]
    assert isinstance(control, JointVelocity)
    assert (control.joint, control.omega_radps, control.ramp_to_omega_radps, control.decay) == (
        "knob_spin",
        -2.5,
        None,
        None,
    )


@pytest.mark.parametrize(
    ("control", "path", "says"),
    [
        (
            {"mode": "joint_position", "joint": "knob_spin", "q_target_expr": "upper_limit"},
            "q_target_expr",
            "has no limits",
        ),
        (
            {"mode": "joint_position", "joint": "lid_hinge", "q_target_expr": "1/(upper_limit - upper_limit)"},
            "q_target_expr",
            "divides by zero",
        ),
    ],
)
def test_expressions_that_fail_on_the_asset(
    cabinet: ArticulatedAsset, control: dict[str, Any], path: str, says: str
) -> None:
    raw = with_control(control)
    parse_document(Plan, raw, "plan")  # the schema alone accepts them
    only_issue(raw, cabinet, f"timeline[1].controls[0].{path}", says)


def test_unknown_keys_in_physics_and_timing_checks_are_kept_as_warnings(cabinet: ArticulatedAsset) -> None:
    raw = paper_plan()
    raw["physics"] = {"friction": 0.3, "joint_dynamics": [{"joint": "lid_hinge", "spring_k": 2.0, "note": "stiff"}]}
    raw["timing_checks"]["settle_time"] = 2.5
    raw["nl_parse"] = {"verb": "open"}
    checked = validate_plan(raw, cabinet)
    assert any(w.startswith("physics.friction:") for w in checked.warnings)
    assert any(w.startswith("timing_checks.settle_time:") for w in checked.warnings)
    assert any("'nl_parse'" in w for w in checked.warnings)
    text = json.loads(checked.document.dumps())
    assert text["physics"]["friction"] == 0.3 and text["timing_checks"]["settle_time"] == 2.5
    assert text["physics"]["joint_dynamics"][0]["note"] == "stiff"


def test_target_warnings(cabinet: ArticulatedAsset) -> None:
    raw = with_control(
        {"mode": "joint_position", "joint": "drawer_slide", "q_target_rad": 0.9, "q_target_expr": "upper_limit"}
    )
    warnings = validate_plan(raw, cabinet).warnings
    assert any(w.startswith("timeline[1].controls[0]: q_target_rad 0.9 differs from q_target_expr") for w in warnings)
    assert any(w.startswith("timeline[1].controls[0]: target 0.9 lies outside [0, 0.6]") for w in warnings)


def test_timeline_past_duration_extends_it(cabinet: ArticulatedAsset) -> None:
    raw = paper_plan()
    raw["timeline"][1]["t1"] = 4.25
    checked = validate_plan(raw, cabinet)
    assert checked.document.duration_s == 4.25
    assert any("duration extended" in w for w in checked.warnings)


def test_empty_timeline(cabinet: ArticulatedAsset) -> None:
    raw = paper_plan()
    raw["timeline"] = []
    only_issue(raw, cabinet, "timeline", "at least 1 item")


def test_not_json(cabinet: ArticulatedAsset) -> None:
    with pytest.raises(PlanValidationError):
        validate_plan("{not json", cabinet)


def test_validation_does_not_mutate_input(cabinet: ArticulatedAsset) -> None:
    raw = with_control({"mode": "joint_position", "joint": "knob_spin", "q_target_expr": "velocity:2"})
    before = copy.deepcopy(raw)
    validate_plan(raw, cabinet)
    assert raw == before
