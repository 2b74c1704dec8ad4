"""One JSON POST with typed errors, bounded retries (rate limits, timeouts, 5xx) and a record of every attempt.

Timeouts: ``connect_s`` to open a connection, ``read_s`` between bytes of the answer, and
``call_s`` for the whole call with its retries and waits. A quota error (the account has
no credit: OpenAI ``insufficient_quota``, a Gemini per-day quota) fails at once with the
provider's message; a plain rate limit is retried after ``Retry-After`` (or Gemini's
``RetryInfo``). Every message passes through :func:`keys.mask`.
"""

from __future__ import annotations

import asyncio
import logging
import ssl
import time
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

from app.engine.errors import (
    ProviderError,
    ProviderQuotaExceeded,
    ProviderRateLimited,
    ProviderResponseError,
    ProviderTimeout,
)
from app.engine.providers.keys import mask
from app.engine.report import TransportAttempt, TransportOutcome

logger = logging.getLogger(__name__)

BACKOFF_S = 0.5
MAX_BACKOFF_S = 20.0
BODY_CHARS = 500
Sleeper = Callable[[float], Awaitable[None]]


@dataclass(frozen=True)
class Timeouts:
    connect_s: float = 10.0
    read_s: float = 60.0
    call_s: float = 240.0
    """Whole call: every attempt and every wait between them."""


@dataclass
class Exchange:
    """One model call's HTTP side: where, with what, and what happened to each attempt."""

    url: str
    headers: dict[str, str]
    provider: str
    secrets: tuple[str, ...] = ()
    attempts: list[TransportAttempt] = field(default_factory=list)


def _httpx() -> Any:
    try:
        import httpx
    except ImportError as exc:  # pragma: no cover - depends on the install
        raise ProviderError("model providers need httpx: pip install 'artimo[models]'") from exc
    return httpx


@lru_cache(maxsize=1)
def _tls() -> ssl.SSLContext:
    """One verifying TLS context per process (loading the CA bundle costs ~20 ms a client otherwise)."""
    return ssl.create_default_context()


def make_client(timeouts: Timeouts) -> Any:
    httpx = _httpx()
    return httpx.AsyncClient(timeout=httpx.Timeout(timeouts.read_s, connect=timeouts.connect_s, pool=timeouts.connect_s), verify=_tls())


def _seconds(text: Any) -> float | None:
    try:
        return float(str(text).strip().removesuffix("s")) if text is not None else None
    except ValueError:
        return None


def _body(response: Any) -> dict[str, Any]:
    try:
        data = response.json()
    except ValueError:
        return {}
    return data if isinstance(data, dict) else {}


def _error(body: dict[str, Any]) -> dict[str, Any]:
    error = body.get("error")
    return error if isinstance(error, dict) else {"message": error} if isinstance(error, str) else {}


def _gemini_retry_delay(error: dict[str, Any]) -> float | None:
    for detail in error.get("details") or []:
        if isinstance(detail, dict) and str(detail.get("@type", "")).endswith("RetryInfo"):
            return _seconds(detail.get("retryDelay"))
    return None


def is_quota(error: dict[str, Any]) -> bool:
    """OpenAI ``insufficient_quota``, or a Gemini quota failure on a per-day quota (no retry helps today)."""
    if "insufficient_quota" in (error.get("code"), error.get("type")):
        return True
    for detail in error.get("details") or []:
        if isinstance(detail, dict) and str(detail.get("@type", "")).endswith("QuotaFailure"):
            if any("PerDay" in str(v.get("quotaId", "")) for v in detail.get("violations") or [] if isinstance(v, dict)):
                return True
    return False


def _fail(exchange: Exchange, outcome: TransportOutcome, began: float, error: ProviderError, status: int | None = None,
          retry_after: float | None = None) -> ProviderError:
    exchange.attempts.append(TransportAttempt(attempt=len(exchange.attempts) + 1, outcome=outcome, status=status,
                                              seconds=round(time.perf_counter() - began, 6), error=error.message, retry_after_s=retry_after))
    return error


