"""2D variants of the metrics (SPEC §6): per-link rasterised masks of matched state pairs.

One camera for every state of a case, GT and prediction alike: azimuth 0, elevation 20
deg, vertical fov 35 deg, 256 x 256 pixels, framing the bounding sphere of the ground
truth's rest pose and key states. Masks are full per-link silhouettes rasterised by
:func:`app.engine.render.gl_backend.render_link_masks` (a link hidden behind another still
has its whole shape). The frames matched in 3D are reused. State scores use the same
dynamic/static weighting as 3D; a link missing from the prediction scores MaskIoU 0,
BoundaryF1 0, ContourCD 1; a link absent from both images (off-screen) counts as agreeing.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from app.engine.asset.kinematics import rest_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.metrics.compiler import GroundTruth
from app.engine.metrics.geometry import AssetGeometry
from app.engine.metrics.masks import Mask, score_masks
from app.engine.metrics.part_scores import posed_boxes
from app.engine.metrics.results import METRICS_2D, WORST, CaseScores, StateScores
from app.engine.metrics.scoring import ground_truth_sequence, weighted
from app.engine.metrics.sequence import PoseSequence
from app.engine.render.camera import Camera, orbit_camera
from app.engine.types import FloatArray, Transform

MASK_SIZE_PX = 256
VIEW_AZIMUTH_DEG = 0.0
VIEW_ELEVATION_DEG = 20.0
VIEW_FOV_DEG = 35.0


def framing(asset: ArticulatedAsset, geometry: AssetGeometry, truth: PoseSequence) -> tuple[FloatArray, float]:
    """(centre (3,), diagonal) of the world box of the rest pose and every GT key state."""
    rest = rest_poses(asset)
    corners = []
    for link in geometry.links:
        stack = np.concatenate([rest[link][None], truth.poses[link]], axis=0)
        lo, hi = posed_boxes(geometry.geometry[link].hull, stack)
        corners.extend([lo.min(axis=0), hi.max(axis=0)])
    low, high = np.min(corners, axis=0), np.max(corners, axis=0)
    return 0.5 * (low + high), float(np.linalg.norm(high - low))


def mask_camera(asset: ArticulatedAsset, geometry: AssetGeometry, truth: PoseSequence) -> Camera:
    """The fixed 2D camera of a case (see the module docstring)."""
    center, diagonal = framing(asset, geometry, truth)
    return orbit_camera(
        center, diagonal, VIEW_AZIMUTH_DEG, VIEW_ELEVATION_DEG, VIEW_FOV_DEG, 1.0, MASK_SIZE_PX, MASK_SIZE_PX
    )


def _masks(
    asset: ArticulatedAsset, poses: Mapping[str, Transform], camera: Camera, links: list[str]
) -> dict[str, Mask]:
    from app.engine.render.gl_backend import render_link_masks  # EGL/moderngl only when 2D is asked for

    return render_link_masks(asset, poses, camera, links) if links else {}


def _state_2d(
    asset: ArticulatedAsset,
    geometry: AssetGeometry,
    state: StateScores,
    gt_poses: dict[str, Transform],
    pred: dict[str, Transform],
    camera: Camera,
) -> StateScores:
    gt_masks = _masks(asset, gt_poses, camera, list(geometry.links))
    changed = [link for link in geometry.links if link in pred and not np.array_equal(pred[link], gt_poses[link])]
    pred_masks = {link: gt_masks[link] for link in geometry.links if link in pred}
    pred_masks.update(_masks(asset, pred, camera, changed))
    links = []
    for entry in state.links:
        if entry.link in pred_masks:
            scores = score_masks(gt_masks[entry.link], pred_masks[entry.link])
            extra = {"P_MaskIoU": scores.mask_iou, "P_BoundaryF1": scores.boundary_f1, "P_ContourCD": scores.contour_cd}
        else:
            extra = {m: WORST[m] for m in METRICS_2D}
        links.append(entry.model_copy(update={"values": {**entry.values, **extra}}))
    flags = [entry.dynamic for entry in links]
    values = {**state.values, **{m: weighted([e.values[m] for e in links], flags) for m in METRICS_2D}}
    return state.model_copy(update={"values": values, "links": links})


def _pred_poses(sequence: PoseSequence, frame: int | None) -> dict[str, Transform]:
    if frame is None:
        return {}
    return {link: pose[frame] for link, pose in sequence.poses.items()}


def add_2d_scores(
    asset: ArticulatedAsset,
    geometry: AssetGeometry,
    truth: GroundTruth,
    prediction: PoseSequence,
    scores: CaseScores,
    *,
    terminal_check: bool = False,
) -> CaseScores:
    """``scores`` with P_MaskIoU, P_BoundaryF1 and P_ContourCD added at link, state and case level.

    Raises
    ------
    RenderError
        No EGL / moderngl.
    """
    gt_states = ground_truth_sequence(asset, truth)
    camera = mask_camera(asset, geometry, gt_states)
    states = []
    for k, state in enumerate(scores.states):
        gt_poses = {link: gt_states.poses[link][k] for link in geometry.links}
        states.append(_state_2d(asset, geometry, state, gt_poses, _pred_poses(prediction, state.pred_frame), camera))
    values = dict(scores.values)
    values.update({m: float(np.mean([s.values[m] for s in states])) for m in METRICS_2D})
    terminal = scores.terminal
    if terminal_check and terminal is not None:
        last = len(states) - 1
        gt_poses = {link: gt_states.poses[link][last] for link in geometry.links}
        end = _state_2d(
            asset, geometry, states[last], gt_poses, _pred_poses(prediction, prediction.frame_count - 1), camera
        )
        terminal = {**terminal, **{m: end.values[m] for m in METRICS_2D}}
        values.update(
            {m: max(values[m], terminal[m]) if m == "P_ContourCD" else min(values[m], terminal[m]) for m in METRICS_2D}
        )
    return scores.model_copy(update={"values": values, "states": states, "terminal": terminal})
