"""Slow clients against a real uvicorn server: a trickling upload holds no admission slot and times out.

Before the fix, 8 connections sending a valid key and a partial multipart body took every
admission slot for as long as they stayed open: ``/healthz`` and status polls waited forever.
"""

from __future__ import annotations

import socket
import threading
import time
import uuid
from collections.abc import Iterator

import httpx
import pytest
import uvicorn

from app.core.config import Settings
from app.crud import jobs as crud_jobs
from app.crud.assets import get_or_create_asset, get_or_create_content
from app.db.session import session_factory
from app.main import create_app

SLOW_CLIENTS = 40
"""More than the database pool (10 + 20): a slow upload must hold no pooled connection either."""
IDLE_TIMEOUT_S = 2.0


@pytest.fixture
def server(settings: Settings) -> Iterator[str]:
    configured = settings.model_copy(update={"api_max_in_flight": 2, "body_idle_timeout_s": IDLE_TIMEOUT_S, "body_timeout_s": 30.0})
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    config = uvicorn.Config(create_app(configured), host="127.0.0.1", port=port, log_config=None, lifespan="on")
    instance = uvicorn.Server(config)
    thread = threading.Thread(target=instance.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 20
    while not instance.started:
        assert time.monotonic() < deadline and thread.is_alive(), "uvicorn did not start"
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}"
    instance.should_exit = True
    thread.join(10)


def _job(settings: Settings, client_id: uuid.UUID) -> uuid.UUID:
    with session_factory(settings.sqlalchemy_url)() as session:
        from app.db.models import ApiClient

        client = session.get(ApiClient, client_id)
        assert client is not None
        content = get_or_create_content(session, sha256=uuid.uuid4().hex * 2, size_bytes=1, storage_key="assets/none.zip")
        asset, _ = get_or_create_asset(session, client=client, content=content, filename="a.zip", urdf="mobility.urdf")
        return crud_jobs.create_job(session, client=client, asset=asset, prompt="open").id


def _trickle(base: str, key: str) -> socket.socket:
    """A POST /v1/assets that sends its headers and the start of its body, then nothing."""
    port = int(base.rsplit(":", 1)[1])
    connection = socket.create_connection(("127.0.0.1", port))
    head = (f"POST /v1/assets HTTP/1.1\r\nHost: 127.0.0.1\r\nAuthorization: Bearer {key}\r\n"
            "Content-Type: multipart/form-data; boundary=xyz\r\nContent-Length: 100000\r\n\r\n")
    part = '--xyz\r\nContent-Disposition: form-data; name="asset"; filename="a.zip"\r\n\r\nPK\x03\x04'
    connection.sendall(head.encode() + part.encode("latin-1"))
    return connection


def test_slow_uploads_block_nothing_and_time_out(server: str, settings: Settings, alice) -> None:  # type: ignore[no-untyped-def]
    job_id = _job(settings, alice.client.id)
    slow = [_trickle(server, alice.key) for _ in range(SLOW_CLIENTS)]
    try:
        time.sleep(0.5)  # every slow request is inside the app, reading its body
        with httpx.Client(base_url=server, timeout=3.0) as http:
            began = time.monotonic()
            assert http.get("/healthz").status_code == 200
            assert http.get("/readyz").status_code in (200, 503)  # answers (readiness itself is not the point)
            status = http.get(f"/v1/animations/{job_id}", headers={"Authorization": f"Bearer {alice.key}"})
            assert status.status_code == 200 and status.json()["status"] == "queued"
            assert time.monotonic() - began < 3.0
        for connection in slow:
            connection.settimeout(IDLE_TIMEOUT_S + 10)
            answer = connection.recv(4096).decode("latin-1")
            assert answer.startswith("HTTP/1.1 408"), answer[:200]
            assert "RequestTimeout" in answer
    finally:
        for connection in slow:
            connection.close()
