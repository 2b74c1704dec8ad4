"""Local work of a model-backed run: everything but the model's own latency.

Usage::

    python -m benchmark.speed_models [--cases benchmark/cases/dev.jsonl] [--assets ROOT] [--limit N] [--latency S]

Each case runs the whole pipeline in process with ``--provider openai`` against a local
server that answers every role at once (``--latency 0``) with a valid reply: the offline
agent's own Causal.json and plan for that case, an "all good" critic verdict and a coverage
choice. Rendering is on (the default for vision roles): 8 reference/overlay images for the
perceiver, coverage views, HEAD/TAIL keyframes per critic case. With zero latency the wall
time of a job is its local work. ``--latency S`` makes every reply take S seconds and
prints how far the wall time exceeds the model's own critical path (the local work that
did not overlap a call in flight). Target (models issue): local work <= 0.5 s per job.
``ROOT`` defaults to ``$ARTIMO_PARTNET_ROOT``, else ``../shared/assets/partnet`` beside the
repository (``benchmark/paths.py``); a root holding none of the cases' assets exits 2.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

from app.engine.asset.cache import load_asset_cached
from app.engine.config import EngineConfig
from app.engine.errors import EngineError
from app.engine.offline.contract_io import causal_document
from app.engine.offline.perceiver import read_prompt
from app.engine.offline.planner import plan_intent
from app.engine.pipeline import PipelineRequest, run_pipeline
from app.engine.providers.registry import ProviderConfig, make_roles
from benchmark.paths import script_cases

ROLES = ("perceiver", "planner", "critic", "coverage")
OK_VERDICT = {"semantic_ok": True, "visibility_ok": True, "link_motion_type": "static_or_unclear", "detailed_reasoning": "looks right",
              "issues": [], "param_fix_hints": [], "confidence": 0.9}
TARGET_S = 0.5


def _replies(asset_dir: Path, prompt: str, cache: Path) -> dict[str, str]:
    """What a good model would answer for this case (the offline agent's reading), per role."""
    asset = load_asset_cached(asset_dir, cache)
    reading = read_prompt(prompt, asset)
    intent = reading.intent
    links = {goal.link for step in intent.steps for goal in step.goals}
    view = {"azimuth_deg": 0, "elevation_deg": 20, "distance_scale": 1.0, "fov_deg": 35}
    return {"perceiver": causal_document(reading.extension, intent, asset).dumps(), "planner": plan_intent(intent, asset).dumps(),
            "critic": json.dumps(OK_VERDICT), "coverage": json.dumps({"selected_views_by_link": dict.fromkeys(sorted(links), view)})}


@contextmanager
def _instant_model(state: dict[str, Any]) -> Iterator[str]:
    """A local OpenAI-compatible server answering ``state["replies"][role]`` after ``state["latency"]`` seconds."""

    class Handler(BaseHTTPRequestHandler):
        protocol_version = "HTTP/1.1"

        def log_message(self, *args: Any) -> None:
            """No access log: the benchmark prints only its numbers."""

        def do_POST(self) -> None:
            began = time.perf_counter()  # the server's reading and decoding is the model side's time too
            payload = json.loads(self.rfile.read(int(self.headers.get("Content-Length", 0))))
            system = str(payload["messages"][0]["content"]).lower()
            role = next((r for r in ROLES if f"you are the {r}" in system or f"you are the visual {r}" in system), "critic")
            time.sleep(state["latency"])
            body = json.dumps({"model": payload["model"], "choices": [{"index": 0, "finish_reason": "stop",
                               "message": {"role": "assistant", "content": state["replies"][role]}}],
                               "usage": {"prompt_tokens": 1000, "completion_tokens": 200}}).encode()
            self.send_response(200)
            self.send_header("Content-Type", "application/json")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)
            state["busy"].append((began, time.perf_counter()))

    server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    server.daemon_threads = True
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/v1"
    finally:
        server.shutdown()
        server.server_close()


def _union(intervals: list[tuple[float, float]]) -> float:
    """Seconds covered by at least one interval (the model's own time on the critical path)."""
    total, end = 0.0, float("-inf")
    for start, stop in sorted(intervals):
        if stop > end:
            total += stop - max(start, end)
            end = stop
    return total


def _job(url: str, asset_dir: Path, prompt: str, out: Path, cache: Path | None, state: dict[str, Any]) -> tuple[float, float, dict[str, float], int]:
    """(wall, local work = wall minus the time some model call was being answered, stages, calls)."""
    config = EngineConfig(asset_cache_dir=cache)
    roles = make_roles("openai", ProviderConfig(api_key="local", base_url=url), config)
    state["busy"] = []
    began = time.perf_counter()
    result = run_pipeline(PipelineRequest(asset=asset_dir, prompt=prompt), roles=roles, config=config, out_dir=out)
    wall = time.perf_counter() - began
    stages = {s.stage: s.seconds for s in result.report.stages}
    return wall, wall - _union(state["busy"]), stages, len(result.report.role_calls)


def _line(name: str, values: list[float]) -> None:
    sys.stdout.write(f"{name:<46} median {statistics.median(values):6.3f} s   mean {statistics.mean(values):6.3f} s   max {max(values):6.3f} s\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=Path, default=Path(__file__).parent / "cases" / "dev.jsonl")
    parser.add_argument("--assets", type=Path, default=None, help="assets root (default: $ARTIMO_PARTNET_ROOT, else ../shared/assets/partnet)")
    parser.add_argument("--limit", type=int, default=20)
    parser.add_argument("--latency", type=float, default=0.0, help="seconds every model reply takes (default 0)")
    parser.add_argument("--no-cache", action="store_true", help="no asset/view cache: every job renders the perceiver's images (cold)")
    args = parser.parse_args(argv)
    found = script_cases(args.cases, args.assets, args.limit)
    if found is None:
        return 2
    cases, root = found
    walls: list[float] = []
    local: list[float] = []
    per_stage: dict[str, list[float]] = {}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        state: dict[str, Any] = {"latency": args.latency, "replies": {}, "busy": []}
        cache = None if args.no_cache else work / "cache"
        with _instant_model(state) as url:
            for index, case in enumerate(cases):
                asset_dir = root / case.asset
                try:
                    state["replies"] = _replies(asset_dir, case.prompt, work / "replies-cache")
                    _job(url, asset_dir, case.prompt, work / f"warm{index}", cache, state)  # first job on the asset: caches fill, renderer warms up
                    wall, own, stages, calls = _job(url, asset_dir, case.prompt, work / f"run{index}", cache, state)
                except EngineError as exc:
                    sys.stdout.write(f"  {case.case_id}: skipped ({type(exc).__name__}: {exc})\n")
                    continue
                walls.append(wall)
                local.append(own)
                for name, seconds in stages.items():
                    per_stage.setdefault(name, []).append(seconds)
                sys.stdout.write(f"  {case.case_id:<48} wall {wall:6.3f} s  local {own:6.3f} s  ({calls} model calls)\n")
    if not walls:
        sys.stdout.write("no case ran\n")
        return 1
    _line(f"wall per job (model latency {args.latency:g} s per call)", walls)
    _line("local work per job (wall minus model time)", local)
    for name, values in per_stage.items():
        _line(f"  stage {name}", values)
    verdict = "met" if statistics.median(local) <= TARGET_S else "NOT met"
    sys.stdout.write(f"target: local work <= {TARGET_S} s per job: {verdict} (median; {'cold, no cache' if args.no_cache else 'warm view cache'})\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
