"""Read a benchmark cases file: JSON Lines, one :class:`Case` per non-blank line."""

from __future__ import annotations

import json
from pathlib import Path

from pydantic import ValidationError

from app.engine.errors import MetricError
from app.engine.metrics.annotation import Case
from app.engine.plan.checks import pydantic_issues

UNSAFE_ID_CHARACTERS = ("/", "\\", "\0")


def parse_case_line(line: str, where: str) -> Case:
    """One case from one JSON line.

    Raises
    ------
    MetricError
        Not JSON, or not a valid case (every problem listed with its field path).
    """
    try:
        raw = json.loads(line)
    except json.JSONDecodeError as exc:
        raise MetricError(f"{where}: not JSON ({exc.msg})") from exc
    try:
        case = Case.model_validate(raw)
    except ValidationError as exc:
        label = raw.get("case_id") if isinstance(raw, dict) else None
        issues = "; ".join(pydantic_issues(exc))
        raise MetricError(f"{where}{f' (case {label})' if label else ''}: {issues}") from exc
    if any(c in case.case_id for c in UNSAFE_ID_CHARACTERS) or case.case_id in ("", ".", ".."):
        raise MetricError(f"{where}: case_id '{case.case_id}' cannot name a prediction folder")
    if any(c in case.asset for c in UNSAFE_ID_CHARACTERS) or case.asset in ("", ".", ".."):
        raise MetricError(f"{where}: asset '{case.asset}' must be a folder name under the assets root")
    return case


def read_cases(path: str | Path) -> list[Case]:
    """Every case of a ``.jsonl`` file, in file order.

    Raises
    ------
    MetricError
        Unreadable file, an invalid line (named by number), duplicate case ids, or no cases.
    """
    source = Path(path)
    try:
        text = source.read_text(encoding="utf-8")
    except OSError as exc:
        raise MetricError(f"cannot read cases file {source}: {exc}") from exc
    cases: list[Case] = []
    seen: dict[str, int] = {}
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        case = parse_case_line(line, f"{source.name} line {number}")
        if case.case_id in seen:
            raise MetricError(
                f"{source.name} line {number}: case_id '{case.case_id}' repeats line {seen[case.case_id]}"
            )
        seen[case.case_id] = number
        cases.append(case)
    if not cases:
        raise MetricError(f"{source.name}: no cases")
    return cases
