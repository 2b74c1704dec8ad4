"""PNG charts of an evaluation (matplotlib, Agg backend; imported only when charts are drawn)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from benchmark.tables import timing_stages

CHART_DPI = 110
PNG_METADATA = {"Software": None}
"""No version/date stamps, so the same data gives the same file."""


def _pyplot() -> Any:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def motion_type_chart(document: dict[str, Any], path: Path) -> Path:
    """Grouped bars: mean +- std of every higher-is-better metric per motion type and overall."""
    plt = _pyplot()
    summary = document["summary"]
    metrics = [m for m in summary["metrics"] if m != "P_ContourCD"]
    groups = [*summary["by_motion_type"].items(), ("overall", summary["overall"])]
    width = 0.8 / max(len(metrics), 1)
    figure, axes = plt.subplots(figsize=(max(6.0, 1.6 * len(groups)), 4.0))
    x = np.arange(len(groups))
    for i, metric in enumerate(metrics):
        means = [(g[1].get(metric) or {}).get("mean", np.nan) for g in groups]
        stds = [(g[1].get(metric) or {}).get("std", 0.0) for g in groups]
        axes.bar(x + (i - (len(metrics) - 1) / 2) * width, means, width, yerr=stds, capsize=2, label=metric)
    axes.set_xticks(x, [f"{name}\n(n={stats['n']})" for name, stats in groups], fontsize=8)
    axes.set_ylim(-1.05 if "P_gIoU" in metrics else 0.0, 1.05)
    axes.axhline(0.0, color="black", linewidth=0.6)
    axes.set_title("Scores by motion type (mean +- std)")
    axes.legend(fontsize=8, loc="lower right")
    figure.tight_layout()
    figure.savefig(path, dpi=CHART_DPI, metadata=PNG_METADATA)
    plt.close(figure)
    return path


def distribution_chart(document: dict[str, Any], path: Path) -> Path:
    """One histogram of per-case scores per metric (cases with scores only)."""
    plt = _pyplot()
    metrics = document["summary"]["metrics"]
    figure, axes = plt.subplots(1, len(metrics), figsize=(3.2 * len(metrics), 3.0), squeeze=False)
    for axis, metric in zip(axes[0], metrics, strict=True):
        values = [c[metric] for c in document["cases"] if c.get(metric) is not None]
        low = -1.0 if metric == "P_gIoU" else 0.0
        axis.hist(values, bins=20, range=(low, 1.0), color="#4477aa")
        axis.set_title(metric, fontsize=9)
        axis.set_xlabel("case score", fontsize=8)
    axes[0][0].set_ylabel("cases", fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=CHART_DPI, metadata=PNG_METADATA)
    plt.close(figure)
    return path


def timing_chart(timing: dict[str, Any], path: Path) -> Path:
    """Mean seconds per case and stage (horizontal bars)."""
    plt = _pyplot()
    stages = timing_stages(timing)
    means = [float(np.mean([entry["timing_s"].get(s, 0.0) for entry in timing["cases"]])) for s in stages]
    figure, axes = plt.subplots(figsize=(6.0, 0.4 * len(stages) + 1.2))
    axes.barh(stages, means, color="#228833")
    axes.set_xlabel("seconds per case (mean)")
    axes.set_title(
        f"Timing: {len(timing['cases'])} cases, {timing['wall_s']:.1f} s wall, {timing['jobs']} job(s)", fontsize=9
    )
    figure.tight_layout()
    figure.savefig(path, dpi=CHART_DPI, metadata=PNG_METADATA)
    plt.close(figure)
    return path
