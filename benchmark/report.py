"""``write_report``: an evaluation's JSON -> ``report.md`` + CSV tables + PNG charts (+ contact sheets).

Layout of the report folder::

    report.md            overall and by-motion-type tables (mean +- std), statuses,
                         per-case scores with matched frames and time, errors, timings
    cases.csv  states.csv  links.csv  by_motion_type.csv  overall.csv  timing.csv
    by_motion_type.png  distribution.png  timing.png
    sheets/<case_id>.png GT vs predicted key states (only with ``contact_sheets=True``)
"""

from __future__ import annotations

import json
import logging
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.errors import MetricError
from app.engine.files import atomic_write_text
from app.engine.metrics.prediction import read_node_map
from benchmark.runner import timing_path
from benchmark.tables import timing_stages, write_tables

logger = logging.getLogger(__name__)

MOTION_TYPE_LABELS = {
    "independent": "Independent",
    "mechanically_coupled": "Mech. coupled",
    "state_dependent": "State-dependent",
    "environment_mediated": "Env.-mediated",
}


def _fmt(value: Any, digits: int = 3) -> str:
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.{digits}f}"
    return str(value)


def _pm(entry: dict[str, float] | None) -> str:
    return "-" if entry is None else f"{entry['mean']:.3f} ± {entry['std']:.3f}"


def _table(header: Sequence[str], rows: Sequence[Sequence[str]]) -> list[str]:
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines.extend("| " + " | ".join(row) + " |" for row in rows)
    return lines


def _summary_section(document: dict[str, Any]) -> list[str]:
    summary = document["summary"]
    metrics = summary["metrics"]
    rows = [
        [MOTION_TYPE_LABELS.get(t, t), str(s["n"]), *(_pm(s.get(m)) for m in metrics)]
        for t, s in summary["by_motion_type"].items()
    ]
    rows.append(["**Overall**", str(summary["overall"]["n"]), *(_pm(summary["overall"].get(m)) for m in metrics)])
    statuses = ", ".join(f"{k}: {v}" for k, v in summary["by_status"].items())
    settings = ", ".join(f"{k}={json.dumps(v)}" for k, v in summary["settings"].items())
    lines = ["## Scores by motion type (mean ± std)", ""]
    lines += _table(["Type", "N", *metrics], rows)
    lines += [
        "",
        f"Cases: {summary['cases']} ({statuses}); means count every case but `case_error`.",
        "",
        f"Settings: {settings}",
        "",
    ]
    return lines


def _case_section(document: dict[str, Any], timing: dict[str, Any] | None, sheets: dict[str, str]) -> list[str]:
    metrics = document["summary"]["metrics"]
    seconds = {} if timing is None else {e["case_id"]: e["timing_s"].get("total") for e in timing["cases"]}
    rows = []
    for case in document["cases"]:
        frames = "-" if case["matched_frames"] is None else " ".join(str(f) for f in case["matched_frames"])
        gt_frames = " ".join(str(s["gt_frame"]) for s in case["states"]) or "-"
        sheet = f"[sheet]({sheets[case['case_id']]})" if case["case_id"] in sheets else ""
        rows.append(
            [
                case["case_id"],
                case["motion_type"],
                case["status"],
                *(_fmt(case.get(m)) for m in metrics),
                gt_frames,
                frames,
                _fmt(seconds.get(case["case_id"]), 2),
                sheet,
            ]
        )
    lines = ["## Cases", ""]
    lines += _table(["Case", "Type", "Status", *metrics, "GT key frames", "Matched frames", "Time (s)", ""], rows)
    errors = [(c["case_id"], c["status"], c["error"]) for c in document["cases"] if c["error"]]
    if errors:
        lines += ["", "### Errors", "", *(f"- `{cid}` ({status}): {text}" for cid, status, text in errors)]
    return [*lines, ""]


def _timing_section(timing: dict[str, Any]) -> list[str]:
    stages = timing_stages(timing)
    rows = []
    for stage in stages:
        values = np.array([e["timing_s"].get(stage, 0.0) for e in timing["cases"]])
        rows.append([stage, f"{values.mean():.3f}", f"{np.median(values):.3f}", f"{values.max():.3f}"])
    lines = [
        "## Timing (seconds per case)",
        "",
        f"Wall time {timing['wall_s']:.2f} s with {timing['jobs']} job(s).",
        "",
    ]
    return lines + _table(["Stage", "Mean", "Median", "Max"], rows) + [""]


def render_markdown(
    document: dict[str, Any], timing: dict[str, Any] | None, charts: Sequence[str], sheets: dict[str, str]
) -> str:
    """The text of ``report.md``."""
    lines = ["# ArtiMo benchmark report", ""]
    lines += _summary_section(document)
    lines += [f"![{Path(c).stem}]({c})" for c in charts] + [""]
    lines += _case_section(document, timing, sheets)
    if timing is not None:
        lines += _timing_section(timing)
    return "\n".join(lines)


def _load(path: Path) -> dict[str, Any]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise MetricError(f"cannot read {path}: {exc}") from exc
    if not isinstance(data, dict):
        raise MetricError(f"{path}: expected a JSON object")
    return data


def write_report(
    out_json: str | Path,
    report_dir: str | Path | None = None,
    *,
    charts: bool = True,
    contact_sheets: bool = False,
    cases_file: str | Path | None = None,
    assets_root: str | Path | None = None,
    pred_root: str | Path | None = None,
    node_map: str | Path | None = None,
) -> Path:
    """Write the report of an :func:`benchmark.runner.evaluate` output; returns ``report.md``'s path.

    ``contact_sheets`` renders GT vs predicted key states per case and needs
    ``cases_file``, ``assets_root`` and ``pred_root`` (and ``node_map`` if one was used:
    the evaluation's inputs) and the renderer.

    Raises
    ------
    MetricError
        Unreadable inputs, or contact sheets asked for without their inputs.
    """
    source = Path(out_json)
    folder = Path(report_dir) if report_dir is not None else source.parent / "report"
    folder.mkdir(parents=True, exist_ok=True)
    document = _load(source)
    timing = _load(timing_path(source)) if timing_path(source).is_file() else None
    write_tables(document, timing, folder)
    drawn: list[str] = []
    if charts:
        from benchmark.charts import distribution_chart, motion_type_chart, timing_chart

        drawn = [
            motion_type_chart(document, folder / "by_motion_type.png").name,
            distribution_chart(document, folder / "distribution.png").name,
        ]
        if timing is not None:
            drawn.append(timing_chart(timing, folder / "timing.png").name)
    sheets: dict[str, str] = {}
    if contact_sheets:
        if cases_file is None or assets_root is None or pred_root is None:
            raise MetricError("contact sheets need cases_file, assets_root and pred_root")
        from benchmark.sheets import write_contact_sheets

        mapping = None if node_map is None else read_node_map(node_map)
        sheets = write_contact_sheets(
            document, Path(cases_file), Path(assets_root), Path(pred_root), folder / "sheets", mapping
        )
    return atomic_write_text(folder / "report.md", render_markdown(document, timing, drawn, sheets))
