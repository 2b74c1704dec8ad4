"""Numeric summaries of an executed plan, per (segment, moving joint): what the critic reads."""

from __future__ import annotations

import json
from typing import Any

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.offline.intent import Intent
from app.engine.plan.schema import JointPosition, JointVelocity, Plan

DIGITS = 5


def _frame(trajectory: Trajectory, time: float) -> int:
    return min(max(round(time * trajectory.fps), 0), trajectory.frame_count - 1)


def _intended(intent: Intent, joint: str) -> str:
    for step in intent.steps:
        for goal in step.goals:
            if goal.joint == joint:
                if goal.omega is not None:
                    return f"spin at {goal.omega:.4g} rad/s ({goal.role})"
                returns = ", then return to rest" if goal.returns == "self_return" and not goal.sustains else ""
                return f"move to {goal.value:.5g} ({goal.expr or 'value'}; {goal.role}){returns}"
        if step.base is not None and any(j == joint for j, _ in step.base.wheels):
            return "roll with the object without slipping"
    return "stay still"


def critic_cases(asset: ArticulatedAsset, plan: Plan, trajectory: Trajectory, intent: Intent) -> list[dict[str, Any]]:
    """One case per joint-moving control of each segment, in timeline order."""
    cases = []
    for index, segment in enumerate(plan.timeline):
        for control in segment.controls:
            if not isinstance(control, JointPosition | JointVelocity):
                continue
            joint = asset.joints[control.joint]
            track = trajectory.joint(control.joint)
            head, tail = _frame(trajectory, segment.t0), _frame(trajectory, segment.t1)
            window = track[head : tail + 1]
            summary = {
                "joint_type": joint.type, "lower": joint.lower, "upper": joint.upper, "rest": joint.rest,
                "t0": segment.t0, "t1": segment.t1, "start_q": round(float(track[head]), DIGITS), "end_q": round(float(track[tail]), DIGITS),
                "delta_q": round(float(track[tail] - track[head]), DIGITS), "min_q": round(float(np.min(window)), DIGITS),
                "max_q": round(float(np.max(window)), DIGITS), "final_q": round(float(track[-1]), DIGITS), "control": control.model_dump(exclude_none=True),
            }
            cases.append({
                "segment_index": index, "phase_type": segment.phase_type, "joint": control.joint, "link": joint.child,
                "intended": _intended(intent, control.joint), "summary": json.dumps(summary), "head_frame": head, "tail_frame": tail,
            })
    return cases
