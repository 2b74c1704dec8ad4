"""The contract on disk: resolved steps -> Causal.json (the paper's fields plus our ``artimo``
block), and any Causal.json -> the extension steps the planners read.

A document from a model without the ``artimo`` block is read from the paper's fields: each
segment's joint targets become absolute goals (``state: value``), whole-object actions a
translation along ``direction_axis_world``.
"""

from __future__ import annotations

from typing import Literal

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.causal import (
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
from app.engine.contracts.steps import BaseMotion, Extension, Goal, JointMove, WheelRoll
from app.engine.contracts.steps import Step as ContractStep
from app.engine.errors import PlanValidationError
from app.engine.lexicon.kinds import info
from app.engine.offline.base_motion import default_distance, wheel_rates
from app.engine.offline.geometry import analyse
from app.engine.offline.intent import Intent, JointGoal, Step
from app.engine.offline.naming import link_kind
from app.engine.plan.checks import joint_limits
from app.engine.plan.expr import evaluate_expr

NOMINAL_BASE_SPEED_MPS = 0.4
"""Speed assumed when writing wheel velocities into the paper's fields (the planner sets the real one)."""


def _semantics(asset: ArticulatedAsset) -> Semantics:
    links = []
    for name in asset.visual_links:
        spec = asset.links[name]
        kind = link_kind(asset, name)
        joint = asset.parent_joint(name)
        moving = joint is not None and joint.movable
        label = spec.semantics.label or (kind.value if kind is not None else None) or ("body" if not moving else name)
        confidence = 0.9 if spec.semantics.source == "semantics.txt" else (0.6 if kind else 0.3)
        how = f"moves via {joint.name} ({joint.type})" if moving and joint is not None else "static part of the object"
        affordance = list(info(kind).affordances) if moving and kind is not None else []
        links.append(LinkSemantic(name=name, label=label, affordance=affordance, conf=confidence, description=f"{label}; {how}"))
    return Semantics(links=links)


def root_link(asset: ArticulatedAsset) -> str:
    """The largest static link (the body), the target of whole-object motion."""
    static = [n for n in asset.visual_links if not any(asset.joints[j].movable and n in asset.moving_links(j) for j in asset.movable_joints)]
    candidates = static or list(asset.visual_links)
    return max(candidates, key=lambda n: len(asset.links[n].vertices()))


def _to(goal: JointGoal) -> str:
    if goal.omega is not None:
        return f"velocity:{goal.omega:.9g}"
    return goal.expr or f"{goal.value:.9g}"


def _paper_fields(step: Step, contract: ContractStep, asset: ArticulatedAsset) -> tuple[Action, Effects]:
    if step.base is not None:
        target = root_link(asset)
        axis = step.base.axis_tuple() if step.base.distance_m > 0 else None
        snapped = axis if axis in {(1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, -1.0)} else None
        action = Action(primitive=step.primitive, target_link=target, target_links=[target], target_role="direct_object",
                        magnitude=round(step.base.distance_m or abs(step.base.yaw_rad), 6), direction_axis_world=snapped, control_return_behavior="unknown")
        speed = step.base.speed_mps or NOMINAL_BASE_SPEED_MPS
        targets = [JointTarget(joint=j, to=f"velocity:{rate * speed:.9g}") for j, rate in step.base.wheels]
        rules = ["wheels roll without slipping: omega = v / r"] if step.base.wheels else []
        if step.base.yaw_rad:
            rules.append(f"the whole object turns {step.base.yaw_rad:.6g} rad about the vertical")
        modes = [ModeFlag(name="coast", set=True)] if step.base.coast else []
        return action, Effects(effect_links=[asset.joints[j].child for j, _ in step.base.wheels], joint_targets=targets, modes=modes, coupling_rules=rules)
    primary = step.target
    assert primary is not None
    controls = list(step.controls)
    role: Literal["control", "direct_object"] = "control" if controls or primary.role == "control" else "direct_object"
    links = [g.link for g in (controls or step.effects)]
    release = contract.controls[0].release if contract.controls else "stays"
    behaviour: Literal["self_return", "stays", "unknown"] = "self_return" if release == "self_return" else "stays"
    magnitude = None if primary.value is None else round(abs(primary.value - asset.joints[primary.joint].rest), 6)
    action = Action(primitive=step.primitive, target_link=primary.link, target_links=list(dict.fromkeys(links)), target_role=role,
                    magnitude=magnitude, control_return_behavior=behaviour)
    return action, Effects(effect_links=[g.link for g in step.effects], joint_targets=[JointTarget(joint=g.joint, to=_to(g)) for g in step.goals],
                           coupling_rules=list(step.coupling))


def causal_document(extension: Extension, intent: Intent, asset: ArticulatedAsset) -> CausalDocument:
    """Causal.json of a reading: the paper's fields for other tools, and the ``artimo`` block."""
    pieces = [_paper_fields(step, contract, asset) for step, contract in zip(intent.steps, extension.steps, strict=True)]
    first_action, first_effects = pieces[0]
    if len(pieces) == 1:
        return CausalDocument(semantics=_semantics(asset), causal=Causal(has_causal=True, action=first_action, effects=first_effects), artimo=extension)
    merged: list[JointTarget] = []
    for _, effects in pieces:
        merged.extend(t for t in effects.joint_targets if t.joint not in {m.joint for m in merged})
    segments = [CausalSegment(segment_id=f"S{i + 1}", time_hint=TimeHint(order_index=i, overlap_ok=step.parallel), action=action, effects=effects)
                for i, (step, (action, effects)) in enumerate(zip(intent.steps, pieces, strict=True))]
    top = Effects(effect_links=list(dict.fromkeys(link for _, e in pieces for link in e.effect_links)), joint_targets=merged,
                  coupling_rules=[r for _, e in pieces for r in e.coupling_rules])
    return CausalDocument(semantics=_semantics(asset), causal=Causal(has_causal=True, action=first_action, effects=top),
                          causal_segments=segments, artimo=extension)


def _move(target: JointTarget, asset: ArticulatedAsset, role: str, release: str) -> JointMove:
    joint = asset.joints[target.joint]
    velocity = target.velocity
    if velocity is not None:
        goal = Goal(state="velocity", omega_radps=velocity, duration_s=2.0)
    else:
        value = float(target.to) if isinstance(target.to, int | float) else evaluate_expr(target.to, joint_limits(asset, target.joint))
        goal = Goal(state="value", value=joint.clamp(value))
    return JointMove(joint=target.joint, link=joint.child, role=role, goal=goal, release=release)  # type: ignore[arg-type]


def _step_of(index: int, action: Action | None, effects: Effects | None, asset: ArticulatedAsset, parallel: bool) -> ContractStep:
    if action is None:
        raise PlanValidationError("causal document has no action", issues=["causal.action: null"])
    targets = effects.joint_targets if effects else []
    start: Literal["after_previous", "with_previous"] = "with_previous" if parallel else "after_previous"
    if action.direction_axis_world is not None:
        obj = analyse(asset)
        distance = action.magnitude if action.magnitude and action.magnitude > 0 else default_distance(obj, abs(action.direction_axis_world[2]) > 0.9)
        rates = dict(wheel_rates(obj.joints.values(), action.direction_axis_world, obj))
        coast = bool(effects and any(m.name == "coast" and m.set for m in effects.modes))
        wheels = [WheelRoll(joint=t.joint, rad_per_m=rates[t.joint]) for t in targets if t.joint in rates]
        base = BaseMotion(axis_world=action.direction_axis_world, distance_m=float(distance), coast=coast, wheels=wheels)
        return ContractStep(id=f"S{index + 1}", op=action.primitive, start=start, base=base)
    control_links = set(action.target_links or [action.target_link]) if action.target_role == "control" else set()
    release = action.control_return_behavior if action.control_return_behavior != "unknown" else "stays"
    controls: list[JointMove] = []
    moved: list[JointMove] = []
    for target in targets:
        joint = asset.joints[target.joint]
        is_control = any(joint.child == link or joint.child in asset.descendants(link) for link in control_links)
        kind = link_kind(asset, joint.child)
        held = release == "stays" and kind is not None and info(kind).holds_effect
        move = _move(target, asset, "control" if is_control else ("effect" if control_links else "direct"),
                     ("held" if held else release) if is_control else "stays")
        (controls if is_control else moved).append(move)
    return ContractStep(id=f"S{index + 1}", op=action.primitive, start=start, controls=controls, effects=moved)


def extension_of(document: CausalDocument, asset: ArticulatedAsset) -> Extension:
    """The steps a planner reads: the ``artimo`` block, else the paper's fields."""
    if document.artimo is not None:
        return document.artimo
    if document.causal_segments:
        ordered = sorted(enumerate(document.causal_segments), key=lambda item: (item[1].time_hint.order_index, item[0]))
        steps = [_step_of(i, s.action, s.effects, asset, s.time_hint.overlap_ok and i > 0) for i, (_, s) in enumerate(ordered)]
    else:
        if not document.causal.has_causal:
            raise PlanValidationError("causal document describes no motion", issues=["causal.has_causal: false"])
        steps = [_step_of(0, document.causal.action, document.causal.effects, asset, False)]
    return Extension(steps=steps)
