"""Throw-away databases for service tests: a uniquely named Postgres database or a SQLite file.

The Postgres server comes from ``$ARTIMO_TEST_POSTGRES_URL`` (default: the CI service at
``postgresql+psycopg://postgres@127.0.0.1:5432/test``, trust auth); ``make services`` starts it.
"""

from __future__ import annotations

import os
import uuid
from collections.abc import Iterator
from contextlib import contextmanager

from sqlalchemy import create_engine, text
from sqlalchemy.engine import make_url
from sqlalchemy.exc import OperationalError

DEFAULT_POSTGRES_URL = "postgresql+psycopg://postgres@127.0.0.1:5432/test"


def postgres_admin_url() -> str:
    return os.environ.get("ARTIMO_TEST_POSTGRES_URL", DEFAULT_POSTGRES_URL)


@contextmanager
def postgres_database(prefix: str = "artimo_test") -> Iterator[str]:
    """Create ``<prefix>_<random>`` on the test server, yield its URL, drop it afterwards."""
    admin_url = make_url(postgres_admin_url())
    name = f"{prefix}_{uuid.uuid4().hex[:12]}"
    admin = create_engine(admin_url, isolation_level="AUTOCOMMIT")
    try:
        with admin.connect() as connection:
            connection.execute(text(f'CREATE DATABASE "{name}"'))
    except OperationalError as exc:
        admin.dispose()
        raise RuntimeError(f"PostgreSQL not reachable at {admin_url!r} (run `make services`): {exc}") from exc
    url = admin_url.set(database=name).render_as_string(hide_password=False)
    try:
        yield url
    finally:
        from app.db.session import get_engine

        get_engine(url).dispose()  # the app's cached pool on this database
        with admin.connect() as connection:
            connection.execute(text(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)'))
        admin.dispose()
