"""Motion cues: the one rotation convention, the tracked point, and keyframe drawing."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image
from support.render_scenes import DOOR_HINGE, joint_sweep

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.render import gl_backend
from app.engine.render.camera import ViewSpec, view_camera
from app.engine.render.cues import draw_rotation_glyph, draw_track, render_keyframes, window_poses
from app.engine.render.motion import MotionCue, motion_cue, tracked_point
from app.engine.render.palette import link_colors


def _signed_area(pixels: np.ndarray) -> float:
    """Shoelace area in pixel coordinates (y down): < 0 means the path turns counter-clockwise on screen."""
    x, y = pixels[:, 0], pixels[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


@pytest.mark.parametrize(("elevation", "start", "end", "badge", "sense"), [
    (40.0, 0.0, 1.2, "DOT-OUT", "ccw"),    # +Z toward a camera above
    (40.0, 1.2, 0.0, "CROSS-IN", "cw"),    # negative motion: only the axis flips (-Z), never the word as well
    (-40.0, 0.0, 1.2, "CROSS-IN", "cw"),   # seen from below, the same motion turns the other way
    (-40.0, 1.2, 0.0, "DOT-OUT", "ccw"),
])  # fmt: skip
def test_rotation_badge_matches_the_apparent_screen_rotation(
    door_scene: ArticulatedAsset, elevation: float, start: float, end: float, badge: str, sense: str
) -> None:
    trajectory = joint_sweep(door_scene, "hinge", start, end)
    camera = view_camera(door_scene, ViewSpec(20.0, elevation), 400, 300)
    frames = np.arange(trajectory.frame_count)
    poses = window_poses(door_scene, trajectory, frames)
    q = trajectory.joint_values()
    cue = motion_cue(
        door_scene,
        "door",
        {"hinge": q["hinge"][0]},
        {"hinge": q["hinge"][-1]},
        {k: v[0] for k, v in poses.items()},
        camera,
    )
    assert cue.kind == "rotation" and cue.joint == "hinge"
    assert cue.badge == badge and cue.screen_rotation == sense
    assert cue.axis_label == ("+Z" if end > start else "-Z")
    np.testing.assert_allclose(cue.pivot, DOOR_HINGE, atol=1e-12)
    _, track = tracked_point(door_scene, "door", poses["door"], camera)
    # close the arc through the projected pivot: the loop's orientation is the apparent rotation sense
    (pivot_px,), _ = camera.project(cue.pivot[None])
    loop = np.vstack([track, pivot_px])
    assert (_signed_area(loop) < 0) == (sense == "ccw")


def test_translation_cue_and_static_links(cabinet: ArticulatedAsset) -> None:
    trajectory = joint_sweep(cabinet, "drawer_slide", 0.0, 0.5)
    camera = view_camera(cabinet, ViewSpec(90.0, 20.0), 400, 300)  # on +Y, the drawer slides toward the camera
    poses = window_poses(cabinet, trajectory, np.array([0, trajectory.frame_count - 1]))
    q = trajectory.joint_values()
    head = {k: v[0] for k, v in q.items()}
    tail = {k: v[-1] for k, v in q.items()}
    cue = motion_cue(cabinet, "drawer", head, tail, {k: v[0] for k, v in poses.items()}, camera)
    assert cue.kind == "translation" and cue.axis_label == "+Y" and cue.toward_viewer
    assert cue.screen_direction[1] > 0.9  # toward a camera above: down the screen
    side = view_camera(cabinet, ViewSpec(0.0, 0.0), 400, 300)  # on +X: the drawer slides to the right
    cue = motion_cue(cabinet, "drawer", head, tail, {k: v[0] for k, v in poses.items()}, side)
    np.testing.assert_allclose(cue.screen_direction, [1.0, 0.0], atol=1e-9)
    assert motion_cue(cabinet, "lid", head, tail, {k: v[0] for k, v in poses.items()}, camera).kind == "static"
    assert motion_cue(cabinet, "base", head, tail, {k: v[0] for k, v in poses.items()}, camera).joint is None


def test_keyframes_draw_cues_on_the_projected_track(door_scene: ArticulatedAsset) -> None:
    trajectory = joint_sweep(door_scene, "hinge", 0.0, 1.2)
    every_frame = window_poses(door_scene, trajectory, np.arange(trajectory.frame_count))
    camera = view_camera(door_scene, ViewSpec(20.0, 30.0), 400, 300, every_frame)  # frames the whole swing
    head, tail = render_keyframes(door_scene, trajectory, "door", 0, trajectory.frame_count - 1, camera)
    assert head.size == tail.size == (400, 300)
    color = np.array(link_colors(door_scene)["door"])
    frames = np.unique(np.rint(np.linspace(0, trajectory.frame_count - 1, trajectory.frame_count)).astype(int))
    poses = window_poses(door_scene, trajectory, frames)
    ids, depth, names = gl_backend.render_id_depth(door_scene, {k: v[0] for k, v in poses.items()}, camera)
    _, track = tracked_point(door_scene, "door", poses["door"], camera, ids, depth, names.index("door"))
    pixels = np.asarray(tail).astype(int)
    end_x, end_y = np.floor(track[-1]).astype(int)
    assert np.abs(pixels[end_y, end_x] - color).max() <= 2  # filled circle at the end
    start_x, start_y = np.floor(track[0]).astype(int)
    assert pixels[start_y, start_x].tolist() == [255, 255, 255]  # hollow circle at the start
    plain = gl_backend.render_rgba(door_scene, {k: v[-1] for k, v in poses.items()}, camera)[..., :3].astype(int)
    middle_x, middle_y = np.floor(track[len(track) // 2]).astype(int)
    assert np.abs(pixels[middle_y, middle_x] - plain[middle_y, middle_x]).max() > 30  # the polyline
    changed = np.abs(pixels - plain).max(axis=2) > 30
    assert (
        changed.sum() > changed[max(0, end_y - 12) : end_y + 12, max(0, end_x - 12) : end_x + 12].sum() + 500
    )  # glyph, box, legend
    head_again, tail_again = render_keyframes(door_scene, trajectory, "door", 0, trajectory.frame_count - 1, camera)
    assert head_again.tobytes() == head.tobytes() and tail_again.tobytes() == tail.tobytes()


def test_keyframe_arguments_are_checked(door_scene: ArticulatedAsset) -> None:
    trajectory = joint_sweep(door_scene, "hinge", 0.0, 1.2)
    camera = view_camera(door_scene, ViewSpec(20.0, 30.0), 200, 150)
    with pytest.raises(RenderError):
        render_keyframes(door_scene, trajectory, "door", 5, 2, camera)
    with pytest.raises(RenderError):
        render_keyframes(door_scene, trajectory, "door", 0, trajectory.frame_count, camera)
    with pytest.raises(RenderError):
        render_keyframes(door_scene, trajectory, "nope", 0, 3, camera)


def test_glyph_drawing_is_pure_and_oriented() -> None:
    image = Image.new("RGB", (200, 200), (255, 255, 255))
    draw_track(image, np.array([[20.0, 20.0], [100.0, 60.0], [180.0, 20.0]]), (200, 30, 30))
    pixels = np.asarray(image).astype(int)
    assert tuple(pixels[20, 180]) == (200, 30, 30)  # filled end
    assert tuple(pixels[20, 20]) == (255, 255, 255)  # hollow start
    cue = MotionCue("l", "j", "rotation", 1.0, np.array([0.0, 0.0, 1.0]), "+Z", np.zeros(3), True, np.zeros(2))
    ccw = Image.new("RGB", (200, 200), (255, 255, 255))
    draw_rotation_glyph(ccw, (100, 90), 50, cue, (30, 30, 200))
    cw = Image.new("RGB", (200, 200), (255, 255, 255))
    draw_rotation_glyph(cw, (100, 90), 50, MotionCue(**{**cue.__dict__, "toward_viewer": False}), (30, 30, 200))
    assert ccw.tobytes() != cw.tobytes()
    assert np.asarray(ccw)[90, 100].tolist() != [255, 255, 255]  # the badge sits in the centre
