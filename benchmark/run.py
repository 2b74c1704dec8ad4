"""``bench run``: animate every case with a provider (in parallel), then evaluate.

Each case runs the same engine entry point the service uses (``run_pipeline``) into
``OUT/<case_id>/``; a case the agent refuses or fails leaves no prediction and is scored
worst by the evaluator. ``OUT/runs.json`` records each case's outcome and wall time.
"""

from __future__ import annotations

import json
import logging
import multiprocessing
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from tqdm import tqdm

from app.engine.config import EngineConfig
from app.engine.errors import EngineError
from app.engine.files import atomic_write_text
from app.engine.metrics.annotation import Case
from app.engine.pipeline import PipelineRequest, run_pipeline
from app.engine.providers.registry import ProviderConfig, make_roles
from benchmark.cases import read_cases

logger = logging.getLogger(__name__)

RUNS_FILE = "runs.json"


@dataclass(frozen=True)
class RunJob:
    case: Case
    asset_dir: str
    out_dir: str
    provider: str
    provider_config: ProviderConfig
    config: EngineConfig


def run_one(job: RunJob) -> dict[str, Any]:
    """Animate one case; never raises for engine failures (they are recorded)."""
    began = time.perf_counter()
    record: dict[str, Any] = {"case_id": job.case.case_id, "asset": job.case.asset, "prompt": job.case.prompt}
    try:
        roles = make_roles(job.provider, job.provider_config, job.config)
        result = run_pipeline(PipelineRequest(asset=Path(job.asset_dir), prompt=job.case.prompt), roles=roles, config=job.config, out_dir=job.out_dir)
        record.update(status="ok", final_state=result.report.final_state)
    except EngineError as exc:
        record.update(status="failed", error_kind=type(exc).__name__, error=str(exc))
    record["seconds"] = round(time.perf_counter() - began, 3)
    return record


def animate_cases(
    cases_file: Path, assets_root: Path, out_dir: Path, *, provider: str = "offline", provider_config: ProviderConfig | None = None,
    config: EngineConfig | None = None, jobs: int = 1, progress: bool = True,
) -> list[dict[str, Any]]:
    """Run the pipeline on every case into ``out_dir/<case_id>``; returns the per-case records (case order)."""
    cases = read_cases(cases_file)
    out_dir.mkdir(parents=True, exist_ok=True)
    work = [RunJob(case, str(assets_root / case.asset), str(out_dir / case.case_id), provider, provider_config or ProviderConfig(), config or EngineConfig())
            for case in cases]
    records: dict[str, dict[str, Any]] = {}
    bar = tqdm(total=len(work), desc="animate", unit="case", disable=not progress)
    if jobs <= 1:
        for job in work:
            records[job.case.case_id] = run_one(job)
            bar.update()
    else:
        with ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("spawn")) as pool:
            futures = [pool.submit(run_one, job) for job in work]
            for future in as_completed(futures):
                record = future.result()
                records[record["case_id"]] = record
                bar.update()
    bar.close()
    ordered = [records[case.case_id] for case in cases]
    atomic_write_text(out_dir / RUNS_FILE, json.dumps(ordered, indent=2) + "\n")
    return ordered
