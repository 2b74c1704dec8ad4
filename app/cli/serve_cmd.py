"""``artimo serve``: the embedded service — migrations, a real Celery worker, the REST API.

Runs the database migrations, starts ``celery -A workers.celery_app worker`` as a child
process (prefork pool: time limits work and a crashed job process is replaced; with
the SQLite broker remote control is off), then serves ``app.main:create_app`` with
uvicorn in the foreground. ``Ctrl-C``/``SIGTERM`` stops uvicorn, then the worker (warm
shutdown, then a kill after :data:`WORKER_STOP_TIMEOUT_S`). ``ARTIMO_DATA_DIR`` holds the
embedded database, broker and artifacts; ``REDIS_URL``/``DATABASE_URL`` switch to Redis
and Postgres.
"""

from __future__ import annotations

import argparse
import logging
import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

from app.cli.output import err, out

if TYPE_CHECKING:
    import uvicorn

    from app.core.config import Settings

logger = logging.getLogger(__name__)

WORKER_STOP_TIMEOUT_S = 20.0
WORKER_RESTART_LIMIT = 5
WORKER_RESTART_WINDOW_S = 600.0
"""More than :data:`WORKER_RESTART_LIMIT` restarts within this many seconds: a crash loop, restarting stops
(``/readyz`` then reports no live worker). Occasional crashes spread over days are always restarted."""
WORKER_POLL_S = 1.0
KEY_PREFIX_SHOWN = 6
EMBEDDED_CLIENT = "embedded"
PR_SET_PDEATHSIG = 1
STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("serve", help="run the REST service with an embedded Celery worker")
    parser.add_argument("--host", default="127.0.0.1", help="interface to listen on (default 127.0.0.1)")
    parser.add_argument("--port", type=int, default=8000, help="TCP port (default 8000)")
    parser.add_argument("--workers", type=int, default=1, help="job worker processes (Celery concurrency, default 1)")
    parser.add_argument(
        "--api-processes", type=int, default=1,
        help="API (uvicorn) processes, default 1; 2 keeps status polls fast under heavy load. Without "
             "REDIS_URL each process keeps its own rate-limit counters",
    )
    parser.set_defaults(handler=_serve)


def worker_command(concurrency: int, *, sqlite_broker: bool) -> list[str]:
    """The Celery worker command line of the embedded service."""
    command = [
        sys.executable, "-m", "celery", "-A", "workers.celery_app", "worker",
        "--pool", "prefork", "--concurrency", str(max(1, concurrency)),
        "--hostname", f"embedded-{os.getpid()}@%h", "--loglevel", "INFO",
    ]
    if sqlite_broker:  # no fanout on kombu's SQLAlchemy transport
        command += ["--without-mingle", "--without-gossip", "--without-heartbeat"]
    return command


def _death_signal_setter() -> Callable[[], None] | None:
    """A pre-exec function asking Linux for SIGTERM when the spawning thread's process dies.

    libc is loaded here, in the parent: between fork and exec the child must not import
    anything (another thread may hold the import lock at fork time).
    """
    if not sys.platform.startswith("linux"):
        return None
    import ctypes

    prctl = ctypes.CDLL(None, use_errno=True).prctl
    return lambda: prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


class WorkerSupervisor:
    """Runs the worker child; restarts it if it dies while the API is up (unless it crash-loops).

    The child gets its own session (a terminal's Ctrl-C reaches only this process, which then
    stops the worker in order) and a parent-death signal (if this process is killed outright).
    Restarts happen in the watcher thread; the parent-death signal follows that thread, which
    lives until :meth:`stop`.
    """

    def __init__(self, command: list[str]) -> None:
        self.command = command
        self.process: subprocess.Popen[bytes] | None = None
        self.stopping = threading.Event()
        self.restarts = 0
        self.gave_up = False
        self._recent: list[float] = []
        self._lock = threading.Lock()
        self._pre_exec = _death_signal_setter()
        self._thread = threading.Thread(target=self._watch, name="worker-supervisor", daemon=True)

    def start(self) -> None:
        with self._lock:
            self._spawn()
        self._thread.start()

    def _spawn(self) -> None:
        self.process = subprocess.Popen(self.command, start_new_session=True, preexec_fn=self._pre_exec)
        logger.info("worker started (pid %d)", self.process.pid)

    def _watch(self) -> None:
        while not self.stopping.wait(WORKER_POLL_S):
            with self._lock:
                if self.stopping.is_set() or self.process is None or self.process.poll() is None:
                    continue
                now = time.monotonic()
                self._recent = [t for t in self._recent if now - t < WORKER_RESTART_WINDOW_S]
                if len(self._recent) >= WORKER_RESTART_LIMIT:
                    self.gave_up = True
                    logger.error("worker exited with %s after %d restarts in %.0f s; not restarting it: jobs will wait and "
                                 "/readyz reports no live worker", self.process.returncode, len(self._recent), WORKER_RESTART_WINDOW_S)
                    return
                self._recent.append(now)
                self.restarts += 1
                logger.error("worker exited with %s; restarting (%d in the last %.0f s)", self.process.returncode,
                             len(self._recent), WORKER_RESTART_WINDOW_S)
                self._spawn()

    def stop(self) -> int | None:
        """Warm shutdown (SIGTERM: the running job finishes), then SIGKILL after the timeout."""
        with self._lock:
            self.stopping.set()
            process = self.process
        if process is None or process.poll() is not None:
            return None if process is None else process.returncode
        process.send_signal(signal.SIGTERM)  # the main process only: it lets its pool finish the job
        try:
            return process.wait(WORKER_STOP_TIMEOUT_S)
        except subprocess.TimeoutExpired:
            logger.warning("worker did not stop in %.0f s; killing it", WORKER_STOP_TIMEOUT_S)
            os.killpg(process.pid, signal.SIGKILL)
            return process.wait()


