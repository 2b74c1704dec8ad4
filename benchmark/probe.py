"""Blind prompt probe: run every prompt of an expectations file through ``artimo animate``, judge it
mechanically, and report the rate right by prompt type — separating wrong answers that carried a
warning, wrong refusals, and *silent* wrong answers (exit 0, no warning). "(warned)" counts right answers
that carried a warning anyway: the price of the warnings, so that warning on everything cannot pass for honesty.

Uses the probe tools of ``../shared/tools/probe`` (``run.py`` runs each prompt as a user would, one
``artimo animate`` process per prompt; ``judge.py`` checks each trajectory against its expectation)::

    python -m benchmark.probe --expect benchmark/heldout/prompts.jsonl --out out/probe-heldout
    python -m benchmark.probe --expect ... --out ... --cli /path/to/other/artimo   # another build, e.g. a baseline
    python -m benchmark.probe --out out/probe-heldout --judge-only                  # re-judge existing runs
    python -m benchmark.probe --expect ... --out ... --in-process                   # this build, no process per prompt (fast)

The assets root is ``--assets``, else ``$ARTIMO_PARTNET_EXTRA_ROOT``, else ``../shared/assets/partnet-extra``
beside the repository; the tools folder is ``$ARTIMO_PROBE_TOOLS``, else ``../shared/tools/probe``.
Writes ``OUT/summary.json`` and prints a table. Exit status 0 (it measures; it does not gate).
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
from collections import Counter, defaultdict
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]


def _default(env: str, relative: str) -> Path:
    value = os.environ.get(env)
    return Path(value) if value else (REPO.parent / relative)


def _warnings(run_dir: Path) -> list[str]:
    report = run_dir / "report.json"
    if not report.is_file():
        return []
    try:
        data = json.loads(report.read_text())
    except (OSError, json.JSONDecodeError):
        return []
    return [str(w) for w in data.get("warnings", [])]


_RANGE_MISS = re.compile(r"final (-?[\d.]+) not in \[(-?[\d.]+),\s*(-?[\d.]+)\]")
BOUND_SLIP = 0.002
"""A final value this close outside a range's end (an expectation that ends a range at a joint limit rounded)."""


def bound_slip(errors: list[str]) -> bool:
    """Whether every error of a wrong answer is a final value outside a range by less than :data:`BOUND_SLIP` at one end:
    the answer reached the limit the writer rounded. Still counted wrong; reported apart so a reader can tell."""
    found = [_RANGE_MISS.search(e) for e in errors]
    return bool(errors) and all(m is not None and min(abs(float(m.group(1)) - float(m.group(k))) for k in (2, 3)) < BOUND_SLIP for m in found)


def _total(counts: Counter[str]) -> int:
    return sum(n for outcome, n in counts.items() if outcome != "right_warned")  # a right answer that warned is counted once, as right


def summarize(out: Path, expect: Path) -> dict[str, Any]:
    verdicts = json.loads((out / "auto_verdicts.json").read_text())
    rows = {json.loads(line)["id"]: json.loads(line) for line in expect.read_text().splitlines() if line.strip()}
    by_type: dict[str, Counter[str]] = defaultdict(Counter)
    cases = []  # outcome per prompt; "right_warned" counts right answers that still carried a warning (false alarms)
    for verdict in verdicts:
        expected = rows[verdict["id"]]["expect"]
        refused = verdict["rc"] != 0
        warnings = _warnings(out / "runs" / verdict["id"]) if not refused else []
        if verdict["verdict"] == "RIGHT":
            outcome = "right"
            by_type[verdict["type"]]["right_warned"] += bool(warnings)
            by_type["all"]["right_warned"] += bool(warnings)
        elif refused:
            outcome = "wrong_refusal"
        elif expected.get("refuse"):
            outcome = "wrong_not_refused" if not warnings else "wrong_warned"
        else:
            outcome = "wrong_warned" if warnings else "wrong_silent"
        by_type[verdict["type"]][outcome] += 1
        by_type["all"][outcome] += 1
        cases.append({"id": verdict["id"], "type": verdict["type"], "outcome": outcome, "prompt": verdict["prompt"], "errors": verdict["errs"],
                      "warnings": warnings, "bound_slip": outcome != "right" and bound_slip([str(e) for e in verdict["errs"]])})
    table = {kind: {"n": _total(c), "right": c["right"], "rate": round(c["right"] / max(_total(c), 1), 4),
                    "right_warned": c["right_warned"], "wrong_warned": c["wrong_warned"], "wrong_refusal": c["wrong_refusal"],
                    "wrong_silent": c["wrong_silent"] + c["wrong_not_refused"]} for kind, c in sorted(by_type.items())}
    return {"expect": str(expect), "types": table, "cases": cases}


def tools_folder() -> Path:
    """The probe tools (``run.py``, ``judge.py``): ``$ARTIMO_PROBE_TOOLS``, else ``../shared/tools/probe``."""
    return _default("ARTIMO_PROBE_TOOLS", "shared/tools/probe")


