"""One JSON POST with typed errors and bounded retries (rate limits, timeouts, 5xx)."""

from __future__ import annotations

import asyncio
import logging
import time
from collections.abc import Awaitable, Callable
from typing import Any

from app.engine.errors import ProviderError, ProviderRateLimited, ProviderResponseError, ProviderTimeout

logger = logging.getLogger(__name__)

BACKOFF_S = 0.5
MAX_BACKOFF_S = 20.0
Sleeper = Callable[[float], Awaitable[None]]


def _httpx() -> Any:
    try:
        import httpx
    except ImportError as exc:  # pragma: no cover - depends on the install
        raise ProviderError("model providers need httpx: pip install 'artimo[models]'") from exc
    return httpx


def make_client(timeout_s: float) -> Any:
    httpx = _httpx()
    return httpx.AsyncClient(timeout=httpx.Timeout(timeout_s, connect=min(10.0, timeout_s)))


def _retry_after(headers: Any) -> float | None:
    value = headers.get("retry-after")
    try:
        return float(value) if value is not None else None
    except ValueError:
        return None


async def _once(client: Any, url: str, payload: dict[str, Any], headers: dict[str, str], provider: str) -> tuple[dict[str, Any], float]:
    httpx = _httpx()
    began = time.perf_counter()
    try:
        response = await client.post(url, json=payload, headers=headers)
    except httpx.TimeoutException as exc:
        raise ProviderTimeout(f"{provider}: no answer from {url} in time") from exc
    except httpx.HTTPError as exc:
        raise ProviderResponseError(f"{provider}: cannot reach {url}: {type(exc).__name__}: {exc}", retriable=True) from exc
    seconds = time.perf_counter() - began
    if response.status_code == 429:
        raise ProviderRateLimited(f"{provider}: rate limited (HTTP 429)", retry_after_s=_retry_after(response.headers))
    if response.status_code >= 400:
        body = response.text[:500]
        raise ProviderResponseError(f"{provider}: HTTP {response.status_code}: {body}", retriable=response.status_code >= 500, status=response.status_code)
    try:
        data = response.json()
    except ValueError as exc:
        raise ProviderResponseError(f"{provider}: the reply is not JSON: {response.text[:200]!r}") from exc
    if not isinstance(data, dict):
        raise ProviderResponseError(f"{provider}: the reply is not a JSON object")
    return data, seconds


async def post_json(
    client: Any, url: str, payload: dict[str, Any], headers: dict[str, str], *, provider: str, attempts: int = 4, sleep: Sleeper = asyncio.sleep
) -> tuple[dict[str, Any], float]:
    """POST ``payload``; returns (reply object, seconds of the successful call).

    Raises
    ------
    ProviderRateLimited, ProviderTimeout, ProviderResponseError
        After the last attempt, or at once for a non-retriable error (4xx other than 429).
    """
    for attempt in range(1, attempts + 1):
        try:
            return await _once(client, url, payload, headers, provider)
        except (ProviderRateLimited, ProviderTimeout, ProviderResponseError) as exc:
            retriable = not isinstance(exc, ProviderResponseError) or exc.context.get("retriable", False)
            if not retriable or attempt == attempts:
                raise
            hinted = exc.context.get("retry_after_s")
            wait = float(hinted) if isinstance(hinted, int | float) else min(MAX_BACKOFF_S, BACKOFF_S * 2 ** (attempt - 1))
            logger.warning("%s (attempt %d/%d); retrying in %.1f s", exc, attempt, attempts, wait)
            await sleep(wait)
    raise ProviderError(f"{provider}: no attempts made")  # pragma: no cover - attempts >= 1
