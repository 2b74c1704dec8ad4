"""What each example plan does, checked on the executed trajectory and with forward kinematics."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation
from support.example_runs import Run, first_motion_time, first_time_at, last_motion_time, run_example

from app.engine.asset.kinematics import base_transforms, link_poses
from app.engine.execute.executor import execute
from app.engine.plan.checks import validate_plan

LIMIT_TOL = 1e-9
SPIN_TOL = 1e-6
PEDAL_DELAY_S = 0.10
BUTTON_DELAY_S = 0.05
WHEELS = ("wheel_front_left", "wheel_front_right", "wheel_rear_left", "wheel_rear_right")
SLIP_TOL_MPS = 1e-4
"""Rolling without slipping: the contact point's world speed stays below 0.1 mm/s."""


def _link_point(run: Run, link: str, local: tuple[float, float, float]) -> np.ndarray:
    """(f, 3) world path of a point fixed in ``link`` (link-frame coordinates, metres)."""
    pose = run.poses[link]
    return pose[:, :3, :3] @ np.asarray(local) + pose[:, :3, 3]


def test_pedal_bin_press_pedal_opens_lid_after_the_linkage_delay() -> None:
    run = run_example("pedal_bin", "plan.json")
    lid, pedal = run.asset.joints["lid_hinge"], run.asset.joints["pedal_pivot"]
    pedal_starts = first_motion_time(run, "pedal_pivot")
    lid_starts = first_motion_time(run, "lid_hinge")
    assert pedal_starts == 0.0
    assert lid_starts >= pedal_starts + PEDAL_DELAY_S
    assert first_time_at(run, "pedal_pivot", pedal.upper) < lid_starts, "pedal fully pressed before the lid moves"
    assert run.q("lid_hinge")[-1] == pytest.approx(lid.lower, abs=LIMIT_TOL)  # open = -1.4 rad
    # the pedal is held down for as long as the lid is open (a pedal bin closes when released)
    lid_open = np.abs(run.q("lid_hinge") - lid.rest) > 0.0
    assert np.allclose(run.q("pedal_pivot")[lid_open], pedal.upper, atol=LIMIT_TOL)
    front_edge = _link_point(run, "lid", (0.296, 0.0, 0.02))
    foot_plate = _link_point(run, "pedal", (0.105, 0.0, 0.0))
    assert front_edge[-1, 2] - front_edge[0, 2] > 0.25, "the lid's front edge rises well above the bin"
    assert foot_plate[-1, 2] < foot_plate[0, 2] - 0.03, "the foot plate goes down when pressed"


def test_microwave_button_releases_the_door_and_springs_back() -> None:
    run = run_example("microwave", "plan.json")
    button, door = run.asset.joints["release_button_slide"], run.asset.joints["door_hinge"]
    pressed_at = first_time_at(run, "release_button_slide", button.upper)
    door_starts = first_motion_time(run, "door_hinge")
    assert door_starts >= first_motion_time(run, "release_button_slide") + BUTTON_DELAY_S
    assert pressed_at < door_starts
    returned_at = first_time_at(run, "release_button_slide", button.rest, tol=LIMIT_TOL, after=pressed_at)
    assert returned_at <= 1.0, "the spring returns the button within its control_release phase"
    after = run.times >= returned_at
    assert np.all(run.q("release_button_slide")[after] == button.rest), "the button stays out once released"
    assert run.q("door_hinge")[run.times == returned_at][0] < door.upper, "button returns while the door still swings"
    assert run.q("door_hinge")[-1] == pytest.approx(door.upper, abs=LIMIT_TOL)
    free_edge = _link_point(run, "door", (0.03, 0.355, 0.145))
    assert free_edge[-1, 0] - free_edge[0, 0] > 0.25, "the door's free edge swings out to the front"


def test_microwave_turntable_spins_up_then_turns_steadily() -> None:
    run = run_example("microwave", "plan_spin_turntable.json")
    angle = run.q("turntable_spin")
    rate = np.diff(angle) * run.trajectory.fps
    assert np.all(rate > 0.0), "counter-clockwise seen from above, never reversing"
    steady = run.times[1:] > 0.5 + 1e-9
    np.testing.assert_allclose(rate[steady], 0.6, atol=SPIN_TOL)
    assert angle[-1] == pytest.approx(0.5 * 0.6 / 2 + 4.5 * 0.6, abs=1e-6)


@pytest.mark.parametrize(
    ("plan_file", "joint", "link", "expected_m"),
    [
        ("plan.json", "drawer_bottom_slide", "drawer_bottom", 0.175),
        ("plan_open_top_drawer.json", "drawer_top_slide", "drawer_top", 0.35),
    ],
)
def test_cabinet_drawer_slides_straight_out_of_its_bay(
    plan_file: str, joint: str, link: str, expected_m: float
) -> None:
    run = run_example("cabinet", plan_file)
    origin = run.poses[link][:, :3, 3]
    shift = origin[-1] - origin[0]
    np.testing.assert_allclose(shift, [expected_m, 0.0, 0.0], atol=1e-12)
    assert np.all(np.diff(origin[:, 0]) >= 0.0), "the drawer only moves outwards"


