"""Property-based API check: no generated request makes the server answer 5xx.

Schemathesis generates requests from ``create_app()``'s OpenAPI schema (including the
multipart upload bodies) and sends them through ASGI with a valid API key; only the
``not_a_server_error`` check runs. Examples per operation are bounded to keep this fast.
"""

from __future__ import annotations

import uuid
from collections.abc import Iterator

import pytest
import schemathesis
from hypothesis import HealthCheck, settings
from schemathesis.checks import not_a_server_error

from app.api.deps import get_enqueuer
from app.core.config import Settings
from app.crud.clients import create_api_client
from app.main import create_app

MAX_EXAMPLES = 25


@pytest.fixture
def fuzz_key(db) -> str:  # type: ignore[no-untyped-def]
    _, key = create_api_client(db, name="schemathesis", rate_limit_per_minute=1_000_000)
    return key


APP = create_app()
"""Built at import (the schema loader needs it then); each test points it at its own settings."""
schema = schemathesis.openapi.from_asgi("/openapi.json", APP)


@pytest.fixture
def configured_app(settings: Settings, db) -> Iterator[None]:  # type: ignore[no-untyped-def]
    """``schemathesis.pytest.from_fixture`` would be neater but breaks on pytest 9 (``Function._nodeid``).

    A worker heartbeat makes ``/readyz`` ready (without one it answers 503, as it must).
    """
    from app.crud.workers import record_heartbeat

    record_heartbeat(db, name="schemathesis-worker", concurrency=1)
    sent: list[uuid.UUID] = []
    APP.state.settings = settings
    APP.dependency_overrides[get_enqueuer] = lambda: sent.append
    yield
    APP.dependency_overrides.clear()
    APP.state.settings = None


@schema.parametrize()
@settings(max_examples=MAX_EXAMPLES, deadline=None, suppress_health_check=list(HealthCheck))
def test_no_server_errors(case, fuzz_key: str, configured_app: None) -> None:  # type: ignore[no-untyped-def]
    case.call_and_validate(headers={"Authorization": f"Bearer {fuzz_key}"}, checks=[not_a_server_error])
