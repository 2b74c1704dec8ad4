"""``artimo serve`` end to end: SQLite database and broker, a real worker child, a generated key."""

from __future__ import annotations

import os
import re
import signal
import sqlite3
import subprocess
import sys
from pathlib import Path

import httpx

from app.client import ArtimoClient
from benchmark.service_stack import child_pids
from tests.support.gltf_validator import assert_valid
from tests.workers import stack
from tests.workers.jobs import PEDAL_BIN, PEDAL_PROMPT

KEY_LINE = re.compile(r"API key \(shown once, stored hashed\): (\S+)")
SERVE_TIMEOUT_S = 40.0
SERVICE_VARIABLES = ("DATABASE_URL", "REDIS_URL", "ARTIMO_API_KEY", "CELERY_QUEUE", "ARTIMO_STORAGE_DIR", "JOB_STAGE_DELAY_S")


def _embedded_env(data_dir: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k not in SERVICE_VARIABLES}
    env["ARTIMO_DATA_DIR"] = str(data_dir)
    return env


def _serve(data_dir: Path, port: int, *extra: str) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "app.cli.main", "serve", "--host", "127.0.0.1", "--port", str(port), "--workers", "1", *extra],
        cwd=stack.REPO, env=_embedded_env(data_dir), stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
        start_new_session=True,
    )


def _children(pid: int) -> set[int]:
    return set(child_pids(pid))


def test_serve_submit_wait_download_and_stop(tmp_path: Path) -> None:
    data_dir, port = tmp_path / "data", stack.free_port()
    server = _serve(data_dir, port)
    url = f"http://127.0.0.1:{port}"
    try:
        assert server.stdout is not None
        first, key_line = server.stdout.readline(), server.stdout.readline()
        assert url in first and str(data_dir) in first and "broker: sqlite" in first
        match = KEY_LINE.search(key_line)
        assert match, first + key_line
        assert f"valid for the database sqlite:///{data_dir / 'artimo.db'}; data folder {data_dir})" in key_line  # whose key it is
        stack.wait_until(lambda: _ready(url), SERVE_TIMEOUT_S, 0.1, "artimo serve /readyz")
        worker_pids = _children(server.pid)
        assert worker_pids, "no worker child process"

        out = tmp_path / "out"
        submitted = subprocess.run(
            [sys.executable, "-m", "app.cli.main", "submit", str(PEDAL_BIN), "--prompt", PEDAL_PROMPT, "--server", url,
             "--key", match.group(1), "--wait", "--out", str(out)],
            cwd=stack.REPO, env=_embedded_env(data_dir), capture_output=True, text=True, timeout=SERVE_TIMEOUT_S,
        )
        assert submitted.returncode == 0, submitted.stderr
        assert_valid([out / "animation.glb"])
        assert (data_dir / "artimo.db").is_file() and (data_dir / "broker.db").is_file()
        with sqlite3.connect(data_dir / "broker.db") as broker:  # a delivered message leaves no row behind
            assert broker.execute("SELECT count(*) FROM kombu_message").fetchone() == (0,)
        with ArtimoClient(url, match.group(1)) as client:
            assert client.list_jobs()["data"][0]["status"] == "succeeded"
        assert httpx.get(f"{url}/v1/animations", headers={"Authorization": "Bearer wrong"}).status_code == 401

        (worker,) = worker_pids  # a worker that dies is replaced, and jobs still run
        os.killpg(worker, signal.SIGKILL)
        worker_pids = stack.wait_until(lambda: _children(server.pid) - {worker}, SERVE_TIMEOUT_S, 0.2, "a replacement worker")
        with ArtimoClient(url, match.group(1)) as client:
            again = client.submit(PEDAL_BIN, PEDAL_PROMPT)
            assert client.wait(again["id"], timeout=SERVE_TIMEOUT_S, poll=0.1)["status"] == "succeeded"
    finally:
        server.terminate()
        code = server.wait(SERVE_TIMEOUT_S)
    assert code == 0
    assert not any(Path(f"/proc/{pid}").exists() for pid in worker_pids), "the worker outlived artimo serve"


def _descendants(pid: int) -> set[int]:
    found, todo = set(), [pid]
    while todo:
        for child in _children(todo.pop()):
            if child not in found:
                found.add(child)
                todo.append(child)
    return found


def _cmdline(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode()
    except OSError:
        return ""


def test_two_api_processes_serve_jobs_and_all_stop(tmp_path: Path) -> None:
    data_dir, port = tmp_path / "data", stack.free_port()
    server = _serve(data_dir, port, "--api-processes", "2")
    url = f"http://127.0.0.1:{port}"
    try:
        assert server.stdout is not None
        match = KEY_LINE.search(server.stdout.readline() + server.stdout.readline())
        assert match
        stack.wait_until(lambda: _ready(url), SERVE_TIMEOUT_S, 0.1, "artimo serve /readyz")
        def api_processes() -> set[int]:
            found = {pid for pid in _children(server.pid) if "spawn_main" in _cmdline(pid)}
            return found if len(found) >= 2 else set()

        assert len(stack.wait_until(api_processes, SERVE_TIMEOUT_S, 0.1, "two API processes")) == 2
        everything = _descendants(server.pid)
        with ArtimoClient(url, match.group(1)) as client:
            jobs = [client.submit(PEDAL_BIN, PEDAL_PROMPT)["id"] for _ in range(3)]
            assert [client.wait(job, timeout=SERVE_TIMEOUT_S, poll=0.1)["status"] for job in jobs] == ["succeeded"] * 3
            assert len({httpx.get(f"{url}/healthz").status_code for _ in range(20)}) == 1
    finally:
        server.terminate()
        code = server.wait(SERVE_TIMEOUT_S)
    assert code == 0
    stack.wait_until(lambda: not any(Path(f"/proc/{pid}").exists() for pid in everything),
                     SERVE_TIMEOUT_S, 0.1, "every child of artimo serve to stop")


def test_second_start_does_not_print_a_new_key(tmp_path: Path) -> None:
    data_dir = tmp_path / "data"
    for expect_new in (True, False):
        server = _serve(data_dir, stack.free_port())
        try:
            assert server.stdout is not None
            server.stdout.readline()
            key_line = server.stdout.readline()
        finally:
            server.terminate()
            assert server.wait(SERVE_TIMEOUT_S) == 0
        assert bool(KEY_LINE.search(key_line)) is expect_new, key_line
    assert f"printed when this database sqlite:///{data_dir / 'artimo.db'} was first served" in key_line
    assert f"(with the same ARTIMO_DATA_DIR={data_dir})" in key_line


def _ready(url: str) -> bool:
    try:
        return httpx.get(f"{url}/readyz", timeout=2).status_code == 200
    except httpx.HTTPError:
        return False
