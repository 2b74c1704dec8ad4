"""Liveness, readiness and metrics (no API key: keep them on a private network or loopback)."""

from __future__ import annotations

import hmac
import logging
from typing import Any

from fastapi import APIRouter, Request, Response
from fastapi.responses import JSONResponse
from sqlalchemy import text
from sqlalchemy.exc import SQLAlchemyError
from sqlalchemy.orm import Session

from app.api.deps import SessionDep, SettingsDep
from app.api.errors import Forbidden, Unauthorized, error_responses
from app.api.metrics import CONTENT_TYPE, render_metrics
from app.api.queue import broker_reachable
from app.core.config import Settings
from app.crud.workers import last_heartbeat, live_workers

logger = logging.getLogger(__name__)

router = APIRouter(tags=["health"])


@router.get("/healthz")
def healthz() -> dict[str, str]:
    """The process is up."""
    return {"status": "ok"}


def _workers(session: Session, settings: Settings) -> str:
    """"ok" when a worker was heard from recently, else why no job would run."""
    alive = live_workers(session, stale_after_s=settings.worker_stale_after_s)
    if alive:
        return "ok"
    last = last_heartbeat(session)
    seen = "never" if last is None else f"last seen {last.isoformat(timespec='seconds')}"
    return f"no live worker ({seen}): jobs would wait"


@router.get("/readyz", responses={503: {"description": "the database, the broker or every job worker is unreachable"}})
def readyz(session: SessionDep, settings: SettingsDep) -> JSONResponse:
    """Ready when the database answers, the broker accepts a connection and a worker can run jobs."""
    checks: dict[str, Any] = {}
    try:
        session.execute(text("SELECT 1"))
        checks["database"] = "ok"
        checks["workers"] = _workers(session, settings)
    except SQLAlchemyError as exc:
        logger.warning("readyz: database: %s", exc)
        checks["database"] = f"unreachable: {type(exc).__name__}"
    checks["broker"] = "ok" if broker_reachable(settings) else "unreachable"
    ready = all(value == "ok" for value in checks.values())
    return JSONResponse({"status": "ready" if ready else "not ready", "checks": checks}, status_code=200 if ready else 503)


LOOPBACK = frozenset({"127.0.0.1", "::1", "localhost"})


def _may_scrape(request: Request, settings: Settings) -> None:
    """``/metrics`` shows every client's activity: only with the metrics token, or from loopback without one.

    Raises
    ------
    Unauthorized, Forbidden
    """
    header = request.headers.get("authorization", "")
    if settings.metrics_token is not None:
        sent = header[len("Bearer "):] if header.startswith("Bearer ") else ""
        if not hmac.compare_digest(sent.encode(), settings.metrics_token.get_secret_value().encode()):
            raise Unauthorized("/metrics needs 'Authorization: Bearer METRICS_TOKEN'")
        return
    host = request.client.host if request.client else ""
    if host not in LOOPBACK:
        raise Forbidden("/metrics answers only on loopback unless the server sets METRICS_TOKEN")


@router.get("/metrics", response_class=Response, responses={200: {"content": {CONTENT_TYPE: {}}}, **error_responses(401, 403)})
def metrics(request: Request, session: SessionDep, settings: SettingsDep) -> Response:
    """Prometheus exposition format (with ``METRICS_TOKEN`` set: ``Authorization: Bearer METRICS_TOKEN``; else loopback only)."""
    _may_scrape(request, settings)
    return Response(render_metrics(session), media_type=CONTENT_TYPE)
