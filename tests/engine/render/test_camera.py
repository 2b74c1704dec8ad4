"""Camera math and framing against hand-computed values (no GL)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.engine.asset.kinematics import link_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.render.camera import FRAME_MARGIN, Camera, ViewSpec, asset_bounds, canonical_views, orbit_camera


def test_projection_matches_hand_values() -> None:
    # eye on +X looking at the origin, +Z up: screen right is +Y, screen up is +Z
    camera = Camera(eye=np.array([5.0, 0.0, 0.0]), target=np.zeros(3), fov_deg=90.0, width=200, height=100)
    assert camera.focal_px == pytest.approx(50.0)
    pixels, depth = camera.project(np.array([[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, -1.0, 0.5]]))
    np.testing.assert_allclose(pixels[0], [100.0, 50.0])
    np.testing.assert_allclose(pixels[1], [110.0, 50.0])  # +Y -> right
    np.testing.assert_allclose(pixels[2], [100.0, 40.0])  # +Z -> up (smaller y)
    np.testing.assert_allclose(pixels[3], [100.0 - 50.0 / 4.0, 50.0 - 50.0 * 0.5 / 4.0])  # depth 4
    np.testing.assert_allclose(depth, [5.0, 5.0, 5.0, 4.0])


def test_matrices_agree_with_project() -> None:
    camera = Camera(
        eye=np.array([1.0, -2.0, 1.5]),
        target=np.array([0.1, 0.2, 0.3]),
        fov_deg=35.0,
        width=320,
        height=240,
        near=0.1,
        far=20.0,
    )
    points = np.array([[0.0, 0.0, 0.0], [0.3, -0.2, 0.8], [-0.5, 0.4, 0.1]])
    clip = (camera.view_projection() @ np.c_[points, np.ones(3)].T).T
    ndc = clip[:, :3] / clip[:, 3:4]
    expected = np.stack([(ndc[:, 0] + 1) / 2 * 320, (1 - ndc[:, 1]) / 2 * 240], axis=1)
    pixels, depth = camera.project(points)
    np.testing.assert_allclose(pixels, expected, atol=1e-9)
    np.testing.assert_allclose(depth, clip[:, 3])  # clip w is the view depth


def test_orbit_angles_and_fov_framing() -> None:
    center = np.array([1.0, 2.0, 3.0])
    camera = orbit_camera(center, 2.0, azimuth_deg=90.0, elevation_deg=0.0, fov_deg=30.0, width=400, height=400)
    offset = camera.eye - center
    distance = FRAME_MARGIN * 1.0 / math.sin(math.radians(15.0))
    np.testing.assert_allclose(offset, [0.0, distance, 0.0], atol=1e-9)  # azimuth 90: on +Y
    high = orbit_camera(center, 2.0, azimuth_deg=0.0, elevation_deg=30.0)
    direction = (high.eye - center) / np.linalg.norm(high.eye - center)
    np.testing.assert_allclose(direction, [math.cos(math.radians(30)), 0.0, math.sin(math.radians(30))], atol=1e-12)


def test_fov_really_changes_the_camera() -> None:
    narrow = orbit_camera(np.zeros(3), 1.0, 0.0, 20.0, fov_deg=20.0, width=600, height=600)
    wide = orbit_camera(np.zeros(3), 1.0, 0.0, 20.0, fov_deg=50.0, width=600, height=600)
    ratio = np.linalg.norm(narrow.eye) / np.linalg.norm(wide.eye)
    assert ratio == pytest.approx(math.sin(math.radians(25)) / math.sin(math.radians(10)))
    # the bounding sphere (radius 0.5) just fits: its angular radius is a bit below half the fov
    for camera in (narrow, wide):
        sphere = math.asin(0.5 / np.linalg.norm(camera.eye))
        half = math.radians(camera.fov_deg / 2)
        assert 0.9 * half < sphere < half


def test_distance_scale_and_wide_images_use_the_narrower_fov() -> None:
    base = orbit_camera(np.zeros(3), 1.0, 0.0, 0.0, fov_deg=40.0, width=800, height=600)
    closer = orbit_camera(np.zeros(3), 1.0, 0.0, 0.0, fov_deg=40.0, distance_scale=0.5, width=800, height=600)
    assert np.linalg.norm(closer.eye) == pytest.approx(0.5 * np.linalg.norm(base.eye))
    tall = orbit_camera(np.zeros(3), 1.0, 0.0, 0.0, fov_deg=40.0, width=300, height=600)
    assert np.linalg.norm(tall.eye) > np.linalg.norm(base.eye)  # the horizontal fov is the limit


def test_canonical_views_are_the_paper_bank() -> None:
    views = canonical_views()
    assert [v.azimuth_deg for v in views] == [0.0, 90.0, 180.0, 270.0]
    assert all(v == ViewSpec(v.azimuth_deg, 20.0, 35.0, 1.0) for v in views)


def test_top_view_is_well_defined_and_bad_cameras_raise() -> None:
    top = orbit_camera(np.zeros(3), 1.0, 0.0, 90.0)
    pixels, _ = top.project(np.array([[0.0, 0.0, 0.0]]))
    np.testing.assert_allclose(pixels[0], [400.0, 300.0])
    with pytest.raises(RenderError):
        Camera(eye=np.zeros(3), target=np.zeros(3))
    with pytest.raises(RenderError):
        Camera(eye=np.array([0.0, 0.0, 2.0]), target=np.zeros(3))  # up parallel to the view
    with pytest.raises(RenderError):
        orbit_camera(np.zeros(3), 1.0, 0.0, 0.0, fov_deg=0.0)
    with pytest.raises(RenderError):
        orbit_camera(np.zeros(3), 1.0, 0.0, 0.0, distance_scale=0.0)


def test_asset_bounds_single_frame_and_union(door_scene: ArticulatedAsset) -> None:
    center, diag = asset_bounds(door_scene)
    # body x in [-0.5, 0.5], closed door panel x in [0.52, 0.56]
    np.testing.assert_allclose(center, [0.03, 0.0, 0.0], atol=1e-9)
    assert diag == pytest.approx(float(np.linalg.norm([1.06, 1.0, 1.0])))
    frames = link_poses(door_scene, {"hinge": np.array([0.0, math.pi / 2])})
    union_center, union_diag = asset_bounds(door_scene, frames)
    opened = asset_bounds(door_scene, {k: v[1] for k, v in frames.items()})
    assert union_diag >= max(diag, opened[1]) - 1e-12
    assert union_center[0] > center[0]  # the open door sticks out along +X
