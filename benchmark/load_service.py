"""Load benchmark of the REST service on loopback: status-poll latency, job throughput, worker memory.

``python -m benchmark.load_service [--clients 200] [--jobs 60] [--api-processes 2] [--database-url URL --redis-url URL]``

Starts its own stack in a temporary data dir (migrations, uvicorn, Celery
workers as subprocesses; embedded SQLite database and broker unless Postgres/Redis URLs
on 127.0.0.1 are given), then measures

1. jobs per minute on the offline agent with 1 and with 2 worker processes (concurrency 1
   each), after a warm-up batch, and the peak RSS of each worker (main + pool process);
2. latency of ``GET /v1/animations/{id}`` with ``--clients`` concurrent async clients, each
   polling every ``--interval`` seconds (a realistic poller), and once more with no pause
   (saturation: the requests per second the API serves).

It prints numbers (and writes them as JSON with ``--out``); it is not a test. Everything is
bounded (jobs, polls, timeouts) and stopped at the end, also on failure.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import logging
import math
import os
import re
import secrets
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from contextlib import ExitStack
from http import HTTPStatus
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

import httpx

from benchmark.service_stack import Stack

logger = logging.getLogger(__name__)

REPO = Path(__file__).resolve().parents[1]
ASSET = REPO / "examples" / "pedal_bin"
PROMPT = "press the pedal to open the bin"
LOOPBACK = {"127.0.0.1", "localhost", "::1"}
POLL_TARGET_P99_MS = 50.0
WARMUP_JOBS = 2
BATCH_POLL_S = 0.25
JOBS_TIMEOUT_S = 600.0
RSS_SAMPLE_S = 0.5
WRK_SECONDS = 10
WARMUP_S = 3.0
CONTENT_LENGTH = re.compile(rb"content-length:\s*(\d+)", re.IGNORECASE)
WRK_PERCENTILE = re.compile(r"^\s+(50|75|90|99)%\s+(\S+)\s*$", re.MULTILINE)
WRK_DURATION = re.compile(r"([0-9.]+)(us|ms|s|m)")
WRK_REQUESTS = re.compile(r"(\d+) requests in")
WRK_RATE = re.compile(r"Requests/sec:\s+([0-9.]+)")
WRK_MAX = re.compile(r"Latency\s+\S+\s+\S+\s+(\S+)")
WRK_ERRORS = re.compile(r"(?:connect|read|write|timeout) (\d+)")
WRK_NON_2XX = re.compile(r"Non-2xx or 3xx responses: (\d+)")


def percentile(values: list[float], fraction: float) -> float:
    """Nearest-rank percentile of ``values`` (``fraction`` in 0..1)."""
    ordered = sorted(values)
    index = min(len(ordered) - 1, max(0, math.ceil(fraction * len(ordered)) - 1))
    return ordered[index]


def _check_loopback(url: str | None) -> None:
    if url is not None and urlsplit(url.replace("+psycopg", "")).hostname not in LOOPBACK:
        raise SystemExit(f"refusing a non-loopback service URL: {url}")


def run_batch(client: httpx.Client, asset_sha: str, count: int, stack: Stack) -> dict[str, Any]:
    """Submit ``count`` jobs as one batch and wait; returns wall time, outcome counts and peak RSS."""
    cases = [{"asset": asset_sha, "prompt": PROMPT, "case_id": f"case-{index:03d}"} for index in range(count)]
    began = time.perf_counter()
    answer = client.post("/v1/batches", json={"name": "load", "cases": cases})
    answer.raise_for_status()
    url = answer.json()["url"]
    peak: dict[str, float] = {}
    deadline = time.monotonic() + JOBS_TIMEOUT_S
    next_sample = 0.0
    while True:
        if time.monotonic() >= next_sample:
            for name, rss in stack.worker_rss().items():
                peak[name] = max(peak.get(name, 0.0), rss)
            next_sample = time.monotonic() + RSS_SAMPLE_S
        batch = client.get(url).json()
        if batch["done"]:
            break
        if time.monotonic() > deadline:
            raise RuntimeError(f"batch not done after {JOBS_TIMEOUT_S:.0f} s: {batch['status_counts']}")
        time.sleep(BATCH_POLL_S)
    wall = time.perf_counter() - began
    return {"jobs": count, "wall_s": round(wall, 3), "jobs_per_minute": round(60.0 * count / wall, 1),
            "status_counts": batch["status_counts"], "peak_rss_mb": {k: round(v, 1) for k, v in sorted(peak.items())}}


def measure_throughput(stack: Stack, client: httpx.Client, asset_sha: str, jobs: int, worker_counts: list[int]) -> list[dict[str, Any]]:
    results = []
    for count in worker_counts:
        stack.start_workers(count)
        try:
            run_batch(client, asset_sha, WARMUP_JOBS * count, stack)
            result = run_batch(client, asset_sha, jobs, stack)
        finally:
            stack.stop_workers()
        result["workers"] = count
        results.append(result)
        logger.info("%d worker(s): %.1f jobs/min", count, result["jobs_per_minute"])
    return results


class _Poller:
    """One keep-alive HTTP/1.1 connection polling one path (a raw client: the load generator
    shares the machine's two cores with the server, and httpx alone would saturate one)."""

    def __init__(self, host: str, port: int, request: bytes) -> None:
        self.host, self.port, self.request = host, port, request
        self.reader: asyncio.StreamReader | None = None
        self.writer: asyncio.StreamWriter | None = None

    async def poll(self) -> int:
        if self.writer is None or self.reader is None:
            self.reader, self.writer = await asyncio.open_connection(self.host, self.port)
        self.writer.write(self.request)
        head = await self.reader.readuntil(b"\r\n\r\n")
        length = CONTENT_LENGTH.search(head)
        await self.reader.readexactly(int(length.group(1)) if length else 0)
        return int(head[9:12])

    def close(self) -> None:
        if self.writer is not None:
            self.writer.close()
        self.reader = self.writer = None


async def _client(poller: _Poller, polls: int, interval: float, latencies: list[float], errors: list[str], ready: asyncio.Event) -> None:
    try:
        await poller.poll()  # connect and warm up (not measured)
    except (OSError, asyncio.IncompleteReadError, asyncio.LimitOverrunError):
        poller.close()
    await ready.wait()
    await asyncio.sleep(interval * secrets.randbelow(1000) / 1000.0)  # spread the clients over one interval
    for _ in range(polls):
        began = time.perf_counter()
        try:
            status = await poller.poll()
            if status != HTTPStatus.OK:
                errors.append(str(status))
        except (OSError, asyncio.IncompleteReadError, asyncio.LimitOverrunError) as exc:
            errors.append(type(exc).__name__)
            poller.close()
        latencies.append((time.perf_counter() - began) * 1000.0)
        if interval > 0:
            await asyncio.sleep(interval)
    poller.close()


async def _poll_load(base_url: str, key: str, path: str, clients: int, polls: int, interval: float) -> dict[str, Any]:
    parts = urlsplit(base_url)
    host, port = parts.hostname or "127.0.0.1", parts.port or 80
    request = f"GET {path} HTTP/1.1\r\nHost: {host}:{port}\r\nAuthorization: Bearer {key}\r\n\r\n".encode()
    latencies: list[float] = []
    errors: list[str] = []
    ready = asyncio.Event()
    tasks = [asyncio.ensure_future(_client(_Poller(host, port, request), polls, interval, latencies, errors, ready)) for _ in range(clients)]
    await asyncio.sleep(WARMUP_S)  # every client connected and polled once
    began = time.perf_counter()
    ready.set()
    await asyncio.gather(*tasks)
    wall = time.perf_counter() - began
    return {
        "tool": "asyncio", "clients": clients, "interval_s": interval, "requests": len(latencies), "errors": len(errors),
        "requests_per_s": round(len(latencies) / wall, 1),
        "p50_ms": round(statistics.median(latencies), 2), "p90_ms": round(percentile(latencies, 0.90), 2),
        "p99_ms": round(percentile(latencies, 0.99), 2), "max_ms": round(max(latencies), 2),
    }


def _wrk_ms(value: str) -> float:
    number, unit = WRK_DURATION.fullmatch(value).groups()  # type: ignore[union-attr]
    return float(number) * {"us": 0.001, "ms": 1.0, "s": 1000.0, "m": 60000.0}[unit]


def _wrk_load(url: str, key: str, clients: int, seconds: int) -> dict[str, Any]:
    """Saturation with wrk (closed loop: each connection sends its next request at once)."""
    command = ["wrk", "-t", "1", "-c", str(clients), "-d", f"{seconds}s", "--latency", "-H", f"Authorization: Bearer {key}", url]
    text = subprocess.run(command, capture_output=True, text=True, check=True, timeout=seconds + 60).stdout
    spread = dict(WRK_PERCENTILE.findall(text))
    if not {"50", "90", "99"} <= set(spread):
        raise RuntimeError(f"unexpected wrk output:\n{text}")
    errors = sum(int(n) for n in WRK_ERRORS.findall(text)) + sum(int(n) for n in WRK_NON_2XX.findall(text))
    return {
        "tool": "wrk", "clients": clients, "interval_s": 0.0, "requests": int(WRK_REQUESTS.search(text).group(1)),  # type: ignore[union-attr]
        "errors": errors, "requests_per_s": float(WRK_RATE.search(text).group(1)),  # type: ignore[union-attr]
        "p50_ms": _wrk_ms(spread["50"]), "p90_ms": _wrk_ms(spread["90"]), "p99_ms": _wrk_ms(spread["99"]),
        "max_ms": _wrk_ms(WRK_MAX.search(text).group(1)),  # type: ignore[union-attr]
    }


def measure_polling(base_url: str, key: str, job_url: str, clients: int, polls: int, interval: float) -> list[dict[str, Any]]:
    """Paced pollers (every ``interval`` s), then saturation (wrk when installed, else the same pollers without pause)."""
    path = urlsplit(job_url).path
    asyncio.run(_poll_load(base_url, key, path, min(clients, 20), 3, 0.0))  # warm-up: connections, caches
    paced = asyncio.run(_poll_load(base_url, key, path, clients, polls, interval))
    if shutil.which("wrk"):
        saturated = _wrk_load(base_url + path, key, clients, WRK_SECONDS)
    else:
        saturated = asyncio.run(_poll_load(base_url, key, path, clients, polls, 0.0))
    return [paced, saturated]


def _report(document: dict[str, Any]) -> None:
    lines = [f"stack: {document['stack']}, {document['cpu_count']} CPUs; API RSS {document['api_rss_mb']:.0f} MB"]
    for row in document["throughput"]:
        lines.append(f"  {row['workers']} worker(s): {row['jobs']} jobs in {row['wall_s']:.1f} s = {row['jobs_per_minute']:.1f} jobs/min "
                     f"{row['status_counts']}; peak RSS MB {row['peak_rss_mb']}")
    for row in document["polling"]:
        verdict = "meets" if row["p99_ms"] < POLL_TARGET_P99_MS else "misses"
        lines.append(f"  status polls ({row['tool']}), {row['clients']} clients every {row['interval_s']:.2f} s: {row['requests']} requests "
                     f"({row['errors']} errors), {row['requests_per_s']:.0f} req/s, p50 {row['p50_ms']:.1f} ms, "
                     f"p90 {row['p90_ms']:.1f} ms, p99 {row['p99_ms']:.1f} ms ({verdict} p99 < {POLL_TARGET_P99_MS:.0f} ms), "
                     f"max {row['max_ms']:.1f} ms")
    sys.stdout.write("\n".join(lines) + "\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmark.load_service", description=__doc__.split("\n\n")[0])
    parser.add_argument("--clients", type=int, default=200, help="concurrent status pollers (default 200)")
    parser.add_argument("--polls", type=int, default=20, help="polls per client (default 20)")
    parser.add_argument("--interval", type=float, default=1.0, help="seconds between one client's polls (default 1.0)")
    parser.add_argument("--jobs", type=int, default=60, help="jobs per throughput run (default 60)")
    parser.add_argument("--api-processes", type=int, default=2, help="uvicorn processes (default 2, as docker-compose and `artimo serve --api-processes 2` run the API)")
    parser.add_argument("--workers", default="1,2", help="worker process counts to measure (default 1,2)")
    parser.add_argument("--database-url", default=None, help="Postgres on loopback (default: embedded SQLite)")
    parser.add_argument("--redis-url", default=None, help="Redis on loopback (default: SQLite broker)")
    parser.add_argument("--out", type=Path, default=None, help="also write the numbers as JSON")
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(asctime)s %(levelname)s %(name)s: %(message)s")
    for url in (args.database_url, args.redis_url):
        _check_loopback(url)
    key = "bench_" + secrets.token_urlsafe(24)
    with ExitStack() as cleanup:
        data_dir = Path(cleanup.enter_context(tempfile.TemporaryDirectory(prefix="artimo-load-")))
        env = {"ARTIMO_DATA_DIR": str(data_dir), "ARTIMO_API_KEY": key, "RATE_LIMIT_PER_MINUTE": str(10**8),
               "CELERY_QUEUE": f"load-{secrets.token_hex(4)}", "LOG_LEVEL": "WARNING"}
        env.update({k: v for k, v in (("DATABASE_URL", args.database_url), ("REDIS_URL", args.redis_url)) if v})
        for name in ("DATABASE_URL", "REDIS_URL"):
            if name not in env:
                os.environ.pop(name, None)
        stack = cleanup.enter_context(Stack(env, data_dir / "logs"))
        base_url = stack.start_api(args.api_processes)
        client = cleanup.enter_context(httpx.Client(base_url=base_url, headers={"Authorization": f"Bearer {key}"}, timeout=60))
        asset_sha = stack.upload_asset(client, ASSET)
        workers = [int(n) for n in args.workers.split(",") if n.strip()]
        throughput = measure_throughput(stack, client, asset_sha, args.jobs, workers)
        job_url = client.get("/v1/animations", params={"limit": 1}).json()["data"][0]["url"]
        polling = measure_polling(base_url, key, job_url, args.clients, args.polls, args.interval)
        document = {"stack": stack.describe(), "cpu_count": os.cpu_count(), "throughput": throughput, "polling": polling,
                    "api_rss_mb": round(stack.api_rss_mb(), 1)}  # measured while the API still runs
    _report(document)
    if args.out is not None:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(json.dumps(document, indent=2) + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
