"""Alembic environment: the database URL comes from the caller or from :func:`get_settings`.

Order of precedence: a connection passed in ``config.attributes["connection"]`` (used by
:func:`app.db.migrate.upgrade`, which holds a lock on it), then ``config.attributes["url"]``,
then ``sqlalchemy.url`` from the config, then ``get_settings().sqlalchemy_url``.
"""

from __future__ import annotations

import logging

from alembic import context
from sqlalchemy import Connection, create_engine, pool

from app.core.config import get_settings
from app.db import models  # noqa: F401  (registers every table on Base.metadata)
from app.db.base import Base

logger = logging.getLogger("alembic.env")

config = context.config
target_metadata = Base.metadata


def _url() -> str:
    configured = None
    if config.file_config.has_section(config.config_ini_section):  # an alembic.ini, if someone passes one
        configured = config.get_main_option("sqlalchemy.url")
    return str(config.attributes.get("url") or configured or get_settings().sqlalchemy_url)


def _configure(**kwargs: object) -> None:
    context.configure(target_metadata=target_metadata, compare_type=True, render_as_batch=True, **kwargs)  # type: ignore[arg-type]


def run_migrations_offline() -> None:
    """Emit SQL to stdout (``alembic upgrade head --sql``)."""
    _configure(url=_url(), literal_binds=True, dialect_opts={"paramstyle": "named"})
    with context.begin_transaction():
        context.run_migrations()


def _run_on(connection: Connection) -> None:
    _configure(connection=connection)
    with context.begin_transaction():
        context.run_migrations()


def run_migrations_online() -> None:
    connection = config.attributes.get("connection")
    if connection is not None:
        _run_on(connection)
        return
    engine = create_engine(_url(), poolclass=pool.NullPool)
    try:
        with engine.connect() as fresh:
            _run_on(fresh)
    finally:
        engine.dispose()


if context.is_offline_mode():
    run_migrations_offline()
else:
    run_migrations_online()
