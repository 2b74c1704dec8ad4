"""2D mask metrics on hand-made masks, checked against brute-force definitions."""

from __future__ import annotations

import numpy as np
import pytest

from app.engine.metrics.masks import boundary, mask_iou, score_masks


def _square(top: int, left: int, size: int = 10, shape: tuple[int, int] = (40, 40)) -> np.ndarray:
    mask = np.zeros(shape, dtype=bool)
    mask[top : top + size, left : left + size] = True
    return mask


def _reference(gt: np.ndarray, pred: np.ndarray) -> tuple[float, float]:
    """(BoundaryF1 with 2 px tolerance, ContourCD / union-box diagonal) by brute force."""
    a, b = np.argwhere(boundary(gt)), np.argwhere(boundary(pred))
    distances = np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2)
    to_gt, to_pred = distances.min(axis=0), distances.min(axis=1)
    precision, recall = np.mean(to_gt <= 2.0), np.mean(to_pred <= 2.0)
    f1 = 2 * precision * recall / (precision + recall) if precision + recall else 0.0
    rows, cols = np.nonzero(gt | pred)
    diagonal = np.hypot(rows.max() - rows.min() + 1, cols.max() - cols.min() + 1)
    return float(f1), float(0.5 * (to_gt.mean() + to_pred.mean()) / diagonal)


def test_identical_masks_score_one_one_zero():
    mask = _square(5, 7)
    scores = score_masks(mask, mask.copy())
    assert (scores.mask_iou, scores.boundary_f1, scores.contour_cd) == (1.0, 1.0, 0.0)


def test_boundary_is_the_mask_minus_its_erosion():
    edge = boundary(_square(5, 5, size=4))
    assert edge.sum() == 12 and not edge[6:8, 6:8].any()
    assert boundary(np.ones((5, 5), dtype=bool)).sum() == 0  # the image border is not a boundary


@pytest.mark.parametrize(("dy", "dx"), [(0, 1), (0, 3), (2, 2), (6, 0), (15, 15)])
def test_shifted_squares_match_the_brute_force_definitions(dy, dx):
    gt, pred = _square(5, 5), _square(5 + dy, 5 + dx)
    scores = score_masks(gt, pred)
    f1, cd = _reference(gt, pred)
    assert scores.mask_iou == pytest.approx(np.sum(gt & pred) / np.sum(gt | pred))
    assert scores.boundary_f1 == pytest.approx(f1)
    assert scores.contour_cd == pytest.approx(cd)


def test_one_pixel_shift_is_within_the_boundary_tolerance():
    scores = score_masks(_square(5, 5), _square(5, 6))
    assert scores.mask_iou == pytest.approx(90 / 110)
    assert scores.boundary_f1 == 1.0 and 0.0 < scores.contour_cd < 0.05


def test_empty_masks():
    empty, full = np.zeros((40, 40), dtype=bool), _square(2, 2)
    both = score_masks(empty, empty)
    one = score_masks(full, empty)
    assert (both.mask_iou, both.boundary_f1, both.contour_cd) == (1.0, 1.0, 0.0)
    assert (one.mask_iou, one.boundary_f1, one.contour_cd) == (0.0, 0.0, 1.0)
    assert mask_iou(empty, full) == 0.0
