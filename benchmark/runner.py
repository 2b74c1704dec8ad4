"""Batch evaluation of a benchmark: ``evaluate(cases_file, assets_root, pred_root, out_json)``.

Layout: ``cases_file`` is JSON Lines (one case per line, ``asset`` a folder under
``assets_root``); the prediction of a case is ``pred_root/<case_id>/trajectory.jsonl`` or,
failing that, ``pred_root/<case_id>/animation.glb``.

Outputs: ``out_json`` holds ``{"summary": ..., "cases": [...]}`` with per-case,
per-state and per-link scores and the matched frames. It is byte-identical for
identical inputs, whatever ``jobs`` is; wall-clock timings therefore go to a sidecar,
``<out_json stem>.timing.json``.
"""

from __future__ import annotations

import json
import logging
import multiprocessing
import time
from collections import OrderedDict
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from tqdm import tqdm

from app.engine.asset.cache import load_asset_cached
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import AssetError, MetricError
from app.engine.files import atomic_write_text
from app.engine.metrics.annotation import Case
from app.engine.metrics.evaluate import CaseOutcome, EvaluationOptions, evaluate_case
from app.engine.metrics.geometry import AssetGeometry, build_geometry
from app.engine.metrics.prediction import NodeMap, find_prediction, read_node_map
from benchmark.cases import read_cases
from benchmark.records import case_record, summarise

logger = logging.getLogger(__name__)

ASSET_CACHE_SIZE = 16
"""Assets (with their sampled geometry) kept per process."""
_ASSETS: OrderedDict[str, tuple[ArticulatedAsset, AssetGeometry]] = OrderedDict()


@dataclass(frozen=True)
class CaseJob:
    """Everything a worker needs for one case (picklable)."""

    index: int
    case: Case
    asset_dir: str
    prediction: str | None
    options: EvaluationOptions
    cache_dir: str | None = None
    """The asset disk cache (``app.engine.asset.cache``); None: load every asset afresh."""


def cached_asset(folder: str, cache_dir: str | None = None) -> tuple[ArticulatedAsset, AssetGeometry]:
    """Load (or reuse) an asset and its per-link reference geometry (through the disk cache when given)."""
    if folder in _ASSETS:
        _ASSETS.move_to_end(folder)
        return _ASSETS[folder]
    asset = load_asset_cached(folder, None if cache_dir is None else Path(cache_dir))
    entry = (asset, build_geometry(asset))
    _ASSETS[folder] = entry
    while len(_ASSETS) > ASSET_CACHE_SIZE:
        _ASSETS.popitem(last=False)
    return entry


def run_job(job: CaseJob) -> tuple[int, dict[str, Any], dict[str, float]]:
    """Evaluate one case: (index, deterministic record, timings in seconds)."""
    start = time.perf_counter()
    try:
        asset, geometry = cached_asset(job.asset_dir, job.cache_dir)
    except (AssetError, MetricError) as exc:
        outcome = CaseOutcome(status="case_error", scores=None, error=f"asset {job.case.asset}: {exc.message}")
        return job.index, case_record(job.case, outcome), {"total": time.perf_counter() - start}
    loaded = time.perf_counter()
    prediction = None if job.prediction is None else Path(job.prediction)
    outcome = evaluate_case(job.case, asset, geometry, prediction, job.options)
    timing = {"load_asset": loaded - start, **outcome.timing_s, "total": time.perf_counter() - start}
    return job.index, case_record(job.case, outcome), timing


def _jobs(cases: list[Case], assets_root: Path, pred_root: Path, options: EvaluationOptions, cache_dir: Path | None) -> list[CaseJob]:
    jobs = []
    for index, case in enumerate(cases):
        found = find_prediction(pred_root / case.case_id)
        jobs.append(
            CaseJob(
                index=index,
                case=case,
                asset_dir=str(assets_root / case.asset),
                prediction=None if found is None else str(found),
                options=options,
                cache_dir=None if cache_dir is None else str(cache_dir),
            )
        )
    return jobs


