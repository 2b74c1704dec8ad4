"""ArtimoClient comes back when a busy server says to (429/503 + Retry-After), within a budget."""

from __future__ import annotations

import httpx
import pytest

from app import client as client_module
from app.client import ArtimoClient, ClientError


def _server(answers: list[tuple[int, dict[str, str]]], seen: list[str]) -> httpx.MockTransport:
    def handle(request: httpx.Request) -> httpx.Response:
        seen.append(f"{request.method} {request.url.path}")
        status, headers = answers.pop(0) if answers else (200, {})
        body = {"detail": "busy"} if status >= 400 else {"id": "job", "status": "queued"}
        return httpx.Response(status, json=body, headers=headers)
    return httpx.MockTransport(handle)


@pytest.fixture
def sleeps(monkeypatch: pytest.MonkeyPatch) -> list[float]:
    slept: list[float] = []
    monkeypatch.setattr(client_module.time, "sleep", slept.append)
    return slept


def test_a_rate_limited_request_is_sent_again_after_retry_after(sleeps: list[float]) -> None:
    seen: list[str] = []
    answers = [(429, {"Retry-After": "3"}), (503, {"Retry-After": "1"})]
    with ArtimoClient("http://artimo", "key", transport=_server(answers, seen)) as api:
        assert api.get("job")["status"] == "queued"
    assert seen == ["GET /v1/animations/job"] * 3 and sleeps == [3.0, 1.0]


def test_the_wait_is_bounded_then_the_error_is_raised(sleeps: list[float]) -> None:
    seen: list[str] = []
    answers = [(429, {"Retry-After": "30"})] * 10
    with ArtimoClient("http://artimo", "key", retry_wait_s=45, transport=_server(answers, seen)) as api:
        with pytest.raises(ClientError) as raised:
            api.get("job")
    assert raised.value.status == 429 and sleeps == [30.0, 15.0] and len(seen) == 3


@pytest.mark.parametrize("answer", [(429, {}), (503, {"Retry-After": "Wed, 21 Oct 2026 07:28:00 GMT"}), (500, {"Retry-After": "1"})])
def test_no_retry_without_a_usable_retry_after(sleeps: list[float], answer: tuple[int, dict[str, str]]) -> None:
    seen: list[str] = []
    with ArtimoClient("http://artimo", "key", transport=_server([answer], seen)) as api:
        with pytest.raises(ClientError):
            api.get("job")
    assert sleeps == [] and len(seen) == 1


def test_retries_can_be_switched_off(sleeps: list[float]) -> None:
    seen: list[str] = []
    with ArtimoClient("http://artimo", "key", retry_wait_s=0, transport=_server([(429, {"Retry-After": "2"})], seen)) as api:
        with pytest.raises(ClientError):
            api.get("job")
    assert sleeps == [] and len(seen) == 1
