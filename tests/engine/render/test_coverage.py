"""Coverage-view selection (geometric) and keyframe framing: the moving link shows, its start and end stay in frame."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
from PIL import Image

from app.engine.agents.expectations import Expectations
from app.engine.agents.keyframes import KEYFRAME_SIZE, critic_keyframes, window_poses
from app.engine.agents.summaries import critic_cases
from app.engine.asset.loader import load_asset
from app.engine.execute.executor import execute
from app.engine.plan.schema import Plan
from app.engine.render.camera import ViewSpec, canonical_views
from app.engine.render.coverage import choose_view, framing_camera, on_bank, visible_pixels


def _slide_tray_far(examples_dir: Path):  # type: ignore[no-untyped-def]
    asset = load_asset(examples_dir / "oven")
    upper = asset.joints["tray_slide"].upper
    plan = Plan.model_validate({"meta": {"fps": 30, "duration_s": 2.0}, "timeline": [
        {"name": "door", "phase_type": "effect_motion", "t0": 0.0, "t1": 1.0, "controls": [{"mode": "joint_position", "joint": "door_hinge", "q_target_expr": "upper_limit"}]},
        {"name": "tray", "phase_type": "effect_motion", "t0": 1.0, "t1": 2.0, "controls": [{"mode": "joint_position", "joint": "tray_slide", "q_target_rad": upper}]}]})
    trajectory = execute(plan, asset)
    case = next(c for c in critic_cases(asset, plan, trajectory, Expectations(motions=())) if c.joint == "tray_slide")
    return asset, trajectory, case


def test_keyframe_camera_keeps_the_start_and_end_of_the_motion_in_frame(examples_dir: Path) -> None:
    asset, trajectory, case = _slide_tray_far(examples_dir)
    poses = window_poses(asset, trajectory, case.head_frame, case.tail_frame)
    for view in canonical_views():
        camera = framing_camera(asset, poses, view, KEYFRAME_SIZE)
        vertices = asset.links[case.link].vertices()
        for pose in (poses[case.link][0], poses[case.link][-1]):
            pixels, depth = camera.project(vertices @ pose[:3, :3].T + pose[:3, 3])
            assert (depth > 0).all()
            assert (pixels >= 0).all() and (pixels[:, 0] <= KEYFRAME_SIZE[0]).all() and (pixels[:, 1] <= KEYFRAME_SIZE[1]).all(), view


def test_geometric_choice_shows_the_link_over_its_motion(examples_dir: Path) -> None:
    asset, trajectory, case = _slide_tray_far(examples_dir)
    poses = window_poses(asset, trajectory, case.head_frame, case.tail_frame)
    choice = choose_view(asset, poses, case.link)
    assert choice.covered and choice.visible_px > 0 and on_bank(choice.view)
    scores = {view.azimuth_deg: visible_pixels(asset, poses, case.link, view) for view in canonical_views()}
    assert scores[choice.view.azimuth_deg] == max(scores.values())
    assert scores[180.0] < scores[0.0]  # from behind the oven the tray is hidden; its front faces +X
    head, tail = critic_keyframes(asset, trajectory, case, choice.view)
    for image in (head, tail):
        with Image.open(io.BytesIO(image.png)) as picture:
            assert picture.size == KEYFRAME_SIZE and np.asarray(picture).std() > 5


def test_bank_membership() -> None:
    assert on_bank(ViewSpec(30.0, 45.0, 25.0, 1.5)) and not on_bank(ViewSpec(15.0, 20.0)) and not on_bank(ViewSpec(0.0, 20.0, 35.0, 0.9))