async def _once(client: Any, exchange: Exchange, payload: dict[str, Any]) -> dict[str, Any]:
    httpx = _httpx()
    name, url = exchange.provider, exchange.url
    began = time.perf_counter()
    try:
        response = await client.post(url, json=payload, headers=exchange.headers)
    except httpx.TimeoutException as exc:
        raise _fail(exchange, "timeout", began, ProviderTimeout(f"{name}: no answer from {url} in time ({type(exc).__name__})")) from exc
    except httpx.HTTPError as exc:
        message = mask(f"{name}: cannot reach {url}: {type(exc).__name__}: {exc}", *exchange.secrets)
        raise _fail(exchange, "network", began, ProviderResponseError(message, retriable=True)) from exc
    status = response.status_code
    if status >= 400:
        body = _body(response)
        error = _error(body)
        text = mask(str(error.get("message") or response.text[:BODY_CHARS]), *exchange.secrets)[:BODY_CHARS]
        if status == 429 and is_quota(error):
            raise _fail(exchange, "quota", began, ProviderQuotaExceeded(f"{name}: quota exhausted (HTTP 429): {text}"), status)
        if status == 429:
            wait = _seconds(response.headers.get("retry-after")) or _gemini_retry_delay(error)
            raise _fail(exchange, "rate_limited", began, ProviderRateLimited(f"{name}: rate limited (HTTP 429): {text}", retry_after_s=wait), status, wait)
        param = error.get("param") if isinstance(error.get("param"), str) else None
        failure = ProviderResponseError(f"{name}: HTTP {status}: {text}", retriable=status >= 500, status=status, param=param)
        raise _fail(exchange, "server_error" if status >= 500 else "client_error", began, failure, status)
    try:
        data = response.json()
    except ValueError as exc:
        snippet = mask(response.text[:200], *exchange.secrets)
        raise _fail(exchange, "unreadable", began, ProviderResponseError(f"{name}: the reply is not JSON: {snippet!r}", status=status), status) from exc
    if not isinstance(data, dict):
        raise _fail(exchange, "unreadable", began, ProviderResponseError(f"{name}: the reply is not a JSON object", status=status), status)
    exchange.attempts.append(TransportAttempt(attempt=len(exchange.attempts) + 1, outcome="ok", status=status,
                                              seconds=round(time.perf_counter() - began, 6)))
    return data


def _retriable(exc: ProviderError) -> bool:
    if isinstance(exc, ProviderRateLimited | ProviderTimeout):
        return True
    return isinstance(exc, ProviderResponseError) and bool(exc.context.get("retriable"))


async def _attempts(client: Any, exchange: Exchange, payload: dict[str, Any], attempts: int, deadline: float, sleep: Sleeper) -> dict[str, Any]:
    for attempt in range(1, attempts + 1):
        try:
            return await _once(client, exchange, payload)
        except ProviderError as exc:
            if not _retriable(exc) or attempt == attempts:
                raise
            hinted = exc.context.get("retry_after_s")
            wait = float(hinted) if isinstance(hinted, int | float) else min(MAX_BACKOFF_S, BACKOFF_S * 2 ** (attempt - 1))
            if time.monotonic() + wait >= deadline:
                raise
            logger.warning("%s (attempt %d/%d); retrying in %.1f s", exc, attempt, attempts, wait)
            await sleep(wait)
    raise ProviderError(f"{exchange.provider}: no attempts made")  # pragma: no cover - attempts >= 1


async def post_json(
    client: Any, exchange: Exchange, payload: dict[str, Any], *, attempts: int = 4, timeouts: Timeouts | None = None, sleep: Sleeper = asyncio.sleep,
) -> dict[str, Any]:
    """POST ``payload``; returns the reply object. ``exchange.attempts`` records every try.

    Raises
    ------
    ProviderQuotaExceeded
        At once (no retry) when the account's quota is used up.
    ProviderRateLimited, ProviderTimeout, ProviderResponseError
        After the last attempt, when the call's time budget is spent, or at once for a
        non-retriable error (4xx other than 429). ``error.transport`` holds the attempts.
    """
    timeouts = timeouts or Timeouts()
    deadline = time.monotonic() + timeouts.call_s
    try:
        async with asyncio.timeout(timeouts.call_s):
            return await _attempts(client, exchange, payload, attempts, deadline, sleep)
    except TimeoutError as exc:
        error: ProviderError = ProviderTimeout(f"{exchange.provider}: no reply within {timeouts.call_s:g} s (the limit per call, retries included)")
        exchange.attempts.append(TransportAttempt(attempt=len(exchange.attempts) + 1, outcome="timeout", error=error.message))
        error.transport = tuple(exchange.attempts)
        raise error from exc
    except ProviderError as exc:
        exc.transport = tuple(exchange.attempts)
        raise
