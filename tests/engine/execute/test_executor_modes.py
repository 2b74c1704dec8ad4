"""Every control mode of SPEC §3 against its closed form."""

from __future__ import annotations

import math

import numpy as np
import pytest
from support.executor_rig import plan, position, run, seg, velocity

from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.ease import CURVES
from app.engine.execute.executor import execute

FPS = 30
EXACT = 1e-12
INTEGRATION = 1e-6
"""Tolerance of the sub-stepped velocity integrals (radians)."""
SPRING = 3e-3
"""Semi-implicit Euler at 1 kHz against the analytic oscillator (unit amplitude)."""


def at(times: np.ndarray, t: float) -> int:
    index = round(t * FPS)
    assert abs(times[index] - t) < 1e-12
    return index


# --- joint_position -----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("curve", "half"), [("linear", 0.5), ("ease_in", 0.25), ("ease_out", 0.75), ("ease_in_out", 0.5)]
)
def test_ease_curves(curve: str, half: float) -> None:
    ease = CURVES[curve]
    assert ease(np.array([0.0, 0.5, 1.0])).tolist() == [0.0, half, 1.0]


@pytest.mark.parametrize(
    ("curve", "closed_form"),
    [
        ("linear", lambda s: s),
        ("ease_in", lambda s: s * s),
        ("ease_out", lambda s: 1 - (1 - s) ** 2),
        ("ease_in_out", lambda s: 3 * s**2 - 2 * s**3),
    ],
)
def test_joint_position_follows_the_curve(rig: ArticulatedAsset, curve: str, closed_form: object) -> None:
    trajectory = run(rig, seg(0.5, 1.5, position("hinge", 2.0, curve=curve)))
    q, t = trajectory.joint("hinge"), trajectory.times
    s = np.clip(t - 0.5, 0.0, 1.0)
    assert np.allclose(q, 2.0 * closed_form(s), atol=EXACT)  # type: ignore[operator]
    assert q[at(t, 1.0)] == pytest.approx(2.0 * closed_form(0.5), abs=EXACT)  # type: ignore[operator]
    assert q[at(t, 1.5)] == 2.0  # the target exactly at t1
    assert np.all(q[at(t, 1.5) :] == 2.0)


def test_expression_target(rig: ArticulatedAsset) -> None:
    trajectory = run(
        rig,
        seg(
            0.0,
            1.0,
            position("door", "0.5*upper_limit"),
            position("shifted", "lower_limit + 0.5*(upper_limit - lower_limit)"),
        ),
    )
    assert trajectory.joint("door")[-1] == 0.75
    assert trajectory.joint("shifted")[-1] == pytest.approx(1.15, abs=EXACT)


def test_q_start_rad_is_honoured(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 1.0, position("hinge", 1.0)), seg(1.0, 2.0, position("hinge", 0.0, q_start_rad=0.4)))
    q, t = trajectory.joint("hinge"), trajectory.times
    assert q[at(t, 1.0)] == pytest.approx(0.4, abs=EXACT)  # jumps to q_start_rad at t0
    assert q[at(t, 1.5)] == pytest.approx(0.2, abs=EXACT)
    assert q[at(t, 2.0)] == 0.0
    assert any("q_start_rad 0.4" in e and "jumps" in e for e in trajectory.event_messages)


def test_without_q_start_the_phase_starts_from_the_current_value(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 1.0, position("hinge", 1.0)), seg(1.0, 2.0, position("hinge", 0.0)))
    q, t = trajectory.joint("hinge"), trajectory.times
    assert q[at(t, 1.0)] == 1.0 and q[at(t, 1.5)] == pytest.approx(0.5, abs=EXACT)
    assert np.all(np.abs(np.diff(q)) <= 1.0 / FPS + EXACT)  # no jump


def test_position_target_beyond_a_limit_is_clamped(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 1.0, position("door", 3.0), position("slide", -1.0)))
    assert trajectory.joint("door")[-1] == 1.5 and trajectory.joint("door").max() == 1.5
    assert trajectory.joint("slide").min() == 0.0
    assert any("door: target 3" in e and "clamped to the limit 1.5" in e for e in trajectory.event_messages)


# --- joint_velocity -------------------------------------------------------------------------


def test_constant_velocity(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.5, 1.5, velocity("hinge", -1.5)))
    expected = -1.5 * (np.clip(trajectory.times, 0.5, 1.5) - 0.5)
    assert np.allclose(trajectory.joint("hinge"), expected, atol=INTEGRATION)


