"""Plan.json: the planner contract (paper supplementary §2.2) as pydantic models.

Control records accept only their listed fields; enumerations (mode, phase_type,
curve) and the contract's numeric ranges are enforced. ``physics`` and
``timing_checks`` keep unknown keys (reported as warnings by ``checks``).
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationInfo, field_validator, model_validator

from app.engine.errors import ExpressionError
from app.engine.plan.expr import parse_expr, parse_velocity

FPS_CHOICES = (24, 30)
MIN_DURATION_S = 1.0
MAX_DURATION_S = 8.0
MAX_TIMELINE_S = 60.0
"""Hard cap on any ``t1`` (the timeline may run past ``duration_s``, which then grows)."""
MAX_OMEGA_RADPS = 20.0
MAX_SPRING_K = 20.0
MAX_DAMPING_C = 5.0
MAX_BASE_SPEED_MPS = 20.0
MAX_TAU_S = 100.0
AXIS_EPS = 1e-9

PhaseType = Literal["control_actuation", "causal_latency", "control_release", "effect_motion", "settle", "hold"]
Curve = Literal["linear", "ease_in", "ease_out", "ease_in_out"]

Finite = Annotated[float, Field(allow_inf_nan=False)]
Omega = Annotated[float, Field(ge=-MAX_OMEGA_RADPS, le=MAX_OMEGA_RADPS, allow_inf_nan=False)]
Tau = Annotated[float, Field(gt=0.0, le=MAX_TAU_S, allow_inf_nan=False)]
Speed = Annotated[float, Field(ge=-MAX_BASE_SPEED_MPS, le=MAX_BASE_SPEED_MPS, allow_inf_nan=False)]
Axis = tuple[Finite, Finite, Finite]


class _Control(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


def _check_axis(axis: tuple[float, float, float]) -> tuple[float, float, float]:
    if math.sqrt(sum(a * a for a in axis)) < AXIS_EPS:
        raise ValueError("axis_world must not be the zero vector")
    return axis


class BaseVelocity(_Control):
    mode: Literal["base_velocity"]
    axis_world: Axis
    v_mps: Speed

    _axis = field_validator("axis_world")(_check_axis)


class BaseVelocityDecay(_Control):
    mode: Literal["base_velocity_decay"]
    axis_world: Axis
    v0_mps: Speed
    tau_s: Tau

    _axis = field_validator("axis_world")(_check_axis)


class BaseYawRate(_Control):
    """Our extension: the whole object turns about the world vertical through ``pivot_world``
    at ``omega_radps`` (counter-clockwise seen from above is positive)."""

    mode: Literal["base_yaw_rate"]
    omega_radps: Omega
    pivot_world: Axis = (0.0, 0.0, 0.0)


class Decay(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    type: Literal["exponential"] = "exponential"
    tau_s: Tau
    min_omega_radps: Annotated[float, Field(ge=0.0, le=MAX_OMEGA_RADPS, allow_inf_nan=False)] = 0.0


class JointVelocity(_Control):
    mode: Literal["joint_velocity"]
    joint: str
    omega_radps: Omega
    ramp_to_omega_radps: Omega | None = None
    decay: Decay | None = None


class JointPosition(_Control):
    mode: Literal["joint_position"]
    joint: str
    q_target_expr: str | None = None
    q_target_rad: Finite | None = None
    q_start_rad: Finite | None = None
    curve: Curve = "linear"

    @field_validator("q_target_expr")
    @classmethod
    def _parse(cls, value: str | None) -> str | None:
        if value is not None:
            try:
                parse_expr(value)
            except ExpressionError as exc:  # a ValueError lets pydantic report the field path
                raise ValueError(exc.message) from exc
        return value

    @model_validator(mode="after")
    def _has_target(self) -> JointPosition:
        if self.q_target_expr is None and self.q_target_rad is None:
            raise ValueError("joint_position needs q_target_expr or q_target_rad")
        return self


class HoldPosition(_Control):
    mode: Literal["hold_position"]
    joint: str


class SpringReturn(_Control):
    mode: Literal["spring_return"]
    joint: str
    spring_k: Annotated[float, Field(ge=0.0, le=MAX_SPRING_K, allow_inf_nan=False)] | None = None
    damping_c: Annotated[float, Field(ge=0.0, le=MAX_DAMPING_C, allow_inf_nan=False)] | None = None
    rest_position: Finite | None = None


class ModeSet(_Control):
    mode: Literal["mode_set"]
    name: str
    set: bool


Control = Annotated[
    BaseVelocity | BaseVelocityDecay | BaseYawRate | JointVelocity | JointPosition | HoldPosition | SpringReturn | ModeSet,
    Field(discriminator="mode"),
]
JOINT_CONTROLS = (JointVelocity, JointPosition, HoldPosition, SpringReturn)


def _velocity_target_to_control(raw: Any) -> Any:
    """A ``joint_position`` whose target is ``velocity:<n>`` becomes ``joint_velocity`` (SPEC §2)."""
    if not isinstance(raw, dict) or raw.get("mode") != "joint_position":
        return raw
    target = raw.get("q_target_expr")
    omega = parse_velocity(target) if isinstance(target, str) else None
    if omega is None:
        return raw
    return {"mode": "joint_velocity", "joint": raw.get("joint"), "omega_radps": omega}


class Segment(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    name: str
    phase_type: PhaseType
    t0: Annotated[float, Field(ge=0.0, le=MAX_TIMELINE_S, allow_inf_nan=False)]
    t1: Annotated[float, Field(gt=0.0, le=MAX_TIMELINE_S, allow_inf_nan=False)]
    controls: list[Control] = Field(default_factory=list)

    @field_validator("controls", mode="before")
    @classmethod
    def _velocity_targets(cls, value: Any) -> Any:
        return [_velocity_target_to_control(c) for c in value] if isinstance(value, list) else value

    @field_validator("t1")
    @classmethod
    def _ordered(cls, t1: float, info: ValidationInfo) -> float:
        t0 = info.data.get("t0")
        if t0 is not None and t0 >= t1:
            raise ValueError(f"t1 ({t1}) must be greater than t0 ({t0})")
        return t1


class Meta(BaseModel):
    model_config = ConfigDict(extra="allow", frozen=True)
    fps: Literal[24, 30] = 30
    duration_s: Annotated[float, Field(ge=MIN_DURATION_S, le=MAX_DURATION_S, allow_inf_nan=False)]


class JointDynamics(BaseModel):
    model_config = ConfigDict(extra="allow", frozen=True)
    joint: str
    spring_k: Annotated[float, Field(ge=0.0, le=MAX_SPRING_K, allow_inf_nan=False)] | None = None
    damping_c: Annotated[float, Field(ge=0.0, le=MAX_DAMPING_C, allow_inf_nan=False)] | None = None
    rest_position: Finite | None = None


class Physics(BaseModel):
    model_config = ConfigDict(extra="allow", frozen=True)
    joint_dynamics: list[JointDynamics] = Field(default_factory=list)


class TimingChecks(BaseModel):
    model_config = ConfigDict(extra="allow", frozen=True)
    control_onset_time: Finite | None = None
    control_peak_time: Finite | None = None
    effect_start_time: Finite | None = None
    enforced_delay_s: Finite | None = None


class Plan(BaseModel):
    """A Plan.json document."""

    model_config = ConfigDict(extra="allow", frozen=True)
    meta: Meta
    physics: Physics = Field(default_factory=Physics)
    timeline: Annotated[list[Segment], Field(min_length=1)]
    timing_checks: TimingChecks | None = None

    @property
    def duration_s(self) -> float:
        """max(meta.duration_s, max t1) (SPEC §3)."""
        return max(self.meta.duration_s, max(s.t1 for s in self.timeline))

    def dumps(self) -> str:
        """Canonical JSON text (stable key order, 2-space indent)."""
        return self.model_dump_json(indent=2, exclude_none=True)
