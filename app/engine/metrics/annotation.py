"""Benchmark cases: the paper's annotation schema (supplementary §3.2) plus SPEC §5 fields.

A case is one JSON object (one line of a cases ``.jsonl`` file)::

    {"case_id": "...", "asset": "<folder under the assets root>", "prompt": "...",
     "motion_type": "independent|mechanically_coupled|state_dependent|environment_mediated",
     "phases": [{"id", "order", "duration_s"}],
     "constraints": [{"phase", "subject", "constraints": {...}}],
     "relations": [{"from_phase", "to_phase", "overlap_allowed", "start_rule"}]}

``subject`` is a joint name, a link name, or ``base``.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

MotionType = Literal["independent", "mechanically_coupled", "state_dependent", "environment_mediated"]
MOTION_TYPES: tuple[str, ...] = ("independent", "mechanically_coupled", "state_dependent", "environment_mediated")
DEFAULT_PHASE_DURATION_S = 1.0
DEFAULT_START_PROGRESS = 0.2
BASE_SUBJECT = "base"

Finite = Annotated[float, Field(allow_inf_nan=False)]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Phase(_Strict):
    id: str
    order: int
    duration_s: Annotated[float, Field(gt=0.0, le=30.0, allow_inf_nan=False)] = DEFAULT_PHASE_DURATION_S


class ConstraintFields(_Strict):
    motion: str | None = None
    target_q: Finite | None = None
    displacement_m: Finite | None = None
    direction_axis_world: tuple[Finite, Finite, Finite] | None = None
    omega_radps: Finite | None = None
    return_mode: Literal["self_return"] | None = None
    rest_position_q: Finite | None = None


class Constraint(_Strict):
    phase: str
    subject: str
    constraints: ConstraintFields = Field(default_factory=ConstraintFields)


class StartRule(_Strict):
    to_start_relative_to: Literal["from_progress"] = "from_progress"
    progress: Annotated[float, Field(ge=0.0, le=1.0, allow_inf_nan=False)] = DEFAULT_START_PROGRESS


class Relation(_Strict):
    from_phase: str
    to_phase: str
    overlap_allowed: bool = False
    start_rule: StartRule | None = None


class Case(_Strict):
    """One benchmark case."""

    case_id: str
    asset: str
    prompt: str
    motion_type: MotionType
    phases: Annotated[list[Phase], Field(min_length=1)]
    constraints: list[Constraint] = Field(default_factory=list)
    relations: list[Relation] = Field(default_factory=list)
    notes: str | None = None

    @model_validator(mode="after")
    def _references(self) -> Case:
        ids = [p.id for p in self.phases]
        if len(set(ids)) != len(ids):
            raise ValueError("phase ids must be unique")
        known = set(ids)
        for index, constraint in enumerate(self.constraints):
            if constraint.phase not in known:
                raise ValueError(f"constraints[{index}].phase '{constraint.phase}' is not a phase id")
        for index, relation in enumerate(self.relations):
            for field in ("from_phase", "to_phase"):
                if getattr(relation, field) not in known:
                    raise ValueError(f"relations[{index}].{field} '{getattr(relation, field)}' is not a phase id")
        return self

    def ordered_phases(self) -> list[Phase]:
        """Phases sorted by ``order`` (ties keep file order)."""
        return sorted(self.phases, key=lambda p: p.order)
