"""The offline agent as a provider: rule-based perceiver and planner, geometric critic."""

from __future__ import annotations

import time

from app.engine.agents.expectations import Expectations
from app.engine.agents.roles import Context, Diagnosed, Perception, Planned, Roles
from app.engine.execute.trajectory import Trajectory
from app.engine.offline.contract_io import causal_document, extension_of
from app.engine.offline.critic import critique
from app.engine.offline.perceiver import read_prompt
from app.engine.offline.planner import plan_intent
from app.engine.offline.tracker import resolve_steps
from app.engine.plan.schema import Plan
from app.engine.report import RoleCall

PROVIDER = "offline"
RULES_VERSION = "offline-rules-2"


def _call(role: str, began: float) -> RoleCall:
    return RoleCall(role=role, provider=PROVIDER, model=RULES_VERSION, prompt_version=RULES_VERSION, seconds=round(time.perf_counter() - began, 6),
                    est_cost_usd=0.0)


class OfflinePerceiver:
    name = PROVIDER
    model = RULES_VERSION

    async def perceive(self, context: Context) -> Perception:
        began = time.perf_counter()
        reading = read_prompt(context.prompt, context.asset)
        document = causal_document(reading.extension, reading.intent, context.asset)
        return Perception(causal=document, intent=reading.intent, calls=(_call("perceiver", began),), understanding=tuple(reading.understanding))


class OfflinePlanner:
    """Schedules the contract's steps; reads only Causal.json (ours or a model's)."""

    name = PROVIDER
    model = RULES_VERSION

    async def plan(self, context: Context, perception: Perception) -> Planned:
        began = time.perf_counter()
        intent = resolve_steps(extension_of(perception.causal, context.asset), context.asset, context.prompt)
        return Planned(plan=plan_intent(intent, context.asset), calls=(_call("planner", began),))


class GeometricCritic:
    name = PROVIDER
    model = RULES_VERSION

    async def critique(self, context: Context, expected: Expectations, plan: Plan, trajectory: Trajectory) -> Diagnosed:
        began = time.perf_counter()
        result = critique(context.asset, plan, trajectory, expected, collisions=context.config.check_collisions)
        return Diagnosed(critique=result, calls=(_call("critic", began),))


def offline_roles() -> Roles:
    return Roles(provider=PROVIDER, perceiver=OfflinePerceiver(), planner=OfflinePlanner(), critic=GeometricCritic())
