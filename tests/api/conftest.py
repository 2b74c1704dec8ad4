"""API test fixtures: one migrated Postgres database per session, an app per test, API clients.

The enqueuer is replaced by a recorder (``sent``), so no worker or broker is needed; the
lifecycle tests run the worker's task function directly on the same database and storage.
"""

from __future__ import annotations

import uuid
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient
from sqlalchemy.orm import Session

from app.api.deps import get_enqueuer
from app.core.config import Settings
from app.crud.clients import create_api_client
from app.db.migrate import upgrade
from app.db.models import ApiClient
from app.db.session import session_factory
from app.main import create_app
from tests.support.databases import postgres_database


@pytest.fixture(scope="session")
def pg_url() -> Iterator[str]:
    with postgres_database("artimo_api") as url:
        upgrade(url)
        yield url


@pytest.fixture
def settings(pg_url: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Settings:
    """Settings of one test: the session's Postgres, storage in ``tmp_path``, no env key."""
    monkeypatch.delenv("ARTIMO_API_KEY", raising=False)
    (tmp_path / "data").mkdir(exist_ok=True)  # as the service makes it at start-up: the SQLite broker lives there
    return Settings(
        auth_cache_s=0.0,
        _env_file=None,  # type: ignore[call-arg]
        artimo_data_dir=tmp_path / "data", database_url=pg_url, redis_url=None,
        artimo_api_key="env-key-" + uuid.uuid4().hex,  # type: ignore[arg-type]
    )


@pytest.fixture
def sent() -> list[uuid.UUID]:
    """Job ids the API handed to the (fake) queue."""
    return []


@pytest.fixture
def app(settings: Settings, sent: list[uuid.UUID]) -> FastAPI:
    application = create_app(settings)
    application.dependency_overrides[get_enqueuer] = lambda: sent.append
    return application


@pytest.fixture
def http(app: FastAPI) -> Iterator[TestClient]:
    with TestClient(app) as client:
        yield client


@pytest.fixture
def db(settings: Settings) -> Iterator[Session]:
    with session_factory(settings.sqlalchemy_url)() as session:
        yield session


@dataclass
class Caller:
    client: ApiClient
    key: str

    @property
    def headers(self) -> dict[str, str]:
        return {"Authorization": f"Bearer {self.key}"}


@pytest.fixture
def make_caller(db: Session):  # type: ignore[no-untyped-def]
    def make(name: str = "tester", rate_limit: int | None = 10_000) -> Caller:
        client, key = create_api_client(db, name=name, rate_limit_per_minute=rate_limit)
        return Caller(client, key)

    return make


@pytest.fixture
def alice(make_caller) -> Caller:  # type: ignore[no-untyped-def]
    return make_caller("alice")


@pytest.fixture
def bob(make_caller) -> Caller:  # type: ignore[no-untyped-def]
    return make_caller("bob")
