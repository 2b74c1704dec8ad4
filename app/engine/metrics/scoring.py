"""Score one case in 3D (SPEC §6): align key states to predicted frames, then score per link.

State score = ``0.8 x mean(dynamic links) + 0.2 x mean(static links)`` (a group that
is empty drops out and the other gets weight 1); case score = mean over the K states.
A link missing from the prediction scores gIoU -1, PC 0, OccF1 0.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.metrics.alignment import Alignment, align
from app.engine.metrics.compiler import GroundTruth, KeyState
from app.engine.metrics.geometry import AssetGeometry
from app.engine.metrics.part_scores import floor_boxes, giou, link_occupancy, point_consistency, posed_boxes
from app.engine.metrics.results import METRICS_3D, WORST, CaseScores, LinkScores, StateScores
from app.engine.metrics.sequence import PoseSequence, trajectory_sequence
from app.engine.types import FloatArray

DYNAMIC_WEIGHT = 0.8
STATIC_WEIGHT = 0.2


def weighted(values: Sequence[float], dynamic: Sequence[bool]) -> float:
    """``0.8 x mean(dynamic) + 0.2 x mean(static)``, renormalised when a group is empty."""
    moving = [v for v, d in zip(values, dynamic, strict=True) if d]
    still = [v for v, d in zip(values, dynamic, strict=True) if not d]
    if moving and still:
        return DYNAMIC_WEIGHT * float(np.mean(moving)) + STATIC_WEIGHT * float(np.mean(still))
    return float(np.mean(moving or still))


def ground_truth_sequence(asset: ArticulatedAsset, truth: GroundTruth) -> PoseSequence:
    """The GT key states as a K-frame pose sequence (posed exactly like a prediction)."""
    full = trajectory_sequence(asset, truth.trajectory, source="ground truth")
    return full.take([state.frame for state in truth.key_states])


def _dynamic_mask(geometry: AssetGeometry, states: Sequence[KeyState]) -> np.ndarray:
    return np.array([[link in state.dynamic_links for link in geometry.links] for state in states], dtype=bool)


def similarity(
    geometry: AssetGeometry, truth: PoseSequence, prediction: PoseSequence, dynamic: np.ndarray
) -> FloatArray:
    """(K, T) state score of gIoU between GT state k and predicted frame t."""
    floor = geometry.extent_floor
    per_link = np.full((len(geometry.links), truth.frame_count, prediction.frame_count), WORST["P_gIoU"])
    for i, link in enumerate(geometry.links):
        if link not in prediction.poses:
            continue
        hull = geometry.geometry[link].hull
        gt_lo, gt_hi = floor_boxes(*posed_boxes(hull, truth.poses[link]), floor)
        pr_lo, pr_hi = floor_boxes(*posed_boxes(hull, prediction.poses[link]), floor)
        per_link[i] = giou(gt_lo[:, None], gt_hi[:, None], pr_lo[None], pr_hi[None])
    count_dynamic = dynamic.sum(axis=1)
    count_static = (~dynamic).sum(axis=1)
    moving = np.einsum("kl,lkt->kt", dynamic.astype(np.float64), per_link) / np.maximum(count_dynamic, 1)[:, None]
    still = np.einsum("kl,lkt->kt", (~dynamic).astype(np.float64), per_link) / np.maximum(count_static, 1)[:, None]
    both = (count_dynamic > 0) & (count_static > 0)
    single = np.where((count_dynamic > 0)[:, None], moving, still)
    return np.asarray(
        np.where(both[:, None], DYNAMIC_WEIGHT * moving + STATIC_WEIGHT * still, single), dtype=np.float64
    )


TIE_POINTS = 64
"""Corresponding sample points per link used to break exact gIoU ties."""


def tie_similarity(geometry: AssetGeometry, truth: PoseSequence, prediction: PoseSequence, dynamic: np.ndarray) -> FloatArray:
    """(K, T) in (0, 1]: how close the predicted link poses are to the GT ones, point for point.

    Used only to order frames whose gIoU state scores tie exactly: a part turning about its
    own symmetry axis (a wheel, a knob) keeps its box, so gIoU cannot tell the frames apart,
    but its corresponding surface samples move.
    """
    total = np.zeros((truth.frame_count, prediction.frame_count))
    weights = np.where(dynamic, DYNAMIC_WEIGHT, STATIC_WEIGHT)
    for i, link in enumerate(geometry.links):
        if link not in prediction.poses:
            continue
        points = geometry.geometry[link].samples[:TIE_POINTS]
        gt = np.einsum("kij,nj->kni", truth.poses[link][:, :3, :3], points) + truth.poses[link][:, None, :3, 3]
        pr = np.einsum("tij,nj->tni", prediction.poses[link][:, :3, :3], points) + prediction.poses[link][:, None, :3, 3]
        distance = np.sqrt(((gt[:, None] - pr[None]) ** 2).sum(axis=-1)).mean(axis=-1)
        total += weights[:, i][:, None] * distance / max(geometry.geometry[link].local_diagonal, 1e-9)
    return np.asarray(1.0 / (1.0 + total), dtype=np.float64)


Memo = dict[tuple[str, bytes, bytes], dict[str, float]]
"""Link values already computed in a case, keyed by (link, GT pose bytes, predicted pose bytes)."""


def _link_scores(
    geometry: AssetGeometry, link: str, dynamic: bool, gt_pose: FloatArray, pred_pose: FloatArray | None, memo: Memo
) -> LinkScores:
    if pred_pose is None:
        return LinkScores(link=link, dynamic=dynamic, missing=True, values={m: WORST[m] for m in METRICS_3D})
    key = (link, gt_pose.tobytes(), pred_pose.tobytes())
    if key in memo:
        return LinkScores(link=link, dynamic=dynamic, missing=False, values=dict(memo[key]))
    shape = geometry.geometry[link]
    floor = geometry.extent_floor
    gt_box = floor_boxes(*posed_boxes(shape.hull, gt_pose[None]), floor)
    pr_box = floor_boxes(*posed_boxes(shape.hull, pred_pose[None]), floor)
    values = {
        "P_gIoU": float(giou(gt_box[0][0], gt_box[1][0], pr_box[0][0], pr_box[1][0])),
        "P_PC": point_consistency(shape, gt_pose, pred_pose, geometry.link_scale(link)),
        "P_OccF1": link_occupancy(shape, gt_pose, pred_pose),
    }
    memo[key] = values
    return LinkScores(link=link, dynamic=dynamic, missing=False, values=values)


def score_state(
    geometry: AssetGeometry,
    state: KeyState,
    truth: PoseSequence,
    gt_index: int,
    prediction: PoseSequence,
    frame: int | None,
    memo: Memo | None = None,
) -> StateScores:
    """Per-link and state scores of GT state ``gt_index`` against predicted ``frame``."""
    memo = {} if memo is None else memo
    links = []
    for link in geometry.links:
        pose = None if frame is None or link not in prediction.poses else prediction.poses[link][frame]
        links.append(_link_scores(geometry, link, link in state.dynamic_links, truth.poses[link][gt_index], pose, memo))
    flags = [entry.dynamic for entry in links]
    values = {m: weighted([entry.values[m] for entry in links], flags) for m in METRICS_3D}
    return StateScores(
        index=state.index,
        phase=state.phase,
        gt_frame=state.frame,
        gt_time_s=state.time_s,
        pred_frame=frame,
        pred_time_s=None if frame is None else float(prediction.times[frame]),
        dynamic_links=list(state.dynamic_links),
        values=values,
        links=links,
    )


def match(geometry: AssetGeometry, truth: GroundTruth, gt_states: PoseSequence, prediction: PoseSequence) -> Alignment:
    """Align the K key states to the prediction's frames by gIoU state score."""
    dynamic = _dynamic_mask(geometry, truth.key_states)
    primary = similarity(geometry, gt_states, prediction, dynamic)
    return align(primary, truth.allow_equal, tie_break=tie_similarity(geometry, gt_states, prediction, dynamic))


def score_case(
    asset: ArticulatedAsset,
    geometry: AssetGeometry,
    truth: GroundTruth,
    prediction: PoseSequence,
    *,
    terminal_check: bool = False,
) -> CaseScores:
    """3D scores of ``prediction`` against the compiled ground truth.

    ``terminal_check`` also compares the last key state with the prediction's last
    frame and keeps, per metric, the minimum of that and the mean over states.
    """
    gt_states = ground_truth_sequence(asset, truth)
    alignment = match(geometry, truth, gt_states, prediction)
    last = prediction.frame_count - 1
    frames = [min(f, last) for f in alignment.frames]
    memo: Memo = {}
    states = [
        score_state(geometry, s, gt_states, k, prediction, frames[k], memo) for k, s in enumerate(truth.key_states)
    ]
    values = {m: float(np.mean([s.values[m] for s in states])) for m in METRICS_3D}
    terminal = None
    if terminal_check:
        end = score_state(geometry, truth.key_states[-1], gt_states, len(states) - 1, prediction, last, memo)
        terminal = dict(end.values)
        values = {m: min(values[m], terminal[m]) for m in METRICS_3D}
    return CaseScores(values=values, states=states, matched_frames=frames, padded=alignment.padded, terminal=terminal)
