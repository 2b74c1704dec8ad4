"""Perceiver and planner backed by a chat model (VLM/LLM); the critic is in :mod:`model_critic`.

Each role renders its prompt template, asks the model for JSON (:func:`ask.ask`), validates
the reply against the role's schema and the asset, and on a validation error sends the
error back as feedback (bounded attempts, then :class:`RoleOutputError`).
"""

from __future__ import annotations

import json
from typing import Any

from app.engine.agents.ask import ask
from app.engine.agents.prompts import PromptStore
from app.engine.agents.roles import Context, Perception, Planned
from app.engine.contracts.causal import CausalDocument
from app.engine.offline.contract_io import extension_of
from app.engine.offline.naming import link_kind
from app.engine.offline.tracker import resolve_steps
from app.engine.plan.checks import check_causal, validate_plan
from app.engine.plan.schema import Plan
from app.engine.providers.base import ChatModel, Image


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


def context_images(context: Context) -> list[Image]:
    return [Image(name=name, png=data) for name, data in sorted(context.images.items())]


class ModelPerceiver:
    def __init__(self, model: ChatModel, prompts: PromptStore) -> None:
        self.chat = model
        self.name = model.provider
        self.model = model.model
        self.prompts = prompts

    async def perceive(self, context: Context) -> Perception:
        images = context_images(context)
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
