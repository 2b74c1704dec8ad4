"""API clients: keys are generated here, stored only as sha256 hashes, and looked up by hash."""

from __future__ import annotations

import hashlib
import secrets
import uuid

from sqlalchemy import select
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session

from app.db.models import ApiClient, utcnow

KEY_PREFIX = "artimo_"
KEY_RANDOM_BYTES = 32
SHOWN_PREFIX_CHARS = 12
ENV_CLIENT_NAME = "ARTIMO_API_KEY"


def hash_key(key: str) -> str:
    """sha256 hex of an API key (what the database stores)."""
    return hashlib.sha256(key.encode("utf-8")).hexdigest()


def new_key() -> str:
    return KEY_PREFIX + secrets.token_urlsafe(KEY_RANDOM_BYTES)


def create_api_client(
    session: Session, *, name: str, key: str | None = None, rate_limit_per_minute: int | None = None
) -> tuple[ApiClient, str]:
    """A new client and its plain key (returned once; only the hash is stored)."""
    key = key or new_key()
    client = ApiClient(
        id=uuid.uuid4(), name=name[:200], key_hash=hash_key(key), key_prefix=key[:SHOWN_PREFIX_CHARS],
        created_at=utcnow(), disabled=False, rate_limit_per_minute=rate_limit_per_minute,
    )
    session.add(client)
    session.commit()
    return client, key


def client_by_key(session: Session, *, key: str) -> ApiClient | None:
    """The enabled client holding ``key``, or ``None``."""
    client = session.execute(select(ApiClient).where(ApiClient.key_hash == hash_key(key))).scalar_one_or_none()
    if client is None or client.disabled:
        return None
    return client


def ensure_client_for_key(session: Session, *, key: str, name: str = ENV_CLIENT_NAME) -> ApiClient:
    """The client of a configured key (``ARTIMO_API_KEY``), created on first use (race-safe)."""
    existing = session.execute(select(ApiClient).where(ApiClient.key_hash == hash_key(key))).scalar_one_or_none()
    if existing is not None:
        return existing
    try:
        client, _ = create_api_client(session, name=name, key=key)
    except IntegrityError:  # another request created it at the same moment
        session.rollback()
        return session.execute(select(ApiClient).where(ApiClient.key_hash == hash_key(key))).scalar_one()
    return client


def list_api_clients(session: Session) -> list[ApiClient]:
    return list(session.execute(select(ApiClient).order_by(ApiClient.created_at, ApiClient.name)).scalars().all())


def set_client_disabled(session: Session, *, client: ApiClient, disabled: bool) -> ApiClient:
    client.disabled = disabled
    session.commit()
    return client
