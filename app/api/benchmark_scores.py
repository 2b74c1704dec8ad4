"""Scores of a benchmark batch: each finished case's prediction against its annotation (SPEC §5).

``POST /v1/benchmarks`` keeps the cases' annotations beside the batch
(``batches/<id>/benchmark.jsonl`` in storage). Scores are computed on request with the
engine's evaluator, the same code ``artimo bench`` runs, and kept per case
(``batches/<id>/scores/<job id>.json``) until the job's trajectory changes. A case whose
job failed or was cancelled scores as a missing prediction (the worst), as in the benchmark.
"""

from __future__ import annotations

import json
from pathlib import Path, PurePosixPath
from typing import Any

from pydantic import BaseModel

from app.core.config import Settings
from app.core.storage import Storage
from app.db.models import TERMINAL, Batch, Job, JobStatus
from app.engine.asset.cache import load_asset_cached
from app.engine.asset.model import ArticulatedAsset
from app.engine.metrics.annotation import Case
from app.engine.metrics.compiler import compile_case
from app.engine.metrics.evaluate import evaluate_case
from app.engine.metrics.geometry import AssetGeometry, build_geometry
from app.engine.metrics.results import METRICS_3D

TRAJECTORY = "trajectory.jsonl"


class StateResult(BaseModel):
    index: int
    phase: str
    gt_time_s: float
    pred_time_s: float | None
    values: dict[str, float]
    gt_joints: dict[str, float]
    pred_joints: dict[str, float]


class CaseResult(BaseModel):
    case_id: str
    job_id: str
    status: str
    values: dict[str, float] | None = None
    """Case scores per metric; ``None`` while the job runs or when the case does not fit its asset."""
    note: str | None = None
    states: list[StateResult] = []
    key: str | None = None
    """What the stored result was computed from (the trajectory's sha256, or the job status)."""


class BatchScores(BaseModel):
    batch_id: str
    summary: dict[str, float]
    """Mean per metric over the evaluated cases, and ``scored``: how many."""
    cases: list[CaseResult]


def annotations_key(batch_id: str) -> str:
    return f"batches/{batch_id}/benchmark.jsonl"


def store_annotations(storage: Storage, batch_id: str, cases: list[Case]) -> None:
    lines = "".join(case.model_dump_json() + "\n" for case in cases)
    storage.put_bytes(annotations_key(batch_id), lines.encode("utf-8"))


def read_annotations(storage: Storage, batch_id: str) -> dict[str, Case] | None:
    if not storage.exists(annotations_key(batch_id)):
        return None
    text = storage.get_bytes(annotations_key(batch_id)).decode("utf-8")
    cases = [Case.model_validate_json(line) for line in text.splitlines() if line.strip()]
    return {case.case_id: case for case in cases}


def _frames(path: Path) -> list[dict[str, Any]]:
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]


class _Assets:
    """Loaded assets and sampled geometry, once per asset within one request."""

    def __init__(self, storage: Storage, settings: Settings) -> None:
        self.storage, self.settings = storage, settings
        self.loaded: dict[str, tuple[ArticulatedAsset, AssetGeometry]] = {}

    def get(self, job: Job) -> tuple[ArticulatedAsset, AssetGeometry]:
        if job.asset.sha256 not in self.loaded:
            asset = load_asset_cached(self.storage.local_path(job.asset.storage_key), self.settings.engine_config().asset_cache_dir,
                                      name=PurePosixPath(job.asset.filename).stem)
            self.loaded[job.asset.sha256] = (asset, build_geometry(asset))
        return self.loaded[job.asset.sha256]


def _score(case: Case, job: Job, assets: _Assets, storage: Storage, key: str) -> CaseResult:
    asset, geometry = assets.get(job)
    trajectory = next((a for a in job.artifacts if a.name == TRAJECTORY), None) if job.status == JobStatus.succeeded else None
    path = storage.local_path(trajectory.storage_key) if trajectory is not None else None
    outcome = evaluate_case(case, asset, geometry, path)
    result = CaseResult(case_id=case.case_id, job_id=str(job.id), status=str(job.status), key=key,
                        note=outcome.error or (None if path else "no prediction: scored as missing"))
    if outcome.scores is None:
        return result
    truth = compile_case(case, asset)
    frames = _frames(path) if path else []
    states = []
    for state in outcome.scores.states:
        gt = {name: float(truth.trajectory.joint(name)[state.gt_frame]) for name in truth.trajectory.joint_names}
        pred = frames[min(state.pred_frame, len(frames) - 1)]["joint_angles"] if frames and state.pred_frame is not None else {}
        states.append(StateResult(index=state.index, phase=state.phase, gt_time_s=state.gt_time_s, pred_time_s=state.pred_time_s,
                                  values=state.values, gt_joints=gt, pred_joints={k: float(v) for k, v in pred.items()}))
    return result.model_copy(update={"values": dict(outcome.scores.values), "states": states})


def batch_scores(batch: Batch, cases: dict[str, Case], storage: Storage, settings: Settings) -> BatchScores:
    """Score every finished case (blocking: run in a thread)."""
    assets = _Assets(storage, settings)
    results = []
    for job in batch.jobs:
        case = cases.get(job.case_id or "")
        if case is None:
            continue
        if JobStatus(job.status) not in TERMINAL:
            results.append(CaseResult(case_id=case.case_id, job_id=str(job.id), status=str(job.status), note="not finished"))
            continue
        trajectory = next((a.sha256 for a in job.artifacts if a.name == TRAJECTORY), None)
        key = f"{job.status}:{trajectory}"
        stored = f"batches/{batch.id}/scores/{job.id}.json"
        if storage.exists(stored):
            cached = CaseResult.model_validate_json(storage.get_bytes(stored))
            if cached.key == key:
                results.append(cached)
                continue
        result = _score(case, job, assets, storage, key)
        storage.put_bytes(stored, result.model_dump_json().encode("utf-8"))
        results.append(result)
    scored = [r for r in results if r.values is not None]
    summary: dict[str, float] = {"scored": float(len(scored))}
    for metric in METRICS_3D:
        if scored:
            summary[metric] = sum(r.values[metric] for r in scored if r.values) / len(scored)
    return BatchScores(batch_id=str(batch.id), summary=summary, cases=results)
