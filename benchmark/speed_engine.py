"""Engine speed: ``run-plan`` as a whole process, execute + export in process, loading assets.

Usage::

    python -m benchmark.speed_engine [--assets ROOT] [--repeats N]

Prints one line per measurement (median of N runs). Targets (issue "engine core"):
whole-process run-plan of a 105-frame plan on a 4-link asset < 0.5 s (the authors'
executor: 2.0-2.5 s here); in-process execute + export < 50 ms.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from app.engine.asset.loader import load_asset
from app.engine.execute.executor import execute
from app.engine.export.glb import glb_bytes
from app.engine.export.jsonl import dumps_trajectory
from app.engine.plan.checks import validate_plan

SAFE_PLAN = {
    "meta": {"fps": 30, "duration_s": 3.5},
    "timeline": [
        {"name": "dial", "phase_type": "control_actuation", "t0": 0.0, "t1": 1.0,
         "controls": [{"mode": "joint_velocity", "joint": "joint_1", "omega_radps": -1.5707963}]},
        {"name": "handle", "phase_type": "control_actuation", "t0": 1.0, "t1": 1.5,
         "controls": [{"mode": "joint_position", "joint": "joint_2", "q_target_rad": -1.5707963, "curve": "ease_in_out"},
                      {"mode": "hold_position", "joint": "joint_1"}]},
        {"name": "door", "phase_type": "effect_motion", "t0": 1.5, "t1": 3.5,
         "controls": [{"mode": "joint_position", "joint": "joint_0", "q_target_expr": "upper_limit", "curve": "linear"},
                      {"mode": "hold_position", "joint": "joint_1"}, {"mode": "hold_position", "joint": "joint_2"}]},
    ],
}


def _report(name: str, seconds: list[float], target: str = "") -> None:
    line = f"{name:<48} median {statistics.median(seconds) * 1000:8.1f} ms   min {min(seconds) * 1000:8.1f} ms"
    sys.stdout.write(line + (f"   target {target}" if target else "") + "\n")


def _whole_process(asset: Path, plan: Path, out: Path, cache: Path, repeats: int, cold: bool) -> list[float]:
    times = []
    for _ in range(repeats):
        environment = {"ARTIMO_CACHE_DIR": str(cache), "PATH": str(Path(sys.executable).parent)}
        if cold:
            for entry in cache.glob("**/*.npz"):
                entry.unlink()
        began = time.perf_counter()
        subprocess.run([str(Path(sys.executable).parent / "artimo"), "run-plan", str(asset), "--plan", str(plan), "--out", str(out)],
                       check=True, capture_output=True, env=environment)
        times.append(time.perf_counter() - began)
    return times


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--assets", type=Path, default=Path(__file__).resolve().parents[2] / "shared/assets/partnet")
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    asset_dir = args.assets / "safe_101593"
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        plan_file = work / "plan.json"
        plan_file.write_text(json.dumps(SAFE_PLAN))
        frames = None
        _whole_process(asset_dir, plan_file, work / "out", work / "cache", 1, cold=False)  # warm the OS file cache
        _report("run-plan whole process, cold asset cache", _whole_process(asset_dir, plan_file, work / "out", work / "cache", args.repeats, cold=True))
        _report("run-plan whole process, warm asset cache", _whole_process(asset_dir, plan_file, work / "out", work / "cache", args.repeats, cold=False), "< 500 ms")
        asset = load_asset(asset_dir)
        in_process = []
        for _ in range(args.repeats * 3):
            began = time.perf_counter()
            plan = validate_plan(SAFE_PLAN, asset).document
            trajectory = execute(plan, asset)
            glb_bytes(asset, trajectory)
            dumps_trajectory(trajectory)
            in_process.append(time.perf_counter() - began)
            frames = trajectory.frame_count
        _report(f"execute + export in process ({frames} frames, warm)", in_process, "< 50 ms")
    loading = []
    for _ in range(max(1, args.repeats // 3)):
        began = time.perf_counter()
        loaded = [load_asset(folder) for folder in sorted(args.assets.iterdir()) if (folder / "mobility.urdf").is_file()]
        count = len(loaded)
        loading.append(time.perf_counter() - began)
    sys.stdout.write(f"{'load all ' + str(count) + ' shared assets':<48} median {statistics.median(loading):8.2f} s\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
