"""Real service components for the worker tests: a fresh Postgres database, a Redis DB number,
Celery worker and API server subprocesses, and Redis restarts like ``.ci/services.sh`` does.
"""

from __future__ import annotations

import io
import os
import signal
import subprocess
import sys
import time
import uuid
import zipfile
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

import httpx
import psycopg
import redis
from redis.backoff import NoBackoff
from redis.retry import Retry

from benchmark.service_stack import free_port

REPO = Path(__file__).resolve().parents[2]
PG_ADMIN_URL = "postgresql://postgres@127.0.0.1:5432/test"
PG_URL_TEMPLATE = "postgresql+psycopg://postgres@127.0.0.1:5432/{name}"
REDIS_HOST, REDIS_PORT = "127.0.0.1", 6379
REDIS_TEST_DBS = range(8, 16)
REDIS_CLAIM_KEY = "artimo-test-session"
REDIS_SERVER_COMMAND = [
    "redis-server", "--daemonize", "yes", "--bind", "127.0.0.1", "-::1", "--port", str(REDIS_PORT), "--save", "",
    "--appendonly", "no", "--dir", "/var/lib/redis", "--logfile", "/var/log/redis/ci.log",
]
"""Exactly the command line of ``.ci/services.sh``."""
START_TIMEOUT_S = 30.0
STOP_TIMEOUT_S = 15.0


def wait_until(predicate, timeout: float, interval: float = 0.05, what: str = "condition"):  # type: ignore[no-untyped-def]
    """Poll ``predicate`` until it returns a truthy value; that value, or AssertionError on timeout."""
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout:.0f} s waiting for {what}")
        time.sleep(interval)


# --- Postgres -------------------------------------------------------------------------------

@contextmanager
def fresh_database(prefix: str = "artimo_w") -> Iterator[str]:
    """A new, empty Postgres database for this session; dropped afterwards. Yields its SQLAlchemy URL."""
    name = f"{prefix}_{uuid.uuid4().hex[:10]}"
    with psycopg.connect(PG_ADMIN_URL, autocommit=True) as admin:
        admin.execute(f'CREATE DATABASE "{name}"')
    try:
        yield PG_URL_TEMPLATE.format(name=name)
    finally:
        with psycopg.connect(PG_ADMIN_URL, autocommit=True) as admin:
            admin.execute(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)')


# --- Redis ----------------------------------------------------------------------------------

def redis_client(db: int = 0) -> redis.Redis:
    """A client that fails at once when Redis is down (no retries: the tests poll themselves)."""
    return redis.Redis(
        host=REDIS_HOST, port=REDIS_PORT, db=db, socket_connect_timeout=1, socket_timeout=5, retry=Retry(NoBackoff(), 0)
    )


def redis_up() -> bool:
    try:
        return bool(redis_client().ping())
    except redis.RedisError:
        return False


@contextmanager
def claimed_redis_db() -> Iterator[int]:
    """A Redis DB number (8..15) no other test session is using; flushed before and after."""
    token = f"{os.getpid()}-{uuid.uuid4().hex[:8]}"
    for db in REDIS_TEST_DBS:
        client = redis_client(db)
        if client.set(REDIS_CLAIM_KEY, token, nx=True, ex=3600):
            client.flushdb()
            client.set(REDIS_CLAIM_KEY, token, ex=3600)
            try:
                yield db
            finally:
                if redis_up():
                    redis_client(db).flushdb()
            return
    raise AssertionError("no free Redis test DB (8..15)")


def restart_redis() -> None:
    """Stop the machine's redis-server and start it again with the command line of .ci/services.sh."""
    try:
        redis_client().shutdown(nosave=True)
    except redis.ConnectionError:
        pass  # shutdown closes the connection
    wait_until(lambda: not redis_up(), 10, what="redis to stop")
    start_redis()


