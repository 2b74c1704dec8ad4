"""Prometheus metrics: requests by route template and status, latencies, jobs by status.

The ASGI middleware labels requests with the matched route's template (``/v1/animations/{job_id}``),
never the raw path, so label cardinality stays bounded. Metrics live in their own registry.
"""

from __future__ import annotations

import logging
import time
from typing import Any

from prometheus_client import CONTENT_TYPE_LATEST, CollectorRegistry, Counter, Gauge, Histogram, generate_latest
from sqlalchemy.exc import SQLAlchemyError
from sqlalchemy.orm import Session
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.crud.jobs import count_jobs_by_status

logger = logging.getLogger(__name__)

REGISTRY = CollectorRegistry(auto_describe=True)
REQUESTS = Counter("artimo_http_requests", "HTTP requests handled", ["method", "route", "status"], registry=REGISTRY)
LATENCY = Histogram(
    "artimo_http_request_duration_seconds", "Time to answer an HTTP request", ["method", "route"], registry=REGISTRY,
    buckets=(0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1, 2.5, 5, 10, 30),
)
JOBS = Gauge("artimo_jobs", "Jobs in the database by status (all clients)", ["status"], registry=REGISTRY)
UNMATCHED_ROUTE = "unmatched"
CONTENT_TYPE = CONTENT_TYPE_LATEST


class MetricsMiddleware:
    """Pure ASGI middleware (does not buffer bodies, works with streaming uploads/downloads)."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        began = time.perf_counter()
        status = {"code": 500}

        async def observe(message: Message) -> None:
            if message["type"] == "http.response.start":
                status["code"] = int(message["status"])
            await send(message)

        try:
            await self.app(scope, receive, observe)
        finally:
            route: Any = scope.get("route")
            template = getattr(route, "path", None) or UNMATCHED_ROUTE
            method = str(scope.get("method", ""))
            REQUESTS.labels(method, template, str(status["code"])).inc()
            LATENCY.labels(method, template).observe(time.perf_counter() - began)


def render_metrics(session: Session) -> bytes:
    """The exposition text, with the jobs gauge refreshed from the database (skipped if it is down)."""
    try:
        for status, count in count_jobs_by_status(session).items():
            JOBS.labels(status).set(count)
    except SQLAlchemyError as exc:
        logger.warning("metrics: jobs gauge not refreshed (%s)", exc)
    return generate_latest(REGISTRY)
