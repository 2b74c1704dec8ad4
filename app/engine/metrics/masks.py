"""2D per-link mask metrics (SPEC §6 "2D variants"), numpy + scipy.ndimage only.

- ``mask_iou``: |G n P| / |G u P|.
- Boundary of a mask: the mask minus its 3x3 erosion (the image border does not count
  as a boundary).
- ``boundary_f1``: precision = share of predicted boundary pixels within
  ``BOUNDARY_TOLERANCE_PX`` (Euclidean) of the GT boundary, recall the converse, F1 their
  harmonic mean; both boundaries empty -> 1, one empty -> 0.
- ``contour_cd``: mean of the two directed mean boundary-to-boundary distances (exact
  Euclidean distance transform), divided by the diagonal of the union mask's inclusive
  bounding box; both empty -> 0, one empty -> 1 (lower is better, range [0, 1]).

Distances are computed on a crop around the union of the two masks (every boundary pixel
lies inside it, so the distances are exact) to keep the transform small.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy import ndimage

BOUNDARY_TOLERANCE_PX = 2.0
CROP_MARGIN_PX = 2

Mask = NDArray[np.bool_]
"""(H, W) bool, True = covered by the link."""

_SQUARE = np.ones((3, 3), dtype=bool)


@dataclass(frozen=True)
class MaskScores:
    mask_iou: float
    boundary_f1: float
    contour_cd: float


def boundary(mask: Mask) -> Mask:
    """Pixels of ``mask`` with a 3x3 neighbour outside it (the image border is not outside)."""
    eroded = np.asarray(ndimage.binary_erosion(mask, structure=_SQUARE, border_value=1), dtype=bool)
    edge: Mask = np.logical_and(mask, np.logical_not(eroded))
    return edge


def mask_iou(gt: Mask, pred: Mask) -> float:
    union = int(np.count_nonzero(gt | pred))
    return 1.0 if union == 0 else int(np.count_nonzero(gt & pred)) / union


def _crop(gt: Mask, pred: Mask) -> tuple[Mask, Mask, float]:
    """Both masks cut to the union's box (+ margin) and the union box's inclusive diagonal (px)."""
    rows = np.flatnonzero((gt | pred).any(axis=1))
    cols = np.flatnonzero((gt | pred).any(axis=0))
    diagonal = float(np.hypot(rows[-1] - rows[0] + 1, cols[-1] - cols[0] + 1))
    r0, r1 = max(rows[0] - CROP_MARGIN_PX, 0), rows[-1] + CROP_MARGIN_PX + 1
    c0, c1 = max(cols[0] - CROP_MARGIN_PX, 0), cols[-1] + CROP_MARGIN_PX + 1
    return gt[r0:r1, c0:c1], pred[r0:r1, c0:c1], diagonal


def score_masks(gt: Mask, pred: Mask) -> MaskScores:
    """All three 2D metrics of one link (masks of the same shape)."""
    iou = mask_iou(gt, pred)
    if not (gt.any() or pred.any()):
        return MaskScores(mask_iou=iou, boundary_f1=1.0, contour_cd=0.0)
    gt_crop, pred_crop, diagonal = _crop(gt, pred)
    edge_gt = boundary(gt_crop)
    edge_pred = boundary(pred_crop)
    if not (edge_gt.any() and edge_pred.any()):
        empty_both = not (edge_gt.any() or edge_pred.any())
        return MaskScores(mask_iou=iou, boundary_f1=1.0 if empty_both else 0.0, contour_cd=0.0 if empty_both else 1.0)
    if np.array_equal(edge_gt, edge_pred):
        return MaskScores(mask_iou=iou, boundary_f1=1.0, contour_cd=0.0)
    to_gt = ndimage.distance_transform_edt(~edge_gt)[edge_pred]
    to_pred = ndimage.distance_transform_edt(~edge_pred)[edge_gt]
    precision = float(np.count_nonzero(to_gt <= BOUNDARY_TOLERANCE_PX)) / to_gt.size
    recall = float(np.count_nonzero(to_pred <= BOUNDARY_TOLERANCE_PX)) / to_pred.size
    f1 = 0.0 if precision + recall == 0.0 else 2.0 * precision * recall / (precision + recall)
    chamfer = 0.5 * (float(to_gt.mean()) + float(to_pred.mean()))
    return MaskScores(mask_iou=iou, boundary_f1=f1, contour_cd=min(chamfer / diagonal, 1.0))
