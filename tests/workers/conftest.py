"""Worker test fixtures on the machine's real services.

One fresh Postgres database and one Redis DB number per session (dropped/flushed at the
end); each test module gets its own Celery queue name, so its workers and API server
see only its jobs. Processes are started by :mod:`tests.workers.stack`.
"""

from __future__ import annotations

import uuid
from collections.abc import Iterator
from pathlib import Path

import pytest

from app.core.config import Settings, get_settings
from tests.workers import stack

TEST_API_KEY = "artimo_worker-tests-key"
STAGE_DELAY_S = "0.3"
"""Per-stage pause of the test workers: a job takes ~2.5 s, long enough to watch, cancel or kill."""
VISIBILITY_TIMEOUT_S = "6"
"""Redis redelivers a dead worker's job after this (production: hard time limit + 120 s)."""


@pytest.fixture(scope="session")
def pg_url() -> Iterator[str]:
    from app.db.migrate import upgrade

    with stack.fresh_database() as url:
        upgrade(url)
        yield url


@pytest.fixture(scope="session")
def redis_db() -> Iterator[int]:
    stack.start_redis()
    with stack.claimed_redis_db() as db:
        yield db


@pytest.fixture(scope="session")
def data_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("artimo-data")


@pytest.fixture(scope="module")
def queue_name() -> str:
    return f"artimo-test-{uuid.uuid4().hex[:10]}"


@pytest.fixture(scope="module")
def service_env(pg_url: str, redis_db: int, data_dir: Path, queue_name: str) -> dict[str, str]:
    """Environment shared by the API server and the workers of one test module."""
    return {
        "DATABASE_URL": pg_url,
        "REDIS_URL": f"redis://127.0.0.1:6379/{redis_db}",
        "CELERY_QUEUE": queue_name,
        "ARTIMO_DATA_DIR": str(data_dir),
        "ARTIMO_API_KEY": TEST_API_KEY,
        "JOB_STAGE_DELAY_S": STAGE_DELAY_S,
        "BROKER_VISIBILITY_TIMEOUT_S": VISIBILITY_TIMEOUT_S,
        "REQUEUE_QUEUED_AFTER_S": "0",
        "RATE_LIMIT_PER_MINUTE": "100000",
        "LOG_LEVEL": "INFO",
    }


@pytest.fixture()
def settings(monkeypatch: pytest.MonkeyPatch, service_env: dict[str, str]) -> Iterator[Settings]:
    """The module's settings in this process (environment patched, cache cleared around the test)."""
    for name, value in service_env.items():
        monkeypatch.setenv(name, value)
    monkeypatch.setenv("JOB_STAGE_DELAY_S", "0")
    get_settings.cache_clear()
    yield get_settings()
    get_settings.cache_clear()


@pytest.fixture(scope="module")
def log_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("logs")


@pytest.fixture(scope="module")
def api(service_env: dict[str, str], log_dir: Path) -> Iterator[str]:
    """A real API server (uvicorn) for the module; yields its base URL."""
    server, url = stack.start_api(service_env, log_dir)
    try:
        yield url
    finally:
        server.stop()


@pytest.fixture()
def workers(service_env: dict[str, str], log_dir: Path, request: pytest.FixtureRequest) -> Iterator[list[stack.Service]]:
    """Start workers with ``workers.append(stack.start_worker(...))``; all are stopped after the test."""
    started: list[stack.Service] = []
    yield started
    for worker in started:
        worker.stop()
    call = getattr(request.node, "rep_call", None)
    if call is not None and call.failed:  # show the workers' logs with the failure
        for worker in started:
            print(f"--- {worker.name} log ---\n{worker.text()[-4000:]}")


@pytest.hookimpl(hookwrapper=True, tryfirst=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[None]):  # type: ignore[no-untyped-def]
    outcome = yield
    report = outcome.get_result()
    setattr(item, f"rep_{report.when}", report)
