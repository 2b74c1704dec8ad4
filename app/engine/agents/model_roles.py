"""Perceiver, planner and critic backed by a chat model (VLM/LLM).

Each role renders its prompt template, asks the model for JSON, validates the reply against
the role's schema and the asset, and on a validation error sends the error back as feedback
(bounded attempts, then :class:`RoleOutputError`). Every call is recorded as a RoleCall.
"""

from __future__ import annotations

import asyncio
import hashlib
import json
import re
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from app.engine.agents.critique import Critique
from app.engine.agents.prompts import PromptStore, RenderedPrompt
from app.engine.agents.roles import Context, Diagnosed, Perception, Planned
from app.engine.agents.summaries import critic_cases
from app.engine.contracts.causal import CausalDocument
from app.engine.errors import ExpressionError, PlanValidationError, RoleOutputError
from app.engine.execute.trajectory import Trajectory
from app.engine.offline.contract_io import extension_of
from app.engine.offline.naming import link_kind
from app.engine.offline.tracker import resolve_steps
from app.engine.plan.checks import check_causal, pydantic_issues, validate_plan
from app.engine.plan.schema import Plan
from app.engine.providers.base import ChatModel, Image, Message, ModelRequest
from app.engine.report import RoleCall

M = TypeVar("M", bound=BaseModel)
_FENCE = re.compile(r"^\s*```(?:json|JSON)?\s*\n(.*)\n\s*```\s*$", re.DOTALL)
MAX_CRITIC_CASES = 8


def _unfence(text: str) -> str:
    """Drop one Markdown code fence around the whole reply, if the model added one."""
    match = _FENCE.match(text)
    return match.group(1) if match else text


async def ask(
    model: ChatModel,
    prompt: RenderedPrompt,
    schema: type[M],
    *,
    attempts: int,
    images: Sequence[Image] = (),
    check: Callable[[M], None] | None = None,
) -> tuple[M, list[RoleCall]]:
    """Ask ``model`` until its reply validates against ``schema`` (and ``check``).

    Raises
    ------
    RoleOutputError
        No valid reply after ``attempts`` tries (the last problems are in the message).
    ProviderError
        The provider failed (after its own retries).
    """
    messages: list[Message] = [Message(role="user", text=prompt.user, images=tuple(images))]
    digest = hashlib.sha256((prompt.system + prompt.user).encode()).hexdigest()
    calls: list[RoleCall] = []
    problems: list[str] = []
    for attempt in range(1, attempts + 1):
        response = await model.complete(ModelRequest(system=prompt.system, messages=tuple(messages)))
        call = RoleCall(role=prompt.role, provider=model.provider, model=response.model, prompt_version=prompt.version,
                        input_sha256=digest, attempts=attempt, seconds=round(response.seconds, 6), usage=response.usage)
        try:
            value = schema.model_validate_json(_unfence(response.text))
            if check is not None:
                check(value)
            calls.append(call)
            return value, calls
        except ValidationError as exc:
            problems = pydantic_issues(exc)
        except PlanValidationError as exc:
            problems = exc.issues or [exc.message]
        except ExpressionError as exc:
            problems = [exc.message]
        calls.append(call.model_copy(update={"error": "; ".join(problems)[:2000]}))
        feedback = "Your reply was not valid:\n" + "\n".join(f"- {p}" for p in problems[:20]) + "\nReply again with the corrected JSON object only."
        messages += [Message(role="assistant", text=response.text), Message(role="user", text=feedback)]
    raise RoleOutputError(f"{prompt.role}: no valid reply after {attempts} attempts: " + "; ".join(problems[:5]), role=prompt.role)


def _links(context: Context) -> list[dict[str, Any]]:
    rows = []
    for name in context.asset.link_order:
        joint = context.asset.parent_joint(name)
        movable = joint is not None and joint.movable
        label = context.asset.links[name].semantics.label or link_kind(context.asset, name) or ("no geometry" if not context.asset.links[name].has_geometry else "part")
        rows.append({"name": name, "label": label, "joint": joint.name if movable and joint else None, "joint_type": joint.type if movable and joint else None})
    return rows


