"""``run_pipeline``: the one engine entry point the CLI and the workers call.

asset + prompt -> preprocess (joint summary, scale context, optional renders) ->
perceiver (Causal.json) -> planner (Plan.json) -> execute -> critic-actor loop ->
export (trajectory.jsonl, animation.glb) -> report.json. The engine knows nothing
about jobs or URLs: progress goes to an ``observer``, cancellation comes from
``should_stop`` (checked between stages). Outputs are written into a hidden folder and
moved into ``out_dir`` when the run ends (:mod:`staging`): a failed run leaves its
report.json there and no output of an earlier run.
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol

from app.engine.agents.expectations import expectations_of
from app.engine.agents.fallback import fallbacks_used
from app.engine.agents.loop import refine
from app.engine.agents.roles import Context, Perception, Roles
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.stored import StoredAsset, load_stored, summaries
from app.engine.bundle import REPORT_FILE, write_animation, write_preview, write_report
from app.engine.config import EngineConfig
from app.engine.contracts.causal import CausalDocument
from app.engine.errors import CancelledError, EngineError, RenderError
from app.engine.files import atomic_write_bytes
from app.engine.report import AssetSummary, RunReport, StageClock
from app.engine.staging import Staging

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
    causal: CausalDocument | None = None
    """Re-plan from this Causal.json instead of perceiving the prompt (``artimo plan``): the perceiver is skipped."""
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
    """Reference and overlay renders (PNG bytes, cached per asset), also written under ``out_dir/images``."""
    from app.engine.render.perceiver_images import perceiver_images

    images = perceiver_images(asset, config.image_size, config.asset_cache_dir)
    for name, data in images.items():
        atomic_write_bytes(out_dir / "images" / name, data)
    return images


def _render_choice(roles: Roles, config: EngineConfig, report: RunReport) -> bool:
    """Whether to render (config, else on for roles that look at images); warns when model roles go without."""
    render = config.render_images if config.render_images is not None else bool(roles.vision)
    if roles.vision and not render:
        report.warnings.append(f"rendering is off (--no-render): the {' and '.join(roles.vision)} model(s) see no images")
    return render


async def _run(request: PipelineRequest, roles: Roles, config: EngineConfig, run: _Run, report: RunReport) -> dict[str, str]:
    with run.stage("load_asset"):
        asset = request.asset if isinstance(request.asset, ArticulatedAsset) else load_stored(request.asset, config.asset_cache_dir, request.urdf, request.stored)
    report.asset = AssetSummary.of(asset)
    with run.stage("preprocess"):
        render = _render_choice(roles, config, report)
        try:
            images = await asyncio.to_thread(_images, asset, config, run.out_dir) if render else {}
        except RenderError as exc:
            if not roles.vision:
                raise
            raise RenderError(f"{exc}; the {' and '.join(roles.vision)} model(s) need images: fix rendering or pass --no-render") from exc
        report.images = bool(images)
        joints, scale = summaries(asset, request.stored)
        context = Context(asset=asset, prompt=request.prompt, joint_summary=joints, scale=scale, config=config,
                          images=images, render=render and bool(roles.vision), keyframe_dir=run.out_dir / "keyframes")
    with run.stage("perceive"):
        if request.causal is not None:
            perception = perception_of(request.causal, asset, request.prompt)
            report.models["perceiver"] = "causal.json (given)"
            report.warnings.append("re-planned from a given causal.json: the perceiver did not run")
        else:
            perception = await roles.perceiver.perceive(context)
        report.add_calls(perception.calls)
        report.warnings.extend([*perception.intent.notes, *perception.notes])
        report.understanding = list(perception.understanding)
    with run.stage("plan"):
        planned = await roles.planner.plan(context, perception)
        report.add_calls(planned.calls)
        report.warnings.extend(planned.notes)
        plan = planned.plan
        if request.fps is not None and request.fps != plan.meta.fps:
            plan = plan.model_copy(update={"meta": plan.meta.model_copy(update={"fps": request.fps})})
    with run.stage("refine"):
        rounds = config.max_critic_rounds if request.max_critic_rounds is None else request.max_critic_rounds
        refined = await refine(context, expectations_of(perception), plan, roles.critic, max_rounds=rounds, should_stop=run.should_stop)
        report.add_calls(refined.calls)
        report.warnings.extend(refined.notes)
        report.critic_rounds = refined.rounds
        report.coverage = refined.coverage
        report.final_state = f"{refined.state} (best round {refined.best_round})"
        report.events.extend(refined.trajectory.event_messages)
        report.execution_events.extend(refined.trajectory.events)
        report.fallbacks = fallbacks_used(roles.perceiver, roles.planner, roles.critic)
    with run.stage("export"):
        outputs = write_animation(run.out_dir, asset, refined.plan, refined.trajectory, perception.causal, config.exports)
    if config.preview:
        with run.stage("preview"):
            try:
                outputs["preview"] = await asyncio.to_thread(write_preview, run.out_dir, asset, refined.trajectory)
            except RenderError as exc:  # the animation itself is complete: say why there is no preview
                report.warnings.append(f"no preview.gif: {exc}")
    return outputs


def perception_of(document: CausalDocument, asset: ArticulatedAsset, prompt: str = "") -> Perception:
    """What a perceiver would have handed on, read back from a Causal.json (ours or a model's)."""
    from app.engine.offline.contract_io import extension_of
    from app.engine.offline.tracker import resolve_steps

    return Perception(causal=document, intent=resolve_steps(extension_of(document, asset), asset, prompt))


def _finish(report: RunReport, run: _Run, outputs: dict[str, str]) -> None:
    report.stages = run.clock.stages
    report.total_s = run.clock.total
    report.outputs = {**outputs, "report": REPORT_FILE}
    write_report(run.out_dir, report)


async def _main(request: PipelineRequest, roles: Roles, config: EngineConfig, run: _Run) -> RunReport:
    report = RunReport(prompt=request.prompt, provider=roles.provider)
    report.models = {"perceiver": roles.perceiver.model, "planner": roles.planner.model, "critic": roles.critic.model}
    try:
        outputs = await _run(request, roles, config, run, report)
        with run.stage("report"):
            _finish(report, run, outputs)
    except EngineError as exc:
        report.add_calls([c for c in getattr(exc, "calls", ()) if c not in report.role_calls])
        report.final_state = f"failed: {type(exc).__name__}"
        report.error, report.error_kind = str(exc), type(exc).__name__
        report.warnings.append(str(exc))
        report.fallbacks = fallbacks_used(roles.perceiver, roles.planner, roles.critic)
        _finish(report, run, {})
        exc.report = report  # the caller gets the failed run's report without reading report.json
        raise
    finally:
        await roles.aclose()
    return report


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
    AssetError, GroundingError, PlanValidationError, RoleOutputError, ProviderError, RenderError, CancelledError
        report.json is still written, with the failure (and nothing else is left in ``out_dir``).
    """
    target = Path(out_dir)
    with Staging(target) as staging:
        try:
            report = asyncio.run(_main(request, roles, config or EngineConfig(), _Run(staging.path, observer, should_stop)))
        except EngineError:
            staging.publish(only=(REPORT_FILE,))
            raise
        staging.publish()
    return PipelineResult(out_dir=target, report=report, outputs=report.outputs)
