"""Run a benchmark through the REST service, then score it: ``python -m benchmark.submit``.

``python -m benchmark.submit --server URL --key KEY --cases FILE --assets ROOT [--out DIR]``

1. uploads each distinct asset folder (``ROOT/<case.asset>``) once (``POST /v1/assets``);
2. submits the cases as batches (``POST /v1/batches``; case ids kept) with the given options;
3. polls the batches with a progress bar until every job has finished (or ``--timeout``);
4. downloads each succeeded case's ``trajectory.jsonl`` and ``animation.glb`` into
   ``OUT/<case_id>/`` and writes ``OUT/service_runs.json`` (status, error, timings per case);
5. runs the benchmark evaluator (:func:`benchmark.runner.evaluate`) on ``OUT`` and prints
   its summary; scores go to ``OUT/evaluation.json``. Failed cases score as missing predictions.
"""

from __future__ import annotations

import argparse
import json
import logging
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from tqdm import tqdm

from app.client import ArtimoClient, ClientError
from app.engine.errors import EngineError
from app.engine.files import atomic_write_text
from app.engine.metrics.annotation import Case
from benchmark.cases import read_cases

logger = logging.getLogger(__name__)

PREDICTION_FILES = ("trajectory.jsonl", "animation.glb")
TERMINAL = frozenset({"succeeded", "failed", "cancelled"})
BATCH_SIZE = 200
"""Cases per ``POST /v1/batches`` (the server's default limit is 500)."""
DEFAULT_POLL_S = 1.0
DEFAULT_TIMEOUT_S = 3600.0


def upload_assets(client: ArtimoClient, cases: Sequence[Case], assets_root: Path) -> dict[str, str]:
    """Upload every distinct asset once; returns {asset folder name: asset id}."""
    ids: dict[str, str] = {}
    for name in sorted({case.asset for case in cases}):
        folder = assets_root / name
        if not folder.is_dir():
            raise SystemExit(f"asset folder {folder} does not exist")
        ids[name] = str(client.upload_asset(folder)["id"])
        logger.info("asset %s -> %s", name, ids[name])
    return ids


def submit_batches(client: ArtimoClient, cases: Sequence[Case], asset_ids: dict[str, str], options: dict[str, Any], name: str) -> list[str]:
    """Submit the cases in batches of :data:`BATCH_SIZE`; returns the batch ids."""
    batch_ids = []
    for start in range(0, len(cases), BATCH_SIZE):
        chunk = cases[start : start + BATCH_SIZE]
        body = [{"asset": asset_ids[case.asset], "prompt": case.prompt, "case_id": case.case_id} for case in chunk]
        batch = client.submit_batch(body, name=f"{name} {start // BATCH_SIZE + 1}", options=options)
        batch_ids.append(str(batch["id"]))
    return batch_ids


def wait_for_batches(client: ArtimoClient, batch_ids: Sequence[str], total: int, *, poll_s: float, timeout_s: float) -> list[dict[str, Any]]:
    """Poll until every job has finished; returns every case record of every batch."""
    deadline = time.monotonic() + timeout_s
    with tqdm(total=total, desc="jobs", unit="job", disable=None) as bar:
        while True:
            cases = [case for batch_id in batch_ids for case in client.get_batch(batch_id)["cases"]]
            finished = sum(case["status"] in TERMINAL for case in cases)
            bar.update(finished - bar.n)
            if finished == total:
                return cases
            if time.monotonic() > deadline:
                raise SystemExit(f"{total - finished} of {total} jobs still unfinished after {timeout_s:.0f} s")
            time.sleep(poll_s)


def download_predictions(client: ArtimoClient, cases: Sequence[dict[str, Any]], out_dir: Path) -> list[dict[str, Any]]:
    """Write OUT/<case_id>/{trajectory.jsonl, animation.glb} for succeeded cases; one run record per case."""
    records = []
    for case in sorted(cases, key=lambda c: str(c["case_id"])):
        record = {"case_id": case["case_id"], "job_id": case["job_id"], "status": case["status"],
                  "error": case["error"], "error_kind": case["error_kind"]}
        if case["status"] == "succeeded":
            target = out_dir / str(case["case_id"])
            record["files"] = [p.name for p in client.download(str(case["job_id"]), target, names=PREDICTION_FILES)]
        records.append(record)
    return records


def _options(args: argparse.Namespace) -> dict[str, Any]:
    options: dict[str, Any] = {}
    if args.provider:
        options["provider"] = args.provider
    if args.critic_rounds is not None:
        options["max_critic_rounds"] = args.critic_rounds
    return options


def run(args: argparse.Namespace) -> dict[str, Any]:
    """Upload, submit, wait, download, evaluate; returns the evaluation document."""
    from benchmark.runner import evaluate

    cases = read_cases(args.cases)
    args.out.mkdir(parents=True, exist_ok=True)
    with ArtimoClient(args.server, args.key) as client:
        asset_ids = upload_assets(client, cases, args.assets)
        batch_ids = submit_batches(client, cases, asset_ids, _options(args), name=args.cases.stem)
        logger.info("submitted %d cases in %d batch(es)", len(cases), len(batch_ids))
        finished = wait_for_batches(client, batch_ids, len(cases), poll_s=args.poll, timeout_s=args.timeout)
        records = download_predictions(client, finished, args.out)
    atomic_write_text(args.out / "service_runs.json", json.dumps({"batches": batch_ids, "cases": records}, indent=2) + "\n")
    failed = [r for r in records if r["status"] != "succeeded"]
    logger.info("%d/%d cases succeeded", len(records) - len(failed), len(records))
    return evaluate(args.cases, args.assets, args.out, args.out / "evaluation.json", jobs=args.jobs)


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmark.submit", description=__doc__.split("\n\n")[0])
    parser.add_argument("--server", required=True, help="service base URL, e.g. http://127.0.0.1:8000")
    parser.add_argument("--key", required=True, help="API key")
    parser.add_argument("--cases", type=Path, required=True, help="cases file (JSON Lines)")
    parser.add_argument("--assets", type=Path, required=True, help="folder holding the cases' asset folders")
    parser.add_argument("--out", type=Path, default=Path("out/bench-service"), help="predictions and scores (default out/bench-service)")
    parser.add_argument("--provider", default=None, help="provider for every job (server default: offline)")
    parser.add_argument("--critic-rounds", type=int, default=None, help="critic-actor rounds 0..3")
    parser.add_argument("--poll", type=float, default=DEFAULT_POLL_S, help="seconds between status polls")
    parser.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT_S, help="give up waiting after this many seconds")
    parser.add_argument("--jobs", type=int, default=2, help="evaluator processes")
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(levelname)s %(name)s: %(message)s")
    try:
        document = run(args)
    except (ClientError, EngineError) as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 1
    summary = {k: v for k, v in document["summary"].items() if k != "settings"}
    sys.stdout.write(json.dumps(summary, indent=2) + "\n")
    sys.stdout.write(f"scores in {args.out / 'evaluation.json'}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
