"""What the executor noticed while running a plan, as typed records (not prose to be parsed)."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict

EventKind = Literal["plan_warning", "target_clamped", "overlap", "limit_reached", "start_jump"]


class ExecutionEvent(BaseModel):
    """One note from execution.

    ``kind`` says what happened: ``plan_warning`` (a warning of the plan check),
    ``target_clamped`` (a ``joint_position`` target outside the limits), ``overlap`` (two
    controls on one joint overlap in time; the later one wins), ``limit_reached`` (a
    velocity control ran into a limit and stopped there), ``start_jump`` (a
    ``q_start_rad`` differs from the joint's current value). ``message`` is the readable
    sentence written to report.json.
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    kind: EventKind
    message: str
    joint: str | None = None
    mode: str | None = None
    """Control mode involved (``joint_velocity`` for a limit stop)."""
    where: str | None = None
    """``timeline[i].controls[j]`` of the control involved."""
    time_s: float | None = None
    value: float | None = None
    """The clamped target, or the limit value reached."""

    def __str__(self) -> str:
        return self.message