def _summary_text(context: Context) -> str:
    return "\n".join(json.dumps(record.model_dump(), separators=(",", ":")) for record in context.joint_summary)


def _images(context: Context) -> list[Image]:
    return [Image(name=name, png=data) for name, data in sorted(context.images.items())]


class ModelPerceiver:
    def __init__(self, model: ChatModel, prompts: PromptStore) -> None:
        self.chat = model
        self.name = model.provider
        self.model = model.model
        self.prompts = prompts

    async def perceive(self, context: Context) -> Perception:
        images = _images(context)
        prompt = self.prompts.render("perceiver", prompt=context.prompt, links=_links(context), joint_summary=_summary_text(context),
                                     scale_context=context.scale.model_dump_json(indent=2), images=[i.name for i in images])

        def check(document: CausalDocument) -> None:
            check_causal(document, context.asset)
            resolve_steps(extension_of(document, context.asset), context.asset, context.prompt)

        document, calls = await ask(self.chat, prompt, CausalDocument, attempts=context.config.role_attempts, images=images, check=check)
        return Perception(causal=document, intent=resolve_steps(extension_of(document, context.asset), context.asset, context.prompt), calls=tuple(calls))


class ModelPlanner:
    def __init__(self, model: ChatModel, prompts: PromptStore) -> None:
        self.chat = model
        self.name = model.provider
        self.model = model.model
        self.prompts = prompts

    async def plan(self, context: Context, perception: Perception) -> Planned:
        prompt = self.prompts.render("planner", prompt=context.prompt, joint_summary=_summary_text(context),
                                     scale_context=context.scale.model_dump_json(indent=2), causal=perception.causal.dumps())
        def check(plan: Plan) -> None:
            validate_plan(plan, context.asset)

        plan, calls = await ask(self.chat, prompt, Plan, attempts=context.config.role_attempts, check=check)
        return Planned(plan=plan, calls=tuple(calls))


class ModelCritic:
    """One model call per (segment, moving joint) case, concurrently; the verdicts are merged."""

    def __init__(self, model: ChatModel, prompts: PromptStore, keyframes: Callable[..., list[Image]] | None = None) -> None:
        self.chat = model
        self.name = model.provider
        self.model = model.model
        self.prompts = prompts
        self.keyframes = keyframes

    async def critique(self, context: Context, perception: Perception, plan: Plan, trajectory: Trajectory) -> Diagnosed:
        cases = critic_cases(context.asset, plan, trajectory, perception.intent)[:MAX_CRITIC_CASES]
        limit = asyncio.Semaphore(context.config.max_concurrent_calls)

        async def one(case: dict[str, Any]) -> tuple[Critique, list[RoleCall]]:
            images = self.keyframes(context.asset, trajectory, case) if self.keyframes is not None and context.config.render_images else []
            prompt = self.prompts.render("critic", prompt=context.prompt, images=[i.name for i in images], **case)
            async with limit:
                return await ask(self.chat, prompt, Critique, attempts=context.config.role_attempts, images=images)

        results = await asyncio.gather(*(one(case) for case in cases))
        issues = [issue for verdict, _ in results for issue in verdict.issues]
        hints = [hint for verdict, _ in results for hint in verdict.param_fix_hints]
        merged = Critique(semantic_ok=all(v.semantic_ok for v, _ in results), visibility_ok=all(v.visibility_ok for v, _ in results),
                          detailed_reasoning="\n\n".join(v.detailed_reasoning for v, _ in results), issues=issues, param_fix_hints=hints,
                          confidence=min((v.confidence for v, _ in results), default=1.0))
        return Diagnosed(critique=merged, calls=tuple(call for _, calls in results for call in calls))
