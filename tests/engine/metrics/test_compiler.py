"""Annotation -> GT plan -> GT trajectory -> key states (SPEC §5), on the primitive cabinet."""

from __future__ import annotations

import math

import numpy as np
import pytest
from support.metric_cases import make_case

from app.engine.errors import MetricError
from app.engine.metrics.compiler import GT_FPS, compile_case, schedule, seconds_to_frames
from app.engine.plan.schema import BaseVelocity, JointPosition, JointVelocity

LID = {"phase": "lid", "subject": "lid_hinge", "constraints": {"target_q": 1.2}}


def _frames(truth):
    return [(t.phase, t.start_frame, t.end_frame) for t in truth.timings]


def test_phases_run_in_order_for_their_durations(cabinet):
    case = make_case(
        [
            {"id": "c", "order": 5, "duration_s": 0.3},
            {"id": "a", "order": 0, "duration_s": 0.5},
            {"id": "b", "order": 2},
        ],
        [LID | {"phase": "a"}],
    )
    truth = compile_case(case, cabinet)
    assert _frames(truth) == [("a", 0, 15), ("b", 15, 45), ("c", 45, 54)]  # b: default 1.0 s
    assert [s.frame for s in truth.key_states] == [15, 45, 54]
    assert [s.time_s for s in truth.key_states] == [0.5, 1.5, 1.8]
    assert truth.allow_equal == (False, False)
    segments = truth.plan.timeline
    assert [(s.name, s.t0, s.t1) for s in segments] == [("a", 0.0, 0.5), ("b", 0.5, 1.5), ("c", 1.5, 1.8)]
    assert truth.trajectory.fps == GT_FPS and truth.trajectory.frame_count == 55


def test_overlap_starts_at_default_progress(cabinet):
    case = make_case(
        [{"id": "lid", "order": 0, "duration_s": 1.0}, {"id": "drawer", "order": 1, "duration_s": 0.4}],
        [LID, {"phase": "drawer", "subject": "drawer_slide", "constraints": {"target_q": 0.5}}],
        [{"from_phase": "lid", "to_phase": "drawer", "overlap_allowed": True}],
    )
    assert [(t.start_frame, t.end_frame) for t in schedule(case)] == [(0, 30), (6, 18)]  # 0.2 x 30 frames


def test_overlap_uses_start_rule_progress(cabinet):
    case = make_case(
        [{"id": "lid", "order": 0, "duration_s": 1.0}, {"id": "drawer", "order": 1, "duration_s": 0.4}],
        [LID],
        [
            {
                "from_phase": "lid",
                "to_phase": "drawer",
                "overlap_allowed": True,
                "start_rule": {"to_start_relative_to": "from_progress", "progress": 0.5},
            }
        ],
    )
    assert [(t.start_frame, t.end_frame) for t in schedule(case)] == [(0, 30), (15, 27)]


def test_non_overlapping_relation_from_an_earlier_phase_delays_the_start(cabinet):
    case = make_case(
        [
            {"id": "a", "order": 0, "duration_s": 1.0},
            {"id": "b", "order": 1, "duration_s": 0.2},
            {"id": "c", "order": 2, "duration_s": 0.2},
        ],
        relations=[
            {"from_phase": "a", "to_phase": "b", "overlap_allowed": True, "start_rule": {"progress": 0.0}},
            {"from_phase": "a", "to_phase": "c", "overlap_allowed": False},
        ],
    )
    assert [(t.start_frame, t.end_frame) for t in schedule(case)] == [(0, 30), (0, 6), (30, 36)]


def test_key_states_follow_end_time_with_partial_progress(cabinet):
    case = make_case(
        [{"id": "lid", "order": 0, "duration_s": 1.0}, {"id": "drawer", "order": 1, "duration_s": 0.4}],
        [LID, {"phase": "drawer", "subject": "drawer_slide", "constraints": {"target_q": 0.5}}],
        [{"from_phase": "lid", "to_phase": "drawer", "overlap_allowed": True}],
    )
    truth = compile_case(case, cabinet)
    assert [(s.phase, s.frame) for s in truth.key_states] == [("drawer", 18), ("lid", 30)]
    assert truth.allow_equal == (True,)  # related by overlap_allowed
    lid = truth.trajectory.joint("lid_hinge")
    s = 18 / 30
    assert lid[18] == pytest.approx(1.2 * (3 * s * s - 2 * s**3), abs=1e-12)  # the lid is still opening
    assert truth.trajectory.joint("drawer_slide")[18] == pytest.approx(0.5)
    assert lid[30] == pytest.approx(1.2)


def test_equal_end_times_keep_phase_order_and_may_share_a_frame(cabinet):
    case = make_case(
        [{"id": "first", "order": 0, "duration_s": 0.6}, {"id": "second", "order": 1, "duration_s": 0.6}],
        [LID | {"phase": "first"}, {"phase": "second", "subject": "knob", "constraints": {"omega_radps": 1.0}}],
        [{"from_phase": "first", "to_phase": "second", "overlap_allowed": True, "start_rule": {"progress": 0.0}}],
    )
    truth = compile_case(case, cabinet)
    assert [(s.phase, s.frame) for s in truth.key_states] == [("first", 18), ("second", 18)]
    assert truth.allow_equal == (True,)


