"""Engine speed: ``run-plan`` as a whole process, execute + export in process, loading assets.

Usage::

    python -m benchmark.speed_engine [--assets ROOT] [--repeats N]

``ROOT`` defaults to ``$ARTIMO_PARTNET_ROOT``, else ``../shared/assets/partnet`` beside the
repository (``benchmark/paths.py``). Prints one line per measurement (median of N runs) and
exits 1 if a run failed. Targets (issues "engine core" and "first hour"): whole-process
run-plan of a 105-frame plan on a 4-link asset < 0.5 s, also with a cold asset cache (the
authors' executor: 2.0-2.5 s here); in-process execute + export < 50 ms.
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
from benchmark.paths import script_root

ASSET = "safe_101593"

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
        done = subprocess.run([str(Path(sys.executable).parent / "artimo"), "run-plan", str(asset), "--plan", str(plan), "--out", str(out)],
                              check=False, capture_output=True, text=True, env=environment)
        times.append(time.perf_counter() - began)
        if done.returncode != 0:
            raise RunFailed(f"artimo run-plan exited {done.returncode}: {done.stderr.strip()[-1000:]}")
    return times


class RunFailed(Exception):
    """A measured command failed: its time means nothing."""


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--assets", type=Path, default=None, help="PartNet-Mobility root (default: $ARTIMO_PARTNET_ROOT, else ../shared/assets/partnet)")
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args(argv)
    root = script_root(args.assets)
    if root is None:
        return 2
    asset_dir = root / ASSET
    if not (asset_dir / "mobility.urdf").is_file():
        sys.stderr.write(f"error: {root} has no {ASSET}/mobility.urdf (the asset this benchmark times); wrong --assets?\n")
        return 2
    try:
        _measure(root, asset_dir, args.repeats)
    except RunFailed as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 1
    return 0


def _measure(root: Path, asset_dir: Path, repeats: int) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        plan_file = work / "plan.json"
        plan_file.write_text(json.dumps(SAFE_PLAN))
        frames = None
        _whole_process(asset_dir, plan_file, work / "out", work / "cache", 1, cold=False)  # warm the OS file cache
        _report("run-plan whole process, cold asset cache", _whole_process(asset_dir, plan_file, work / "out", work / "cache", repeats, cold=True), "< 500 ms")
        _report("run-plan whole process, warm asset cache", _whole_process(asset_dir, plan_file, work / "out", work / "cache", repeats, cold=False), "< 500 ms")
        asset = load_asset(asset_dir)
        in_process = []
        for _ in range(repeats * 3):
            began = time.perf_counter()
            plan = validate_plan(SAFE_PLAN, asset).document
            trajectory = execute(plan, asset)
            glb_bytes(asset, trajectory)
            dumps_trajectory(trajectory)
            in_process.append(time.perf_counter() - began)
            frames = trajectory.frame_count
        _report(f"execute + export in process ({frames} frames, warm)", in_process, "< 50 ms")
    loading = []
    for _ in range(max(1, repeats // 3)):
        began = time.perf_counter()
        loaded = [load_asset(folder) for folder in sorted(root.iterdir()) if (folder / "mobility.urdf").is_file()]
        count = len(loaded)
        loading.append(time.perf_counter() - began)
    sys.stdout.write(f"{'load all ' + str(count) + ' shared assets':<48} median {statistics.median(loading):8.2f} s\n")


if __name__ == "__main__":
    raise SystemExit(main())
