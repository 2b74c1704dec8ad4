"""``run_plan``: asset + Plan.json -> the output files of SPEC §4 (no models involved)."""

from __future__ import annotations

import logging
from collections.abc import Iterable
from pathlib import Path

from app.engine.asset.cache import load_asset_cached
from app.engine.asset.model import ArticulatedAsset
from app.engine.bundle import REPORT_FILE, write_animation, write_preview, write_report
from app.engine.errors import EngineError, RenderError
from app.engine.execute.executor import execute
from app.engine.plan.checks import validate_plan
from app.engine.plan.schema import Plan
from app.engine.report import AssetSummary, RunReport, StageClock
from app.engine.staging import Staging

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

    The files are written into a hidden folder and moved into ``out_dir`` at the end; a
    failed run replaces the previous outputs there with a report.json naming the failure.

    Raises
    ------
    AssetError, PlanValidationError, ExportError
    """
    clock = StageClock()
    with Staging(out_dir) as staging:
        try:
            report = _run(asset, plan, staging.path, clock, cache_dir=cache_dir, preview=preview, exports=exports)
        except EngineError as exc:
            _failure_report(asset, exc, clock, staging.path)
            staging.publish(only=(REPORT_FILE,))
            raise
        staging.publish()
    return report


def _run(
    asset: ArticulatedAsset | str | Path, plan: Plan | str | bytes | dict[str, object], target: Path, clock: StageClock, *,
    cache_dir: Path | None, preview: bool, exports: Iterable[str],
) -> RunReport:
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
        events=[e.message for e in trajectory.events if e.kind != "plan_warning"],
        execution_events=[e for e in trajectory.events if e.kind != "plan_warning"],
        stages=clock.stages,
        total_s=clock.total,
        outputs={**outputs, "report": REPORT_FILE},
    )
    write_report(target, report)
    return report


def _failure_report(asset: ArticulatedAsset | str | Path, error: EngineError, clock: StageClock, target: Path) -> None:
    """report.json of a run that failed: what failed and why (no other output is published)."""
    report = RunReport(asset=AssetSummary.of(asset) if isinstance(asset, ArticulatedAsset) else None, provider="plan",
                       final_state=f"failed: {type(error).__name__}", error=str(error), error_kind=type(error).__name__,
                       warnings=[str(error)], stages=clock.stages, total_s=clock.total, outputs={"report": REPORT_FILE})
    write_report(target, report)
