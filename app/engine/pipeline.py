"""``run_pipeline``: the one engine entry point the CLI and the workers call.

asset + prompt -> preprocess (joint summary, scale context, optional renders) ->
perceiver (Causal.json) -> planner (Plan.json) -> execute -> critic-actor loop ->
export (trajectory.jsonl, animation.glb) -> report.json. The engine knows nothing
about jobs or URLs: progress goes to an ``observer``, cancellation comes from
``should_stop`` (checked between stages).
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol

from app.engine.agents.loop import refine
from app.engine.agents.roles import Context, Roles
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.stored import StoredAsset, load_stored, summaries
from app.engine.bundle import REPORT_FILE, write_animation, write_preview, write_report
from app.engine.config import EngineConfig
from app.engine.errors import CancelledError, EngineError, RenderError
from app.engine.files import atomic_write_bytes
from app.engine.report import AssetSummary, RunReport, StageClock

logger = logging.getLogger(__name__)

STAGES: tuple[tuple[str, int], ...] = (
    ("load_asset", 5), ("preprocess", 15), ("perceive", 35), ("plan", 50), ("refine", 85), ("export", 96), ("preview", 99), ("report", 100),
)


class PipelineObserver(Protocol):
    def on_stage(self, stage: str, progress: int) -> None: ...

    def on_message(self, message: str) -> None: ...


@dataclass(frozen=True)
class PipelineRequest:
    asset: Path | ArticulatedAsset
    prompt: str
    max_critic_rounds: int | None = None
    fps: int | None = None
    """Frame rate of the output (24 or 30); ``None`` keeps the planner's."""
    urdf: str | None = None
    """Which URDF to load when the asset folder/zip holds several."""
    stored: StoredAsset | None = None
    """What the caller already knows of ``asset`` (hash, name, summaries): nothing is computed twice."""


@dataclass
class PipelineResult:
    out_dir: Path
    report: RunReport
    outputs: dict[str, str] = field(default_factory=dict)


class _Run:
    def __init__(self, out_dir: Path, observer: PipelineObserver | None, should_stop: Callable[[], bool] | None) -> None:
        self.out_dir = out_dir
        self.observer = observer
        self.should_stop = should_stop
        self.clock = StageClock()

    def stage(self, name: str):  # type: ignore[no-untyped-def]
        if self.should_stop is not None and self.should_stop():
            raise CancelledError(f"cancelled before stage {name}")
        progress = dict(STAGES)[name]
        if self.observer is not None:
            self.observer.on_stage(name, progress)
        return self.clock.stage(name)


def _images(asset: ArticulatedAsset, config: EngineConfig, out_dir: Path) -> dict[str, bytes]:
    """Reference and overlay renders (PNG bytes), also written under ``out_dir/images``."""
    import io

    from app.engine.render.views import render_overlay_views, render_reference_views

    images: dict[str, bytes] = {}
    size = config.image_size
    for prefix, renders in (("reference", render_reference_views(asset, size=size)), ("overlay", render_overlay_views(asset, size=size))):
        for index, image in enumerate(renders, start=1):
            buffer = io.BytesIO()
            image.save(buffer, format="PNG")
            name = f"{prefix}_view_{index:02d}.png"
            images[name] = buffer.getvalue()
            atomic_write_bytes(out_dir / "images" / name, images[name])
    return images


async def _run(request: PipelineRequest, roles: Roles, config: EngineConfig, run: _Run) -> PipelineResult:
    with run.stage("load_asset"):
        asset = request.asset if isinstance(request.asset, ArticulatedAsset) else load_stored(request.asset, config.asset_cache_dir, request.urdf, request.stored)
    report = RunReport(asset=AssetSummary.of(asset), prompt=request.prompt, provider=roles.provider)
    report.models = {"perceiver": roles.perceiver.model, "planner": roles.planner.model, "critic": roles.critic.model}
    try:
        with run.stage("preprocess"):
            images = _images(asset, config, run.out_dir) if config.render_images else {}
            joints, scale = summaries(asset, request.stored)
            context = Context(asset=asset, prompt=request.prompt, joint_summary=joints, scale=scale, config=config, images=images)
        with run.stage("perceive"):
            perception = await roles.perceiver.perceive(context)
            report.role_calls.extend(perception.calls)
            report.warnings.extend(perception.intent.notes)
        with run.stage("plan"):
            planned = await roles.planner.plan(context, perception)
            report.role_calls.extend(planned.calls)
            plan = planned.plan
            if request.fps is not None and request.fps != plan.meta.fps:
                plan = plan.model_copy(update={"meta": plan.meta.model_copy(update={"fps": request.fps})})
        with run.stage("refine"):
            rounds = config.max_critic_rounds if request.max_critic_rounds is None else request.max_critic_rounds
            refined = await refine(context, perception, plan, roles.critic, max_rounds=rounds, should_stop=run.should_stop)
            report.role_calls.extend(refined.calls)
            report.critic_rounds = refined.rounds
            report.final_state = f"{refined.state} (best round {refined.best_round})"
            report.events.extend(refined.trajectory.events)
        with run.stage("export"):
            outputs = write_animation(run.out_dir, asset, refined.plan, refined.trajectory, perception.causal)
        if config.preview:
            with run.stage("preview"):
                try:
                    outputs["preview"] = write_preview(run.out_dir, asset, refined.trajectory)
                except RenderError as exc:  # the animation itself is complete: say why there is no preview
                    report.warnings.append(f"no preview.gif: {exc}")
        with run.stage("report"):
            report.stages = run.clock.stages
            report.total_s = run.clock.total
            report.outputs = {**outputs, "report": REPORT_FILE}
            write_report(run.out_dir, report)
    except EngineError as exc:
        report.final_state = f"failed: {type(exc).__name__}"
        report.warnings.append(str(exc))
        report.stages = run.clock.stages
        report.total_s = run.clock.total
        report.outputs = {"report": REPORT_FILE}
        write_report(run.out_dir, report)
        exc.report = report  # the caller gets the failed run's report without reading report.json
        raise
    return PipelineResult(out_dir=run.out_dir, report=report, outputs=report.outputs)


def run_pipeline(
    request: PipelineRequest,
    *,
    roles: Roles,
    config: EngineConfig | None = None,
    out_dir: str | Path,
    observer: PipelineObserver | None = None,
    should_stop: Callable[[], bool] | None = None,
) -> PipelineResult:
    """Animate ``request.prompt`` on ``request.asset`` into ``out_dir``.

    Raises
    ------
    AssetError, GroundingError, PlanValidationError, RoleOutputError, ProviderError, CancelledError
        report.json is still written, with the failure.
    """
    target = Path(out_dir)
    target.mkdir(parents=True, exist_ok=True)
    async def main() -> PipelineResult:
        try:
            return await _run(request, roles, config or EngineConfig(), _Run(target, observer, should_stop))
        finally:
            await roles.aclose()

    return asyncio.run(main())
