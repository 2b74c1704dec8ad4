"""API keys, rate limits, and the open health/readiness/metrics routes."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from app.crud.clients import hash_key, set_client_disabled
from app.db.models import ApiClient
from app.main import create_app


@pytest.mark.parametrize(
    "headers",
    [{}, {"Authorization": "Bearer wrong"}, {"Authorization": "Basic dXNlcjpwdw=="}, {"Authorization": "Bearer"},
     {"Authorization": "Bearer " + "x" * 1000}],
)
def test_missing_or_bad_key_is_401(http, headers) -> None:
    for method, path in (("GET", "/v1/animations"), ("POST", "/v1/assets"), ("GET", "/v1/batches/00000000-0000-0000-0000-000000000000")):
        response = http.request(method, path, headers=headers)
        assert response.status_code == 401, (path, response.text)
        assert response.headers["www-authenticate"] == "Bearer"


def test_an_address_sending_wrong_keys_gets_429_but_valid_keys_still_work(settings, alice) -> None:
    with TestClient(create_app(settings.model_copy(update={"auth_failures_per_minute": 3}))) as http:
        codes = [http.get("/v1/animations", headers={"Authorization": f"Bearer guess-{n}"}).status_code for n in range(4)]
        assert codes == [401, 401, 401, 429]
        refused = http.get("/v1/animations")
        assert refused.status_code == 429 and 1 <= int(refused.headers["retry-after"]) <= 60
        assert http.get("/v1/animations", headers=alice.headers).status_code == 200


def test_disabled_key_is_401(http, alice, db) -> None:
    assert http.get("/v1/animations", headers=alice.headers).status_code == 200
    set_client_disabled(db, client=db.get(ApiClient, alice.client.id), disabled=True)
    assert http.get("/v1/animations", headers=alice.headers).status_code == 401


def test_env_key_is_accepted_and_gets_one_client(http, settings, db) -> None:
    key = settings.artimo_api_key.get_secret_value()
    headers = {"Authorization": f"Bearer {key}"}
    assert http.get("/v1/animations", headers=headers).status_code == 200
    assert http.get("/v1/animations", headers=headers).status_code == 200
    rows = db.query(ApiClient).filter(ApiClient.key_hash == hash_key(key)).all()
    assert len(rows) == 1 and rows[0].name == "ARTIMO_API_KEY"


def test_rate_limit_is_429_with_retry_after(http, make_caller) -> None:
    limited, other = make_caller("limited", rate_limit=3), make_caller("other", rate_limit=3)
    codes = [http.get("/v1/animations", headers=limited.headers).status_code for _ in range(4)]
    assert codes == [200, 200, 200, 429]
    response = http.get("/v1/animations", headers=limited.headers)
    assert response.status_code == 429 and 1 <= int(response.headers["retry-after"]) <= 60
    assert http.get("/v1/animations", headers=other.headers).status_code == 200


def test_rate_limit_is_shared_through_redis(settings, make_caller) -> None:
    caller = make_caller("redis-limited", rate_limit=2)
    redis_settings = settings.model_copy(update={"redis_url": "redis://127.0.0.1:6379/15"})
    with TestClient(create_app(redis_settings)) as first, TestClient(create_app(redis_settings)) as second:
        codes = [app.get("/v1/animations", headers=caller.headers).status_code for app in (first, second, first)]
    assert codes == [200, 200, 429]


def test_health_routes_need_no_key(http, db) -> None:
    from app.crud.workers import record_heartbeat

    assert http.get("/healthz").json() == {"status": "ok"}
    record_heartbeat(db, name="test-worker@here", concurrency=1)
    ready = http.get("/readyz")
    assert ready.status_code == 200 and ready.json()["checks"] == {"database": "ok", "workers": "ok", "broker": "ok"}


def test_readyz_is_503_when_no_worker_can_run_jobs(http, db, settings) -> None:
    """Jobs would wait forever: not ready (the supervisor gave up, or no worker was ever started)."""
    from datetime import timedelta

    from app.crud.workers import record_heartbeat, remove_heartbeat
    from app.db.models import utcnow

    record_heartbeat(db, name="test-worker@here", concurrency=1, now=utcnow() - timedelta(seconds=settings.worker_stale_after_s + 5))
    response = http.get("/readyz")
    assert response.status_code == 503 and response.json()["checks"]["workers"].startswith("no live worker (last seen")
    record_heartbeat(db, name="test-worker@here", concurrency=1)
    assert http.get("/readyz").status_code == 200
    remove_heartbeat(db, name="test-worker@here")
    assert http.get("/readyz").status_code == 503


def test_readyz_is_503_when_the_broker_is_down(settings) -> None:
    with TestClient(create_app(settings.model_copy(update={"redis_url": "redis://127.0.0.1:1/0"}))) as http:
        response = http.get("/readyz")
    assert response.status_code == 503 and response.json()["checks"]["broker"] == "unreachable"


def test_readyz_is_503_when_the_sqlite_broker_cannot_be_opened(settings) -> None:
    (settings.data_dir / "broker.db").mkdir(parents=True)  # a folder where the broker's database file should be
    with TestClient(create_app(settings)) as http:
        response = http.get("/readyz")
    assert response.status_code == 503 and response.json()["checks"]["broker"] == "unreachable"


def test_readyz_is_503_when_the_database_is_down(settings) -> None:
    broken = settings.model_copy(update={"database_url": "postgresql+psycopg://postgres@127.0.0.1:1/none"})
    with TestClient(create_app(broken)) as http:
        response = http.get("/readyz")
        assert response.status_code == 503 and response.json()["checks"]["database"].startswith("unreachable")
        assert http.get("/v1/animations", headers={"Authorization": "Bearer x"}).status_code == 503


def test_metrics_count_requests_by_route_and_jobs_by_status(app, http, alice) -> None:
    http.get("/v1/animations", headers=alice.headers)
    http.get("/v1/animations/00000000-0000-0000-0000-000000000000", headers=alice.headers)
    with TestClient(app, client=("127.0.0.1", 40000)) as local:  # no METRICS_TOKEN: loopback only
        text = local.get("/metrics").text
    assert 'artimo_http_requests_total{method="GET",route="/v1/animations",status="200"}' in text
    assert 'route="/v1/animations/{job_id}",status="404"' in text
    assert 'artimo_jobs{status="queued"}' in text
    assert "artimo_http_request_duration_seconds_bucket" in text


def test_openapi_docs_are_served(http) -> None:
    assert http.get("/docs").status_code == 200
    paths = http.get("/openapi.json").json()["paths"]
    assert "multipart/form-data" in paths["/v1/animations"]["post"]["requestBody"]["content"]
    assert {"/v1/assets", "/v1/animations/{job_id}/{name}", "/v1/batches/{batch_id}", "/metrics"} <= set(paths)


def test_key_cache_forgets_a_disabled_key_within_its_ttl(app, settings, http, alice, db) -> None:
    import time

    settings.auth_cache_s = 0.3
    assert http.get("/v1/animations", headers=alice.headers).status_code == 200
    set_client_disabled(db, client=db.get(ApiClient, alice.client.id), disabled=True)
    assert http.get("/v1/animations", headers=alice.headers).status_code == 200  # still remembered
    time.sleep(0.35)
    assert http.get("/v1/animations", headers=alice.headers).status_code == 401
