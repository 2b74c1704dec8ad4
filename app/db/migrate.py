"""Run the Alembic migrations from code: embedded start-up (API, worker), tests, ``python -m app.db.migrate``.

Concurrent callers are serialised: on Postgres with an advisory lock held on the migrating
connection, on SQLite with an ``flock`` next to the database file. Upgrading an up-to-date
database does nothing, so every process may call :func:`upgrade` at start-up.
"""

from __future__ import annotations

import fcntl
import logging
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from alembic import command
from alembic.config import Config
from alembic.runtime.migration import MigrationContext
from alembic.script import ScriptDirectory
from sqlalchemy import Connection, create_engine, pool, text
from sqlalchemy.engine import make_url

MIGRATIONS_DIR = Path(__file__).resolve().parents[2] / "migrations"
PG_MIGRATION_LOCK = 0x41525449  # "ARTI": one advisory lock id for schema changes

logger = logging.getLogger(__name__)


def alembic_config(url: str | None = None) -> Config:
    """An in-memory Alembic config (no alembic.ini, no pyproject needed at run time)."""
    config = Config()
    config.set_main_option("script_location", str(MIGRATIONS_DIR))
    if url is not None:
        config.attributes["url"] = url
    return config


@contextmanager
def _sqlite_lock(url: str) -> Iterator[None]:
    database = make_url(url).database
    if not database or database == ":memory:":
        yield
        return
    lock_path = Path(database).with_name(Path(database).name + ".migrate.lock")
    lock_path.parent.mkdir(parents=True, exist_ok=True)
    with open(lock_path, "a+") as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def _run(url: str, action: str, revision: str) -> None:
    engine = create_engine(url, poolclass=pool.NullPool)
    try:
        with engine.connect() as connection:
            if connection.dialect.name == "postgresql":
                connection.execute(text("SELECT pg_advisory_lock(:id)"), {"id": PG_MIGRATION_LOCK})
                connection.commit()
            config = alembic_config(url)
            config.attributes["connection"] = connection
            getattr(command, action)(config, revision)
            connection.commit()
            if connection.dialect.name == "postgresql":
                connection.execute(text("SELECT pg_advisory_unlock(:id)"), {"id": PG_MIGRATION_LOCK})
                connection.commit()
    finally:
        engine.dispose()


def upgrade(url: str, revision: str = "head") -> None:
    """Bring the database at ``url`` to ``revision`` (default: the newest)."""
    parsed = make_url(url)
    if parsed.get_backend_name() == "sqlite" and parsed.database and parsed.database != ":memory:":
        Path(parsed.database).parent.mkdir(parents=True, exist_ok=True)
    with _sqlite_lock(url) if url.startswith("sqlite") else _nothing():
        _run(url, "upgrade", revision)
    logger.info("database schema at %s", revision)


def downgrade(url: str, revision: str = "base") -> None:
    """Take the database at ``url`` back to ``revision`` (default: empty)."""
    with _sqlite_lock(url) if url.startswith("sqlite") else _nothing():
        _run(url, "downgrade", revision)


@contextmanager
def _nothing() -> Iterator[None]:
    yield


def current_revision(connection: Connection) -> str | None:
    return MigrationContext.configure(connection).get_current_revision()


def head_revision() -> str | None:
    return ScriptDirectory.from_config(alembic_config()).get_current_head()


def main() -> int:
    """``python -m app.db.migrate``: upgrade the configured database to head."""
    from app.core.config import get_settings
    from app.core.logging import configure_logging

    settings = get_settings()
    configure_logging(settings)
    upgrade(settings.sqlalchemy_url)
    return 0


if __name__ == "__main__":
    sys.exit(main())