def run_jobs(jobs: list[CaseJob], workers: int) -> list[tuple[dict[str, Any], dict[str, float]]]:
    """Run every job (in ``workers`` processes when > 1); results in job order."""
    results: dict[int, tuple[dict[str, Any], dict[str, float]]] = {}
    bar = tqdm(total=len(jobs), desc="evaluate", unit="case", disable=None)
    try:
        if workers <= 1:
            for job in jobs:
                index, record, timing = run_job(job)
                results[index] = (record, timing)
                bar.update(1)
        else:
            context = multiprocessing.get_context("spawn")
            with ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
                ordered = sorted(jobs, key=lambda j: (j.asset_dir, j.index))  # same asset -> warm caches
                futures = [pool.submit(run_job, job) for job in ordered]
                for future in as_completed(futures):
                    index, record, timing = future.result()
                    results[index] = (record, timing)
                    bar.update(1)
    finally:
        bar.close()
    return [results[job.index] for job in jobs]


def _settings(cases_file: Path, node_map: NodeMap | None, options: EvaluationOptions) -> dict[str, Any]:
    from app.engine.metrics.compiler import GT_FPS
    from app.engine.metrics.geometry import POINTS_PER_LINK
    from app.engine.metrics.part_scores import OCC_RESOLUTION

    return {
        "cases_file": cases_file.name,
        "gt_fps": GT_FPS,
        "points_per_link": POINTS_PER_LINK,
        "voxel_resolution": OCC_RESOLUTION,
        "with_2d": options.with_2d,
        "terminal_check": options.terminal_check,
        "node_map": None if node_map is None else {"nodes": dict(node_map.nodes), "up_axis": node_map.up_axis},
    }


def evaluate(
    cases_file: str | Path,
    assets_root: str | Path,
    pred_root: str | Path,
    out_json: str | Path,
    *,
    node_map: str | Path | None = None,
    with_2d: bool = False,
    jobs: int = 1,
    terminal_check: bool = False,
    cache_dir: str | Path | None = None,
) -> dict[str, Any]:
    """Evaluate every case of ``cases_file`` and write ``out_json`` (+ the timing sidecar).

    Parameters
    ----------
    node_map
        JSON file mapping GLB node names to link names (see
        :mod:`app.engine.metrics.prediction`), for third-party GLBs.
    with_2d
        Also compute P_MaskIoU, P_BoundaryF1 and P_ContourCD (needs the renderer).
    jobs
        Worker processes (``spawn`` start method: a calling script needs the usual
        ``if __name__ == "__main__":`` guard); the output does not depend on it.
    cache_dir
        The asset disk cache (what ``artimo`` uses); ``None`` loads every asset afresh.

    Returns
    -------
    The written document ``{"summary": ..., "cases": [...]}``.

    Raises
    ------
    MetricError
        Unreadable cases file or node map.
    """
    cases_path, out_path = Path(cases_file), Path(out_json)
    cases = read_cases(cases_path)
    mapping = None if node_map is None else read_node_map(node_map)
    options = EvaluationOptions(with_2d=with_2d, terminal_check=terminal_check, node_map=mapping)
    start = time.perf_counter()
    cache = None if cache_dir is None else Path(cache_dir)
    results = run_jobs(_jobs(cases, Path(assets_root), Path(pred_root), options, cache), max(1, int(jobs)))
    wall = time.perf_counter() - start
    records = [record for record, _ in results]
    document = {"summary": summarise(records, _settings(cases_path, mapping, options)), "cases": records}
    atomic_write_text(out_path, json.dumps(document, indent=2, allow_nan=False) + "\n")
    timing = {
        "wall_s": wall,
        "jobs": max(1, int(jobs)),
        "cases": [{"case_id": r["case_id"], "timing_s": t} for r, t in results],
    }
    atomic_write_text(timing_path(out_path), json.dumps(timing, indent=2) + "\n")
    logger.info("evaluated %d cases in %.2f s -> %s", len(records), wall, out_path)
    return document


def timing_path(out_json: str | Path) -> Path:
    """Where :func:`evaluate` writes the wall-clock timings for ``out_json``."""
    path = Path(out_json)
    return path.with_name(f"{path.stem}.timing.json")