def judge(out: Path, expect: Path, assets: Path, tools: Path | None = None) -> dict[str, Any]:
    """Judge the runs in ``out`` with ``judge.py`` (its output in OUT/judge.txt) and write OUT/summary.json.

    Raises
    ------
    RuntimeError
        ``judge.py`` failed (its error output is the message).
    """
    env = {**os.environ, "PYOPENGL_PLATFORM": os.environ.get("PYOPENGL_PLATFORM", "egl"), "PROBE_DIR": str(out), "PROBE_EXPECT": str(expect),
           "PROBE_ASSETS": str(assets)}
    judged = subprocess.run([sys.executable, str((tools or tools_folder()) / "judge.py")], env=env, capture_output=True, text=True)
    (out / "judge.txt").write_text(judged.stdout + judged.stderr)
    if judged.returncode != 0:
        raise RuntimeError(judged.stderr.strip() or f"judge.py failed on {out}")
    summary = summarize(out, expect)
    (out / "summary.json").write_text(json.dumps(summary, indent=1))
    return summary


def run_in_process(expect: Path, out: Path, assets: Path) -> None:
    """What ``run.py`` does (one ``artimo animate`` per prompt), in this process: OUT/runs/<id> and run_results.json."""
    import time

    from app.engine.asset.cache import load_asset_cached
    from app.engine.config import EngineConfig
    from app.engine.errors import EngineError
    from app.engine.offline.roles import offline_roles
    from app.engine.pipeline import PipelineRequest, run_pipeline

    results: dict[str, dict[str, Any]] = {}
    loaded: dict[str, Any] = {}
    config = EngineConfig()
    for line in expect.read_text().splitlines():
        if not line.strip():
            continue
        row = json.loads(line)
        began = time.perf_counter()
        try:
            if row["asset_dir"] not in loaded:
                loaded[row["asset_dir"]] = load_asset_cached(assets / row["asset_dir"], None)
            asset = loaded[row["asset_dir"]]
            run_pipeline(PipelineRequest(asset=asset, prompt=row["prompt"]), roles=offline_roles(), config=config, out_dir=out / "runs" / row["id"])
            results[row["id"]] = {"rc": 0, "stderr": "", "wall_s": time.perf_counter() - began}
        except EngineError as exc:
            results[row["id"]] = {"rc": 1, "stderr": f"error: {exc}", "wall_s": time.perf_counter() - began}
        except Exception as exc:  # a crash is a result of the probe, counted, not the end of the run
            results[row["id"]] = {"rc": 2, "stderr": f"crash: {type(exc).__name__}: {exc}", "wall_s": time.perf_counter() - began}
            sys.stderr.write(f"{row['id']}: crash: {type(exc).__name__}: {exc}\n")
    (out / "run_results.json").write_text(json.dumps(results))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--expect", type=Path, default=REPO / "benchmark" / "heldout" / "prompts.jsonl")
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--assets", type=Path, default=None)
    parser.add_argument("--cli", default=None, help="the artimo executable to probe (default: this environment's)")
    parser.add_argument("--judge-only", action="store_true", help="judge and summarise runs already in --out")
    parser.add_argument("--in-process", action="store_true", help="run this build's offline agent in this process (same outputs, much faster)")
    args = parser.parse_args(argv)
    assets = args.assets or _default("ARTIMO_PARTNET_EXTRA_ROOT", "shared/assets/partnet-extra")
    tools = tools_folder()
    for path, what in ((assets, "assets root (--assets / $ARTIMO_PARTNET_EXTRA_ROOT)"), (tools, "probe tools ($ARTIMO_PROBE_TOOLS)"),
                       (args.expect, "expectations file (--expect)")):
        if not path.exists():
            sys.stderr.write(f"error: {what} not found: {path}\n")
            return 2
    cli = args.cli or shutil.which("artimo") or str(Path(sys.executable).with_name("artimo"))
    args.out.mkdir(parents=True, exist_ok=True)
    env = {**os.environ, "PYOPENGL_PLATFORM": os.environ.get("PYOPENGL_PLATFORM", "egl")}
    if args.in_process and not args.judge_only:
        run_in_process(args.expect, args.out, assets)
    elif not args.judge_only:
        subprocess.run([sys.executable, str(tools / "run.py"), cli, str(args.out), str(args.expect), str(assets)], check=True, env=env)
    try:
        summary = judge(args.out, args.expect, assets, tools)
    except RuntimeError as exc:
        sys.stderr.write(f"{exc}\n")
        return 2
    lines = [f"{'type':14s} {'n':>4s} {'right':>6s} {'rate':>6s} {'(warned)':>9s} {'warned':>7s} {'refused':>8s} {'silent':>7s}"]
    for kind, row in summary["types"].items():
        lines.append(f"{kind:14s} {row['n']:4d} {row['right']:6d} {row['rate']:6.1%} {row['right_warned']:9d} {row['wrong_warned']:7d} {row['wrong_refusal']:8d} {row['wrong_silent']:7d}")
    slips = sum(bool(c.get("bound_slip")) for c in summary["cases"])
    if slips:
        lines.append(f"{slips} wrong answers miss a range only by < {BOUND_SLIP} at one end (a limit the expectation rounded); counted wrong")
    lines.append(f"details: {args.out / 'summary.json'}, judge output: {args.out / 'judge.txt'}")
    sys.stdout.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
