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

TABLES = {"api_client", "asset", "asset_content", "batch", "job", "artifact", "job_event", "worker_heartbeat"}


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


def test_shared_assets_become_per_client_records_and_back(url: str) -> None:
    """0001 -> 0002 keeps every job's asset: the first uploader keeps the id, the second gets its own record."""
    import uuid
    from datetime import UTC, datetime, timedelta

    from sqlalchemy import text

    migrate.upgrade(url, "0001")
    engine = create_engine(url, poolclass=pool.NullPool)
    alice, bob, shared = uuid.uuid4(), uuid.uuid4(), uuid.uuid4()
    early = datetime(2026, 1, 1, tzinfo=UTC)

    def value(identifier: uuid.UUID) -> object:
        return identifier if url.startswith("postgresql") else identifier.hex

    with engine.begin() as connection:
        for client in (alice, bob):
            connection.execute(text("INSERT INTO api_client (id, name, key_hash, key_prefix, created_at, disabled) "
                                    "VALUES (:id, 'c', :hash, 'p', :at, false)"), {"id": value(client), "hash": uuid.uuid4().hex, "at": early})
        connection.execute(text("INSERT INTO asset (id, sha256, filename, size_bytes, storage_key, created_at) "
                                "VALUES (:id, :sha, 'bin.zip', 10, 'assets/x.zip', :at)"), {"id": value(shared), "sha": "a" * 64, "at": early})
        for client, offset in ((alice, 0), (bob, 1)):
            at = early + timedelta(hours=offset)
            connection.execute(text("INSERT INTO client_asset (client_id, asset_id, created_at) VALUES (:c, :a, :at)"),
                               {"c": value(client), "a": value(shared), "at": at})
            connection.execute(text(
                "INSERT INTO job (id, client_id, asset_id, prompt, options, status, progress, timings, attempts, cancel_requested, created_at) "
                "VALUES (:id, :c, :a, 'open', '{}', 'queued', 0, '{}', 0, false, :at)"),
                {"id": value(uuid.uuid4()), "c": value(client), "a": value(shared), "at": at})
    migrate.upgrade(url)
    with engine.connect() as connection:
        rows = connection.execute(text("SELECT a.id, a.client_id, a.filename, a.urdf, c.sha256 FROM asset a "
                                       "JOIN asset_content c ON c.id = a.content_id ORDER BY a.created_at")).all()
        jobs = dict(connection.execute(text("SELECT client_id, asset_id FROM job")).all())
    assert [(str(r[2]), r[3], r[4]) for r in rows] == [("bin.zip", "", "a" * 64)] * 2
    as_uuid = [uuid.UUID(str(r[0])) for r in rows]
    assert as_uuid[0] == shared and as_uuid[1] != shared  # alice keeps the id, bob has his own
    assert {uuid.UUID(str(k)): uuid.UUID(str(v)) for k, v in jobs.items()} == {alice: as_uuid[0], bob: as_uuid[1]}
    migrate.downgrade(url, "0001")
    with engine.connect() as connection:
        assets = connection.execute(text("SELECT id FROM asset")).all()
        grants = connection.execute(text("SELECT client_id FROM client_asset")).all()
        job_assets = {uuid.UUID(str(r[0])) for r in connection.execute(text("SELECT asset_id FROM job")).all()}
    assert [uuid.UUID(str(r[0])) for r in assets] == [shared] and len(grants) == 2 and job_assets == {shared}
    engine.dispose()
