"""JSON records of evaluated cases and the summary over them (deterministic key order).

Cases with ``status == "case_error"`` have no scores and are left out of the means;
every other case (including ``no_prediction`` and ``prediction_error``, scored worst)
counts. ``std`` is the population standard deviation.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from app.engine.metrics.annotation import MOTION_TYPES, Case
from app.engine.metrics.evaluate import CaseOutcome
from app.engine.metrics.results import METRICS_2D, METRICS_3D

STATUSES = ("scored", "no_prediction", "prediction_error", "case_error")


def case_record(case: Case, outcome: CaseOutcome) -> dict[str, Any]:
    """The JSON object of one case (scores ``None`` when the case itself is broken)."""
    scores = outcome.scores
    record: dict[str, Any] = {
        "case_id": case.case_id,
        "asset": case.asset,
        "motion_type": case.motion_type,
        "status": outcome.status,
        "prediction": outcome.prediction_source,
    }
    values = {} if scores is None else scores.values
    for metric in METRICS_3D:
        record[metric] = values.get(metric)
    for metric in METRICS_2D:
        if metric in values:
            record[metric] = values[metric]
    record["matched_frames"] = None if scores is None else scores.matched_frames
    record["padded"] = False if scores is None else scores.padded
    record["error"] = outcome.error
    record["notes"] = list(outcome.notes)
    record["terminal"] = None if scores is None else scores.terminal
    record["states"] = [] if scores is None else [s.model_dump(mode="json") for s in scores.states]
    return record


def metric_names(records: Sequence[dict[str, Any]]) -> tuple[str, ...]:
    """3D metrics, plus the 2D ones when any record has them."""
    with_2d = any(r.get(m) is not None for r in records for m in METRICS_2D)
    return METRICS_3D + (METRICS_2D if with_2d else ())


def _stats(records: Sequence[dict[str, Any]], metrics: tuple[str, ...]) -> dict[str, Any]:
    out: dict[str, Any] = {"n": len(records)}
    for metric in metrics:
        values = [float(r[metric]) for r in records if r.get(metric) is not None]
        out[metric] = {"mean": float(np.mean(values)), "std": float(np.std(values))} if values else None
    return out


def summarise(records: Sequence[dict[str, Any]], settings: dict[str, Any]) -> dict[str, Any]:
    """Overall and per-motion-type means (and stds) of every metric."""
    metrics = metric_names(records)
    counted = [r for r in records if r["status"] != "case_error"]
    by_type = {
        t: _stats([r for r in counted if r["motion_type"] == t], metrics)
        for t in MOTION_TYPES
        if any(r["motion_type"] == t for r in counted)
    }
    return {
        "cases": len(records),
        "counted": len(counted),
        "by_status": {s: sum(1 for r in records if r["status"] == s) for s in STATUSES},
        "metrics": list(metrics),
        "overall": _stats(counted, metrics),
        "by_motion_type": by_type,
        "settings": settings,
    }
