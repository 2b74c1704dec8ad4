"""``run_plan``: asset + Plan.json -> the output files of SPEC §4 (no models involved)."""

from __future__ import annotations

import logging
from collections.abc import Iterable
from pathlib import Path

from app.engine.asset.cache import load_asset_cached
from app.engine.asset.model import ArticulatedAsset
from app.engine.bundle import REPORT_FILE, write_animation, write_preview, write_report
from app.engine.errors import RenderError
from app.engine.execute.executor import execute
from app.engine.plan.checks import validate_plan
from app.engine.plan.schema import Plan
from app.engine.report import AssetSummary, RunReport, StageClock

logger = logging.getLogger(__name__)

PLAN_STATE = "plan executed as given: executor and exporters only (no perceiver, planner or critic)"
"""``report.json``'s ``final_state`` of a run-plan run (its ``provider`` is ``plan``)."""


def run_plan(
    asset: ArticulatedAsset | str | Path, plan: Plan | str | bytes | dict[str, object], out_dir: str | Path, *,
    cache_dir: Path | None = None, preview: bool = False, exports: Iterable[str] = (),
) -> RunReport:
    """Validate and execute ``plan`` on ``asset`` and write plan.json, trajectory.jsonl,
    animation.glb, interaction.json and report.json into ``out_dir`` (and ``preview.gif``
    with ``preview``; the ``exports`` usd, mjcf, ros, csv, npz when asked).

    Raises
    ------
    AssetError, PlanValidationError, ExportError
    """
    clock = StageClock()
    target = Path(out_dir)
    with clock.stage("load_asset"):
        model = asset if isinstance(asset, ArticulatedAsset) else load_asset_cached(asset, cache_dir)
    with clock.stage("validate_plan"):
        checked = validate_plan(plan if isinstance(plan, Plan | dict | str | bytes) else str(plan), model)
    with clock.stage("execute"):
        trajectory = execute(checked.document, model)
    with clock.stage("export"):
        outputs = write_animation(target, model, checked.document, trajectory, exports=exports)
    warnings = list(checked.warnings)
    if preview:
        with clock.stage("preview"):
            try:
                outputs["preview"] = write_preview(target, model, trajectory)
            except RenderError as exc:
                warnings.append(f"no preview.gif: {exc}")
    report = RunReport(
        asset=AssetSummary.of(model),
        provider="plan",
        final_state=PLAN_STATE,
        warnings=warnings,
        events=[e for e in trajectory.events if e not in checked.warnings],
        stages=clock.stages,
        total_s=clock.total,
        outputs={**outputs, "report": REPORT_FILE},
    )
    write_report(target, report)
    return report
