"""Benchmark cases for the metric tests: a builder on the primitive cabinet and the smoke cases file."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from app.engine.metrics.annotation import Case

SMOKE_CASES = Path(__file__).resolve().parents[1] / "benchmark" / "data" / "smoke_cases.jsonl"
"""Five small cases on real PartNet assets (safe, microwave x2, toaster, storage)."""


def make_case(
    phases: list[dict[str, Any]],
    constraints: list[dict[str, Any]] | None = None,
    relations: list[dict[str, Any]] | None = None,
    **extra: Any,
) -> Case:
    """A case on the cabinet (or ``asset=...``) from its annotation parts."""
    document = {
        "case_id": "test_case",
        "asset": "cabinet",
        "prompt": "test",
        "motion_type": "independent",
        "phases": phases,
        "constraints": constraints or [],
        "relations": relations or [],
    }
    document.update(extra)
    return Case.model_validate(document)
