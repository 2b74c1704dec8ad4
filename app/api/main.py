"""All routers of the API."""

from __future__ import annotations

from fastapi import APIRouter

from app.api.routes import animations, artifacts, assets, batches, health

api_router = APIRouter()
api_router.include_router(health.router)
api_router.include_router(assets.router)
api_router.include_router(animations.router)
api_router.include_router(artifacts.router)
api_router.include_router(batches.router)
