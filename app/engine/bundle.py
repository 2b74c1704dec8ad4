"""Write the output files of one run (SPEC §4) into a folder, each atomically."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.causal import CausalDocument
from app.engine.execute.trajectory import Trajectory
from app.engine.export.glb import export_glb
from app.engine.export.jsonl import write_trajectory_jsonl
from app.engine.export.outputs import write_run_outputs
from app.engine.files import atomic_write_bytes, atomic_write_text
from app.engine.plan.schema import Plan
from app.engine.report import RunReport

PLAN_FILE = "plan.json"
CAUSAL_FILE = "causal.json"
TRAJECTORY_FILE = "trajectory.jsonl"
GLB_FILE = "animation.glb"
REPORT_FILE = "report.json"
PREVIEW_FILE = "preview.gif"


def write_animation(out_dir: Path, asset: ArticulatedAsset, plan: Plan, trajectory: Trajectory, causal: CausalDocument | None = None,
                    exports: Iterable[str] = ()) -> dict[str, str]:
    """Write causal.json (if given), plan.json, trajectory.jsonl, animation.glb, interaction.json and the
    asked-for ``exports`` (usd, mjcf, ros, csv, npz); returns {kind: file name}."""
    out_dir.mkdir(parents=True, exist_ok=True)
    written = {}
    if causal is not None:
        atomic_write_text(out_dir / CAUSAL_FILE, causal.dumps() + "\n")
        written["causal"] = CAUSAL_FILE
    atomic_write_text(out_dir / PLAN_FILE, plan.dumps() + "\n")
    written["plan"] = PLAN_FILE
    write_trajectory_jsonl(trajectory, out_dir / TRAJECTORY_FILE)
    written["trajectory"] = TRAJECTORY_FILE
    export_glb(asset, trajectory, out_dir / GLB_FILE)
    written["glb"] = GLB_FILE
    written.update(write_run_outputs(out_dir, asset, plan, trajectory, causal, exports))
    return written


def write_preview(out_dir: Path, asset: ArticulatedAsset, trajectory: Trajectory) -> str:
    """Render ``preview.gif`` (needs EGL; raises RenderError without it); returns its file name."""
    from app.engine.render.preview import render_preview_gif

    atomic_write_bytes(out_dir / PREVIEW_FILE, render_preview_gif(asset, trajectory))
    return PREVIEW_FILE


def write_report(out_dir: Path, report: RunReport) -> Path:
    return atomic_write_text(out_dir / REPORT_FILE, report.model_dump_json(indent=2) + "\n")
