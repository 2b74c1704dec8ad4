"""Actuated phases from today's contracts: Causal.json actions and Plan.json segments.

An :class:`ActuatedPhase` is a window in which an external actor moves a link. The
causal contract says *what* the actor touches (its action's ``target_role``: a
``control`` such as a pedal or button, or a ``direct_object`` moved by hand; a
``direct_object`` that is the body itself is a whole-object push); the plan says *when*
(the segments whose controls move that link's joint, or the base). Effects (links that
follow a control, wheels that roll under a push) get no phase.

Without a causal document (``run-plan``) the plan alone decides: joints moved in
``control_actuation`` segments are controls; base motion is a push; joints moved in other
segments are moved by hand only when the plan actuates no control and they do not move
together with the base (rolling wheels).
"""

from __future__ import annotations

from collections.abc import Iterable

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.causal import Action as CausalAction
from app.engine.contracts.causal import CausalDocument
from app.engine.interaction.model import Action, ActuatedPhase, ActuationKind
from app.engine.plan.schema import (
    BaseVelocity,
    BaseVelocityDecay,
    BaseYawRate,
    JointPosition,
    JointVelocity,
    Plan,
    Segment,
)

VERB_ACTIONS: dict[str, Action] = {
    "press": "push", "push": "push", "pull": "pull", "turn": "turn", "twist": "turn", "rotate": "turn", "spin": "turn",
}
"""Causal verbs that say unambiguously how the actor moves; others (open, close) are left to the geometry."""


def _moved_joints(segment: Segment) -> list[str]:
    """Joints a segment drives (position or velocity; holds and spring returns move no actor)."""
    return [c.joint for c in segment.controls if isinstance(c, JointPosition | JointVelocity)]


def _moves_base(segment: Segment) -> bool:
    return any(isinstance(c, BaseVelocity | BaseVelocityDecay | BaseYawRate) for c in segment.controls)


def driving_joint(asset: ArticulatedAsset, link: str) -> str | None:
    """The movable joint nearest above ``link`` (through fixed joints), or None when the link is part of the body."""
    current = link
    while True:
        joint = asset.parent_joint(current)
        if joint is None:
            return None
        if joint.movable:
            return joint.name
        current = joint.parent


def _merge(phases: Iterable[ActuatedPhase]) -> list[ActuatedPhase]:
    """Sort by (t0, link) and join windows of the same link, joint and kind that touch or overlap."""
    merged: list[ActuatedPhase] = []
    for phase in sorted(phases, key=lambda p: (p.t0, p.link, p.joint or "", p.t1)):
        previous = next((m for m in reversed(merged) if (m.link, m.joint, m.kind) == (phase.link, phase.joint, phase.kind)), None)
        if previous is not None and phase.t0 <= previous.t1 + 1e-9:
            merged[merged.index(previous)] = previous.model_copy(update={"t1": max(previous.t1, phase.t1)})
        else:
            merged.append(phase)
    return merged


def _for_action(asset: ArticulatedAsset, plan: Plan, action: CausalAction) -> list[ActuatedPhase]:
    verb = VERB_ACTIONS.get(action.primitive.strip().lower())
    found: list[ActuatedPhase] = []
    for link in action.target_links or [action.target_link]:
        if link not in asset.links:
            continue
        joint = driving_joint(asset, link)
        if joint is None:
            found.extend(ActuatedPhase(link=link, joint=None, t0=s.t0, t1=s.t1, kind="whole_object_push", action=verb)
                         for s in plan.timeline if _moves_base(s))
            continue
        kind: ActuationKind = "control_actuation" if action.target_role == "control" else "direct_manipulation"
        segments = [s for s in plan.timeline if joint in _moved_joints(s)]
        if kind == "control_actuation":
            segments = [s for s in segments if s.phase_type == "control_actuation"] or segments[:1]
        found.extend(ActuatedPhase(link=link, joint=joint, t0=s.t0, t1=s.t1, kind=kind, action=verb) for s in segments)
    return found


def _from_plan(asset: ArticulatedAsset, plan: Plan) -> list[ActuatedPhase]:
    has_control = any(s.phase_type == "control_actuation" for s in plan.timeline)
    found = []
    for segment in plan.timeline:
        if _moves_base(segment):
            found.append(ActuatedPhase(link=asset.root_link, joint=None, t0=segment.t0, t1=segment.t1, kind="whole_object_push"))
            continue
        if segment.phase_type == "control_actuation":
            kind: ActuationKind = "control_actuation"
        elif has_control or segment.phase_type == "control_release":
            continue
        else:
            kind = "direct_manipulation"
        found.extend(ActuatedPhase(link=asset.joints[j].child, joint=j, t0=segment.t0, t1=segment.t1, kind=kind)
                     for j in dict.fromkeys(_moved_joints(segment)) if j in asset.joints)
    return found


def actuated_phases(asset: ArticulatedAsset, plan: Plan, causal: CausalDocument | None = None) -> list[ActuatedPhase]:
    """The phases that need an external actor, merged per link and sorted by start time."""
    actions: list[CausalAction] = []
    if causal is not None:
        actions.extend([causal.causal.action] if causal.causal.action is not None else [])
        actions.extend(segment.action for segment in causal.causal_segments or [])
    if not actions:
        return _merge(_from_plan(asset, plan))
    found: list[ActuatedPhase] = []
    for action in actions:
        found.extend(_for_action(asset, plan, action))
    return _merge(found)

