"""Contract steps -> resolved steps, tracking where every joint is as the steps run.

The same :class:`Tracker` serves the perceiver while it builds steps (it asks "is the door
closed now?", "is this already there?") and the planner when it reads a Causal.json, so both
resolve every goal against the same state: what "back to where it was" and "another 10
degrees" mean depends on what happened before.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.steps import Extension, JointMove
from app.engine.contracts.steps import Step as ContractStep
from app.engine.errors import GroundingError
from app.engine.offline.geometry import ObjectGeometry, analyse
from app.engine.offline.intent import BaseGoal, Intent, JointGoal, Return, Step
from app.engine.offline.resolve import resolve, target_expression

if TYPE_CHECKING:
    from app.engine.offline.grounding import Part

ANY_HOST = "*"
"""The key of :attr:`Tracker.releases` when the prompt names no part the control releases ("pulls back the bolts")."""


@dataclass
class Tracker:
    asset: ArticulatedAsset
    obj: ObjectGeometry
    now: dict[str, float] = field(default_factory=dict)
    before: dict[str, float] = field(default_factory=dict)
    """Each joint's value before its last move ("back to where it was")."""
    held: dict[str, str] = field(default_factory=dict)
    """effect joint -> the control joint holding it (a pedal holding a lid)."""
    releases: dict[str, Part] = field(default_factory=dict)
    """host joint (or :data:`ANY_HOST`) -> the control the prompt says releases it (:mod:`.stated`)."""

    @classmethod
    def of(cls, asset: ArticulatedAsset) -> Tracker:
        return cls(asset=asset, obj=analyse(asset))

    def value(self, joint: str) -> float:
        return self.now.get(joint, self.asset.joints[joint].rest)

    def goal_of(self, move: JointMove, role: str) -> JointGoal:
        geometry = self.obj.joints[move.joint]
        start = self.value(move.joint)
        resolved = resolve(move.goal, geometry, self.obj, self.asset, start, self.before.get(move.joint))
        returns: Return = "self_return" if move.release == "self_return" else "stays"
        if resolved.value is None and resolved.omega is None:
            raise GroundingError(f"could not work out where {move.link} ({move.joint}) should go for '{move.goal.state}': say how far "
                                 "or which way, e.g. 'turn it a quarter turn clockwise'")
        if resolved.value is None:
            return JointGoal(move.joint, move.link, geometry.category, role, omega=resolved.omega, returns="stays", start=start)  # type: ignore[arg-type]
        value = float(resolved.value)
        return JointGoal(move.joint, move.link, geometry.category, role, value=value, expr=target_expression(geometry, value),  # type: ignore[arg-type]
                         returns=returns, sustains=move.release == "held", start=start)

    def apply(self, step: ContractStep) -> Step:
        """Resolve ``step`` against the current state, then advance the state past it."""
        controls = tuple(self.goal_of(m, "control") for m in step.controls)
        effects = tuple(self.goal_of(m, m.role) for m in step.effects)
        for goal in (*controls, *effects):
            if goal.value is not None:
                if abs(goal.value - self.value(goal.joint)) > 1e-9 or goal.joint not in self.before:
                    self.before[goal.joint] = self.value(goal.joint)  # a step that leaves it where it is keeps "where it was"
                self.now[goal.joint] = goal.value
            elif goal.omega is not None:
                self.before[goal.joint] = self.value(goal.joint)
        for goal in controls:
            if goal.returns == "self_return" and not goal.sustains:
                self.now[goal.joint] = self.asset.joints[goal.joint].rest
            if goal.sustains:
                for effect in effects:
                    self.held[effect.joint] = goal.joint
        for goal in (*controls, *effects):
            if goal.value is not None and abs(goal.value - self.asset.joints[goal.joint].rest) < 1e-12:
                for held_joint, holder in list(self.held.items()):
                    if holder == goal.joint:
                        del self.held[held_joint]
        base = None
        if step.base is not None:
            motion = step.base
            axis = np.asarray(motion.axis_world if motion.axis_world is not None else (1.0, 0.0, 0.0), dtype=np.float64)
            base = BaseGoal(axis=axis, distance_m=motion.distance_m, speed_mps=motion.speed_mps, coast=motion.coast,
                            wheels=tuple((w.joint, w.rad_per_m) for w in motion.wheels), yaw_rad=motion.yaw_rad, pivot=motion.pivot_world)
            for wheel in motion.wheels if motion.distance_m is not None else ():
                self.now[wheel.joint] = self.value(wheel.joint) + wheel.rad_per_m * motion.distance_m  # rolled along: where it ends
        coupling = tuple(f"{c.joint} drives {e.joint}" for c in controls for e in effects)
        return Step(primitive=step.op, controls=controls, effects=effects, base=base, parallel=step.start == "with_previous",
                    speed_factor=step.speed_factor, duration_s=step.duration_s, coupling=coupling, pause_before_s=step.wait_before_s,
                    hold_s=step.hold_s)


def resolve_steps(extension: Extension, asset: ArticulatedAsset, prompt: str = "", notes: tuple[str, ...] = ()) -> Intent:
    """The resolved steps of a Causal.json ``artimo`` block."""
    tracker = Tracker.of(asset)
    return Intent(prompt=prompt, steps=tuple(tracker.apply(step) for step in extension.steps), notes=notes)
