"""The critic's output: the paper's motion-diagnosis contract (supplementary §2.4).

One vocabulary is shared by the planner, critic and actor: phase types are the
planner's (``control_actuation``, ``causal_latency``, ``control_release``,
``effect_motion``, ``settle``, ``hold``), so a hint scoped to a phase always matches.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field

from app.engine.plan.schema import Control, PhaseType

IssueCode = Literal["WRONG_DIRECTION", "UNEXPECTED_EXTRA_MOTION", "EXCESSIVE_MOTION", "MOTION_TOO_SMALL", "NO_RELEASE_RETURN"]
HintType = Literal["adjust_joint_target", "adjust_joint_velocity", "adjust_timing", "adjust_direction"]
HintDirection = Literal["increase", "decrease", "flip", "zero"]
Strength = Literal["small", "medium", "large", "extra_large"]
ChangeKind = Literal["target", "velocity", "timing"]
UNDO_TOLERANCE = 1e-6
"""Relative difference under which a patched value equals an earlier one."""
STRENGTH_FACTOR: dict[str, float] = {"small": 1.10, "medium": 1.20, "large": 1.35, "extra_large": 2.00}
MAX_FACTOR = 2.0
"""Largest change one hint may make (the extra_large strength)."""
ISSUE_SEVERITY: dict[str, float] = {
    "WRONG_DIRECTION": 3.0, "MOTION_TOO_SMALL": 2.0, "EXCESSIVE_MOTION": 2.0, "UNEXPECTED_EXTRA_MOTION": 2.0, "NO_RELEASE_RETURN": 1.0,
}


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Issue(_Model):
    code: IssueCode
    expected: str
    observed: str
    segment_index: Annotated[int, Field(ge=0)]
    phase_type: PhaseType
    joint: str
    link: str
    severity: float | None = None
    """How far off (0..1, our addition); the loop ranks iterations with it."""


class FixHint(_Model):
    type: HintType
    joint: str
    segment_index: Annotated[int, Field(ge=0)]
    phase_type: PhaseType
    direction: HintDirection
    strength: Strength | None = None
    why: str = ""
    factor: Annotated[float, Field(ge=1.0, le=MAX_FACTOR)] | None = None
    """Our addition: the exact factor for increase/decrease (the geometric critic measures it); the
    actor uses it instead of the strength's factor. Model critics give the strength only."""


class Repairability(_Model):
    param_fixable: bool = True
    structural_fix_needed: bool = False
    preferred_repair_level: Literal["param", "structural"] = "param"


class Critique(_Model):
    """A diagnosis of one executed plan (all checked links/joints together)."""

    semantic_ok: bool = True
    visibility_ok: bool = True
    link_motion_type: Literal["rotational_cw", "rotational_ccw", "prismatic", "static_or_unclear"] = "static_or_unclear"
    detailed_reasoning: str = ""
    repairability: Repairability = Field(default_factory=Repairability)
    issues: list[Issue] = Field(default_factory=list)
    param_fix_hints: list[FixHint] = Field(default_factory=list)
    proposed_param_patch: None = None
    confidence: Annotated[float, Field(ge=0.0, le=1.0)] = 1.0

    @property
    def ok(self) -> bool:
        return not self.issues

    def score(self) -> float:
        """Badness of the diagnosed execution: 0 = nothing wrong (lower is better)."""
        return float(sum(ISSUE_SEVERITY[i.code] * (i.severity if i.severity is not None else 1.0) for i in self.issues))


class Patch(_Model):
    """One change the actor made to a plan (a typed record; report.json lists them per round).

    ``before``/``after`` are the control record of ``joint`` in segment ``segment_index``
    (target and velocity changes); ``span_before``/``span_after`` the segment's
    ``(t0, t1)`` (timing changes, which also shift every later segment). ``value_before`` /
    ``value_after`` is the number that changed: the resolved target (rad or m), the angular
    velocity (rad/s) or the segment's duration (s).
    """

    segment_index: Annotated[int, Field(ge=0)]
    change: ChangeKind
    hint: FixHint
    joint: str | None = None
    value_before: float
    value_after: float
    before: Control | None = None
    after: Control | None = None
    span_before: tuple[float, float] | None = None
    span_after: tuple[float, float] | None = None

    @property
    def key(self) -> tuple[int, str | None, str]:
        return (self.segment_index, self.joint, self.change)

    def undoes(self, earlier: Patch) -> bool:
        """Whether this patch takes ``earlier``'s value back to where it was (the loop would oscillate)."""
        if self.key != earlier.key:
            return False
        return abs(self.value_after - earlier.value_before) <= UNDO_TOLERANCE * max(1.0, abs(earlier.value_before))
