"""CSV tables of an evaluation document (cases, states, links, by motion type, overall, timing)."""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from app.engine.files import atomic_write_text

CASE_COLUMNS = ("case_id", "asset", "motion_type", "status", "prediction")


def _cell(value: Any) -> Any:
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, list):
        return " ".join(str(v) for v in value)
    return value


def write_csv(path: Path, header: Sequence[str], rows: Sequence[Sequence[Any]]) -> Path:
    """Write a CSV (``\\n`` line ends, floats in full precision, ``None`` as empty)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(header)
    for row in rows:
        writer.writerow([_cell(v) for v in row])
    return atomic_write_text(path, buffer.getvalue())


def case_rows(document: dict[str, Any]) -> tuple[list[str], list[list[Any]]]:
    metrics = document["summary"]["metrics"]
    header = [*CASE_COLUMNS, *metrics, "matched_frames", "padded", "error"]
    rows = [
        [c.get(k) for k in CASE_COLUMNS] + [c.get(m) for m in metrics] + [c["matched_frames"], c["padded"], c["error"]]
        for c in document["cases"]
    ]
    return header, rows


def state_rows(document: dict[str, Any]) -> tuple[list[str], list[list[Any]]]:
    metrics = document["summary"]["metrics"]
    header = [
        "case_id",
        "state",
        "phase",
        "gt_frame",
        "gt_time_s",
        "pred_frame",
        "pred_time_s",
        "dynamic_links",
        *metrics,
    ]
    rows = []
    for case in document["cases"]:
        for s in case["states"]:
            head = [
                case["case_id"],
                s["index"],
                s["phase"],
                s["gt_frame"],
                s["gt_time_s"],
                s["pred_frame"],
                s["pred_time_s"],
                s["dynamic_links"],
            ]
            rows.append(head + [s["values"].get(m) for m in metrics])
    return header, rows


def link_rows(document: dict[str, Any]) -> tuple[list[str], list[list[Any]]]:
    metrics = document["summary"]["metrics"]
    header = ["case_id", "state", "link", "dynamic", "missing", *metrics]
    rows = []
    for case in document["cases"]:
        for s in case["states"]:
            for link in s["links"]:
                rows.append(
                    [case["case_id"], s["index"], link["link"], link["dynamic"], link["missing"]]
                    + [link["values"].get(m) for m in metrics]
                )
    return header, rows


def _stat_cells(stats: dict[str, Any], metrics: Sequence[str]) -> list[Any]:
    cells: list[Any] = []
    for metric in metrics:
        entry = stats.get(metric)
        cells.extend([None, None] if entry is None else [entry["mean"], entry["std"]])
    return cells


def group_rows(document: dict[str, Any]) -> tuple[list[str], list[list[Any]], list[list[Any]]]:
    """(header, rows by motion type, overall row) of the summary."""
    summary = document["summary"]
    metrics = summary["metrics"]
    header = ["group", "n"] + [f"{m}_{s}" for m in metrics for s in ("mean", "std")]
    by_type = [[t, stats["n"], *_stat_cells(stats, metrics)] for t, stats in summary["by_motion_type"].items()]
    overall = [["overall", summary["overall"]["n"], *_stat_cells(summary["overall"], metrics)]]
    return header, by_type, overall


def timing_stages(timing: dict[str, Any]) -> list[str]:
    """Stage names of a timing sidecar, sorted, ``total`` last."""
    return [*sorted({stage for entry in timing["cases"] for stage in entry["timing_s"]} - {"total"}), "total"]


def timing_rows(timing: dict[str, Any]) -> tuple[list[str], list[list[Any]]]:
    stages = timing_stages(timing)
    rows = [[entry["case_id"], *(entry["timing_s"].get(stage) for stage in stages)] for entry in timing["cases"]]
    return ["case_id", *stages], rows


def write_tables(document: dict[str, Any], timing: dict[str, Any] | None, folder: Path) -> list[Path]:
    """Every CSV of the report into ``folder``; returns the written paths."""
    written = [
        write_csv(folder / "cases.csv", *case_rows(document)),
        write_csv(folder / "states.csv", *state_rows(document)),
        write_csv(folder / "links.csv", *link_rows(document)),
    ]
    header, by_type, overall = group_rows(document)
    written.append(write_csv(folder / "by_motion_type.csv", header, by_type))
    written.append(write_csv(folder / "overall.csv", header, overall))
    if timing is not None:
        written.append(write_csv(folder / "timing.csv", *timing_rows(timing)))
    return written
