"""``GET /v1/assets`` and ``GET /v1/batches``: what a client has, for choosing (the page's lists)."""

from __future__ import annotations

import uuid
from typing import Annotated

from fastapi import APIRouter, Query, Request
from pydantic import BaseModel

from app.api.deps import ClientDep, SessionDep
from app.api.errors import error_responses
from app.api.presenters import asset_public
from app.crud.listings import MAX_LISTED, list_client_assets, list_client_batches
from app.schemas.assets import AssetPublic
from app.schemas.common import UtcDatetime

router = APIRouter(tags=["listings"])

Limit = Annotated[int, Query(ge=1, le=MAX_LISTED)]


class AssetsPublic(BaseModel):
    data: list[AssetPublic]


class BatchListItem(BaseModel):
    id: uuid.UUID
    url: str
    name: str | None
    created_at: UtcDatetime
    count: int


class BatchesPublic(BaseModel):
    data: list[BatchListItem]


@router.get("/v1/assets", response_model=AssetsPublic, responses=error_responses(401, 429), tags=["assets"])
def list_assets(request: Request, client: ClientDep, session: SessionDep, limit: Limit = 50) -> AssetsPublic:
    """This client's assets, most recently used first."""
    return AssetsPublic(data=[asset_public(request, asset) for asset in list_client_assets(session, client=client, limit=limit)])


@router.get("/v1/batches", response_model=BatchesPublic, responses=error_responses(401, 429), tags=["batches"])
def list_batches(request: Request, client: ClientDep, session: SessionDep, limit: Limit = 50) -> BatchesPublic:
    """This client's batches (name, size), newest first."""
    base = str(request.base_url).rstrip("/")
    items = [
        BatchListItem(id=batch.id, url=f"{base}/v1/batches/{batch.id}", name=batch.name,
                      created_at=batch.created_at, count=count)
        for batch, count in list_client_batches(session, client=client, limit=limit)
    ]
    return BatchesPublic(data=items)