def _serve(args: argparse.Namespace) -> int:
    from app.core.config import get_settings
    from app.core.logging import configure_logging
    from app.db.migrate import upgrade
    from workers.broker import uses_redis

    # Our handlers from the start: a stop signal before uvicorn runs is remembered (and
    # serving is skipped), and the signal uvicorn re-raises after its shutdown lands here
    # instead of killing the process before the worker is stopped.
    received: list[int] = []
    previous = {sig: signal.signal(sig, lambda signum, _frame: received.append(signum)) for sig in STOP_SIGNALS}
    settings = get_settings()
    logging.getLogger().handlers.clear()  # the CLI's basicConfig handler; this process logs like the service
    configure_logging(settings)
    settings.data_dir.mkdir(parents=True, exist_ok=True)
    upgrade(settings.sqlalchemy_url)
    broker = "redis" if uses_redis(settings) else "sqlite"
    supervisor = WorkerSupervisor(worker_command(args.workers, sqlite_broker=broker == "sqlite"))
    supervisor.start()
    began = time.monotonic()
    try:
        out(f"ArtiMo service on http://{args.host}:{args.port}  (data: {settings.data_dir}, broker: {broker})")
        key_line, client_id = _api_key(settings)
        out(key_line)
        if settings.database_url is None:  # embedded mode: a link that opens the page signed in
            out(f"Page: {_page_url(settings, args, client_id)}")
        sys.stdout.flush()
        return _run_api(args, received)
    finally:
        supervisor.stop()
        for sig, handler in previous.items():
            signal.signal(sig, handler)
        logger.info("service stopped after %.0f s (signals: %s)", time.monotonic() - began, received)


def _run_api(args: argparse.Namespace, received: list[int]) -> int:
    """uvicorn in the foreground until a stop signal; 0 on a clean stop."""
    import uvicorn

    if received:
        return 0
    config = uvicorn.Config("app.main:create_app", factory=True, host=args.host, port=args.port, log_config=None,
                            workers=max(1, args.api_processes))
    server = uvicorn.Server(config)
    try:
        if config.workers > 1:
            return _run_api_processes(config)
        server.run()
    except SystemExit as exc:  # uvicorn exits when it cannot bind
        err(f"API server stopped: exit {exc.code}")
        return 1
    return 0 if server.started or received else 1


def _run_api_processes(config: uvicorn.Config) -> int:
    """uvicorn's supervisor: one listening socket, ``config.workers`` server processes (restarted if one
    dies); SIGINT/SIGTERM stop them all, then control returns here to stop the job worker."""
    from uvicorn.supervisors import Multiprocess

    sock = config.bind_socket()
    try:
        Multiprocess(config, sockets=[sock]).run()
    finally:
        sock.close()
    return 0


def _api_key(settings: Settings) -> tuple[str, str]:
    """The line telling the user which API key to use (a generated key is shown only once), and its client's id."""
    from sqlalchemy import select

    from app.crud.clients import create_api_client, ensure_client_for_key
    from app.db.models import ApiClient
    from app.db.session import session_factory

    where = f"database {settings.database_shown}"
    with session_factory(settings.sqlalchemy_url)() as session:
        if settings.artimo_api_key is not None:
            client = ensure_client_for_key(session, key=settings.artimo_api_key.get_secret_value())
            shown = settings.artimo_api_key.get_secret_value()[:KEY_PREFIX_SHOWN]
            return (f"API key: the value of $ARTIMO_API_KEY ({shown}...), registered in the {where} "
                    f"(data folder {settings.data_dir})"), str(client.id)
        existing = session.execute(select(ApiClient).where(ApiClient.name == EMBEDDED_CLIENT)).scalars().first()
        if existing is not None:
            return (f"API key: the '{EMBEDDED_CLIENT}' key printed when this {where} was first served "
                    f"({existing.key_prefix}...); or set ARTIMO_API_KEY, or run: artimo keys create --name NAME "
                    f"(with the same ARTIMO_DATA_DIR={settings.data_dir})"), str(existing.id)
        client, key = create_api_client(session, name=EMBEDDED_CLIENT)
        return f"API key (shown once, stored hashed): {key}  (valid for the {where}; data folder {settings.data_dir})", str(client.id)


def _page_url(settings: Settings, args: argparse.Namespace, client_id: str) -> str:
    """The page's address with a signed, expiring sign-in token in its fragment (never sent to the server)."""
    from app.api.signing import page_token

    host = "127.0.0.1" if args.host in ("0.0.0.0", "::", "") else args.host
    host = f"[{host}]" if ":" in host else host
    return f"http://{host}:{args.port}/#login={page_token(settings, client_id, settings.page_login_ttl_s)}"
