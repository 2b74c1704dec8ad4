"""initial schema: api_client, asset, client_asset, batch, job, artifact, job_event

Revision ID: 0001
Revises:
Create Date: 2026-11-22 05:49:32
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0001"
down_revision: str | Sequence[str] | None = None
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

_TZ = sa.DateTime(timezone=True)
_INDEXES: tuple[tuple[str, str, tuple[str, ...], bool], ...] = (
    ("ix_api_client_key_hash", "api_client", ("key_hash",), True),
    ("ix_asset_sha256", "asset", ("sha256",), True),
    ("ix_client_asset_asset_id", "client_asset", ("asset_id",), False),
    ("ix_batch_client_id", "batch", ("client_id",), False),
    ("ix_job_asset_id", "job", ("asset_id",), False),
    ("ix_job_batch_id", "job", ("batch_id",), False),
    ("ix_job_client_id", "job", ("client_id",), False),
    ("ix_job_created_at", "job", ("created_at",), False),
    ("ix_job_status", "job", ("status",), False),
    ("ix_artifact_job_id", "artifact", ("job_id",), False),
    ("ix_job_event_job_id", "job_event", ("job_id",), False),
)


def _fk(column: str, table: str, target: str, ondelete: str) -> sa.ForeignKeyConstraint:
    return sa.ForeignKeyConstraint([column], [f"{target}.id"], name=f"fk_{table}_{column}_{target}", ondelete=ondelete)


def upgrade() -> None:
    op.create_table(
        "api_client",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("name", sa.String(length=200), nullable=False),
        sa.Column("key_hash", sa.String(length=64), nullable=False),
        sa.Column("key_prefix", sa.String(length=12), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
        sa.Column("disabled", sa.Boolean(), nullable=False),
        sa.Column("rate_limit_per_minute", sa.Integer(), nullable=True),
        sa.PrimaryKeyConstraint("id", name="pk_api_client"),
    )
    op.create_table(
        "asset",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("sha256", sa.String(length=64), nullable=False),
        sa.Column("filename", sa.String(length=500), nullable=False),
        sa.Column("size_bytes", sa.Integer(), nullable=False),
        sa.Column("storage_key", sa.String(length=500), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
        sa.PrimaryKeyConstraint("id", name="pk_asset"),
    )
    op.create_table(
        "client_asset",
        sa.Column("client_id", sa.Uuid(), nullable=False),
        sa.Column("asset_id", sa.Uuid(), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
        _fk("asset_id", "client_asset", "asset", "CASCADE"),
        _fk("client_id", "client_asset", "api_client", "CASCADE"),
        sa.PrimaryKeyConstraint("client_id", "asset_id", name="pk_client_asset"),
    )
    op.create_table(
        "batch",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("client_id", sa.Uuid(), nullable=False),
        sa.Column("name", sa.String(length=200), nullable=True),
        sa.Column("created_at", _TZ, nullable=False),
        _fk("client_id", "batch", "api_client", "CASCADE"),
        sa.PrimaryKeyConstraint("id", name="pk_batch"),
    )
    op.create_table(
        "job",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("client_id", sa.Uuid(), nullable=False),
        sa.Column("asset_id", sa.Uuid(), nullable=False),
        sa.Column("batch_id", sa.Uuid(), nullable=True),
        sa.Column("case_id", sa.String(length=200), nullable=True),
        sa.Column("prompt", sa.Text(), nullable=False),
        sa.Column("options", sa.JSON(), nullable=False),
        sa.Column("status", sa.String(length=16), nullable=False),
        sa.Column("stage", sa.String(length=32), nullable=True),
        sa.Column("progress", sa.Integer(), nullable=False),
        sa.Column("error", sa.Text(), nullable=True),
        sa.Column("error_kind", sa.String(length=64), nullable=True),
        sa.Column("timings", sa.JSON(), nullable=False),
        sa.Column("attempts", sa.Integer(), nullable=False),
        sa.Column("cancel_requested", sa.Boolean(), nullable=False),
        sa.Column("worker", sa.String(length=200), nullable=True),
        sa.Column("created_at", _TZ, nullable=False),
        sa.Column("started_at", _TZ, nullable=True),
        sa.Column("finished_at", _TZ, nullable=True),
        _fk("asset_id", "job", "asset", "RESTRICT"),
        _fk("batch_id", "job", "batch", "CASCADE"),
        _fk("client_id", "job", "api_client", "CASCADE"),
        sa.PrimaryKeyConstraint("id", name="pk_job"),
    )
    op.create_table(
        "artifact",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("job_id", sa.Uuid(), nullable=False),
        sa.Column("name", sa.String(length=300), nullable=False),
        sa.Column("storage_key", sa.String(length=500), nullable=False),
        sa.Column("sha256", sa.String(length=64), nullable=False),
        sa.Column("size_bytes", sa.Integer(), nullable=False),
        sa.Column("content_type", sa.String(length=100), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
        _fk("job_id", "artifact", "job", "CASCADE"),
        sa.PrimaryKeyConstraint("id", name="pk_artifact"),
        sa.UniqueConstraint("job_id", "name", name="uq_artifact_job_name"),
    )
    op.create_table(
        "job_event",
        sa.Column("id", sa.Integer(), autoincrement=True, nullable=False),
        sa.Column("job_id", sa.Uuid(), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
        sa.Column("kind", sa.String(length=16), nullable=False),
        sa.Column("stage", sa.String(length=32), nullable=True),
        sa.Column("progress", sa.Integer(), nullable=True),
        sa.Column("message", sa.Text(), nullable=True),
        _fk("job_id", "job_event", "job", "CASCADE"),
        sa.PrimaryKeyConstraint("id", name="pk_job_event"),
    )
    for name, table, columns, unique in _INDEXES:
        op.create_index(name, table, list(columns), unique=unique)


def downgrade() -> None:
    for name, table, _columns, _unique in reversed(_INDEXES):
        op.drop_index(name, table_name=table)
    for table in ("job_event", "artifact", "job", "batch", "client_asset", "asset", "api_client"):
        op.drop_table(table)
