"""Run the offline agent in memory (perceive -> plan -> critic loop) with cached assets."""

from __future__ import annotations

import asyncio
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from app.engine.agents.expectations import expectations_of
from app.engine.agents.loop import refine
from app.engine.agents.roles import Context
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.summary import joint_summary, scale_context
from app.engine.config import EngineConfig
from app.engine.contracts.causal import CausalDocument
from app.engine.execute.trajectory import Trajectory
from app.engine.offline.roles import offline_roles
from app.engine.plan.schema import Plan
from tests.conftest import EXAMPLES, partnet_root


@cache
def asset(name: str) -> ArticulatedAsset:
    """``examples/<x>`` from the repo, ``extra/<x>`` from the partnet-extra folder next to the PartNet one (dev assets
    only: the held-out split's assets never appear in these tests), anything else from the PartNet folder."""
    return load_asset(asset_dir(name))


def asset_dir(name: str) -> Path:
    """The folder :func:`asset` loads ``name`` from."""
    if name.startswith("examples/"):
        return Path(EXAMPLES / name.split("/", 1)[1])
    if name.startswith("extra/"):
        return partnet_root().parent / "partnet-extra" / name.split("/", 1)[1]
    return partnet_root() / name


@dataclass
class Outcome:
    causal: CausalDocument
    plan: Plan
    trajectory: Trajectory
    state: str


def replan(name: str, causal_json: str, *, collisions: bool = True) -> Plan:
    """The final plan made from a causal.json text alone (planner + critic loop, no perceiver)."""
    from app.engine.pipeline import perception_of

    model = asset(name)
    roles = offline_roles()
    config = EngineConfig(check_collisions=collisions)
    context = Context(asset=model, prompt="", joint_summary=joint_summary(model), scale=scale_context(model), config=config)

    async def run() -> Plan:
        perception = perception_of(CausalDocument.model_validate_json(causal_json), model)
        planned = await roles.planner.plan(context, perception)
        refined = await refine(context, expectations_of(perception), planned.plan, roles.critic, max_rounds=config.max_critic_rounds)
        return refined.plan

    return asyncio.run(run())


def animate(name: str, prompt: str, *, collisions: bool = True) -> Outcome:
    return animate_model(asset(name), prompt, collisions=collisions)


def animate_model(model: ArticulatedAsset, prompt: str, *, collisions: bool = True) -> Outcome:
    """:func:`animate` on an asset already loaded (a variant written by a test)."""
    roles = offline_roles()
    config = EngineConfig(check_collisions=collisions)
    context = Context(asset=model, prompt=prompt, joint_summary=joint_summary(model), scale=scale_context(model), config=config)

    async def run() -> Outcome:
        perception = await roles.perceiver.perceive(context)
        planned = await roles.planner.plan(context, perception)
        refined = await refine(context, expectations_of(perception), planned.plan, roles.critic, max_rounds=config.max_critic_rounds)
        return Outcome(perception.causal, refined.plan, refined.trajectory, refined.state)

    return asyncio.run(run())