def test_velocity_ramp_integrates_exactly(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 2.0, velocity("hinge", 1.0, ramp_to_omega_radps=3.0)))
    t = trajectory.times
    assert np.allclose(trajectory.joint("hinge"), t + t**2 / 2, atol=INTEGRATION)  # w = 1 + t
    assert trajectory.joint("hinge")[-1] == pytest.approx(4.0, abs=INTEGRATION)


def test_velocity_decay(rig: ArticulatedAsset) -> None:
    omega, tau = 2.0, 0.5
    trajectory = run(rig, seg(0.0, 2.0, velocity("hinge", omega, decay={"type": "exponential", "tau_s": tau})))
    t = trajectory.times
    assert np.allclose(trajectory.joint("hinge"), omega * tau * (1 - np.exp(-t / tau)), atol=INTEGRATION)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_velocity_decay_with_a_floor(rig: ArticulatedAsset, sign: float) -> None:
    omega, tau, floor = 2.0 * sign, 0.5, 0.5
    trajectory = run(rig, seg(0.0, 2.0, velocity("hinge", omega, decay={"tau_s": tau, "min_omega_radps": floor})))
    t = trajectory.times
    knee = tau * math.log(abs(omega) / floor)  # |w| reaches the floor here
    decaying = omega * tau * (1 - np.exp(-np.minimum(t, knee) / tau))
    expected = decaying + sign * floor * np.maximum(t - knee, 0.0)
    assert np.allclose(trajectory.joint("hinge"), expected, atol=1e-5)


def test_velocity_floor_above_the_command(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 1.0, velocity("hinge", -1.0, decay={"tau_s": 1.0, "min_omega_radps": 2.0})))
    assert trajectory.joint("hinge")[-1] == pytest.approx(-2.0, abs=INTEGRATION)  # |w| >= min_omega, sign kept


def test_velocity_stops_at_a_limit_and_says_so(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 3.0, velocity("door", 1.0)), seg(0.0, 3.0, velocity("slide", -0.2)), duration=3.0)
    q, t = trajectory.joint("door"), trajectory.times
    assert np.allclose(q[: at(t, 1.5)], t[: at(t, 1.5)], atol=INTEGRATION)
    assert q[at(t, 1.5)] == pytest.approx(1.5, abs=INTEGRATION)
    assert np.all(q[at(t, 1.5) + 1 :] == 1.5)  # stays exactly at the limit
    assert np.all(trajectory.joint("slide") == 0.0)
    door = [e for e in trajectory.event_messages if e.startswith("door:")]
    assert len(door) == 1 and "reached the upper limit 1.5 at t=1.50" in door[0]
    assert any(e.startswith("slide:") and "lower limit 0" in e for e in trajectory.event_messages)


def test_continuous_joint_winds_freely(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 2.0, velocity("wheel", 2 * math.pi)))
    assert trajectory.joint("wheel")[-1] == pytest.approx(4 * math.pi, rel=EXACT)
    assert np.all(np.diff(trajectory.joint("wheel")) > 0)  # never wrapped
    assert not trajectory.events


# --- spring_return ----------------------------------------------------------------------------


def test_spring_matches_the_damped_oscillator(rig: ArticulatedAsset) -> None:
    k, c, x0 = 10.0, 1.0, 1.0
    spring = {"mode": "spring_return", "joint": "hinge", "spring_k": k, "damping_c": c, "rest_position": 0.0}
    trajectory = run(rig, seg(0.0, 1.0, position("hinge", x0)), seg(1.0, 4.0, spring), duration=4.0)
    s = trajectory.times - 1.0
    active = s >= 0
    wd = math.sqrt(k - c * c / 4)
    analytic = np.exp(-c * s / 2) * (x0 * np.cos(wd * s) + (c / 2) * x0 / wd * np.sin(wd * s))
    assert np.abs(trajectory.joint("hinge")[active] - analytic[active]).max() < SPRING


def test_spring_settles_at_its_rest_position(rig: ArticulatedAsset) -> None:
    spring = {"mode": "spring_return", "joint": "hinge", "spring_k": 20.0, "damping_c": 5.0, "rest_position": 0.3}
    trajectory = run(rig, seg(0.0, 1.0, position("hinge", 2.0)), seg(1.0, 6.0, spring), duration=6.0)
    assert abs(trajectory.joint("hinge")[-1] - 0.3) < 1e-4


def test_spring_defaults_come_from_physics(rig: ArticulatedAsset) -> None:
    physics = {"joint_dynamics": [{"joint": "hinge", "spring_k": 10.0, "damping_c": 1.0, "rest_position": 0.5}]}
    spring = {"mode": "spring_return", "joint": "hinge"}
    with_defaults = run(
        rig, seg(0.0, 1.0, position("hinge", 1.5)), seg(1.0, 3.0, spring), duration=3.0, physics=physics
    )
    explicit = {"mode": "spring_return", "joint": "hinge", "spring_k": 10.0, "damping_c": 1.0, "rest_position": 0.5}
    spelled_out = run(rig, seg(0.0, 1.0, position("hinge", 1.5)), seg(1.0, 3.0, explicit), duration=3.0)
    assert np.array_equal(with_defaults.q, spelled_out.q)


