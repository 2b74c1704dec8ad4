"""Export speed: all five exports of a 105-frame plan on safe_101593 (4 links with geometry), in process.

Usage::

    python -m benchmark.speed_exports [--assets ROOT] [--repeats N]

Prints one line per measurement (median of N warm runs, after one warm-up that pays the
imports). Target (issue "Exports"): usd + mjcf + ros + csv + npz in < 200 ms, excluding
mesh copying, i.e. with the meshes left out of ``animation.usda`` and ``scene.xml``; the
same with meshes embedded, each exporter alone, and ``interaction.json`` (written on every
run) are printed too. ``ROOT`` defaults to ``$ARTIMO_PARTNET_ROOT``, else
``../shared/assets/partnet`` beside the repository (``benchmark/paths.py``); a root without
safe_101593 exits 2.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from app.engine.asset.loader import load_asset
from app.engine.execute.executor import execute
from app.engine.export.csv_table import write_csv
from app.engine.export.mjcf import write_mjcf
from app.engine.export.npz_arrays import write_npz
from app.engine.export.ros import write_ros
from app.engine.export.track import ExportTrack, build_track
from app.engine.export.usd import write_usd
from app.engine.interaction.phases import actuated_phases
from app.engine.interaction.targets import interaction_targets, write_interactions
from app.engine.plan.checks import validate_plan
from benchmark.paths import script_root
from benchmark.speed_engine import ASSET, SAFE_PLAN

Step = Callable[[], object]


def _median_ms(step: Step, repeats: int) -> tuple[float, float]:
    step()  # warm-up: imports (pxr), first-call caches
    times = []
    for _ in range(repeats):
        began = time.perf_counter()
        step()
        times.append(time.perf_counter() - began)
    return statistics.median(times) * 1000, min(times) * 1000


def _line(name: str, timing: tuple[float, float], target: str = "") -> None:
    text = f"{name:<56} median {timing[0]:8.1f} ms   min {timing[1]:8.1f} ms"
    sys.stdout.write(text + (f"   target {target}" if target else "") + "\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--assets", type=Path, default=None, help="PartNet-Mobility root (default: $ARTIMO_PARTNET_ROOT, else ../shared/assets/partnet)")
    parser.add_argument("--repeats", type=int, default=15)
    args = parser.parse_args(argv)
    root = script_root(args.assets)
    if root is None:
        return 2
    if not (root / ASSET / "mobility.urdf").is_file():
        sys.stderr.write(f"error: {root} has no {ASSET}/mobility.urdf (the asset this benchmark times); wrong --assets?\n")
        return 2
    asset = load_asset(root / ASSET)
    plan = validate_plan(SAFE_PLAN, asset).document
    trajectory = execute(plan, asset)
    ends = [(segment.name, segment.t1) for segment in plan.timeline]
    links = len(asset.visual_links)
    sys.stdout.write(f"{ASSET}: {links} links with geometry, {trajectory.frame_count} frames at {trajectory.fps} fps\n")
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)

        def all_exports(geometry: bool) -> Step:
            def run() -> None:
                track = build_track(asset, trajectory)
                write_usd(track, out, geometry=geometry)
                write_mjcf(track, out, ends, geometry=geometry)
                write_ros(track, out)
                write_csv(track, out)
                write_npz(track, out)
            return run

        _line("all 5 exports, meshes excluded (usd mjcf ros csv npz)", _median_ms(all_exports(False), args.repeats), "< 200 ms")
        _line("all 5 exports, meshes embedded", _median_ms(all_exports(True), args.repeats))
        track = build_track(asset, trajectory)
        singles: dict[str, Callable[[ExportTrack], object]] = {
            "build_track (forward kinematics of every frame)": lambda _: build_track(asset, trajectory),
            "usd, meshes excluded": lambda t: write_usd(t, out, geometry=False),
            "mjcf, meshes excluded": lambda t: write_mjcf(t, out, ends, geometry=False),
            "ros": lambda t: write_ros(t, out),
            "csv": lambda t: write_csv(t, out),
            "npz": lambda t: write_npz(t, out),
        }
        for name, writer in singles.items():
            _line(f"  {name}", _median_ms(lambda w=writer: w(track), args.repeats))  # type: ignore[misc]
        phases = actuated_phases(asset, plan)
        _line("interaction.json (every run)", _median_ms(
            lambda: write_interactions(out, interaction_targets(asset, trajectory, phases, track)), args.repeats))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
