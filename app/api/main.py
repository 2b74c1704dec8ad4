"""All routers of the API."""

from __future__ import annotations

from fastapi import APIRouter

from app.api.routes import animations, artifacts, assets, batches, benchmarks, events, health, links, listings, plans

api_router = APIRouter()
api_router.include_router(health.router)
api_router.include_router(listings.router)  # GET /v1/assets and /v1/batches before their /{ref} routes
api_router.include_router(assets.router)
api_router.include_router(plans.router)
api_router.include_router(animations.router)
api_router.include_router(events.router)  # /v1/animations/{id}/events before the artifacts' /{id}/{name}
api_router.include_router(links.router)
api_router.include_router(artifacts.router)
api_router.include_router(batches.router)
api_router.include_router(benchmarks.router)
