"""Typed results of scoring one case (serialised as the benchmark's JSON)."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict

METRICS_3D: tuple[str, ...] = ("P_gIoU", "P_PC", "P_OccF1")
METRICS_2D: tuple[str, ...] = ("P_MaskIoU", "P_BoundaryF1", "P_ContourCD")
WORST: dict[str, float] = {
    "P_gIoU": -1.0,
    "P_PC": 0.0,
    "P_OccF1": 0.0,
    "P_MaskIoU": 0.0,
    "P_BoundaryF1": 0.0,
    "P_ContourCD": 1.0,
}
"""Score of a missing link (and of a case without a usable prediction)."""
HIGHER_IS_BETTER: dict[str, bool] = {name: name != "P_ContourCD" for name in WORST}


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")


class LinkScores(_Frozen):
    """One link in one matched state pair; ``values`` maps metric name -> value."""

    link: str
    dynamic: bool
    missing: bool
    values: dict[str, float]


class StateScores(_Frozen):
    """One GT key state and the predicted frame it was matched to."""

    index: int
    phase: str
    gt_frame: int
    gt_time_s: float
    pred_frame: int | None
    pred_time_s: float | None
    dynamic_links: list[str]
    values: dict[str, float]
    """State score per metric: 0.8 x mean(dynamic) + 0.2 x mean(static)."""
    links: list[LinkScores]


class CaseScores(_Frozen):
    """Scores of one case (3D, and 2D when requested)."""

    values: dict[str, float]
    """Case score per metric: mean of the state scores (terminal check applied when on)."""
    states: list[StateScores]
    matched_frames: list[int] | None
    padded: bool
    terminal: dict[str, float] | None = None
    """Terminal-state scores when the terminal check is on."""
