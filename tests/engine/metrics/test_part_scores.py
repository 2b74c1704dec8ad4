"""gIoU, PC and OccF1 on hand-computable boxes and point sets; the seeded per-link sampling."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from scipy.spatial import cKDTree

from app.engine.metrics.geometry import LinkGeometry, build_geometry, hull_vertices, sample_surface
from app.engine.metrics.part_scores import (
    chamfer,
    floor_boxes,
    giou,
    link_occupancy,
    occupancy_f1,
    point_consistency,
    posed_boxes,
    transform_points,
)

UNIT = (np.zeros(3), np.ones(3))


def _box(lo, hi):
    return np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)


def _pose(translation=(0.0, 0.0, 0.0), angle_z=0.0):
    pose = np.eye(4)
    c, s = math.cos(angle_z), math.sin(angle_z)
    pose[:2, :2] = [[c, -s], [s, c]]
    pose[:3, 3] = translation
    return pose


@pytest.mark.parametrize(
    ("other", "expected"),
    [
        (UNIT, 1.0),
        (_box([0.5, 0, 0], [1.5, 1, 1]), 1 / 3),  # I = 0.5, U = 1.5, C = 1.5
        (_box([2, 0, 0], [3, 1, 1]), 0 - (3 - 2) / 3),  # disjoint: IoU 0, C = 3, U = 2
        (_box([0, 0, 0], [2, 2, 2]), 1 / 8),  # nested
        (_box([10, 0, 0], [11, 1, 1]), 2 / 11 - 1),  # far apart: tends to -1
    ],
)
def test_giou_on_boxes(other, expected):
    assert giou(*UNIT, *other) == pytest.approx(expected, abs=1e-12)


def test_identical_boxes_score_exactly_one():
    lo, hi = np.array([0.1, -0.3, 0.7]), np.array([0.4, 0.2, 1.9])
    assert giou(lo, hi, lo.copy(), hi.copy()) == 1.0


def test_flat_boxes_are_floored_so_distant_coplanar_squares_do_not_match():
    first = floor_boxes(*_box([0, 0, 0], [1, 1, 0]), 1e-3)
    second = floor_boxes(*_box([5, 0, 0], [6, 1, 0]), 1e-3)
    assert first[1][2] - first[0][2] == pytest.approx(1e-3)
    assert giou(*first, *second) < -0.5  # the authors' evaluator gives 1.0 here


def test_posed_boxes_of_a_rotated_cube():
    hull = hull_vertices(np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]))
    lo, hi = posed_boxes(hull, np.stack([_pose((1.0, 2.0, 3.0)), _pose(angle_z=math.pi / 4)]))
    assert np.allclose(lo[0], [0.5, 1.5, 2.5]) and np.allclose(hi[0], [1.5, 2.5, 3.5])
    assert np.allclose(hi[1] - lo[1], [math.sqrt(2), math.sqrt(2), 1.0])


def test_hull_keeps_every_extreme_vertex():
    points = np.random.default_rng(3).normal(size=(500, 3))
    hull = hull_vertices(points)
    assert hull.shape[0] < 500
    rotation = _pose(angle_z=0.7)[:3, :3]
    assert np.allclose((points @ rotation.T).min(axis=0), (hull @ rotation.T).min(axis=0))


def _grid_link(spacing=1.0, count=6):
    axis = np.arange(count) * spacing
    samples = np.array([[x, y, z] for x in axis for y in axis for z in axis])
    return LinkGeometry(
        name="grid", samples=samples, hull=hull_vertices(samples), local_diagonal=1.0, tree=cKDTree(samples)
    )


def test_chamfer_of_a_half_step_shift_is_half_a_step():
    link = _grid_link()
    assert chamfer(link, np.eye(4), _pose((0.5, 0.0, 0.0))) == pytest.approx(0.5)
    assert point_consistency(link, np.eye(4), _pose((0.5, 0.0, 0.0)), scale=10.0) == pytest.approx(math.exp(-1.0))


def test_chamfer_is_invariant_to_a_common_rigid_motion():
    link = _grid_link(spacing=0.3)
    common = _pose((0.2, -1.0, 0.4), angle_z=0.9)
    moved = _pose((0.05, 0.02, 0.0), angle_z=0.1)
    assert chamfer(link, common, common @ moved) == pytest.approx(chamfer(link, np.eye(4), moved), abs=1e-12)


def test_chamfer_with_a_scaled_prediction_uses_world_points():
    link = _grid_link()
    scaled = np.diag([2.0, 2.0, 2.0, 1.0])
    world = link.samples * 2.0
    expected = 0.5 * (cKDTree(link.samples).query(world)[0].mean() + cKDTree(world).query(link.samples)[0].mean())
    assert chamfer(link, np.eye(4), scaled) == pytest.approx(expected)


def test_identical_poses_score_exactly_one():
    link = _grid_link(spacing=0.37)
    pose = _pose((0.3, 0.1, -0.2), angle_z=1.3)
    assert point_consistency(link, pose, pose.copy(), scale=1.0) == 1.0
    assert link_occupancy(link, pose, pose.copy()) == 1.0


def test_occupancy_f1_on_hand_counted_cells():
    a = np.array([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
    b = np.array([[0.0, 0.0, 0.0]])
    assert occupancy_f1(a, b) == pytest.approx(2 * 1 / (2 + 1))
    assert occupancy_f1(a, a.copy()) == 1.0
    assert occupancy_f1(np.zeros((4, 3)), np.full((4, 3), 5.0)) == 0.0


def test_occupancy_grid_is_32_cells_per_axis():
    line = np.stack([np.linspace(0.0, 1.0, 1000), np.zeros(1000), np.zeros(1000)], axis=1)
    # shifted by one cell: the two sets share 31 of their 32 occupied cells along x
    cell = (1.0 + 0.04) / 32 / 1.0
    shifted = line + np.array([cell * 1.0001, 0.0, 0.0])
    assert 0.9 < occupancy_f1(line, shifted) < 1.0


def test_transform_points_matches_matrix_product():
    points = np.random.default_rng(0).normal(size=(50, 3))
    pose = _pose((1.0, 2.0, 3.0), angle_z=0.4)
    assert np.allclose(transform_points(pose, points), points @ pose[:3, :3].T + pose[:3, 3])


def test_sampling_is_seeded_by_asset_and_link_not_the_global_rng():
    vertices = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 2.0]])
    faces = np.array([[0, 1, 2], [0, 1, 3]])
    np.random.seed(1)
    first = sample_surface(vertices, faces, 256, "asset:link:256")
    np.random.seed(2)
    second = sample_surface(vertices, faces, 256, "asset:link:256")
    assert np.array_equal(first, second)
    assert not np.array_equal(first, sample_surface(vertices, faces, 256, "asset:other:256"))
    on_big = np.count_nonzero(first[:, 2] > 1e-12)  # the triangle in xz has twice the area
    assert 140 < on_big < 200


def test_asset_geometry_samples_every_visual_link(cabinet):
    geometry = build_geometry(cabinet)
    assert geometry.links == cabinet.visual_links
    assert all(g.samples.shape == (2048, 3) for g in geometry.geometry.values())
    lid = geometry.geometry["lid"]
    assert np.all(lid.samples.min(axis=0) >= [-1.0 - 1e-9, 0.0 - 1e-9, 0.0 - 1e-9])
    assert lid.local_diagonal == pytest.approx(math.sqrt(4 + 1 + 0.01))
    assert geometry.link_scale("knob") == pytest.approx(0.3)  # 0.1 x 0.2 x 0.2 box (rounded cylinder)
    assert dataclasses.replace(geometry, object_diagonal=100.0).link_scale("knob") == pytest.approx(5.0)  # floored
    assert build_geometry(cabinet).geometry["lid"].samples.tobytes() == lid.samples.tobytes()
