"""``/v1/assets``: upload an asset once, reuse it by id or sha256."""

from __future__ import annotations

from fastapi import APIRouter, Path, Request, Response, status
from fastapi.concurrency import run_in_threadpool

from app.api.deps import ClientDep, SessionDep, SettingsDep, StorageDep, release_connection
from app.api.errors import error_responses
from app.api.forms import ASSET_FILES_SCHEMA, URDF_FIELD_SCHEMA, multipart_openapi, read_form, upload_folder, urdf_field
from app.api.intake import asset_by_ref, store_upload
from app.api.presenters import asset_public
from app.core.asset_summary import read_summary
from app.schemas.assets import AssetPublic, AssetSummary

router = APIRouter(prefix="/v1/assets", tags=["assets"])

ERRORS = error_responses(401, 413, 415, 422, 429)


@router.post(
    "",
    status_code=status.HTTP_201_CREATED,
    response_model=AssetPublic,
    responses={200: {"model": AssetPublic, "description": "identical content was already stored"}, **ERRORS},
    openapi_extra=multipart_openapi({"asset": ASSET_FILES_SCHEMA, "urdf": URDF_FIELD_SCHEMA}, ["asset"]),
)
async def upload_asset(
    request: Request, response: Response, client: ClientDep, session: SessionDep, settings: SettingsDep, storage: StorageDep
) -> AssetPublic:
    """Store and validate an asset (201), or find the one you already uploaded with the same content (200)."""
    await release_connection(session, client)
    async with upload_folder(settings) as folder:
        form = await read_form(request, settings, folder)
        asset, created = await store_upload(form.files_of("asset"), work=folder, session=session, storage=storage, client=client,
                                            settings=settings, urdf=urdf_field(form))
    if not created:
        response.status_code = status.HTTP_200_OK
    return asset_public(request, asset, created=created)


@router.get("/{ref}", response_model=AssetPublic, responses=error_responses(401, 404, 409, 429))
def get_asset(
    request: Request, client: ClientDep, session: SessionDep,
    ref: str = Path(min_length=1, max_length=100, description="asset id or sha256"),
) -> AssetPublic:
    """An asset this client uploaded."""
    return asset_public(request, asset_by_ref(session, client=client, ref=ref))


@router.get("/{ref}/summary", response_model=AssetSummary, responses=error_responses(401, 404, 409, 429))
async def get_asset_summary(
    client: ClientDep, session: SessionDep, storage: StorageDep,
    ref: str = Path(min_length=1, max_length=100, description="asset id or sha256"),
) -> AssetSummary:
    """Joints (type, links, axis, limits), link labels, sizes, where each part sits and which end of each
    joint is closed/open/rest: what a prompt can name and move."""
    asset = await run_in_threadpool(asset_by_ref, session, client=client, ref=ref)
    return await run_in_threadpool(read_summary, storage, asset)
