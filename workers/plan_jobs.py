"""Run a plan job: the submitted Plan.json is executed and exported, no agent roles run.

The API stored the plan as ``plans/<sha256>.json`` and put the hash in the job's options
(:data:`app.api.plan_jobs.PLAN_OPTION`); :func:`app.engine.run.run_plan` writes plan.json,
trajectory.jsonl, animation.glb and a report.json whose ``provider`` is ``plan``.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

from app.core.config import Settings
from app.core.storage import LocalStorage
from app.engine.asset.cache import load_asset_cached
from app.engine.report import RunReport
from app.engine.run import run_plan
from workers.observer import JobObserver

logger = logging.getLogger(__name__)

PLAN_OPTION = "plan_sha256"
"""Same name as ``app.api.plan_jobs.PLAN_OPTION`` (workers do not import the API)."""


def is_plan_job(options: dict[str, Any]) -> bool:
    return bool(options.get(PLAN_OPTION))


def run_plan_job(options: dict[str, Any], asset_zip: Path, out_dir: Path, observer: JobObserver, settings: Settings, *,
                 urdf: str | None = None) -> RunReport:
    """Execute the job's stored plan on ``asset_zip`` into ``out_dir``.

    Raises
    ------
    CancelledError, AssetError, PlanValidationError, ExportError
        As :func:`app.engine.run.run_plan`; ``StorageError`` when the stored plan is gone.
    """
    from app.engine.errors import CancelledError

    plan = LocalStorage(settings.storage_dir).get_bytes(f"plans/{options[PLAN_OPTION]}.json")
    if observer.should_stop():
        raise CancelledError("cancelled before stage execute")
    observer.on_stage("execute", 50)
    config = settings.engine_config()
    asset = load_asset_cached(asset_zip, config.asset_cache_dir, urdf=urdf)
    report = run_plan(asset, plan, out_dir, cache_dir=config.asset_cache_dir, preview=bool(options.get("preview")),
                      exports=tuple(options.get("exports") or ()))
    observer.on_stage("report", 100)
    logger.info("plan %s executed", options[PLAN_OPTION][:12])
    return report
