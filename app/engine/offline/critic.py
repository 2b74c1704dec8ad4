"""Geometric critic: diagnose an executed plan against the intended motion, no images needed.

Checks, each mapped to the paper's issue codes and a bounded repair hint:
- every intended joint target is reached at the end of the segment that drives it, moving
  the intended way (WRONG_DIRECTION, MOTION_TOO_SMALL, EXCESSIVE_MOTION);
- joints nobody asked to move stay still (UNEXPECTED_EXTRA_MOTION);
- self-returning controls are back at rest at the end (NO_RELEASE_RETURN);
- velocity controls do not run into a limit, parts do not pass through each other.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from app.engine.agents.critique import MAX_FACTOR, STRENGTH_FACTOR, Critique, FixHint, Issue, Repairability
from app.engine.agents.expectations import Expectations, ExpectedMotion
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.offline.collisions import find_collisions
from app.engine.plan.schema import JointPosition, JointVelocity, Plan

ANGLE_TOLERANCE = 0.02
LENGTH_TOLERANCE = 0.002
RELATIVE_TOLERANCE = 0.05
STILL_TOLERANCE = 1e-4


@dataclass(frozen=True)
class _Driver:
    segment_index: int
    phase_type: str
    t0: float
    t1: float
    mode: str


def _drivers(plan: Plan) -> dict[str, list[_Driver]]:
    """Segments that move each joint (position or velocity controls), in timeline order."""
    found: dict[str, list[_Driver]] = {}
    for index, segment in enumerate(plan.timeline):
        for control in segment.controls:
            if isinstance(control, JointPosition | JointVelocity):
                found.setdefault(control.joint, []).append(_Driver(index, segment.phase_type, segment.t0, segment.t1, control.mode))
    return found


def _frame_index(trajectory: Trajectory, time: float) -> int:
    return min(max(round(time * trajectory.fps), 0), trajectory.frame_count - 1)


def _value(trajectory: Trajectory, joint: str, time: float) -> float:
    return float(trajectory.joint(joint)[_frame_index(trajectory, time)])


def _needed(ratio: float) -> float:
    """The factor that undoes ``ratio`` (moved / wanted), capped at the largest one a hint may make."""
    return min(MAX_FACTOR, 1.0 / max(ratio, 1e-9) if ratio < 1.0 else ratio)


def _strength(ratio: float) -> str:
    """The strength whose factor best undoes ``ratio``: nearest on a log scale."""
    return min(STRENGTH_FACTOR, key=lambda name: abs(math.log(STRENGTH_FACTOR[name]) - math.log(_needed(ratio))))


class _Diagnosis:
    def __init__(self, asset: ArticulatedAsset, plan: Plan, trajectory: Trajectory) -> None:
        self.asset = asset
        self.plan = plan
        self.trajectory = trajectory
        self.issues: list[Issue] = []
        self.hints: list[FixHint] = []
        self.notes: list[str] = []

    def flag(self, code: str, driver: _Driver, joint: str, expected: str, observed: str, hint: tuple[str, str, str | None] | None, severity: float,
             factor: float | None = None) -> None:
        link = self.asset.joints[joint].child
        self.issues.append(Issue(code=code, expected=expected, observed=observed, segment_index=driver.segment_index, phase_type=driver.phase_type,  # type: ignore[arg-type]
                                 joint=joint, link=link, severity=round(min(max(severity, 0.0), 1.0), 4)))
        if hint is not None:
            kind, direction, strength = hint
            self.hints.append(FixHint(type=kind, joint=joint, segment_index=driver.segment_index, phase_type=driver.phase_type,  # type: ignore[arg-type]
                                      direction=direction, strength=strength, why=f"{code}: expected {expected}, observed {observed}",  # type: ignore[arg-type]
                                      factor=factor if factor is not None and factor > 1.0 else None))
        self.notes.append(f"[{code}] {joint} in segment {driver.segment_index}: expected {expected}; observed {observed}")

    def tolerance(self, joint: str, expected: float) -> float:
        floor = LENGTH_TOLERANCE if self.asset.joints[joint].type == "prismatic" else ANGLE_TOLERANCE
        return max(floor, RELATIVE_TOLERANCE * abs(expected))

    def check_target(self, goal: ExpectedMotion, driver: _Driver) -> None:
        start = _value(self.trajectory, goal.joint, driver.t0)
        end = _value(self.trajectory, goal.joint, driver.t1)
        if goal.omega is not None:
            wanted = goal.omega * (driver.t1 - driver.t0)
        else:
            assert goal.target is not None
            wanted = goal.target - start
        moved = end - start
        tolerance = self.tolerance(goal.joint, wanted)
        if abs(wanted) <= tolerance:
            return
        kind = "adjust_joint_velocity" if driver.mode == "joint_velocity" else "adjust_joint_target"
        text = f"{wanted:+.4g} (to {start + wanted:.4g})"
        if abs(moved) <= tolerance:
            self.flag("MOTION_TOO_SMALL", driver, goal.joint, text, f"{moved:+.4g}", (kind, "increase", "extra_large"), 1.0)
        elif math.copysign(1.0, moved) != math.copysign(1.0, wanted):
            self.flag("WRONG_DIRECTION", driver, goal.joint, text, f"{moved:+.4g}", ("adjust_direction", "flip", None), 1.0)
        elif abs(moved - wanted) > tolerance:
            ratio = moved / wanted
            code, direction = ("MOTION_TOO_SMALL", "increase") if ratio < 1 else ("EXCESSIVE_MOTION", "decrease")
            self.flag(code, driver, goal.joint, text, f"{moved:+.4g}", (kind, direction, _strength(ratio)), abs(1.0 - ratio), _needed(ratio))

    def check_return(self, goal: ExpectedMotion, drivers: list[_Driver], returns: list[_Driver]) -> None:
        """A self-returning control must be back at rest at the end; ``returns`` are its drivers after the press."""
        rest = self.asset.joints[goal.joint].rest
        final = float(self.trajectory.joint(goal.joint)[-1])
        if abs(final - rest) <= self.tolerance(goal.joint, goal.target - rest if goal.target is not None else 0.0):
            return
        expected, observed = f"back at rest {rest:.4g}", f"ends at {final:.4g}"
        last = returns[-1] if returns else None
        if last is not None and last.mode == "joint_position":  # a return that falls short (or overshoots): scale it
            start = _value(self.trajectory, goal.joint, last.t0)
            wanted, moved = rest - start, _value(self.trajectory, goal.joint, last.t1) - start
            if abs(wanted) > 1e-9:
                ratio = moved / wanted
                direction = "flip" if ratio < -1e-9 else "increase" if ratio < 1.0 else "decrease"
                strength = None if direction == "flip" else _strength(max(abs(ratio), 0.05))
                factor = None if direction == "flip" else _needed(max(abs(ratio), 0.05))
                self.flag("NO_RELEASE_RETURN", last, goal.joint, expected, observed, ("adjust_joint_target", direction, strength), min(1.0, abs(1.0 - ratio)), factor)
                return
        self.flag("NO_RELEASE_RETURN", drivers[-1], goal.joint, expected, observed, ("adjust_timing", "increase", "extra_large"), 1.0)

    def check_still(self, expected: set[str], drivers: dict[str, list[_Driver]]) -> None:
        for index, joint in enumerate(self.trajectory.joint_names):
            spec = self.asset.joints[joint]
            if joint in expected or spec.mimic is not None:
                continue
            track = self.trajectory.q[:, index]
            if float(np.ptp(track)) <= STILL_TOLERANCE:
                continue
            driver = (drivers.get(joint) or [_Driver(0, self.plan.timeline[0].phase_type, 0.0, 0.0, "joint_position")])[0]
            kind = "adjust_joint_velocity" if driver.mode == "joint_velocity" else "adjust_joint_target"
            self.flag("UNEXPECTED_EXTRA_MOTION", driver, joint, "no motion", f"moves over {float(np.ptp(track)):.4g}", (kind, "zero", None), 1.0)

    def check_limits(self, drivers: dict[str, list[_Driver]]) -> None:
        for event in self.trajectory.events:
            if event.kind != "limit_reached" or event.mode != "joint_velocity" or event.joint is None:
                continue
            for driver in drivers.get(event.joint, []):
                if driver.mode == "joint_velocity":
                    self.flag("EXCESSIVE_MOTION", driver, event.joint, "stay within the joint range", event.message, ("adjust_joint_velocity", "decrease", "medium"), 0.5)
                    break

    def check_collisions(self, expected: set[str], drivers: dict[str, list[_Driver]]) -> None:
        """Parts resting inside others where a motion ends (a passing graze of a quirky asset is tolerated)."""
        moving = {link for joint in expected if joint in self.asset.joints for link in self.asset.moving_links(joint)}
        ends = [_frame_index(self.trajectory, d.t1) for joint in expected for d in drivers.get(joint, [])] + [self.trajectory.frame_count - 1]
        off_target = {i.joint for i in self.issues if i.code in ("MOTION_TOO_SMALL", "WRONG_DIRECTION")}
        for hit in find_collisions(self.asset, self.trajectory, moving, frames=ends)[:3]:
            if any(hit.other_link in self.asset.moving_links(j) or hit.moving_link in self.asset.moving_links(j) for j in off_target):
                continue  # a part that has not moved out of the way yet (a door not opened far enough): that part is flagged already
            owners = [j for j in sorted(expected) if j in self.asset.joints and drivers.get(j)]
            movers = [j for j in owners if hit.moving_link in self.asset.moving_links(j)] + [j for j in owners if hit.other_link in self.asset.moving_links(j)]
            if not movers:
                continue
            joint = movers[0]
            active = [d for d in drivers[joint] if d.t0 - 1e-9 <= hit.time_s <= d.t1 + 1e-9] or drivers[joint][-1:]
            self.flag("EXCESSIVE_MOTION", active[0], joint, f"{hit.moving_link} clear of {hit.other_link}",
                      f"{hit.fraction:.0%} of it inside {hit.other_link} at t={hit.time_s:.2f} s", ("adjust_joint_target", "decrease", "medium"), hit.fraction)


def critique(asset: ArticulatedAsset, plan: Plan, trajectory: Trajectory, expected: Expectations, *, collisions: bool = True) -> Critique:
    """Diagnose ``trajectory`` (the execution of ``plan``) against the ``expected`` motions."""
    diagnosis = _Diagnosis(asset, plan, trajectory)
    drivers = _drivers(plan)
    claimed: dict[str, int] = {}
    for goal in expected.motions:
        joint_drivers = drivers.get(goal.joint, [])
        position = claimed.get(goal.joint, 0)
        if position >= len(joint_drivers):
            if joint_drivers or not diagnosis.plan.timeline:
                continue
            fake = _Driver(0, plan.timeline[0].phase_type, 0.0, trajectory.duration_s, "joint_position")
            diagnosis.flag("MOTION_TOO_SMALL", fake, goal.joint, "a control that moves it", "no control in the plan", None, 1.0)
            continue
        diagnosis.check_target(goal, joint_drivers[position])
        claimed[goal.joint] = position + 1
        if goal.returns_to_rest:
            diagnosis.check_return(goal, joint_drivers, joint_drivers[position + 1 :])
            claimed[goal.joint] = len(joint_drivers)
    diagnosis.check_still(expected.joints, drivers)
    diagnosis.check_limits(drivers)
    if collisions:
        diagnosis.check_collisions(expected.joints, drivers)
    structural = any(h is None for h in diagnosis.hints) or any(i.code == "MOTION_TOO_SMALL" and i.observed == "no control in the plan" for i in diagnosis.issues)
    return Critique(
        semantic_ok=not diagnosis.issues,
        detailed_reasoning="\n".join(diagnosis.notes) or "every intended motion reached its target; nothing else moved",
        repairability=Repairability(param_fixable=not structural, structural_fix_needed=structural, preferred_repair_level="structural" if structural else "param"),
        issues=diagnosis.issues,
        param_fix_hints=diagnosis.hints,
        confidence=1.0,
    )
