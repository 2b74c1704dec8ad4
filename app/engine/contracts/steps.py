"""The ``artimo`` extension block of Causal.json: everything the planner needs, losslessly.

The paper's Causal.json says which links are controls and effects and where joints end
(``upper_limit``, ``0.5*upper_limit``); it cannot say *what an amount is measured from*, how
fast, how long to hold, how long to wait, or that the whole object turns. This block can, and
both perceivers (offline rules and models) emit it; the planners read only it (a Causal.json
without it is read from the paper's fields, see :func:`app.engine.offline.contract_io.steps_of`).

Per step: what it does (``op``), why (asked / a mechanism / a prerequisite), when it starts
(after the previous step or with it, after a wait), its joint moves (control or effect, the
goal and what it is measured from, what the control does when let go), its whole-object
motion (translation and yaw), its manner (speed factor, duration) and how long it holds.

Goal semantics (``Goal``), resolved against the asset's geometry by the planner:

- ``state`` names the end: ``open`` / ``closed`` (decided from geometry, never the sign of a
  limit), ``pressed``, ``up`` / ``down``, ``rest`` (the joint's rest value), ``upper`` / ``lower``
  (a limit), ``cw`` / ``ccw`` (a turn as seen facing the part), ``left`` / ``right`` /
  ``forward`` / ``backward`` (the part's motion as seen facing the object), ``toward`` (the part's
  motion along the world direction ``direction_world``: "onto the rim on the -X side"), ``vertical`` /
  ``flat`` (an orientation of the part; with ``direction_world``, the one reached moving that way:
  "fold the handle forward until it lies flat"), ``previous`` (where the joint was before its last
  move: "back to where it was"), ``value`` (exactly ``value``), ``velocity`` (spin at
  ``omega_radps``).
- ``amount`` with ``unit`` says how far toward that end: a ``fraction`` of the way, or an angle
  (``rad``) or distance (``m``) — measured from ``measured_from``: ``closed`` (the closed end:
  "to 90 degrees", "halfway"), ``current`` (where the joint is when the step starts: "another 10
  degrees", "back 5 cm") or ``rest``. Without ``amount`` the joint goes all the way to ``state``.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

EXTENSION_VERSION: Literal[1] = 1
Finite = Annotated[float, Field(allow_inf_nan=False)]
NonNegative = Annotated[float, Field(ge=0.0, allow_inf_nan=False)]
GoalState = Literal["open", "closed", "pressed", "up", "down", "rest", "upper", "lower", "cw", "ccw", "left", "right", "forward",
                    "backward", "toward", "vertical", "flat", "previous", "value", "velocity"]
MeasuredFrom = Literal["closed", "current", "rest"]
Role = Literal["control", "effect", "direct"]
MAX_STEP_S = 30.0
"""The longest one step may be told to last."""
Release = Literal["self_return", "stays", "held"]
Why = Literal["asked", "mechanism", "prerequisite", "latch", "release", "return"]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Goal(_Strict):
    state: GoalState
    amount: NonNegative | None = None
    unit: Literal["fraction", "rad", "m"] | None = None
    measured_from: MeasuredFrom = "closed"
    value: Finite | None = None
    """The joint value for ``state: value``."""
    omega_radps: Finite | None = None
    duration_s: NonNegative | None = None
    """Spin time for ``state: velocity``."""
    direction_world: tuple[Finite, Finite, Finite] | None = None
    """The world direction for ``state: toward``; for ``vertical`` / ``flat``, the way the part moves to get there."""

    @model_validator(mode="after")
    def _complete(self) -> Goal:
        if (self.amount is None) != (self.unit is None):
            raise ValueError("amount and unit go together")
        if self.unit == "fraction" and self.amount is not None and self.amount > 1.0 + 1e-9:
            raise ValueError("a fraction amount must be at most 1")
        if self.state == "value" and self.value is None:
            raise ValueError("state 'value' needs value")
        if self.state == "velocity" and self.omega_radps is None:
            raise ValueError("state 'velocity' needs omega_radps")
        if self.state == "toward" and self.direction_world is None:
            raise ValueError("state 'toward' needs direction_world")
        return self


class JointMove(_Strict):
    joint: str
    link: str
    role: Role
    goal: Goal
    release: Release = "stays"
    """What a control does after its actuation: spring back, stay, or stay held while its effect lasts."""
    q: Finite | None = None
    """The resolved target (information for readers; the planner resolves ``goal`` itself)."""


class WheelRoll(_Strict):
    joint: str
    rad_per_m: Finite


class BaseMotion(_Strict):
    """Whole-object motion: a translation and/or a yaw about the vertical through ``pivot_world``."""

    axis_world: tuple[Finite, Finite, Finite] | None = None
    distance_m: NonNegative = 0.0
    yaw_rad: Finite = 0.0
    pivot_world: tuple[Finite, Finite, Finite] | None = None
    speed_mps: NonNegative | None = None
    coast: bool = False
    wheels: list[WheelRoll] = Field(default_factory=list)

    @model_validator(mode="after")
    def _moves(self) -> BaseMotion:
        if self.distance_m > 0 and self.axis_world is None:
            raise ValueError("a translation needs axis_world")
        if self.yaw_rad != 0 and self.pivot_world is None:
            raise ValueError("a yaw needs pivot_world")
        return self


class Step(_Strict):
    id: str
    op: str
    """What the step does (a verb sense: open, press, turn, move, yaw, ...)."""
    why: Why = "asked"
    clause: int | None = None
    """Index of the prompt clause it realises (``None`` for steps the mechanism adds)."""
    start: Literal["after_previous", "with_previous"] = "after_previous"
    wait_before_s: NonNegative = 0.0
    """Seconds before the step starts: after the previous step ends, or, ``with_previous``, after it starts."""
    controls: list[JointMove] = Field(default_factory=list)
    effects: list[JointMove] = Field(default_factory=list)
    base: BaseMotion | None = None
    speed_factor: Annotated[float, Field(gt=0.0, le=10.0, allow_inf_nan=False)] = 1.0
    duration_s: Annotated[float, Field(gt=0.0, le=MAX_STEP_S, allow_inf_nan=False)] | None = None
    hold_s: NonNegative = 0.0
    """Seconds everything stays in its end state before releases and the next step."""
    note: str = ""

    @model_validator(mode="after")
    def _something(self) -> Step:
        if not self.controls and not self.effects and self.base is None:
            raise ValueError(f"step {self.id} moves nothing")
        return self


class Extension(_Strict):
    """The ``artimo`` block of Causal.json."""

    version: Literal[1] = EXTENSION_VERSION
    steps: list[Step] = Field(min_length=1)
