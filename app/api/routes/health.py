"""Liveness, readiness and metrics (no API key: keep them on a private network or loopback)."""

from __future__ import annotations

import logging
from typing import Any

from fastapi import APIRouter, Response
from fastapi.responses import JSONResponse
from sqlalchemy import text
from sqlalchemy.exc import SQLAlchemyError

from app.api.deps import SessionDep, SettingsDep
from app.api.metrics import CONTENT_TYPE, render_metrics
from app.api.queue import broker_reachable

logger = logging.getLogger(__name__)

router = APIRouter(tags=["health"])


@router.get("/healthz")
def healthz() -> dict[str, str]:
    """The process is up."""
    return {"status": "ok"}


@router.get("/readyz", responses={503: {"description": "the database or the broker is unreachable"}})
def readyz(session: SessionDep, settings: SettingsDep) -> JSONResponse:
    """Ready when the database answers and the broker accepts a connection."""
    checks: dict[str, Any] = {}
    try:
        session.execute(text("SELECT 1"))
        checks["database"] = "ok"
    except SQLAlchemyError as exc:
        logger.warning("readyz: database: %s", exc)
        checks["database"] = f"unreachable: {type(exc).__name__}"
    checks["broker"] = "ok" if broker_reachable(settings) else "unreachable"
    ready = all(value == "ok" for value in checks.values())
    return JSONResponse({"status": "ready" if ready else "not ready", "checks": checks}, status_code=200 if ready else 503)


@router.get("/metrics", response_class=Response, responses={200: {"content": {CONTENT_TYPE: {}}}})
def metrics(session: SessionDep) -> Response:
    """Prometheus exposition format."""
    return Response(render_metrics(session), media_type=CONTENT_TYPE)
