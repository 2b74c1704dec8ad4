"""Intent <-> Causal.json (the perceiver contract).

``causal_from_intent`` writes what the offline perceiver understood in the paper's schema;
``intent_from_causal`` reads any Causal.json (ours or a VLM's) back into steps the planner
schedules, so the planner role works from the contract alone.
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import PlanValidationError
from app.engine.offline.base_motion import wheel_rates
from app.engine.offline.geometry import analyse
from app.engine.offline.grounding import movable_parts
from app.engine.offline.intent import BaseGoal, Intent, JointGoal, Step
from app.engine.offline.naming import link_category
from app.engine.plan.causal import (
    Action,
    Causal,
    CausalDocument,
    CausalSegment,
    Effects,
    JointTarget,
    LinkSemantic,
    ModeFlag,
    Semantics,
    TimeHint,
)
from app.engine.plan.checks import joint_limits
from app.engine.plan.expr import evaluate_expr

AFFORDANCES: dict[str, list[str]] = {
    "door": ["open", "close"], "lid": ["open", "close", "lift"], "screen": ["open", "close"], "window": ["open", "close"],
    "drawer": ["pull_out", "push_in"], "tray": ["pull_out", "push_in"], "container": ["pull_out", "push_in", "lift"],
    "knob": ["turn"], "handle": ["turn", "press_down", "lift"], "lever": ["press_down", "lift"], "latch": ["unlatch"],
    "button": ["press"], "switch": ["toggle"], "pedal": ["press"], "wheel": ["roll"], "turntable": ["spin"],
}
BASE_TARGET = "base"
NOMINAL_BASE_SPEED_MPS = 0.4
"""Speed assumed when writing wheel velocities into Causal.json (the planner sets the real one)."""


def _semantics(asset: ArticulatedAsset) -> Semantics:
    links = []
    for name in asset.visual_links:
        spec = asset.links[name]
        category = link_category(asset, name)
        joint = asset.parent_joint(name)
        moving = joint is not None and joint.movable
        label = spec.semantics.label or category or ("body" if not moving else name)
        confidence = 0.9 if spec.semantics.source == "semantics.txt" else (0.6 if category else 0.3)
        how = f"moves via {joint.name} ({joint.type})" if moving and joint is not None else "static part of the object"
        links.append(LinkSemantic(name=name, label=label, affordance=AFFORDANCES.get(category or "", []) if moving else [], conf=confidence, description=f"{label}; {how}"))
    return Semantics(links=links)


def _root_link(asset: ArticulatedAsset) -> str:
    """The largest static link (the body), used as the target of whole-object motion."""
    static = [n for n in asset.visual_links if not any(asset.joints[j].movable and n in asset.moving_links(j) for j in asset.movable_joints)]
    candidates = static or list(asset.visual_links)
    return max(candidates, key=lambda n: len(asset.links[n].vertices()))


def _to(goal: JointGoal) -> str:
    if goal.omega is not None:
        return f"velocity:{goal.omega:.9g}"
    return goal.expr or f"{goal.value:.9g}"


def _segment_parts(step: Step, asset: ArticulatedAsset) -> tuple[Action, Effects]:
    controls = list(step.controls)
    primary = step.target
    if step.base is not None:
        target = _root_link(asset)
        action = Action(primitive=step.primitive, target_link=target, target_links=[target], target_role="direct_object",
                        magnitude=round(step.base.distance_m, 6), direction_axis_world=step.base.axis_tuple(), control_return_behavior="unknown")
        speed = step.base.speed_mps or NOMINAL_BASE_SPEED_MPS
        targets = [JointTarget(joint=j, to=f"velocity:{rate * speed:.9g}") for j, rate in step.base.wheels]
        rules = ["wheels roll without slipping: omega = v / r"] if step.base.wheels else []
        modes = [ModeFlag(name="coast", set=True)] if step.base.coast else []
        return action, Effects(effect_links=[asset.joints[j].child for j, _ in step.base.wheels], joint_targets=targets, modes=modes, coupling_rules=rules)
    assert primary is not None
    role: Literal["control", "direct_object"] = "control" if controls or primary.role == "control" else "direct_object"
    links = [g.link for g in (controls or step.effects)]
    behaviour = controls[0].returns if controls else "stays"
    magnitude = None if primary.value is None else round(abs(primary.value - asset.joints[primary.joint].rest), 6)
    action = Action(primitive=step.primitive, target_link=primary.link, target_links=list(dict.fromkeys(links)), target_role=role,
                    magnitude=magnitude, control_return_behavior=behaviour)
    effects = Effects(
        effect_links=[g.link for g in step.effects],
        joint_targets=[JointTarget(joint=g.joint, to=_to(g)) for g in step.goals],
        coupling_rules=list(step.coupling),
    )
    return action, effects


def causal_from_intent(intent: Intent, asset: ArticulatedAsset) -> CausalDocument:
    """The Causal.json of an offline reading."""
    pieces = [_segment_parts(step, asset) for step in intent.steps]
    merged_targets: list[JointTarget] = []
    for _, effects in pieces:
        merged_targets.extend(t for t in effects.joint_targets if t.joint not in {m.joint for m in merged_targets})
    first_action, first_effects = pieces[0]
    if len(pieces) == 1:
        return CausalDocument(semantics=_semantics(asset), causal=Causal(has_causal=True, action=first_action, effects=first_effects))
    segments = [
        CausalSegment(segment_id=f"S{i + 1}", time_hint=TimeHint(order_index=i, overlap_ok=step.parallel), action=action, effects=effects)
        for i, (step, (action, effects)) in enumerate(zip(intent.steps, pieces, strict=True))
    ]
    top_effects = Effects(effect_links=list(dict.fromkeys(link for _, e in pieces for link in e.effect_links)), joint_targets=merged_targets,
                          coupling_rules=[r for _, e in pieces for r in e.coupling_rules])
    return CausalDocument(semantics=_semantics(asset), causal=Causal(has_causal=True, action=first_action, effects=top_effects), causal_segments=segments)


def _goal_of(target: JointTarget, asset: ArticulatedAsset, role: str, returns: str) -> JointGoal:
    joint = asset.joints[target.joint]
    category = link_category(asset, joint.child)
    velocity = target.velocity
    if velocity is not None:
        return JointGoal(target.joint, joint.child, category, role, omega=velocity, returns="stays")  # type: ignore[arg-type]
    if isinstance(target.to, int | float):
        value, expr = float(target.to), None
    else:
        value, expr = evaluate_expr(target.to, joint_limits(asset, target.joint)), target.to
    return JointGoal(target.joint, joint.child, category, role, value=joint.clamp(value), expr=expr, returns=returns)  # type: ignore[arg-type]


def _step_of(action: Action | None, effects: Effects | None, asset: ArticulatedAsset, parallel: bool) -> Step:
    if action is None:
        raise PlanValidationError("causal document has no action", issues=["causal.action: null"])
    targets = effects.joint_targets if effects else []
    if action.direction_axis_world is not None:
        axis = np.asarray(action.direction_axis_world, dtype=np.float64)
        obj = analyse(asset)
        distance = action.magnitude if action.magnitude and action.magnitude > 0 else max(0.1, round(0.5 * obj.diag, 2))
        rates = dict(wheel_rates(movable_parts(asset, obj), axis, obj))
        coast = bool(effects and any(m.name == "coast" and m.set for m in effects.modes))
        wheels = tuple((t.joint, rates[t.joint]) for t in targets if t.joint in rates)
        return Step(primitive=action.primitive, base=BaseGoal(axis=axis, distance_m=float(distance), coast=coast, wheels=wheels), parallel=parallel)
    control_links = set(action.target_links or [action.target_link]) if action.target_role == "control" else set()
    controls: list[JointGoal] = []
    moved: list[JointGoal] = []
    for target in targets:
        joint = asset.joints[target.joint]
        is_control = any(joint.child == link or joint.child in asset.descendants(link) for link in control_links)
        goal = _goal_of(target, asset, "control" if is_control else ("effect" if control_links else "direct"), action.control_return_behavior)
        (controls if is_control else moved).append(goal)
    sustaining = action.control_return_behavior == "stays" and any(g.category == "pedal" for g in controls)
    controls = [JointGoal(**{**g.__dict__, "sustains": sustaining and g.category == "pedal"}) for g in controls]
    return Step(primitive=action.primitive, controls=tuple(controls), effects=tuple(moved), parallel=parallel,
                coupling=tuple(effects.coupling_rules) if effects else ())


def intent_from_causal(document: CausalDocument, asset: ArticulatedAsset, prompt: str = "") -> Intent:
    """Steps encoded by a Causal.json (top level, or its ordered segments)."""
    if document.causal_segments:
        ordered = sorted(enumerate(document.causal_segments), key=lambda item: (item[1].time_hint.order_index, item[0]))
        steps = [_step_of(s.action, s.effects, asset, s.time_hint.overlap_ok and i > 0) for i, (_, s) in enumerate(ordered)]
    else:
        if not document.causal.has_causal:
            raise PlanValidationError("causal document describes no motion", issues=["causal.has_causal: false"])
        steps = [_step_of(document.causal.action, document.causal.effects, asset, False)]
    return Intent(prompt=prompt, steps=tuple(steps))

