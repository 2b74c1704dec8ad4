"""Causal.json: the perceiver contract (paper supplementary §2.1) as pydantic models."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from app.engine.contracts.steps import Extension
from app.engine.errors import ExpressionError
from app.engine.plan.expr import parse_expr, parse_velocity

AXES_WORLD: tuple[tuple[float, float, float], ...] = (
    (1.0, 0.0, 0.0),
    (-1.0, 0.0, 0.0),
    (0.0, 1.0, 0.0),
    (0.0, -1.0, 0.0),
    (0.0, 0.0, 1.0),
    (0.0, 0.0, -1.0),
)
ReturnBehavior = Literal["self_return", "stays", "unknown"]
Confidence = Annotated[float, Field(ge=0.0, le=1.0, allow_inf_nan=False)]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class LinkSemantic(_Strict):
    name: str
    label: str
    affordance: list[str] = Field(default_factory=list)
    conf: Confidence = 0.0
    description: str = ""


class Semantics(_Strict):
    links: list[LinkSemantic] = Field(default_factory=list)


class Action(_Strict):
    primitive: str
    target_link: str
    target_links: list[str] = Field(default_factory=list)
    target_role: Literal["control", "direct_object"]
    magnitude: Annotated[float, Field(allow_inf_nan=False)] | None = None
    direction_axis_world: tuple[float, float, float] | None = None
    control_return_behavior: ReturnBehavior = "unknown"

    @field_validator("direction_axis_world")
    @classmethod
    def _signed_unit_axis(cls, value: tuple[float, float, float] | None) -> tuple[float, float, float] | None:
        if value is not None and tuple(float(v) for v in value) not in AXES_WORLD:
            raise ValueError(f"direction_axis_world must be one of {[list(a) for a in AXES_WORLD]}")
        return value

    @model_validator(mode="after")
    def _primary_first(self) -> Action:
        if self.target_links and self.target_link not in self.target_links:
            raise ValueError("target_link must appear in target_links")
        return self


class JointTarget(_Strict):
    joint: str
    to: str | float

    @field_validator("to")
    @classmethod
    def _target(cls, value: str | float) -> str | float:
        if isinstance(value, str):
            if value.strip().startswith("velocity"):
                if parse_velocity(value) is None:
                    raise ValueError(f"velocity target {value!r} must be velocity:<number>")
            else:
                try:
                    parse_expr(value)
                except ExpressionError as exc:  # a ValueError lets pydantic report the field path
                    raise ValueError(exc.message) from exc
        return value

    @property
    def velocity(self) -> float | None:
        return parse_velocity(self.to) if isinstance(self.to, str) else None


class ModeFlag(_Strict):
    name: str
    set: bool


class Effects(_Strict):
    effect_links: list[str] = Field(default_factory=list)
    joint_targets: list[JointTarget] = Field(default_factory=list)
    modes: list[ModeFlag] = Field(default_factory=list)
    coupling_rules: list[str] = Field(default_factory=list)


class Causal(_Strict):
    has_causal: bool
    action: Action | None = None
    effects: Effects | None = None

    @model_validator(mode="after")
    def _consistent(self) -> Causal:
        if not self.has_causal and (self.action is not None or self.effects is not None):
            raise ValueError("has_causal=false requires action and effects to be null")
        if self.has_causal and self.action is None:
            raise ValueError("has_causal=true requires an action")
        return self


class TimeHint(_Strict):
    order_index: Annotated[int, Field(ge=0)]
    overlap_ok: bool = False


class CausalSegment(_Strict):
    segment_id: str
    time_hint: TimeHint
    action: Action
    effects: Effects | None = None


class CausalDocument(_Strict):
    """A Causal.json document."""

    semantics: Semantics = Field(default_factory=Semantics)
    causal: Causal
    causal_segments: list[CausalSegment] | None = None
    artimo: Extension | None = None
    """Our extension block (:mod:`app.engine.contracts.steps`): the lossless step list the planners read."""

    def all_joint_targets(self) -> list[JointTarget]:
        """Joint targets of the top level and every segment, in order."""
        targets = list(self.causal.effects.joint_targets) if self.causal.effects else []
        for segment in self.causal_segments or []:
            if segment.effects:
                targets.extend(segment.effects.joint_targets)
        return targets

    def dumps(self) -> str:
        return self.model_dump_json(indent=2)
