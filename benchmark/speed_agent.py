"""Offline agent speed: ``artimo animate`` as a whole process, per case, without renders.

Usage::

    python -m benchmark.speed_agent [--cases benchmark/cases/dev.jsonl] [--assets ROOT] [--limit N]

Prints the median / max wall time of one whole ``artimo animate`` process per case (cold
asset cache and warm cache), and the in-process pipeline time. Target (offline-agent
issue): under 3 s per case.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from app.engine.errors import EngineError
from app.engine.pipeline import PipelineRequest, run_pipeline
from app.engine.providers.registry import make_roles
from benchmark.cases import read_cases

DEFAULT_ASSETS = Path(__file__).resolve().parents[2] / "shared/assets/partnet"


def _animate(asset: Path, prompt: str, out: Path, cache: Path) -> float:
    began = time.perf_counter()
    environment = {**os.environ, "ARTIMO_CACHE_DIR": str(cache)}
    command = [str(Path(sys.executable).parent / "artimo"), "animate", str(asset), "--prompt", prompt, "--out", str(out)]
    subprocess.run(command, check=False, capture_output=True, env=environment)
    return time.perf_counter() - began


def _line(name: str, values: list[float]) -> None:
    sys.stdout.write(f"{name:<44} median {statistics.median(values):6.2f} s   max {max(values):6.2f} s   (n={len(values)})\n")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=Path, default=Path(__file__).parent / "cases" / "dev.jsonl")
    parser.add_argument("--assets", type=Path, default=DEFAULT_ASSETS)
    parser.add_argument("--limit", type=int, default=20)
    args = parser.parse_args()
    cases = read_cases(args.cases)[: args.limit]
    cold, warm, inside = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for index, case in enumerate(cases):
            cache = work / f"cache{index}"
            cold.append(_animate(args.assets / case.asset, case.prompt, work / f"cold{index}", cache))
            warm.append(_animate(args.assets / case.asset, case.prompt, work / f"warm{index}", cache))
            began = time.perf_counter()
            try:
                run_pipeline(PipelineRequest(asset=args.assets / case.asset, prompt=case.prompt), roles=make_roles("offline"), out_dir=work / f"in{index}")
            except EngineError as exc:  # a refusal still counts its time
                sys.stdout.write(f"  {case.case_id}: {type(exc).__name__}\n")
            inside.append(time.perf_counter() - began)
    _line("artimo animate, whole process, cold cache", cold)
    _line("artimo animate, whole process, warm cache", warm)
    _line("run_pipeline in process (asset load included)", inside)
    sys.stdout.write("target: under 3 s per case, whole process\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
