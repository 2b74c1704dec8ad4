"""Alembic: upgrade head -> downgrade base round trip on Postgres and SQLite; schema == models."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from alembic.autogenerate import compare_metadata
from alembic.runtime.migration import MigrationContext
from sqlalchemy import create_engine, inspect, pool

from app.db import migrate
from app.db.base import Base
from tests.support.databases import postgres_database

TABLES = {"api_client", "asset", "client_asset", "batch", "job", "artifact", "job_event"}


@pytest.fixture(params=["postgresql", "sqlite"])
def url(request: pytest.FixtureRequest, tmp_path: Path) -> Iterator[str]:
    if request.param == "sqlite":
        yield f"sqlite:///{tmp_path / 'nested' / 'artimo.db'}"
        return
    with postgres_database("artimo_migrations") as pg_url:
        yield pg_url


def _tables(url: str) -> set[str]:
    engine = create_engine(url, poolclass=pool.NullPool)
    try:
        with engine.connect() as connection:
            return set(inspect(connection).get_table_names()) - {"alembic_version"}
    finally:
        engine.dispose()


def _differences(url: str) -> list[object]:
    engine = create_engine(url, poolclass=pool.NullPool)
    try:
        with engine.connect() as connection:
            context = MigrationContext.configure(connection, opts={"compare_type": True})
            return list(compare_metadata(context, Base.metadata))
    finally:
        engine.dispose()


def test_round_trip_and_schema_matches_models(url: str) -> None:
    migrate.upgrade(url)
    assert _tables(url) == TABLES
    assert _differences(url) == []
    engine = create_engine(url, poolclass=pool.NullPool)
    with engine.connect() as connection:
        assert migrate.current_revision(connection) == migrate.head_revision()
    engine.dispose()
    migrate.upgrade(url)  # idempotent
    migrate.downgrade(url)
    assert _tables(url) == set()
    migrate.upgrade(url)
    assert _tables(url) == TABLES


def test_every_model_table_is_created_by_a_migration() -> None:
    assert set(Base.metadata.tables) == TABLES


def test_offline_sql_renders(capsys: pytest.CaptureFixture[str]) -> None:
    from alembic import command

    config = migrate.alembic_config("postgresql+psycopg://user@localhost/db")
    command.upgrade(config, "head", sql=True)
    sql = capsys.readouterr().out
    assert "CREATE TABLE job" in sql and "CREATE UNIQUE INDEX ix_asset_sha256" in sql


def test_concurrent_upgrades_are_serialised(url: str) -> None:
    """API and worker starting together both call upgrade(): neither fails, the schema is made once."""
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=3) as pool_:
        list(pool_.map(migrate.upgrade, [url] * 3))
    assert _tables(url) == TABLES
