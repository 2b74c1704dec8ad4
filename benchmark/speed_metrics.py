"""Time the evaluator: ``python -m benchmark.speed_metrics [--assets ROOT] [--cases FILE] [--with-2d]``.

Without ``--cases`` every asset under ROOT gets a synthetic case that moves each
controllable joint in turn (up to ``MAX_PHASES``) and then holds. Each case is scored
against a ``half_way`` prediction (nothing coincides with the ground truth, so no pose
shortcut applies: the slow path) and the ``perfect`` one. Prints one line per case and
a summary: seconds per case for 3D (and 2D), with asset loading and per-asset sampling
reported separately (they are cached across cases of the same asset).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path
from typing import Any

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import MetricError
from app.engine.metrics.annotation import Case
from app.engine.metrics.compiler import compile_case
from app.engine.metrics.geometry import build_geometry
from app.engine.metrics.scoring import score_case
from app.engine.metrics.sequence import trajectory_sequence
from benchmark.cases import read_cases
from benchmark.paths import assets_or_partnet
from benchmark.synthetic import degraded_trajectories

MAX_PHASES = 6


def synthetic_case(asset: ArticulatedAsset) -> Case:
    """Move every controllable joint (at most ``MAX_PHASES``) one after the other, then hold."""
    phases: list[dict[str, Any]] = []
    constraints: list[dict[str, Any]] = []
    for name in asset.controllable_joints[:MAX_PHASES]:
        joint = asset.joints[name]
        phase = f"move_{name}"
        phases.append({"id": phase, "order": len(phases), "duration_s": 0.8})
        if joint.bounded and joint.upper is not None and joint.lower is not None:
            target = joint.lower + 0.7 * (joint.upper - joint.lower)
            constraints.append({"phase": phase, "subject": name, "constraints": {"target_q": target}})
        else:
            constraints.append({"phase": phase, "subject": name, "constraints": {"omega_radps": 2.0}})
    if not phases:
        phases.append({"id": "lift", "order": 0, "duration_s": 1.0})
        constraints.append(
            {
                "phase": "lift",
                "subject": "base",
                "constraints": {"displacement_m": 0.2, "direction_axis_world": [0, 0, 1]},
            }
        )
    phases.append({"id": "hold_end_state", "order": len(phases), "duration_s": 0.3})
    return Case.model_validate(
        {
            "case_id": f"speed_{asset.name}",
            "asset": asset.name,
            "prompt": "synthetic",
            "motion_type": "independent",
            "phases": phases,
            "constraints": constraints,
        }
    )


def _time_case(case: Case, asset: ArticulatedAsset, geometry: Any, with_2d: bool) -> dict[str, float]:
    start = time.perf_counter()
    truth = compile_case(case, asset)
    row = {"compile": time.perf_counter() - start}
    predictions = degraded_trajectories(asset, truth)
    for name in ("half_way", "perfect"):
        start = time.perf_counter()
        sequence = trajectory_sequence(asset, predictions[name], name)
        scores = score_case(asset, geometry, truth, sequence)
        row[f"3d_{name}"] = time.perf_counter() - start
        row[f"gIoU_{name}"] = scores.values["P_gIoU"]
        if with_2d:
            from app.engine.metrics.scores2d import add_2d_scores

            start = time.perf_counter()
            add_2d_scores(asset, geometry, truth, sequence, scores)
            row[f"2d_{name}"] = time.perf_counter() - start
    return row


def _say(line: str) -> None:
    sys.stdout.write(line + "\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--assets", type=Path, default=None, help="assets root (default: $ARTIMO_PARTNET_ROOT, else ../shared/assets/partnet)")
    parser.add_argument("--cases", type=Path, default=None, help="cases .jsonl (default: one synthetic case per asset)")
    parser.add_argument("--with-2d", action="store_true")
    args = parser.parse_args(argv)
    try:
        args.assets = assets_or_partnet(args.assets)
    except MetricError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 2
    if args.cases is not None:
        cases = read_cases(args.cases)
    else:
        cases = [
            synthetic_case(load_asset(folder))
            for folder in sorted(args.assets.iterdir())
            if (folder / "mobility.urdf").is_file()
        ]
    cache: dict[str, tuple[ArticulatedAsset, Any, float, float]] = {}
    rows = []
    for case in cases:
        if case.asset not in cache:
            start = time.perf_counter()
            asset = load_asset(args.assets / case.asset)
            loaded = time.perf_counter()
            cache[case.asset] = (asset, build_geometry(asset), loaded - start, time.perf_counter() - loaded)
        asset, geometry, load_s, geometry_s = cache[case.asset]
        row = {"load": load_s, "geometry": geometry_s, **_time_case(case, asset, geometry, args.with_2d)}
        rows.append(row)
        links, states = len(geometry.links), len(compile_case(case, asset).key_states)
        extra = f" 2d half/perfect {row['2d_half_way']:.3f}/{row['2d_perfect']:.3f}" if args.with_2d else ""
        _say(
            f"{case.case_id:45s} links={links:3d} K={states:2d} load={load_s:.3f} sample={geometry_s:.3f} "
            f"3d half/perfect {row['3d_half_way']:.3f}/{row['3d_perfect']:.3f}{extra} gIoU half={row['gIoU_half_way']:.3f}"
        )
    for key in ["load", "geometry", "compile", "3d_half_way", "3d_perfect"] + (
        ["2d_half_way", "2d_perfect"] if args.with_2d else []
    ):
        values = [r[key] for r in rows]
        _say(
            f"{key:12s} mean {statistics.mean(values):.4f} s  median {statistics.median(values):.4f} s  max {max(values):.4f} s  (n={len(values)})"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
