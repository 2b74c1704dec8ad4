"""Typed dependencies of the routes: settings, DB session, storage, the caller, the enqueuer."""

from __future__ import annotations

import hmac
from collections.abc import Iterator
from functools import lru_cache
from pathlib import Path
from typing import Annotated

from fastapi import Depends, Request
from fastapi.security import HTTPAuthorizationCredentials, HTTPBearer
from sqlalchemy.orm import Session

from app.api.errors import RateLimited, Unauthorized
from app.api.queue import Enqueuer, celery_enqueuer
from app.api.ratelimit import RateLimiter, make_rate_limiter
from app.core.config import Settings, get_settings
from app.core.storage import LocalStorage, Storage
from app.crud.clients import client_by_key, ensure_client_for_key
from app.db.models import ApiClient
from app.db.session import session_factory

MAX_KEY_CHARS = 256

SettingsDep = Annotated[Settings, Depends(get_settings)]


def get_db(settings: SettingsDep) -> Iterator[Session]:
    """One session per request on the configured database."""
    with session_factory(settings.sqlalchemy_url)() as session:
        yield session


SessionDep = Annotated[Session, Depends(get_db)]


@lru_cache(maxsize=8)
def _storage(root: Path) -> LocalStorage:
    return LocalStorage(root)


def get_storage(settings: SettingsDep) -> Storage:
    return _storage(settings.storage_dir)


StorageDep = Annotated[Storage, Depends(get_storage)]


def get_enqueuer(settings: SettingsDep) -> Enqueuer:
    """Replace with ``app.dependency_overrides[get_enqueuer]`` to run the API without workers."""
    return celery_enqueuer(settings)


EnqueuerDep = Annotated[Enqueuer, Depends(get_enqueuer)]


def get_rate_limiter(request: Request, settings: SettingsDep) -> RateLimiter:
    """The app's limiter (created on first use from ``REDIS_URL``)."""
    limiter: RateLimiter | None = getattr(request.app.state, "rate_limiter", None)
    if limiter is None:
        limiter = make_rate_limiter(settings.redis_url)
        request.app.state.rate_limiter = limiter
    return limiter


_bearer = HTTPBearer(auto_error=False, description="an API key: `artimo keys create --name NAME`, or $ARTIMO_API_KEY")


def _authenticate(session: Session, settings: Settings, key: str) -> ApiClient | None:
    client = client_by_key(session, key=key)
    if client is not None:
        return client
    configured = settings.artimo_api_key.get_secret_value() if settings.artimo_api_key else None
    if configured and hmac.compare_digest(key.encode(), configured.encode()):
        client = ensure_client_for_key(session, key=key)
        return None if client.disabled else client
    return None


def get_client(
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
        Too many requests of this key in the current minute.
    """
    if credentials is None or not credentials.credentials or len(credentials.credentials) > MAX_KEY_CHARS:
        raise Unauthorized()
    client = _authenticate(session, settings, credentials.credentials)
    if client is None:
        raise Unauthorized()
    limit = client.rate_limit_per_minute or settings.rate_limit_per_minute
    retry_after = limiter.hit(str(client.id), limit)
    if retry_after is not None:
        raise RateLimited(limit, retry_after)
    return client


ClientDep = Annotated[ApiClient, Depends(get_client)]