def test_spring_without_stiffness_is_a_critically_damped_return(rig: ArticulatedAsset) -> None:
    spring = {"mode": "spring_return", "joint": "hinge", "rest_position": 0.2}
    trajectory = run(rig, seg(0.0, 1.0, position("hinge", 1.0)), seg(1.0, 2.0, spring))
    q, t = trajectory.joint("hinge"), trajectory.times
    phase = q[at(t, 1.0) : at(t, 2.0) + 1]
    assert phase[0] == 1.0 and phase[-1] == 0.2  # reaches the rest exactly at t1
    assert np.all(np.diff(phase) <= 0) and np.all(phase >= 0.2)  # no overshoot
    assert np.all(np.abs(np.diff(phase)[:3]) < np.abs(np.diff(phase)[3:6]).max())  # eases out of the start


def test_spring_rest_defaults_to_the_joint_rest(rig: ArticulatedAsset) -> None:
    trajectory = run(
        rig, seg(0.0, 1.0, position("shifted", 1.5)), seg(1.0, 2.0, {"mode": "spring_return", "joint": "shifted"})
    )
    assert trajectory.joint("shifted")[-1] == 0.3  # rest = 0 clamped into [0.3, 2]


# --- hold, mimic, overlaps ----------------------------------------------------------------------


def test_hold_position(rig: ArticulatedAsset) -> None:
    trajectory = run(
        rig, seg(0.0, 1.0, velocity("hinge", 1.0)), seg(1.0, 2.0, {"mode": "hold_position", "joint": "hinge"})
    )
    q, t = trajectory.joint("hinge"), trajectory.times
    assert np.all(q[at(t, 1.0) :] == q[at(t, 1.0)])
    assert q[at(t, 1.0)] == pytest.approx(1.0, abs=INTEGRATION)


def test_mimic_follows_its_leader(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 2.0, velocity("hinge", 1.0, ramp_to_omega_radps=-2.0)))
    assert np.allclose(trajectory.joint("follower"), -0.5 * trajectory.joint("hinge") + 0.2, atol=EXACT)
    assert trajectory.joint_names == rig.movable_joints


def test_later_overlapping_control_wins_and_is_reported(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 2.0, velocity("hinge", 1.0)), seg(0.5, 1.5, position("hinge", 2.0)))
    q, t = trajectory.joint("hinge"), trajectory.times
    expected = np.where(t < 0.5, t, np.where(t < 1.5, 0.5 + 1.5 * (t - 0.5), 2.0 + (t - 1.5)))
    assert np.allclose(q, expected, atol=INTEGRATION)
    notes = [e for e in trajectory.event_messages if "overlap" in e]
    assert notes == [
        "hinge: timeline[0].controls[0] and timeline[1].controls[0] overlap on [0.500, 1.500] s; timeline[1].controls[0] wins"
    ]


def test_order_in_the_timeline_decides_not_start_time(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.5, 1.5, position("hinge", 2.0)), seg(0.0, 2.0, velocity("hinge", 1.0)))
    assert np.allclose(trajectory.joint("hinge"), trajectory.times, atol=INTEGRATION)  # the velocity always wins
    assert any("timeline[1].controls[0] wins" in e for e in trajectory.event_messages)


def test_uncontrolled_joint_keeps_its_value_between_phases(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.0, 0.5, position("hinge", 1.0)), seg(1.5, 2.0, velocity("hinge", 2.0)))
    q, t = trajectory.joint("hinge"), trajectory.times
    assert np.all(q[at(t, 0.5) : at(t, 1.5) + 1] == 1.0)
    assert q[-1] == pytest.approx(2.0, abs=INTEGRATION)
    for other in ("door", "slide", "wheel", "shifted"):
        assert np.all(trajectory.joint(other) == rig.joints[other].rest)


# --- base motion and modes ----------------------------------------------------------------------


def test_base_velocity_uses_the_unit_axis(rig: ArticulatedAsset) -> None:
    trajectory = run(rig, seg(0.5, 1.5, {"mode": "base_velocity", "axis_world": [0, 2, 0], "v_mps": 0.5}))
    t = trajectory.times
    y = 0.5 * (np.clip(t, 0.5, 1.5) - 0.5)
    assert np.allclose(trajectory.base_translation, np.stack([0 * t, y, 0 * t], axis=1), atol=EXACT)
    assert trajectory.base_translation[-1].tolist() == pytest.approx([0.0, 0.5, 0.0], abs=EXACT)  # v*T, not 2*v*T
    assert np.all(trajectory.base_rotation_xyzw == [0.0, 0.0, 0.0, 1.0])


