"""preview.gif: evenly spaced frames of the whole trajectory, timed like it, seen from the side that moves."""

from __future__ import annotations

import io
import itertools
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.execute.executor import execute
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.checks import validate_plan
from app.engine.render.cues import window_poses
from app.engine.render.preview import FINAL_HOLD_MS, preview_frames, preview_view, render_preview_gif


def _trajectory(asset: ArticulatedAsset, joint: str, target: str, duration: float = 2.0) -> Trajectory:
    plan = {"meta": {"fps": 30, "duration_s": duration}, "timeline": [
        {"name": "move", "phase_type": "effect_motion", "t0": 0.0, "t1": duration,
         "controls": [{"mode": "joint_position", "joint": joint, "q_target_expr": target, "curve": "linear"}]}]}
    return execute(validate_plan(plan, asset).document, asset)


def _frames(gif: bytes) -> list[tuple[np.ndarray, int]]:
    out = []
    with Image.open(io.BytesIO(gif)) as image:
        for index in range(image.n_frames):
            image.seek(index)
            out.append((np.asarray(image.convert("RGB"), dtype=np.int16), int(image.info["duration"])))
    return out


@pytest.mark.parametrize(("count", "cap", "expected"), [(1, 60, [0]), (5, 60, [0, 1, 2, 3, 4]), (61, 3, [0, 30, 60])])
def test_frames_are_evenly_spaced_with_both_ends(count: int, cap: int, expected: list[int]) -> None:
    assert preview_frames(count, cap).tolist() == expected


def test_no_frames_is_an_error() -> None:
    with pytest.raises(RenderError, match="no frames"):
        preview_frames(0, 60)


def test_gif_plays_the_motion_in_real_time(examples_dir: Path) -> None:
    asset = load_asset(examples_dir / "pedal_bin")
    trajectory = _trajectory(asset, "lid_hinge", "lower_limit")
    frames = _frames(render_preview_gif(asset, trajectory, size=(160, 120), max_frames=21))
    assert len(frames) == 21 and frames[0][0].shape == (120, 160, 3)
    durations = [duration for _, duration in frames]
    assert durations[-1] == FINAL_HOLD_MS
    assert sum(durations[:-1]) == pytest.approx(1000 * (trajectory.frame_count - 1) / trajectory.fps, abs=10 * len(durations))
    changed = [float(np.abs(a - b).mean()) for (a, _), (b, _) in itertools.pairwise(frames)]
    assert all(change > 0 for change in changed), "the lid opens through every shown frame"


def test_the_view_faces_the_moving_parts(examples_dir: Path, load_partnet: Callable[[str], ArticulatedAsset]) -> None:
    bin_asset = load_asset(examples_dir / "pedal_bin")  # authored with its front (the pedal) toward +X
    pedal = _trajectory(bin_asset, "pedal_pivot", "upper_limit")
    pedal_view = preview_view(bin_asset, window_poses(bin_asset, pedal, preview_frames(pedal.frame_count, 10)))
    assert np.cos(np.radians(pedal_view.azimuth_deg)) > 0
    storage = load_partnet("storage_19179")  # PartNet-Mobility: drawers face -X
    drawer = _trajectory(storage, "joint_0", "0.5")  # a drawer slides out by 0.5 m
    drawer_view = preview_view(storage, window_poses(storage, drawer, preview_frames(drawer.frame_count, 10)))
    assert np.cos(np.radians(drawer_view.azimuth_deg)) < 0
