"""Resolved steps: the contract's steps with every goal turned into a joint value.

:func:`app.engine.offline.tracker.resolve_steps` builds these from Causal.json's ``artimo``
block; the planner schedules them and the geometric critic checks a trajectory against them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from app.engine.lexicon.kinds import PartKind
from app.engine.types import FloatArray

Role = Literal["control", "direct", "effect"]
Return = Literal["self_return", "stays", "unknown"]


@dataclass(frozen=True)
class JointGoal:
    """Move ``joint`` to ``value`` (or spin it at ``omega``)."""

    joint: str
    link: str
    category: PartKind | None
    role: Role
    value: float | None = None
    expr: str | None = None
    omega: float | None = None
    returns: Return = "unknown"
    sustains: bool = False
    """Releasing this control would undo its effect (a pedal holding a lid open)."""
    start: float | None = None
    """The joint's value when the step starts."""


@dataclass(frozen=True, eq=False)
class BaseGoal:
    """Translate the whole object by ``distance_m`` along the unit ``axis`` and/or turn it by ``yaw_rad``
    about the vertical through ``pivot``."""

    axis: FloatArray
    distance_m: float
    speed_mps: float | None = None
    coast: bool = False
    wheels: tuple[tuple[str, float], ...] = ()
    """(joint, radians per metre travelled) of wheels that roll without slipping."""
    yaw_rad: float = 0.0
    pivot: tuple[float, float, float] | None = None

    def axis_tuple(self) -> tuple[float, float, float]:
        rounded = np.round(self.axis, 6) + 0.0
        return (float(rounded[0]), float(rounded[1]), float(rounded[2]))


@dataclass(frozen=True)
class Step:
    """One causally distinct phase of the request."""

    primitive: str
    controls: tuple[JointGoal, ...] = ()
    effects: tuple[JointGoal, ...] = ()
    base: BaseGoal | None = None
    parallel: bool = False
    speed_factor: float = 1.0
    duration_s: float | None = None
    coupling: tuple[str, ...] = ()
    pause_before_s: float = 0.0
    """Seconds the scene holds still before this step starts ("..., wait, then ...")."""
    hold_s: float = 0.0
    """Seconds the step's end state is held before its controls are let go."""

    @property
    def goals(self) -> tuple[JointGoal, ...]:
        return self.controls + self.effects

    @property
    def target(self) -> JointGoal | None:
        """The first physically manipulated part."""
        if self.controls:
            return self.controls[0]
        return self.effects[0] if self.effects else None


@dataclass(frozen=True)
class Intent:
    prompt: str
    steps: tuple[Step, ...]
    notes: tuple[str, ...] = ()
