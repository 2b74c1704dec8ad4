"""The critic backed by a chat model (VLM): one call per (segment, moving joint) case, concurrently.

With rendering on, the first round selects a view per moving link (coverage role, model
or geometric) and every case gets HEAD/TAIL keyframes from its link's view, rendered in a
worker thread while other cases' calls are in flight. Each verdict is checked against the
asset and the plan (known joints and links, the link moved by the joint, a segment that
exists and controls the hinted joint) and sent back on error, like the other roles.
"""

from __future__ import annotations

import asyncio

from app.engine.agents.ask import ask
from app.engine.agents.coverage import geometric_views, select_views
from app.engine.agents.critique import Critique
from app.engine.agents.expectations import Expectations
from app.engine.agents.keyframes import critic_keyframes, render_off_loop, window_poses
from app.engine.agents.prompts import PromptStore
from app.engine.agents.roles import Context, Diagnosed
from app.engine.agents.summaries import CriticCase, critic_cases
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import EngineError, PlanValidationError
from app.engine.execute.trajectory import Trajectory
from app.engine.files import atomic_write_bytes
from app.engine.plan.schema import Plan
from app.engine.providers.base import ChatModel, Image
from app.engine.render.camera import ViewSpec
from app.engine.report import CoverageChoice, RoleCall
from app.engine.types import Transforms

MAX_CRITIC_CASES = 8


def check_critique(critique: Critique, asset: ArticulatedAsset, plan: Plan) -> None:
    """Every joint, link and segment the critic names must exist, and hints must name a control they can change.

    Raises
    ------
    PlanValidationError
        Listing each problem with its field path (sent back to the model).
    """
    problems: list[str] = []
    count = len(plan.timeline)
    for index, issue in enumerate(critique.issues):
        where = f"issues[{index}]"
        if issue.joint not in asset.joints:
            problems.append(f"{where}.joint: unknown joint '{issue.joint}' (movable joints: {', '.join(asset.movable_joints)})")
        elif issue.link not in asset.links:
            problems.append(f"{where}.link: unknown link '{issue.link}'")
        elif issue.link not in asset.moving_links(issue.joint):
            problems.append(f"{where}.link: '{issue.link}' is not moved by joint '{issue.joint}' (it moves {asset.joints[issue.joint].child})")
        if issue.segment_index >= count:
            problems.append(f"{where}.segment_index: {issue.segment_index} does not exist (the plan has segments 0..{count - 1})")
    for index, hint in enumerate(critique.param_fix_hints):
        where = f"param_fix_hints[{index}]"
        if hint.segment_index >= count:
            problems.append(f"{where}.segment_index: {hint.segment_index} does not exist (the plan has segments 0..{count - 1})")
            continue
        if hint.type == "adjust_timing":
            continue
        controlled = [c.joint for c in plan.timeline[hint.segment_index].controls if hasattr(c, "joint")]
        if hint.joint not in controlled:
            listing = ", ".join(controlled) or "none"
            problems.append(f"{where}.joint: segment {hint.segment_index} has no control of '{hint.joint}' (it controls: {listing})")
    if problems:
        raise PlanValidationError("critic reply does not fit the asset and plan", issues=problems)


def _merge(results: list[tuple[Critique, list[RoleCall]]]) -> Critique:
    verdicts = [v for v, _ in results]
    return Critique(semantic_ok=all(v.semantic_ok for v in verdicts), visibility_ok=all(v.visibility_ok for v in verdicts),
                    detailed_reasoning="\n\n".join(v.detailed_reasoning for v in verdicts),
                    issues=[i for v in verdicts for i in v.issues], param_fix_hints=[h for v in verdicts for h in v.param_fix_hints],
                    confidence=min((v.confidence for v in verdicts), default=1.0))


class ModelCritic:
    def __init__(self, model: ChatModel, prompts: PromptStore, *, coverage: ChatModel | None = None) -> None:
        self.chat = model
        self.name = model.provider
        self.model = model.model
        self.prompts = prompts
        self.coverage_model = coverage
        """Model of the coverage role; None selects views geometrically."""
        self.views: dict[str, CoverageChoice] = {}
        self.rounds = 0

    async def _select(self, context: Context, expected: Expectations, trajectory: Trajectory, cases: list[CriticCase]) -> tuple[list[RoleCall], list[str]]:
        windows: dict[str, dict[str, Transforms]] = {}
        for case in cases:
            if case.link not in self.views and case.link not in windows:
                windows[case.link] = await render_off_loop(window_poses, context.asset, trajectory, case.head_frame, case.tail_frame)
        if not windows:
            return [], []
        if self.coverage_model is None:
            self.views.update(await render_off_loop(geometric_views, context.asset, windows))
            return [], []
        chosen, calls, notes = await select_views(self.coverage_model, self.prompts, context, expected, windows)
        self.views.update(chosen)
        return calls, notes

    def _view(self, link: str) -> ViewSpec:
        choice = self.views[link]
        return ViewSpec(choice.azimuth_deg, choice.elevation_deg, choice.fov_deg, choice.distance_scale)

    async def critique(self, context: Context, expected: Expectations, plan: Plan, trajectory: Trajectory) -> Diagnosed:
        cases = critic_cases(context.asset, plan, trajectory, expected)[:MAX_CRITIC_CASES]
        limit = asyncio.Semaphore(context.config.max_concurrent_calls)
        round_index, self.rounds = self.rounds, self.rounds + 1
        calls: list[RoleCall] = []
        notes: list[str] = []
        if context.render:
            calls, notes = await self._select(context, expected, trajectory, cases)

        async def one(case: CriticCase) -> tuple[Critique, list[RoleCall]]:
            images: list[Image] = []
            if context.render:
                images = await render_off_loop(critic_keyframes, context.asset, trajectory, case, self._view(case.link))
                if context.keyframe_dir is not None:
                    for image in images:
                        atomic_write_bytes(context.keyframe_dir / f"round_{round_index:02d}_{image.name}", image.png)
            prompt = self.prompts.render("critic", prompt=context.prompt, images=[i.name for i in images], **case.variables())
            async with limit:
                return await ask(self.chat, prompt, Critique, attempts=context.config.role_attempts, images=images,
                                 check=lambda verdict: check_critique(verdict, context.asset, plan))

        outcomes = await asyncio.gather(*(one(case) for case in cases), return_exceptions=True)
        results = [o for o in outcomes if not isinstance(o, BaseException)]
        calls += [call for _, made in results for call in made]
        failures = [o for o in outcomes if isinstance(o, BaseException)]
        for failure in failures:
            calls += list(getattr(failure, "calls", ()))
        if failures:
            first = failures[0]
            if isinstance(first, EngineError):
                first.calls = tuple(calls)
            raise first
        coverage = tuple(dict.fromkeys(self.views[c.link] for c in cases if c.link in self.views))
        return Diagnosed(critique=_merge(results), calls=tuple(calls), notes=tuple(notes), coverage=coverage)
