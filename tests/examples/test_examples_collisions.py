"""No example part interpenetrates another, at rest or anywhere along the example plans."""

from __future__ import annotations

import functools

import numpy as np
import pytest
from support.example_runs import EXAMPLE_NAMES, all_plans, example_asset, run_example
from support.penetration import Contact, PenetrationChecker

from app.engine.asset.kinematics import link_poses, rest_poses

FRAME_STRIDE = 5


@functools.cache
def _checker(name: str) -> PenetrationChecker:
    return PenetrationChecker(example_asset(name))


def _describe(contacts: list[Contact]) -> str:
    return "; ".join(
        f"{c.point_link} inside {c.part_link}/{c.part} by {c.depth_m * 1000:.2f} mm at {c.point_world}"
        for c in contacts[:3]
    )


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_rest_pose_is_free_of_contacts(name: str) -> None:
    contacts = _checker(name).contacts(rest_poses(example_asset(name)))
    assert not contacts, _describe(contacts)


@pytest.mark.parametrize(("name", "plan_file"), all_plans())
def test_plan_is_free_of_contacts_at_every_fifth_frame(name: str, plan_file: str) -> None:
    run = run_example(name, plan_file)
    checker = _checker(name)
    frames = sorted({*range(0, run.trajectory.frame_count, FRAME_STRIDE), run.trajectory.frame_count - 1})
    for frame in frames:
        contacts = checker.contacts({link: pose[frame] for link, pose in run.poses.items()})
        assert not contacts, f"frame {frame} (t={run.times[frame]:.3f} s): {_describe(contacts)}"


@pytest.mark.parametrize(
    ("name", "joint", "value", "culprits"),
    [
        ("oven", "tray_slide", -0.2, {("tray", "door")}),  # pulling the tray out through the closed door
        ("cabinet", "door_hinge", 0.1, {("door", "body")}),  # swinging the door into the carcass
        ("pedal_bin", "lid_hinge", 0.2, {("lid", "body")}),  # pushing the lid down into the bin
        ("cabinet", "drawer_top_slide", -0.05, {("drawer_top", "body")}),  # drawer pushed through the back wall
    ],
)
def test_checker_reports_parts_driven_into_each_other(
    name: str, joint: str, value: float, culprits: set[tuple[str, str]]
) -> None:
    asset = example_asset(name)
    poses = {link: pose[0] for link, pose in link_poses(asset, {joint: np.array([value])}).items()}
    contacts = _checker(name).contacts(poses)
    pairs = {(c.point_link, c.part_link) for c in contacts} | {(c.part_link, c.point_link) for c in contacts}
    assert culprits <= pairs
    assert max(c.depth_m for c in contacts) > 1e-3
