"""Typed dependencies of the routes: settings, DB session, storage, the caller, the enqueuer."""

from __future__ import annotations

import hmac
import logging
import threading
import time
import uuid
from collections.abc import AsyncIterator
from functools import lru_cache
from pathlib import Path
from typing import Annotated

from fastapi import Depends, Request
from fastapi.concurrency import run_in_threadpool
from fastapi.security import HTTPAuthorizationCredentials, HTTPBearer
from sqlalchemy.orm import Session

from app.api.errors import RateLimited, Unauthorized
from app.api.queue import Enqueuer, celery_enqueuer
from app.api.ratelimit import MemoryRateLimiter, RateLimiter, make_rate_limiter
from app.api.signing import PAGE_TOKEN_PREFIX, page_token_client
from app.core.config import Settings, get_settings
from app.core.storage import LocalStorage, Storage
from app.crud.clients import client_by_key, ensure_client_for_key, hash_key
from app.db.models import ApiClient
from app.db.session import session_factory

logger = logging.getLogger(__name__)

MAX_KEY_CHARS = 256


async def app_settings(request: Request) -> Settings:
    """The app's settings (``create_app(settings)``), else the cached environment settings.

    Dependencies here are ``async`` when they do no I/O: FastAPI runs every sync dependency
    in the thread pool, and those hops (not the queries) dominated a status poll.
    """
    configured: Settings | None = getattr(request.app.state, "settings", None)
    return configured or get_settings()


SettingsDep = Annotated[Settings, Depends(app_settings)]


async def get_db(settings: SettingsDep) -> AsyncIterator[Session]:
    """One session per request on the configured database (opened lazily, closed in a thread)."""
    session = session_factory(settings.sqlalchemy_url)()
    try:
        yield session
    finally:
        await run_in_threadpool(session.close)


SessionDep = Annotated[Session, Depends(get_db)]


@lru_cache(maxsize=8)
def _storage(root: Path) -> LocalStorage:
    return LocalStorage(root)


async def get_storage(settings: SettingsDep) -> Storage:
    return _storage(settings.storage_dir)


StorageDep = Annotated[Storage, Depends(get_storage)]


async def get_enqueuer(settings: SettingsDep) -> Enqueuer:
    """Replace with ``app.dependency_overrides[get_enqueuer]`` to run the API without workers."""
    return celery_enqueuer(settings)


EnqueuerDep = Annotated[Enqueuer, Depends(get_enqueuer)]


async def get_rate_limiter(request: Request, settings: SettingsDep) -> RateLimiter:
    """The app's limiter (created on first use from ``REDIS_URL``)."""
    limiter: RateLimiter | None = getattr(request.app.state, "rate_limiter", None)
    if limiter is None:
        limiter = make_rate_limiter(settings.redis_url)
        request.app.state.rate_limiter = limiter
    return limiter


_bearer = HTTPBearer(auto_error=False, description="an API key: `artimo keys create --name NAME`, or $ARTIMO_API_KEY")


class _KeyCache:
    """Recently authenticated keys (by hash) -> their detached client rows, for ``ttl`` seconds.

    A status poll then costs one query instead of two; only successes are remembered.
    """

    def __init__(self) -> None:
        self._entries: dict[tuple[str, str], tuple[float, ApiClient]] = {}
        self._lock = threading.Lock()

    def get(self, database: str, key: str, ttl: float) -> ApiClient | None:
        if ttl <= 0:
            return None
        with self._lock:
            entry = self._entries.get((database, hash_key(key)))
        return entry[1] if entry is not None and time.monotonic() - entry[0] < ttl else None

    def put(self, database: str, key: str, client: ApiClient, ttl: float) -> None:
        if ttl <= 0:
            return
        with self._lock:
            if len(self._entries) > MAX_CACHED_KEYS:
                self._entries.clear()
            self._entries[(database, hash_key(key))] = (time.monotonic(), client)


