"""A throw-away service stack for benchmarks: migrations, one API process, N Celery workers.

Everything runs as subprocesses of this one (own process groups, logs under ``log_dir``)
and is stopped when the :class:`Stack` context exits. The benchmark package talks to the
service only over HTTP and command lines (it imports neither ``workers`` nor the API).
"""

from __future__ import annotations

import contextlib
import io
import os
import signal
import socket
import subprocess
import sys
import time
import zipfile
from pathlib import Path
from types import TracebackType
from typing import IO

import httpx

START_TIMEOUT_S = 60.0
STOP_TIMEOUT_S = 20.0
PAGE_KB = 1024.0


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def child_pids(pid: int) -> list[int]:
    """Direct children of a process (from /proc; empty when it is gone)."""
    found: list[int] = []
    for task in Path(f"/proc/{pid}/task").glob("*"):
        try:
            found += [int(c) for c in (task / "children").read_text().split()]
        except OSError:
            continue
    return found


def process_rss_mb(pid: int | None) -> float:
    """Resident memory of one process, MiB (0 when it is gone)."""
    if pid is None:
        return 0.0
    try:
        for line in Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return float(line.split()[1]) / PAGE_KB
    except OSError:
        return 0.0
    return 0.0


def zip_folder(folder: Path) -> bytes:
    """Deterministic zip of an asset folder (sorted names, fixed timestamps)."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for path in sorted(p for p in folder.rglob("*") if p.is_file()):
            archive.writestr(zipfile.ZipInfo(path.relative_to(folder).as_posix(), date_time=(1980, 1, 1, 0, 0, 0)), path.read_bytes())
    return buffer.getvalue()


class Stack:
    """Migrated database, API and workers for one benchmark run (a context manager)."""

    def __init__(self, env: dict[str, str], log_dir: Path) -> None:
        self.env = {**os.environ, **env}
        self.log_dir = log_dir
        self.api: subprocess.Popen[bytes] | None = None
        self.workers: dict[str, subprocess.Popen[bytes]] = {}
        self._logs: list[IO[bytes]] = []
        self._generation = 0
        self.api_processes = 1

    def __enter__(self) -> Stack:
        self.log_dir.mkdir(parents=True, exist_ok=True)
        subprocess.run([sys.executable, "-m", "app.db.migrate"], env=self.env, check=True, capture_output=True)
        return self

    def __exit__(self, kind: type[BaseException] | None, value: BaseException | None, trace: TracebackType | None) -> None:
        self.stop_workers()
        if self.api is not None:
            self._stop(self.api)
        for handle in self._logs:
            handle.close()

    def _spawn(self, name: str, command: list[str], env: dict[str, str] | None = None) -> subprocess.Popen[bytes]:
        log = open(self.log_dir / f"{name}.log", "ab")  # closed in __exit__
        self._logs.append(log)
        return subprocess.Popen(command, env={**self.env, **(env or {})}, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)

    @staticmethod
    def _stop(process: subprocess.Popen[bytes]) -> None:
        """SIGTERM to the main process (warm shutdown), then SIGKILL to whatever is left in its group."""
        if process.poll() is None:
            process.send_signal(signal.SIGTERM)
            with contextlib.suppress(subprocess.TimeoutExpired):  # still running: the group kill below ends it
                process.wait(STOP_TIMEOUT_S)
        with contextlib.suppress(ProcessLookupError):  # the group is already gone
            os.killpg(process.pid, signal.SIGKILL)
        process.wait(STOP_TIMEOUT_S)

    def start_api(self, processes: int = 1) -> str:
        """uvicorn on a free loopback port (``processes`` > 1: its own supervisor and worker processes)."""
        port = free_port()
        self.api_processes = processes
        self.api = self._spawn("api", [sys.executable, "-m", "uvicorn", "app.main:create_app", "--factory", "--host", "127.0.0.1",
                                       "--port", str(port), "--log-level", "warning", "--no-access-log", "--workers", str(processes)])
        url = f"http://127.0.0.1:{port}"
        deadline = time.monotonic() + START_TIMEOUT_S
        while time.monotonic() < deadline:
            if self.api.poll() is not None:
                raise RuntimeError(f"API exited; see {self.log_dir / 'api.log'}")
            with contextlib.suppress(httpx.HTTPError):  # not listening yet
                checks = httpx.get(f"{url}/readyz", timeout=2).json().get("checks", {})
                if checks.get("database") == "ok" and checks.get("broker") == "ok":  # workers may start later
                    return url
            time.sleep(0.1)
        raise RuntimeError(f"API not ready after {START_TIMEOUT_S:.0f} s")

    def api_rss_mb(self) -> float:
        """RSS of the API: its process plus, with several processes, uvicorn's worker processes (MiB)."""
        if self.api is None:
            return 0.0
        return process_rss_mb(self.api.pid) + sum(process_rss_mb(c) for c in child_pids(self.api.pid))

    def start_workers(self, count: int) -> None:
        """``count`` worker processes (prefork, concurrency 1 each); returns when all logged ``ready``."""
        self._generation += 1
        sqlite_broker = "REDIS_URL" not in self.env
        for index in range(count):
            name = f"worker{self._generation}-{index}"
            command = [sys.executable, "-m", "celery", "-A", "workers.celery_app", "worker", "--pool", "prefork",
                       "--concurrency", "1", "--hostname", f"{name}@%h", "--loglevel", "INFO"]
            if sqlite_broker:
                command += ["--without-mingle", "--without-gossip", "--without-heartbeat"]
            self.workers[name] = self._spawn(name, command, {"LOG_LEVEL": "INFO"})  # INFO: readiness is read from the log
        deadline = time.monotonic() + START_TIMEOUT_S
        for name, process in self.workers.items():
            log = self.log_dir / f"{name}.log"
            while " ready." not in log.read_text(errors="replace"):
                if process.poll() is not None or time.monotonic() > deadline:
                    raise RuntimeError(f"worker {name} did not start; see {log}")
                time.sleep(0.1)

    def stop_workers(self) -> None:
        for process in self.workers.values():
            self._stop(process)
        self.workers.clear()

    def worker_rss(self) -> dict[str, float]:
        """RSS per worker (main process + its pool processes), MiB."""
        return {name: process_rss_mb(p.pid) + sum(process_rss_mb(c) for c in child_pids(p.pid)) for name, p in self.workers.items()}

    def upload_asset(self, client: httpx.Client, folder: Path) -> str:
        data = zip_folder(folder)
        answer = client.post("/v1/assets", files={"asset": (f"{folder.name}.zip", data, "application/zip")})
        answer.raise_for_status()
        return str(answer.json()["sha256"])

    def describe(self) -> str:
        database = "postgres" if self.env.get("DATABASE_URL", "").startswith("postgresql") else "sqlite"
        broker = "redis" if self.env.get("REDIS_URL") else "sqlite"
        return f"{self.api_processes} uvicorn process(es), database {database}, broker {broker}"