def start_redis() -> None:
    if redis_up():
        return
    Path("/var/lib/redis").mkdir(parents=True, exist_ok=True)
    Path("/var/log/redis").mkdir(parents=True, exist_ok=True)
    subprocess.run(REDIS_SERVER_COMMAND, check=True, capture_output=True)
    wait_until(redis_up, 15, what="redis to start")


# --- processes ------------------------------------------------------------------------------

@dataclass
class Service:
    """A subprocess (own process group) with its output in a log file."""

    name: str
    process: subprocess.Popen[bytes]
    log: Path
    extra: dict[str, str] = field(default_factory=dict)

    def text(self) -> str:
        return self.log.read_text(errors="replace") if self.log.exists() else ""

    def alive(self) -> bool:
        return self.process.poll() is None

    def kill9(self) -> None:
        """SIGKILL the whole process group (main process and pool children), no cleanup at all."""
        if self.alive():
            os.killpg(self.process.pid, signal.SIGKILL)
        self.process.wait(STOP_TIMEOUT_S)

    def stop(self) -> None:
        """SIGTERM to the main process (warm shutdown), then SIGKILL to whatever is left in the group."""
        if self.alive():
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(STOP_TIMEOUT_S)
            except subprocess.TimeoutExpired:
                pass
        try:
            os.killpg(self.process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        self.process.wait(STOP_TIMEOUT_S)


def spawn(name: str, command: list[str], env: dict[str, str], log_dir: Path) -> Service:
    log = log_dir / f"{name}.log"
    with open(log, "ab") as handle:
        process = subprocess.Popen(command, cwd=REPO, env={**os.environ, **env}, stdout=handle, stderr=subprocess.STDOUT, start_new_session=True)
    return Service(name=name, process=process, log=log)


def start_worker(name: str, env: dict[str, str], log_dir: Path, *, concurrency: int = 1, extra_args: list[str] | None = None) -> Service:
    """A real Celery worker (prefork pool); returns once it logged ``ready``."""
    command = [
        sys.executable, "-m", "celery", "-A", "workers.celery_app", "worker", "--pool", "prefork",
        "--concurrency", str(concurrency), "--hostname", f"{name}@%h", "--loglevel", "INFO", *(extra_args or []),
    ]
    worker = spawn(name, command, env, log_dir)
    try:
        wait_until(lambda: " ready." in worker.text() or not worker.alive(), START_TIMEOUT_S, 0.1, f"worker {name}")
    except AssertionError:
        worker.stop()
        raise
    if not worker.alive():
        raise AssertionError(f"worker {name} exited:\n{worker.text()[-3000:]}")
    return worker


def start_api(env: dict[str, str], log_dir: Path, name: str = "api") -> tuple[Service, str]:
    """uvicorn serving ``app.main:create_app`` on a free loopback port; returns once /readyz finds the database and broker."""
    port = free_port()
    command = [sys.executable, "-m", "uvicorn", "app.main:create_app", "--factory", "--host", "127.0.0.1", "--port", str(port), "--log-level", "warning"]
    api = spawn(name, command, env, log_dir)
    url = f"http://127.0.0.1:{port}"

    def ready() -> bool:
        if not api.alive():
            raise AssertionError(f"API exited:\n{api.text()[-3000:]}")
        try:
            checks = httpx.get(f"{url}/readyz", timeout=2).json().get("checks", {})
            return checks.get("database") == "ok" and checks.get("broker") == "ok"  # workers start after the API
        except httpx.HTTPError:
            return False

    try:
        wait_until(ready, START_TIMEOUT_S, 0.1, "API /readyz")
    except AssertionError:
        api.stop()
        raise
    return api, url


# --- assets ---------------------------------------------------------------------------------

def zip_folder(folder: Path) -> bytes:
    """A deterministic zip of an asset folder (sorted names, fixed timestamps)."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for path in sorted(p for p in folder.rglob("*") if p.is_file()):
            info = zipfile.ZipInfo(path.relative_to(folder).as_posix(), date_time=(1980, 1, 1, 0, 0, 0))
            archive.writestr(info, path.read_bytes())
    return buffer.getvalue()