def test_cabinet_knob_unlatches_before_the_door_opens_and_returns_while_it_swings() -> None:
    run = run_example("cabinet", "plan_open_door.json")
    knob, door = run.asset.joints["latch_knob_turn"], run.asset.joints["door_hinge"]
    unlatched_at = first_time_at(run, "latch_knob_turn", knob.lower)
    door_starts = first_motion_time(run, "door_hinge")
    assert first_motion_time(run, "latch_knob_turn") == 0.0
    assert unlatched_at < door_starts, "the door moves only once the knob has turned"
    knob_back = first_time_at(run, "latch_knob_turn", knob.rest, tol=LIMIT_TOL, after=unlatched_at)
    assert door_starts < knob_back < last_motion_time(run, "door_hinge"), "the knob returns while the door opens"
    assert run.q("latch_knob_turn")[-1] == knob.rest
    assert run.q("door_hinge")[-1] == pytest.approx(door.lower, abs=LIMIT_TOL)
    knob_centre = run.poses["latch_knob"][:, :3, 3]
    assert knob_centre[-1, 0] - knob_centre[0, 0] > 0.4, "the free edge (with the knob) swings out to the front"


def test_oven_tray_slides_out_only_after_the_door_is_open() -> None:
    run = run_example("oven", "plan.json")
    door, tray = run.asset.joints["door_hinge"], run.asset.joints["tray_slide"]
    tray_moving = np.abs(run.q("tray_slide") - tray.rest) > 0.0
    assert tray_moving.any()
    assert np.allclose(run.q("door_hinge")[tray_moving], door.upper, atol=LIMIT_TOL), (
        "door open whenever the tray is out"
    )
    assert first_time_at(run, "door_hinge", door.upper) < first_motion_time(run, "tray_slide")
    tray_front = run.poses["tray"][:, :3, 3]
    np.testing.assert_allclose(tray_front[-1] - tray_front[0], [0.32, 0.0, 0.0], atol=1e-12)
    door_top = _link_point(run, "door", (0.0, 0.0, 0.505))
    assert door_top[-1, 2] < run.poses["tray"][-1, 2, 3], "the open door lies below the pulled-out tray"


def contact_slip(run: Run, wheel: str, radius: float) -> np.ndarray:
    """(f - 2,) world speed (m/s) of the wheel's lowest point, frames 1 .. f-2.

    Rigid-body velocity from FK poses by central differences: v = v_centre + w x (p - centre)
    with p = centre - radius * z (the lowest point of a wheel rolling on the plane z = 0).
    """
    pose = run.poses[wheel]
    dt = 2.0 / run.trajectory.fps
    centre = pose[:, :3, 3]
    v_centre = (centre[2:] - centre[:-2]) / dt
    relative = pose[2:, :3, :3] @ np.transpose(pose[:-2, :3, :3], (0, 2, 1))
    omega = Rotation.from_matrix(relative).as_rotvec() / dt
    lever = np.broadcast_to([0.0, 0.0, -radius], omega.shape)
    return np.linalg.norm(v_centre + np.cross(omega, lever), axis=1)


def _wheel_radius(run: Run, wheel: str) -> float:
    vertices = run.asset.links[wheel].vertices()
    return float(np.max(np.hypot(vertices[:, 0], vertices[:, 2])))


@pytest.mark.parametrize(
    ("plan_file", "distance_m"), [("plan.json", 0.5), ("plan_roll_to_stop.json", 0.5 * (1.0 - np.exp(-4.0)))]
)
def test_toy_car_wheels_roll_without_slipping(plan_file: str, distance_m: float) -> None:
    run = run_example("toy_car", plan_file)
    np.testing.assert_allclose(run.trajectory.base_translation[-1], [distance_m, 0.0, 0.0], atol=1e-12)
    moving = np.linalg.norm(np.diff(run.trajectory.base_translation, axis=0), axis=1) > 0.0
    for wheel in WHEELS:
        radius = _wheel_radius(run, wheel)
        assert radius == pytest.approx(0.03, abs=1e-9)
        assert run.poses[wheel][:, 2, 3] == pytest.approx(radius), "the wheel centre stays one radius above the ground"
        slip = contact_slip(run, wheel, radius)
        assert slip.max() < SLIP_TOL_MPS, f"{wheel} slips at {slip.max():.2e} m/s"
        # and the wheel does turn while the car moves (a dragged, locked wheel would 'slip' at the car speed)
        turning = np.abs(np.diff(run.q(f"{wheel}_axle"))) > 0.0
        assert np.array_equal(turning, moving)


def test_rolling_check_catches_a_wrong_wheel_sign() -> None:
    run = run_example("toy_car", "plan.json")
    raw = run.raw
    flipped = {**raw, "timeline": [dict(s) for s in raw["timeline"]]}
    flipped["timeline"][0]["controls"] = [
        {**c, "omega_radps": -c["omega_radps"]} if c.get("joint") == "wheel_front_right_axle" else c
        for c in raw["timeline"][0]["controls"]
    ]
    trajectory = execute(validate_plan(flipped, run.asset).document, run.asset)
    base = base_transforms(trajectory.base_translation, trajectory.base_rotation_xyzw)
    poses = link_poses(run.asset, trajectory.joint_values(), base=base)
    wrong = Run(run.asset, run.plan, flipped, trajectory, poses, ())
    slip = contact_slip(wrong, "wheel_front_right", 0.03)
    assert slip.max() == pytest.approx(2 * 0.25, rel=1e-6), "reversed wheel: contact point moves at twice the car speed"
    assert contact_slip(wrong, "wheel_front_left", 0.03).max() < SLIP_TOL_MPS
