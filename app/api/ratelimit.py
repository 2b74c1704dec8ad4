"""Per-API-key rate limit: a fixed one-minute window, in Redis when configured, else in this process.

With several API processes the Redis window is shared; the in-process one counts per
process (the embedded single-process default). If Redis cannot be reached the limiter
falls back to counting in-process and says so in the log, rather than failing requests.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Callable
from typing import Protocol

logger = logging.getLogger(__name__)

WINDOW_S = 60
REDIS_TIMEOUT_S = 1.0
REDIS_KEY_PREFIX = "artimo:ratelimit"


class RateLimiter(Protocol):
    def hit(self, key: str, limit: int) -> int | None:
        """Count one request of ``key``; ``None`` if allowed, else seconds until the window resets."""
        ...


def _retry_after(now: float, window: int) -> int:
    return max(1, math.ceil((window + 1) * WINDOW_S - now))


class MemoryRateLimiter:
    def __init__(self, clock: Callable[[], float] = time.time) -> None:
        self._clock = clock
        self._lock = threading.Lock()
        self._window = -1
        self._counts: dict[str, int] = {}

    def hit(self, key: str, limit: int) -> int | None:
        now = self._clock()
        window = int(now // WINDOW_S)
        with self._lock:
            if window != self._window:
                self._window, self._counts = window, {}
            count = self._counts.get(key, 0) + 1
            self._counts[key] = count
        return _retry_after(now, window) if count > limit else None


class RedisRateLimiter:
    def __init__(self, url: str, clock: Callable[[], float] = time.time) -> None:
        import redis

        self._errors: tuple[type[Exception], ...] = (redis.RedisError, OSError)
        self._client = redis.Redis.from_url(url, socket_timeout=REDIS_TIMEOUT_S, socket_connect_timeout=REDIS_TIMEOUT_S)
        self._clock = clock
        self._fallback = MemoryRateLimiter(clock)

    def hit(self, key: str, limit: int) -> int | None:
        now = self._clock()
        window = int(now // WINDOW_S)
        name = f"{REDIS_KEY_PREFIX}:{key}:{window}"
        try:
            pipe = self._client.pipeline()
            pipe.incr(name)
            pipe.expire(name, 2 * WINDOW_S)
            count = int(pipe.execute()[0])
        except self._errors as exc:
            logger.warning("rate limit: Redis unavailable (%s); counting in this process", exc)
            return self._fallback.hit(key, limit)
        return _retry_after(now, window) if count > limit else None


def make_rate_limiter(redis_url: str | None) -> RateLimiter:
    return RedisRateLimiter(redis_url) if redis_url else MemoryRateLimiter()
