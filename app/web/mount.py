"""The page at ``/`` and the API docs at ``/docs`` and ``/redoc``, all served from this machine.

No build step: ``static/`` holds the page's HTML, CSS and ES modules as written; the
front-end packages (three.js, Swagger UI, Redoc) come from the npm registry at set-up
time (``npm ci --prefix app/web``, run by ``make demo``/``make test`` and the Dockerfile)
into ``app/web/node_modules`` and are served under ``/vendor/``. The page loads three.js
through an import map; nothing is fetched from another host.
"""

from __future__ import annotations

import logging
from functools import lru_cache
from pathlib import Path

from fastapi import FastAPI
from fastapi.openapi.docs import get_redoc_html, get_swagger_ui_html, get_swagger_ui_oauth2_redirect_html
from fastapi.responses import FileResponse, HTMLResponse, PlainTextResponse, Response
from starlette.staticfiles import StaticFiles
from starlette.types import Receive, Scope, Send

logger = logging.getLogger(__name__)

WEB_DIR = Path(__file__).resolve().parent
STATIC_DIR = WEB_DIR / "static"
PACKAGES_DIR = WEB_DIR / "node_modules"
VENDOR = {
    "three": PACKAGES_DIR / "three",
    "swagger-ui": PACKAGES_DIR / "swagger-ui-dist",
    "redoc": PACKAGES_DIR / "redoc" / "bundles",
}
"""URL folder under ``/vendor/`` -> installed package folder."""
INSTALL_HINT = "front-end packages are not installed: run `npm ci --prefix app/web` (make demo / make test do it)"
FAVICON = "/static/favicon.svg"
NO_CACHE = {"Cache-Control": "no-cache"}
REDOC_REMOTE_LOGO = b"https://cdn.redoc.ly/redoc/logo-mini.svg"


def _missing_packages() -> list[str]:
    return [name for name, folder in VENDOR.items() if not folder.is_dir()]


class _MissingPackage:
    """ASGI app answering 503 with the install hint for a package folder that is not there."""

    def __init__(self, name: str) -> None:
        self.response = PlainTextResponse(f"/vendor/{name}: {INSTALL_HINT}", status_code=503)

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        await self.response(scope, receive, send)


@lru_cache(maxsize=1)
def _redoc_bundle() -> bytes:
    """Redoc's bundle with its one remote reference (the attribution logo) pointed at a local file."""
    return (VENDOR["redoc"] / "redoc.standalone.js").read_bytes().replace(REDOC_REMOTE_LOGO, FAVICON.encode())


def _mount_vendor(app: FastAPI) -> None:
    if "redoc" in VENDOR and VENDOR["redoc"].is_dir():

        @app.get("/vendor/redoc/redoc.standalone.js", include_in_schema=False)
        async def redoc_bundle() -> Response:
            return Response(_redoc_bundle(), media_type="text/javascript", headers={"Cache-Control": "public, max-age=3600"})

    for name, folder in VENDOR.items():
        if folder.is_dir():
            app.mount(f"/vendor/{name}", StaticFiles(directory=folder), name=f"vendor-{name}")
        else:
            app.mount(f"/vendor/{name}", _MissingPackage(name), name=f"vendor-{name}")


def _docs_routes(app: FastAPI) -> None:
    openapi_url = app.openapi_url or "/openapi.json"

    @app.get("/docs", include_in_schema=False)
    async def swagger_ui() -> HTMLResponse:
        return get_swagger_ui_html(
            openapi_url=openapi_url, title=f"{app.title} - API docs",
            swagger_js_url="/vendor/swagger-ui/swagger-ui-bundle.js", swagger_css_url="/vendor/swagger-ui/swagger-ui.css",
            swagger_favicon_url=FAVICON, oauth2_redirect_url="/docs/oauth2-redirect",
        )

    @app.get("/docs/oauth2-redirect", include_in_schema=False)
    async def swagger_redirect() -> HTMLResponse:
        return get_swagger_ui_oauth2_redirect_html()

    @app.get("/redoc", include_in_schema=False)
    async def redoc() -> HTMLResponse:
        return get_redoc_html(openapi_url=openapi_url, title=f"{app.title} - API reference",
                              redoc_js_url="/vendor/redoc/redoc.standalone.js", redoc_favicon_url=FAVICON,
                              with_google_fonts=False)


def install_web(app: FastAPI) -> None:
    """Serve the page (``/``), its files (``/static``), the packages (``/vendor``) and the docs.

    Create the app with ``docs_url=None, redoc_url=None``: the stock docs pages load their
    scripts from a CDN.
    """
    missing = _missing_packages()
    if missing:
        logger.warning("%s (missing: %s)", INSTALL_HINT, ", ".join(missing))

    @app.get("/", include_in_schema=False)
    async def page() -> FileResponse:
        return FileResponse(STATIC_DIR / "index.html", media_type="text/html", headers=NO_CACHE)

    app.mount("/static", StaticFiles(directory=STATIC_DIR), name="static")
    _mount_vendor(app)
    _docs_routes(app)