_KEYS = _KeyCache()
MAX_CACHED_KEYS = 10_000


def _authenticate(session: Session, settings: Settings, key: str) -> ApiClient | None:
    cached = _KEYS.get(settings.sqlalchemy_url, key, settings.auth_cache_s)
    if cached is not None:
        return cached
    client = _lookup(session, settings, key)
    if client is not None and settings.auth_cache_s > 0:
        session.expunge(client)
        _KEYS.put(settings.sqlalchemy_url, key, client, settings.auth_cache_s)
    return client


def _lookup(session: Session, settings: Settings, key: str) -> ApiClient | None:
    if key.startswith(PAGE_TOKEN_PREFIX):  # the page's signed sign-in link (app.api.signing)
        client_id = page_token_client(settings, key)
        found = None if client_id is None else session.get(ApiClient, uuid.UUID(client_id))
        return None if found is None or found.disabled else found
    client = client_by_key(session, key=key)
    if client is not None:
        return client
    configured = settings.artimo_api_key.get_secret_value() if settings.artimo_api_key else None
    if configured and hmac.compare_digest(key.encode(), configured.encode()):
        client = ensure_client_for_key(session, key=key)
        return None if client.disabled else client
    return None


async def _count(limiter: RateLimiter, key: str, limit: int) -> int | None:
    if isinstance(limiter, MemoryRateLimiter):  # no I/O: no thread hop
        return limiter.hit(key, limit)
    return await run_in_threadpool(limiter.hit, key, limit)


async def _refuse(request: Request, settings: Settings, limiter: RateLimiter) -> Unauthorized | RateLimited:
    """401 for a missing or wrong key; 429 once one address keeps sending them (key guessing, floods)."""
    address = request.client.host if request.client else "unknown"
    limit = settings.auth_failures_per_minute
    retry_after = await _count(limiter, f"unauthenticated:{address}", limit)
    if retry_after is not None:
        logger.warning("too many unauthenticated requests from %s", address)
        return RateLimited(limit, retry_after)
    return Unauthorized()


async def get_client(
    request: Request,
    session: SessionDep,
    settings: SettingsDep,
    limiter: Annotated[RateLimiter, Depends(get_rate_limiter)],
    credentials: Annotated[HTTPAuthorizationCredentials | None, Depends(_bearer)],
) -> ApiClient:
    """The caller, authenticated by its API key and counted against its rate limit.

    Raises
    ------
    Unauthorized
        No key, or a key that is unknown or disabled.
    RateLimited
        Too many requests of this key in the current minute, or too many without a valid key
        from this address.
    """
    if credentials is None or not credentials.credentials or len(credentials.credentials) > MAX_KEY_CHARS:
        raise await _refuse(request, settings, limiter)
    key = credentials.credentials
    client = _KEYS.get(settings.sqlalchemy_url, key, settings.auth_cache_s) or await run_in_threadpool(_authenticate, session, settings, key)
    if client is None:
        raise await _refuse(request, settings, limiter)
    limit = client.rate_limit_per_minute or settings.rate_limit_per_minute
    retry_after = await _count(limiter, str(client.id), limit)
    if retry_after is not None:
        raise RateLimited(limit, retry_after)
    return client


ClientDep = Annotated[ApiClient, Depends(get_client)]


def _detach(session: Session, client: ApiClient) -> None:
    if client in session:
        session.expunge(client)
    session.rollback()  # ends the transaction: the pooled connection goes back


async def release_connection(session: Session, client: ApiClient) -> None:
    """Give the session's database connection back before a long wait (an upload's body).

    Authentication may have opened a transaction; holding its connection while a client
    sends a body slowly would let slow uploads exhaust the pool. The client row is detached
    (its loaded fields stay readable); the session opens a new transaction when used again.
    """
    if session.in_transaction():
        await run_in_threadpool(_detach, session, client)