def test_constraints_become_controls(cabinet):
    case = make_case(
        [
            {"id": "open", "order": 0, "duration_s": 1.0},
            {"id": "spin", "order": 1, "duration_s": 0.5},
            {"id": "close", "order": 2},
            {"id": "carry", "order": 3, "duration_s": 2.0},
        ],
        [
            LID | {"phase": "open"},
            {"phase": "spin", "subject": "knob_spin", "constraints": {"omega_radps": 2.0}},
            {"phase": "close", "subject": "lid", "constraints": {"return_mode": "self_return", "rest_position_q": 0.1}},
            {
                "phase": "carry",
                "subject": "base",
                "constraints": {"displacement_m": 0.6, "direction_axis_world": [3.0, 0.0, 4.0]},
            },
        ],
    )
    truth = compile_case(case, cabinet)
    controls = [c for segment in truth.plan.timeline for c in segment.controls]
    assert (
        isinstance(controls[0], JointPosition)
        and controls[0].curve == "ease_in_out"
        and controls[0].q_target_rad == 1.2
    )
    assert isinstance(controls[1], JointVelocity) and controls[1].omega_radps == 2.0
    assert (
        isinstance(controls[2], JointPosition) and controls[2].joint == "lid_hinge" and controls[2].q_target_rad == 0.1
    )
    assert isinstance(controls[3], BaseVelocity) and controls[3].v_mps == pytest.approx(0.3)
    trajectory = truth.trajectory
    assert trajectory.joint("knob_spin")[45] == pytest.approx(1.0, abs=1e-9)
    assert trajectory.joint("lid_hinge")[75] == pytest.approx(0.1)
    assert np.allclose(trajectory.base_translation[-1], [0.36, 0.0, 0.48])
    carry = truth.key_states[-1]
    assert carry.base_constrained and set(carry.dynamic_links) == set(cabinet.visual_links)


def test_a_link_subject_means_its_parent_joint_and_descendants_are_dynamic(cabinet):
    case = make_case(
        [{"id": "open", "order": 0}], [{"phase": "open", "subject": "lid", "constraints": {"target_q": 1.0}}]
    )
    state = compile_case(case, cabinet).key_states[0]
    assert state.constrained_joints == ("lid_hinge",)
    assert state.dynamic_links == ("lid", "flap")  # the flap hangs below the lid (and mimics it)


def test_the_root_link_means_the_base(cabinet):
    case = make_case(
        [{"id": "move", "order": 0}], [{"phase": "move", "subject": "world", "constraints": {"motion": "translate"}}]
    )
    state = compile_case(case, cabinet).key_states[0]
    assert state.base_constrained and state.dynamic_links == cabinet.visual_links


def test_a_phase_without_constraints_only_lets_time_pass(cabinet):
    case = make_case(
        [{"id": "open", "order": 0}, {"id": "hold_end_state", "order": 1, "duration_s": 0.5}], [LID | {"phase": "open"}]
    )
    truth = compile_case(case, cabinet)
    assert truth.key_states[1].dynamic_links == ()
    assert truth.plan.timeline[1].controls == [] and truth.plan.timeline[1].phase_type == "hold"
    assert truth.trajectory.joint("lid_hinge")[45] == pytest.approx(1.2)


def test_durations_round_half_up_to_frames():
    assert seconds_to_frames(0.15) == 5
    assert seconds_to_frames(0.3) == 9
    assert seconds_to_frames(1 / 60 - 1e-6) == 0


@pytest.mark.parametrize(
    ("constraint", "message"),
    [
        ({"subject": "hinge_9"}, "constraints[0].subject: subject 'hinge_9' is not a joint"),
        (
            {"subject": "root_fixed", "constraints": {"target_q": 0.1}},
            "constraints[0].constraints.target_q: joint 'root_fixed' (subject 'root_fixed') is fixed",
        ),
        ({"subject": "flap_mimic", "constraints": {"target_q": 0.1}}, "mimics 'lid_hinge'"),
        (
            {"subject": "base", "constraints": {"target_q": 0.1}},
            "constraints[0].constraints.target_q: the base has no joint value",
        ),
        (
            {"subject": "base", "constraints": {"displacement_m": 0.1}},
            "direction_axis_world: a non-zero axis is required",
        ),
        ({"subject": "drawer_slide", "constraints": {"displacement_m": 0.1}}, "displacement_m: applies to 'base' only"),
        ({"subject": "knob_spin", "constraints": {"omega_radps": 50.0}}, "omega_radps: 50.0 exceeds"),
        (
            {"subject": "base", "constraints": {"displacement_m": 100.0, "direction_axis_world": [0, 0, 1]}},
            "exceeds 20.0 m/s",
        ),
    ],
)
def test_bad_constraints_name_the_case_and_field(cabinet, constraint, message):
    case = make_case([{"id": "p", "order": 0}], [{"phase": "p", "subject": "lid_hinge"} | constraint])
    with pytest.raises(MetricError) as caught:
        compile_case(case, cabinet)
    assert "case test_case" in str(caught.value) and message in str(caught.value)


def test_a_relation_against_the_phase_order_is_rejected(cabinet):
    case = make_case(
        [{"id": "a", "order": 0}, {"id": "b", "order": 1}], relations=[{"from_phase": "b", "to_phase": "a"}]
    )
    with pytest.raises(MetricError, match=r"relations\[0\]: from_phase 'b' must come before"):
        compile_case(case, cabinet)


def test_a_schedule_longer_than_the_plan_limit_is_rejected(cabinet):
    case = make_case([{"id": f"p{i}", "order": i, "duration_s": 30.0} for i in range(3)])
    with pytest.raises(MetricError, match="more than 60"):
        compile_case(case, cabinet)


def test_omega_hits_the_limit_and_stops(cabinet):
    case = make_case(
        [{"id": "open", "order": 0, "duration_s": 2.0}],
        [{"phase": "open", "subject": "lid_hinge", "constraints": {"omega_radps": 2.0}}],
    )
    truth = compile_case(case, cabinet)
    assert truth.trajectory.joint("lid_hinge")[-1] == pytest.approx(math.pi / 2)
    assert any("upper limit" in note for note in truth.notes)
