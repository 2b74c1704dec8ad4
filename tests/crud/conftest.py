"""CRUD tests run on a migrated throw-away Postgres database."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from sqlalchemy.orm import Session

from app.db.migrate import upgrade
from app.db.session import session_factory
from tests.support.databases import postgres_database


@pytest.fixture(scope="session")
def crud_url() -> Iterator[str]:
    with postgres_database("artimo_crud") as url:
        upgrade(url)
        yield url


@pytest.fixture
def db(crud_url: str) -> Iterator[Session]:
    with session_factory(crud_url)() as session:
        yield session
