"""``/v1/batches``: many (asset, prompt) cases in one request, followed as one."""

from __future__ import annotations

import logging
import uuid

from fastapi import APIRouter, Request, Response, status

from app.api.deps import ClientDep, EnqueuerDep, SessionDep, SettingsDep
from app.api.errors import NotFound, PayloadTooLarge, Unprocessable, error_responses
from app.api.presenters import batch_public
from app.api.queue import check_job_quota, dispatch_jobs
from app.crud.assets import find_assets_for_client
from app.crud.batches import BatchCase, create_batch, get_batch_for_client
from app.schemas.batches import BatchCreate, BatchPublic

logger = logging.getLogger(__name__)

router = APIRouter(prefix="/v1/batches", tags=["batches"])

ERRORS = error_responses(401, 404, 429)


@router.post(
    "", status_code=status.HTTP_202_ACCEPTED, response_model=BatchPublic,
    responses=error_responses(401, 413, 422, 429, 503),
)
def create_batch_route(
    request: Request, response: Response, body: BatchCreate, client: ClientDep, session: SessionDep,
    settings: SettingsDep, enqueue: EnqueuerDep,
) -> BatchPublic:
    """Queue one job per case; assets must be uploaded first (``POST /v1/assets``)."""
    if len(body.cases) > settings.max_batch_cases:
        raise PayloadTooLarge(f"{len(body.cases)} cases, more than the limit of {settings.max_batch_cases}",
                              limit=settings.max_batch_cases)
    check_job_quota(session, client=client, adding=len(body.cases), limit=settings.max_active_jobs_per_client)
    cases = []
    for index, case in enumerate(body.cases):
        found = find_assets_for_client(session, client=client, ref=case.asset)
        if len(found) != 1:
            problem = "no asset" if not found else f"{len(found)} assets (one per URDF; use the asset id) for"
            raise Unprocessable(f"case {index}: {problem} {case.asset!r} (upload it with POST /v1/assets first)", case=index)
        asset = found[0]
        options = {**body.options.stored(), **(case.options.stored() if case.options else {})}
        if (missing := settings.missing_provider_key(options.get("provider"))) is not None:
            raise Unprocessable(f"case {index}: {missing}", case=index)
        cases.append(BatchCase(asset=asset, prompt=case.prompt.strip(), case_id=case.case_id, options=options))
    batch = create_batch(session, client=client, cases=cases, name=body.name)
    dispatch_jobs(session, batch.jobs, enqueue)
    session.refresh(batch)
    public = batch_public(request, batch)
    response.headers["Location"] = public.url
    return public


@router.get("/{batch_id}", response_model=BatchPublic, responses=ERRORS)
def get_batch(request: Request, batch_id: uuid.UUID, client: ClientDep, session: SessionDep) -> BatchPublic:
    """Per-case status and output links."""
    batch = get_batch_for_client(session, batch_id=batch_id, client=client)
    if batch is None:
        raise NotFound(f"no batch {batch_id}")
    return batch_public(request, batch)
