"""per-client asset records over shared content (asset_content), the chosen URDF, worker heartbeats

Before: one ``asset`` row per content hash, shared by every client that uploaded the bytes
(``client_asset`` grants), so a second uploader learned the first one's id, name and time.
After: ``asset_content`` holds the bytes' hash, size and storage key once; ``asset`` is one
client's record over it (own id, file name, time, and which URDF to use). Existing data is
kept: the earliest grantee of a shared asset keeps its id, every other grantee gets a new
record and its jobs point to it. Written as plain SQL so ``alembic upgrade --sql`` works.

Revision ID: 0002
Revises: 0001
Create Date: 2026-11-25 09:00:00
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0002"
down_revision: str | Sequence[str] | None = "0001"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

_TZ = sa.DateTime(timezone=True)


def _new_uuid() -> str:
    """SQL for a fresh UUID value of a ``Uuid`` column (native on PostgreSQL, 32 hex characters on SQLite)."""
    return "gen_random_uuid()" if op.get_context().dialect.name == "postgresql" else "lower(hex(randomblob(16)))"


def _asset_table() -> None:
    op.create_table(
        "asset",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("client_id", sa.Uuid(), nullable=False),
        sa.Column("content_id", sa.Uuid(), nullable=False),
        sa.Column("filename", sa.String(length=500), nullable=False),
        sa.Column("urdf", sa.String(length=500), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
        sa.ForeignKeyConstraint(["client_id"], ["api_client.id"], name="fk_asset_client_id_api_client", ondelete="CASCADE"),
        sa.ForeignKeyConstraint(["content_id"], ["asset_content.id"], name="fk_asset_content_id_asset_content", ondelete="RESTRICT"),
        sa.PrimaryKeyConstraint("id", name="pk_asset"),
        sa.UniqueConstraint("client_id", "content_id", "urdf", name="uq_asset_client_content_urdf"),
    )
    op.create_index("ix_asset_client_id", "asset", ["client_id"])
    op.create_index("ix_asset_content_id", "asset", ["content_id"])


def _drop_job_asset_fk() -> None:
    with op.batch_alter_table("job") as batch:
        batch.drop_constraint("fk_job_asset_id_asset", type_="foreignkey")


def _add_job_asset_fk() -> None:
    with op.batch_alter_table("job") as batch:
        batch.create_foreign_key("fk_job_asset_id_asset", "asset", ["asset_id"], ["id"], ondelete="RESTRICT")


def upgrade() -> None:
    uuid = _new_uuid()
    op.create_table(
        "asset_content",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("sha256", sa.String(length=64), nullable=False),
        sa.Column("size_bytes", sa.Integer(), nullable=False),
        sa.Column("storage_key", sa.String(length=500), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
        sa.Column("legacy_asset_id", sa.Uuid(), nullable=True),
        sa.PrimaryKeyConstraint("id", name="pk_asset_content"),
    )
    op.execute(f"INSERT INTO asset_content (id, sha256, size_bytes, storage_key, created_at, legacy_asset_id) "
               f"SELECT {uuid}, sha256, size_bytes, storage_key, created_at, id FROM asset")
    op.create_table(
        "asset_record_staging",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("client_id", sa.Uuid(), nullable=False),
        sa.Column("legacy_asset_id", sa.Uuid(), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
    )
    # a record per grant: the earliest grantee of each asset keeps the asset's id
    op.execute(
        f"INSERT INTO asset_record_staging (id, client_id, legacy_asset_id, created_at) "
        f"SELECT CASE WHEN NOT EXISTS (SELECT 1 FROM client_asset o WHERE o.asset_id = g.asset_id AND "
        f"(o.created_at < g.created_at OR (o.created_at = g.created_at AND o.client_id < g.client_id))) "
        f"THEN g.asset_id ELSE {uuid} END, g.client_id, g.asset_id, g.created_at FROM client_asset g"
    )
    # jobs of a client without a grant for their asset (not made by the API, but possible)
    op.execute(
        f"INSERT INTO asset_record_staging (id, client_id, legacy_asset_id, created_at) "
        f"SELECT {uuid}, p.client_id, p.asset_id, p.created_at FROM (SELECT j.client_id, j.asset_id, MIN(j.created_at) AS created_at "
        f"FROM job j WHERE NOT EXISTS (SELECT 1 FROM client_asset g WHERE g.client_id = j.client_id AND g.asset_id = j.asset_id) "
        f"GROUP BY j.client_id, j.asset_id) p"
    )
    _drop_job_asset_fk()
    op.execute("UPDATE job SET asset_id = (SELECT r.id FROM asset_record_staging r "
               "WHERE r.client_id = job.client_id AND r.legacy_asset_id = job.asset_id)")
    op.drop_index("ix_client_asset_asset_id", table_name="client_asset")
    op.drop_table("client_asset")
    op.create_table(  # the old shared rows, kept only for their file names until the copy below
        "asset_name_staging",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("filename", sa.String(length=500), nullable=False),
    )
    op.execute("INSERT INTO asset_name_staging (id, filename) SELECT id, filename FROM asset")
    op.drop_index("ix_asset_sha256", table_name="asset")
    op.drop_table("asset")
    _asset_table()
    op.execute(
        "INSERT INTO asset (id, client_id, content_id, filename, urdf, created_at) "
        "SELECT r.id, r.client_id, c.id, n.filename, '', r.created_at FROM asset_record_staging r "
        "JOIN asset_content c ON c.legacy_asset_id = r.legacy_asset_id JOIN asset_name_staging n ON n.id = r.legacy_asset_id"
    )
    op.drop_table("asset_record_staging")
    op.drop_table("asset_name_staging")
    with op.batch_alter_table("asset_content") as batch:
        batch.drop_column("legacy_asset_id")
    op.create_index("ix_asset_content_sha256", "asset_content", ["sha256"], unique=True)
    _add_job_asset_fk()
    op.create_table(
        "worker_heartbeat",
        sa.Column("name", sa.String(length=200), nullable=False),
        sa.Column("concurrency", sa.Integer(), nullable=False),
        sa.Column("started_at", _TZ, nullable=False),
        sa.Column("last_seen", _TZ, nullable=False),
        sa.PrimaryKeyConstraint("name", name="pk_worker_heartbeat"),
    )
    op.create_index("ix_worker_heartbeat_last_seen", "worker_heartbeat", ["last_seen"])


def downgrade() -> None:
    """Back to one shared row per content: the earliest record of each content gives its id and name."""
    op.drop_index("ix_worker_heartbeat_last_seen", table_name="worker_heartbeat")
    op.drop_table("worker_heartbeat")
    op.create_table(
        "asset_shared_staging",
        sa.Column("id", sa.Uuid(), nullable=False),
        sa.Column("content_id", sa.Uuid(), nullable=False),
        sa.Column("filename", sa.String(length=500), nullable=False),
    )
    op.execute(
        "INSERT INTO asset_shared_staging (id, content_id, filename) SELECT a.id, a.content_id, a.filename FROM asset a "
        "WHERE NOT EXISTS (SELECT 1 FROM asset o WHERE o.content_id = a.content_id AND "
        "(o.created_at < a.created_at OR (o.created_at = a.created_at AND o.id < a.id)))"
    )
    op.create_table(
        "grant_staging",
        sa.Column("client_id", sa.Uuid(), nullable=False),
        sa.Column("asset_id", sa.Uuid(), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
    )
    op.execute("INSERT INTO grant_staging (client_id, asset_id, created_at) SELECT a.client_id, s.id, MIN(a.created_at) "
               "FROM asset a JOIN asset_shared_staging s ON s.content_id = a.content_id GROUP BY a.client_id, s.id")
    _drop_job_asset_fk()
    op.execute("UPDATE job SET asset_id = (SELECT s.id FROM asset a JOIN asset_shared_staging s ON s.content_id = a.content_id "
               "WHERE a.id = job.asset_id)")
    op.drop_index("ix_asset_content_id", table_name="asset")
    op.drop_index("ix_asset_client_id", table_name="asset")
    op.drop_table("asset")
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
    op.execute("INSERT INTO asset (id, sha256, filename, size_bytes, storage_key, created_at) "
               "SELECT s.id, c.sha256, s.filename, c.size_bytes, c.storage_key, c.created_at "
               "FROM asset_shared_staging s JOIN asset_content c ON c.id = s.content_id")
    op.create_index("ix_asset_sha256", "asset", ["sha256"], unique=True)
    op.create_table(
        "client_asset",
        sa.Column("client_id", sa.Uuid(), nullable=False),
        sa.Column("asset_id", sa.Uuid(), nullable=False),
        sa.Column("created_at", _TZ, nullable=False),
        sa.ForeignKeyConstraint(["asset_id"], ["asset.id"], name="fk_client_asset_asset_id_asset", ondelete="CASCADE"),
        sa.ForeignKeyConstraint(["client_id"], ["api_client.id"], name="fk_client_asset_client_id_api_client", ondelete="CASCADE"),
        sa.PrimaryKeyConstraint("client_id", "asset_id", name="pk_client_asset"),
    )
    op.execute("INSERT INTO client_asset (client_id, asset_id, created_at) SELECT client_id, asset_id, created_at FROM grant_staging")
    op.create_index("ix_client_asset_asset_id", "client_asset", ["asset_id"])
    op.drop_table("grant_staging")
    op.drop_table("asset_shared_staging")
    op.drop_index("ix_asset_content_sha256", table_name="asset_content")
    op.drop_table("asset_content")
    _add_job_asset_fk()
