"""``create_app()``: the ArtiMo HTTP API (``uvicorn --factory app.main:create_app``)."""

from __future__ import annotations

import logging
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager

from fastapi import FastAPI
from fastapi.concurrency import run_in_threadpool

from app.api.admission import AdmissionMiddleware
from app.api.errors import install_error_handlers
from app.api.guards import RequestGuardMiddleware
from app.api.main import api_router
from app.api.metrics import MetricsMiddleware
from app.core.config import Settings, get_settings
from app.core.logging import configure_logging
from app.db.migrate import upgrade
from app.web.mount import install_web

logger = logging.getLogger(__name__)

DESCRIPTION = """Text-driven articulated mesh animation as a service (the page at `/` shows and corrects results).

Upload a URDF asset (one `.zip`, or the URDF and its meshes) with a prompt to
`POST /v1/animations`, poll the returned `url`, download `animation.glb`.
Every `/v1` route needs `Authorization: Bearer KEY`.
"""


def embedded(settings: Settings) -> bool:
    """No ``DATABASE_URL``: the SQLite default, whose schema this process keeps up to date."""
    return settings.database_url is None


@asynccontextmanager
async def lifespan(app: FastAPI) -> AsyncIterator[None]:
    settings: Settings = app.state.settings or get_settings()
    configure_logging(settings)
    settings.data_dir.mkdir(parents=True, exist_ok=True)  # embedded database, SQLite broker, default storage
    if embedded(settings):
        await run_in_threadpool(upgrade, settings.sqlalchemy_url)
        logger.info("embedded database ready at %s", settings.sqlalchemy_url)
    yield


def create_app(settings: Settings | None = None) -> FastAPI:
    """The FastAPI application (OpenAPI docs at ``/docs``).

    ``settings`` replaces :func:`get_settings` for this app (tests, embedding); by default
    every request reads the cached environment settings.
    """
    app = FastAPI(title="ArtiMo", version="0.1.0", description=DESCRIPTION, lifespan=lifespan,
                  docs_url=None, redoc_url=None)  # local copies instead (app.web.mount): no CDN
    app.state.settings = settings  # read by app.api.deps.app_settings
    install_error_handlers(app)
    app.include_router(api_router)
    install_web(app)
    configured = settings or get_settings()
    app.add_middleware(MetricsMiddleware)
    app.add_middleware(AdmissionMiddleware, max_in_flight=configured.api_max_in_flight)
    app.add_middleware(RequestGuardMiddleware, max_json_body_bytes=configured.max_json_body_bytes,
                       body_idle_timeout_s=configured.body_idle_timeout_s, body_timeout_s=configured.body_timeout_s)
    return app
