"""The embedded service's worker supervisor: restarts a dying worker, stops only on a crash loop."""

from __future__ import annotations

import sys
import time

import pytest

from app.cli import serve_cmd
from app.cli.serve_cmd import WorkerSupervisor

CRASH = [sys.executable, "-c", "raise SystemExit(3)"]


def _wait(predicate, timeout: float = 20.0) -> None:  # type: ignore[no-untyped-def]
    deadline = time.monotonic() + timeout
    while not predicate():
        assert time.monotonic() < deadline, "timed out"
        time.sleep(0.05)


def test_a_crash_loop_stops_the_restarts(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(serve_cmd, "WORKER_POLL_S", 0.05)
    supervisor = WorkerSupervisor(CRASH)
    supervisor.start()
    try:
        _wait(lambda: supervisor.gave_up)
        assert supervisor.restarts == serve_cmd.WORKER_RESTART_LIMIT
    finally:
        supervisor.stop()


def test_crashes_spread_over_time_are_always_restarted(monkeypatch: pytest.MonkeyPatch) -> None:
    """Before: the sixth crash in the service's life ended the restarts for good."""
    monkeypatch.setattr(serve_cmd, "WORKER_POLL_S", 0.05)
    monkeypatch.setattr(serve_cmd, "WORKER_RESTART_WINDOW_S", 0.3)  # each crash is "long" after the ones before
    monkeypatch.setattr(serve_cmd, "WORKER_RESTART_LIMIT", 2)
    supervisor = WorkerSupervisor([sys.executable, "-c", "import time; time.sleep(0.4); raise SystemExit(3)"])
    supervisor.start()
    try:
        _wait(lambda: supervisor.restarts >= 6)
        assert not supervisor.gave_up
    finally:
        supervisor.stop()
