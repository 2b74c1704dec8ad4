"""Fixed-window rate limiters (in-process and Redis)."""

from __future__ import annotations

import uuid

from app.api.ratelimit import MemoryRateLimiter, RedisRateLimiter


class Clock:
    def __init__(self, now: float) -> None:
        self.now = now

    def __call__(self) -> float:
        return self.now


def test_memory_window_counts_per_key_and_resets() -> None:
    clock = Clock(600.0)
    limiter = MemoryRateLimiter(clock)
    assert [limiter.hit("a", 2) for _ in range(3)] == [None, None, 60]
    assert limiter.hit("b", 2) is None
    clock.now = 659.2
    assert limiter.hit("a", 2) == 1
    clock.now = 660.0
    assert limiter.hit("a", 2) is None


def test_redis_window_is_shared_between_limiters() -> None:
    clock = Clock(1200.0)
    key = uuid.uuid4().hex
    first = RedisRateLimiter("redis://127.0.0.1:6379/15", clock)
    second = RedisRateLimiter("redis://127.0.0.1:6379/15", clock)
    assert [first.hit(key, 2), second.hit(key, 2), first.hit(key, 2)] == [None, None, 60]


def test_redis_down_falls_back_to_counting_in_process() -> None:
    limiter = RedisRateLimiter("redis://127.0.0.1:1/0", Clock(0.0))
    assert [limiter.hit("k", 1), limiter.hit("k", 1)] == [None, 60]
