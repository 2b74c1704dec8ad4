"""A small benchmark on real PartNet assets: the smoke cases plus one broken case, and predictions."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from support.metric_cases import SMOKE_CASES

from app.engine.asset.loader import load_asset
from app.engine.export.glb import export_glb
from app.engine.export.jsonl import write_trajectory_jsonl
from app.engine.metrics.compiler import compile_case
from benchmark.cases import read_cases
from benchmark.synthetic import degraded_trajectories

BROKEN = {
    "case_id": "broken_subject",
    "asset": "safe_101593",
    "prompt": "x",
    "motion_type": "independent",
    "phases": [{"id": "p", "order": 0}],
    "constraints": [{"phase": "p", "subject": "no_such_joint", "constraints": {"target_q": 1.0}}],
}


@pytest.fixture(scope="session")
def bench(tmp_path_factory: pytest.TempPathFactory, partnet: Path) -> dict[str, Path]:
    """{"cases", "assets", "pred"}: predictions are perfect (safe, jsonl), half-way (microwave door),
    missing (microwave tray), perfect GLB (toaster) and unreadable (storage)."""
    root = tmp_path_factory.mktemp("bench")
    cases_file = root / "cases.jsonl"
    cases_file.write_text(SMOKE_CASES.read_text() + json.dumps(BROKEN) + "\n")
    pred = root / "pred"
    for case in read_cases(SMOKE_CASES):
        asset = load_asset(partnet / case.asset)
        truth = compile_case(case, asset)
        folder = pred / case.case_id
        if case.case_id == "safe_101593_open_door":
            write_trajectory_jsonl(truth.trajectory, folder / "trajectory.jsonl")
        elif case.case_id == "microwave_7119_open_door":
            write_trajectory_jsonl(degraded_trajectories(asset, truth)["half_way"], folder / "trajectory.jsonl")
        elif case.case_id == "toaster_103477_press_lever":
            export_glb(asset, truth.trajectory, folder / "animation.glb")
        elif case.case_id == "storage_19179_lift":
            folder.mkdir(parents=True)
            (folder / "trajectory.jsonl").write_text('{"joint_angles": {"joint_0": "open"}}\n')
    return {"cases": cases_file, "assets": partnet, "pred": pred}
