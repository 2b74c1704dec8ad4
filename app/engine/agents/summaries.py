"""Numeric summaries of an executed plan, per (segment, moving joint): what the critic reads."""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np

from app.engine.agents.expectations import Expectations
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.plan.schema import JointPosition, JointVelocity, Plan

DIGITS = 5


@dataclass(frozen=True)
class CriticCase:
    """One (segment, moving joint) the critic diagnoses: the numbers and the keyframe window."""

    segment_index: int
    phase_type: str
    joint: str
    link: str
    intended: str
    summary: str
    """JSON of the joint's numbers over the segment (start/end/min/max/final values, limits, control)."""
    head_frame: int
    tail_frame: int

    def variables(self) -> dict[str, Any]:
        """The critic template's variables."""
        return asdict(self)


def _frame(trajectory: Trajectory, time: float) -> int:
    return min(max(round(time * trajectory.fps), 0), trajectory.frame_count - 1)


def critic_cases(asset: ArticulatedAsset, plan: Plan, trajectory: Trajectory, expected: Expectations) -> list[CriticCase]:
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
            cases.append(CriticCase(segment_index=index, phase_type=segment.phase_type, joint=control.joint, link=joint.child,
                                    intended=expected.describe(control.joint), summary=json.dumps(summary), head_frame=head, tail_frame=tail))
    return cases
