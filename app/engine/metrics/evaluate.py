"""Evaluate one benchmark case end to end: compile, load the prediction, score (3D, 2D).

Outcomes (``CaseOutcome.status``):

- ``scored``: the prediction was read and scored;
- ``no_prediction``: there is no prediction file; scored as a prediction in which every
  link is missing (the worst score), never skipped;
- ``prediction_error``: the prediction exists but cannot be read; scored worst too, with
  the reason in ``error``;
- ``case_error``: the case itself does not fit its asset; no scores (the benchmark, not
  the method, is at fault).
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import MetricError
from app.engine.metrics.annotation import Case
from app.engine.metrics.compiler import GroundTruth, compile_case
from app.engine.metrics.geometry import AssetGeometry
from app.engine.metrics.prediction import NodeMap, load_prediction
from app.engine.metrics.results import CaseScores
from app.engine.metrics.scoring import score_case
from app.engine.metrics.sequence import PoseSequence, empty_sequence

logger = logging.getLogger(__name__)

Status = Literal["scored", "no_prediction", "prediction_error", "case_error"]


@dataclass(frozen=True)
class EvaluationOptions:
    """Switches of one evaluation run (all off by default, as in the paper's protocol)."""

    with_2d: bool = False
    terminal_check: bool = False
    node_map: NodeMap | None = None


@dataclass(frozen=True, eq=False)
class CaseOutcome:
    """What evaluating one case produced; ``timing_s`` is wall time per stage (not deterministic)."""

    status: Status
    scores: CaseScores | None
    error: str | None = None
    prediction_source: str | None = None
    notes: tuple[str, ...] = ()
    timing_s: dict[str, float] = field(default_factory=dict)


def _timed(timing: dict[str, float], stage: str, start: float) -> float:
    now = time.perf_counter()
    timing[stage] = timing.get(stage, 0.0) + (now - start)
    return now


def _read(
    prediction: Path | None, asset: ArticulatedAsset, options: EvaluationOptions
) -> tuple[PoseSequence, Status, str | None]:
    if prediction is None:
        return empty_sequence(asset, "none", "no prediction file"), "no_prediction", None
    try:
        return load_prediction(prediction, asset, node_map=options.node_map), "scored", None
    except MetricError as exc:
        return empty_sequence(asset, prediction.name, "unreadable prediction"), "prediction_error", exc.message


def _score(
    asset: ArticulatedAsset,
    geometry: AssetGeometry,
    truth: GroundTruth,
    sequence: PoseSequence,
    options: EvaluationOptions,
    timing: dict[str, float],
) -> CaseScores:
    start = time.perf_counter()
    scores = score_case(asset, geometry, truth, sequence, terminal_check=options.terminal_check)
    start = _timed(timing, "metrics_3d", start)
    if options.with_2d:
        from app.engine.metrics.scores2d import add_2d_scores  # needs the optional renderer

        scores = add_2d_scores(asset, geometry, truth, sequence, scores, terminal_check=options.terminal_check)
        _timed(timing, "metrics_2d", start)
    return scores


def evaluate_case(
    case: Case,
    asset: ArticulatedAsset,
    geometry: AssetGeometry,
    prediction: Path | None,
    options: EvaluationOptions | None = None,
) -> CaseOutcome:
    """Score ``prediction`` (a file, or ``None`` when the method produced nothing) for ``case``.

    Raises
    ------
    RenderError
        2D scoring was requested and the renderer is unavailable.
    """
    options = options or EvaluationOptions()
    timing: dict[str, float] = {}
    start = time.perf_counter()
    try:
        truth = compile_case(case, asset)
    except MetricError as exc:
        return CaseOutcome(status="case_error", scores=None, error=exc.message, timing_s=timing)
    start = _timed(timing, "compile", start)
    sequence, status, error = _read(prediction, asset, options)
    _timed(timing, "prediction", start)
    try:
        scores = _score(asset, geometry, truth, sequence, options, timing)
    except MetricError as exc:
        return CaseOutcome(status="case_error", scores=None, error=exc.message, timing_s=timing)
    if status != "scored":
        unmatched = [s.model_copy(update={"pred_frame": None, "pred_time_s": None}) for s in scores.states]
        scores = scores.model_copy(update={"matched_frames": None, "padded": False, "states": unmatched})
    notes = truth.notes + sequence.notes
    if error is not None:
        logger.info("case %s: %s", case.case_id, error)
    return CaseOutcome(
        status=status,
        scores=scores,
        error=error,
        prediction_source=None if prediction is None else prediction.name,
        notes=tuple(notes),
        timing_s=timing,
    )
