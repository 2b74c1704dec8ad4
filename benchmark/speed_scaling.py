"""Scaling with the joint count: ``python -m benchmark.speed_scaling [--joints 64,256,1024,4096] [--repeats N]``.

A generated chain of N revolute joints in a row (one box per link, nothing else), written to a
temporary folder. Per N, the median seconds of N-independent steps of ``artimo inspect`` and of
a run, in process (joint and link limits raised past N):

- ``load``     ``load_asset`` (URDF checks, meshes, tree order);
- ``summary``  the joint summary and scale context (``artimo inspect --json``'s first parts);
- ``layout``   ``asset_layout``: part positions and joint ends (``artimo inspect``, the asset
  summary route), which reads the offline agent's per-asset geometry
  (``app/engine/offline/geometry.py``: per joint, the links it moves, a slice of a depth-first layout, read
  whole up to ``MAX_MOVED_POINTS`` = 8192 points and on an even stride above: a chain's first joints move every
  link after them, so below that cap the layout grows with the square of the chain, above it linearly);
- ``run``      validate + execute + GLB of a 1 s plan turning the first joint;

and ``inspect`` the whole ``artimo --no-cache inspect`` process (N <= 256, its default limit).
Each line ends with the growth since the previous N (times 4 joints: x4 is linear, x16 quadratic).
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

from app.engine.asset.layout import asset_layout
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.safety import AssetLimits
from app.engine.asset.summary import joint_summary, scale_context
from app.engine.execute.executor import execute
from app.engine.export.glb import glb_bytes
from app.engine.plan.checks import validate_plan

DEFAULT_LIMIT = AssetLimits().max_joints
STEPS = ("load", "summary", "layout", "run", "inspect")
T = TypeVar("T")


def chain_urdf(joints: int) -> str:
    """``joints`` revolute joints about x, each link a 2 x 2 x 10 cm box standing on its joint."""
    links = [f'<link name="l{i}"><visual><origin xyz="0 0 0.05"/><geometry><box size="0.02 0.02 0.1"/></geometry></visual></link>'
             for i in range(joints + 1)]
    chain = [f'<joint name="j{i}" type="revolute"><origin xyz="0 0 0.1"/><parent link="l{i}"/><child link="l{i + 1}"/>'
             f'<axis xyz="1 0 0"/><limit lower="-0.5" upper="0.5" effort="1" velocity="1"/></joint>' for i in range(joints)]
    return '<?xml version="1.0"?>\n<robot name="chain">\n' + "\n".join(links + chain) + "\n</robot>\n"


PLAN = {"meta": {"fps": 30, "duration_s": 1.0},
        "timeline": [{"name": "turn", "phase_type": "control_actuation", "t0": 0.0, "t1": 1.0,
                      "controls": [{"mode": "joint_position", "joint": "j0", "q_target_rad": 0.4, "curve": "linear"}]}]}


def _median(step: Callable[[T], object], repeats: int, setup: Callable[[], T]) -> float:
    """Median seconds of ``step(setup())`` (``setup`` untimed)."""
    times = []
    for _ in range(repeats):
        given = setup()
        began = time.perf_counter()
        step(given)
        times.append(time.perf_counter() - began)
    return statistics.median(times)


def _measure(folder: Path, joints: int, repeats: int) -> dict[str, float | None]:
    limits = AssetLimits(max_links=joints + 1, max_joints=joints)

    def fresh() -> ArticulatedAsset:  # the offline geometry is cached per asset object: a new one each time
        return load_asset(folder, limits=limits)

    def run(asset: ArticulatedAsset) -> None:
        glb_bytes(asset, execute(validate_plan(PLAN, asset).document, asset))

    def whole_inspect(_: None) -> None:
        command = [str(Path(sys.executable).parent / "artimo"), "--no-cache", "inspect", str(folder)]
        subprocess.run(command, check=True, capture_output=True)

    return {
        "load": _median(lambda _: fresh(), repeats, lambda: None),
        "summary": _median(lambda asset: (joint_summary(asset), scale_context(asset)), repeats, fresh),
        "layout": _median(asset_layout, repeats, fresh),
        "run": _median(run, repeats, fresh),
        "inspect": _median(whole_inspect, repeats, lambda: None) if joints <= DEFAULT_LIMIT else None,
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--joints", default="64,256,1024,4096", help="comma-separated joint counts (default 64,256,1024,4096)")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args(argv)
    counts = sorted({int(n) for n in args.joints.split(",")})
    sys.stdout.write(f"{'joints':>7}" + "".join(f"{name:>18}" for name in STEPS) + "\n")
    previous: dict[str, float | None] = {}
    with tempfile.TemporaryDirectory() as tmp:
        for joints in counts:
            folder = Path(tmp) / f"chain{joints}"
            folder.mkdir()
            (folder / "mobility.urdf").write_text(chain_urdf(joints))
            times = _measure(folder, joints, args.repeats)
            cells = []
            for name in STEPS:
                seconds, before = times[name], previous.get(name)
                growth = f" x{seconds / before:<5.1f}" if seconds is not None and before else " " * 7
                cells.append(f"{'-' if seconds is None else f'{seconds:8.3f} s'}{growth}".rjust(18))
            sys.stdout.write(f"{joints:>7}" + "".join(cells) + "\n")
            previous = times
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