def test_base_velocity_decay(rig: ArticulatedAsset) -> None:
    v0, tau = 1.0, 0.5
    trajectory = run(
        rig, seg(0.0, 2.0, {"mode": "base_velocity_decay", "axis_world": [3, 0, 4], "v0_mps": v0, "tau_s": tau})
    )
    distance = v0 * tau * (1 - np.exp(-trajectory.times / tau))
    assert np.allclose(trajectory.base_translation, distance[:, None] * np.array([0.6, 0.0, 0.8]), atol=EXACT)


def test_simultaneous_base_velocities_add(rig: ArticulatedAsset) -> None:
    trajectory = run(
        rig,
        seg(
            0.0,
            2.0,
            {"mode": "base_velocity", "axis_world": [1, 0, 0], "v_mps": 1.0},
            {"mode": "base_velocity", "axis_world": [0, 1, 0], "v_mps": 0.5},
        ),
        seg(1.0, 2.0, {"mode": "base_velocity", "axis_world": [-1, 0, 0], "v_mps": 0.25}),
    )
    assert trajectory.base_translation[-1].tolist() == pytest.approx([2.0 - 0.25, 1.0, 0.0], abs=EXACT)
    assert trajectory.has_base_motion()


def test_mode_set_flags(rig: ArticulatedAsset) -> None:
    trajectory = run(
        rig,
        seg(1.0, 1.5, {"mode": "mode_set", "name": "latched", "set": True}),
        seg(
            1.5,
            2.0,
            {"mode": "mode_set", "name": "latched", "set": False},
            {"mode": "mode_set", "name": "lit", "set": True},
        ),
    )
    t = trajectory.times
    assert all(m == {} for m in trajectory.modes[: at(t, 1.0)])
    assert all(m == {"latched": True} for m in trajectory.modes[at(t, 1.0) : at(t, 1.5)])
    assert all(m == {"latched": False, "lit": True} for m in trajectory.modes[at(t, 1.5) :])
    assert np.all(trajectory.q == trajectory.q[0]) and not trajectory.has_base_motion()  # no motion


# --- the time grid --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("fps", "duration", "last_t1", "frames"),
    [(30, 2.0, 1.0, 61), (24, 2.0, 2.0, 49), (30, 2.0, 2.5, 76), (24, 1.05, 1.0, 26), (24, 8.0, 3.0, 193)],
)
def test_frame_grid(rig: ArticulatedAsset, fps: int, duration: float, last_t1: float, frames: int) -> None:
    trajectory = execute(plan(seg(0.0, last_t1, velocity("hinge", 1.0)), duration=duration, fps=fps), rig)
    assert trajectory.fps == fps and trajectory.frame_count == frames
    assert np.array_equal(trajectory.times, np.arange(frames) / fps)
    assert trajectory.q.shape == (frames, len(rig.movable_joints))
    assert trajectory.base_translation.shape == (frames, 3) and len(trajectory.modes) == frames


def test_frame_zero_is_the_rest_pose(rig: ArticulatedAsset) -> None:
    trajectory = run(
        rig,
        seg(
            0.0,
            1.0,
            velocity("hinge", 3.0),
            position("door", 1.0),
            {"mode": "spring_return", "joint": "slide", "spring_k": 5.0, "rest_position": 0.4},
        ),
        seg(0.0, 1.0, velocity("shifted", 1.0), {"mode": "base_velocity", "axis_world": [1, 0, 0], "v_mps": 2.0}),
    )
    assert np.array_equal(trajectory.q[0], rig.rest_vector())
    assert trajectory.joint("shifted")[0] == 0.3 and trajectory.joint("follower")[0] == 0.2
    assert np.array_equal(trajectory.base_translation[0], np.zeros(3))
    assert trajectory.joint("shifted")[-1] == pytest.approx(1.3, abs=INTEGRATION)


def test_execute_is_deterministic(rig: ArticulatedAsset) -> None:
    segments = (
        seg(0.0, 1.0, velocity("hinge", 1.0, decay={"tau_s": 0.3, "min_omega_radps": 0.1})),
        seg(1.0, 2.0, {"mode": "spring_return", "joint": "hinge", "spring_k": 7.0}),
    )
    a, b = run(rig, *segments), run(rig, *segments)
    assert a.q.tobytes() == b.q.tobytes() and a.events == b.events
