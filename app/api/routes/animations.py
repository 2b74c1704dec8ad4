"""``/v1/animations``: submit a job (202), read it, list them, cancel it."""

from __future__ import annotations

import logging
import uuid
from functools import partial
from typing import Annotated, Any

from fastapi import APIRouter, Query, Request, Response, status
from fastapi.concurrency import run_in_threadpool
from sqlalchemy.orm import Session

from app.api.deps import ClientDep, EnqueuerDep, SessionDep, SettingsDep, StorageDep, release_connection
from app.api.errors import Conflict, NotFound, Unprocessable, error_responses
from app.api.forms import (
    ASSET_FILES_SCHEMA,
    URDF_FIELD_SCHEMA,
    multipart_openapi,
    read_form,
    upload_folder,
    urdf_field,
    validate_fields,
)
from app.api.intake import asset_by_ref, asset_with_urdf, store_upload
from app.api.plan_jobs import PLAN_LABEL, accept_plan, take_plan_file
from app.api.presenters import job_public, job_url
from app.api.queue import Enqueuer, check_job_quota, dispatch_jobs
from app.core.config import Settings
from app.crud import jobs as crud_jobs
from app.db.models import ApiClient, Asset, Job, JobStatus
from app.schemas.jobs import MAX_PROMPT_CHARS, JobAccepted, JobCreate, JobPublic, JobsPublic

logger = logging.getLogger(__name__)

router = APIRouter(prefix="/v1/animations", tags=["animations"])

MAX_OFFSET = 1_000_000_000
JOB_FIELDS = ("prompt", "plan", "provider", "perceiver_model", "planner_model", "critic_model", "fps", "max_critic_rounds", "preview", "exports")
_TEXT = {"type": "string"}
SUBMIT_BODY = multipart_openapi(
    {
        "asset": ASSET_FILES_SCHEMA,
        "asset_ref": {"type": "string", "maxLength": 100, "description": "instead of files: an asset id or sha256 from POST /v1/assets"},
        "urdf": URDF_FIELD_SCHEMA,
        "prompt": {"type": "string", "minLength": 1, "maxLength": MAX_PROMPT_CHARS},
        "plan": {"type": "string", "description": "instead of a prompt: a Plan.json to execute and export (text up to 64 KiB, or a file part)"},
        "provider": {**_TEXT, "description": "offline (default), openai or gemini"},
        "perceiver_model": _TEXT, "planner_model": _TEXT, "critic_model": _TEXT,
        "fps": {"type": "integer", "enum": [24, 30]},
        "max_critic_rounds": {"type": "integer", "minimum": 0, "maximum": 3},
        "preview": {"type": "boolean", "description": "also render preview.gif (an animated GIF of the result)"},
        "exports": {"type": "string", "maxLength": 100, "description": "also write these formats, comma-separated: usd, mjcf, ros, csv, npz"},
    },
    [],
)
ERRORS = error_responses(401, 404, 429)


def _queue_job(session: Session, client: ApiClient, asset: Asset, spec: JobCreate, enqueue: Enqueuer, settings: Settings,
               plan_options: dict[str, Any]) -> Job:
    check_job_quota(session, client=client, adding=1, limit=settings.max_active_jobs_per_client)
    prompt = spec.prompt or PLAN_LABEL
    job = crud_jobs.create_job(session, client=client, asset=asset, prompt=prompt, options={**spec.stored(), **plan_options})
    dispatch_jobs(session, [job], enqueue)
    return job


def _job_or_404(session: Session, job_id: uuid.UUID, client: ApiClient) -> Job:
    job = crud_jobs.get_job_for_client(session, job_id=job_id, client=client)
    if job is None:
        raise NotFound(f"no animation job {job_id}")
    return job


@router.post(
    "",
    status_code=status.HTTP_202_ACCEPTED,
    response_model=JobAccepted,
    responses=error_responses(401, 404, 409, 413, 415, 422, 429, 503),
    openapi_extra=SUBMIT_BODY,
)
async def create_animation(
    request: Request, response: Response, client: ClientDep, session: SessionDep, settings: SettingsDep,
    storage: StorageDep, enqueue: EnqueuerDep,
) -> JobAccepted:
    """Submit an asset (file(s) or ``asset_ref``) and a prompt (or a ``plan`` to execute as is); poll the returned ``url``."""
    await release_connection(session, client)
    async with upload_folder(settings) as folder:
        form = await read_form(request, settings, folder)
        take_plan_file(form)
        spec = validate_fields(JobCreate, form, JOB_FIELDS)
        if (missing := settings.missing_provider_key(spec.provider)) is not None:
            raise Unprocessable(missing, field="provider")
        files, ref, urdf = form.files_of("asset"), (form.value("asset_ref") or "").strip(), urdf_field(form)
        if files and ref:
            raise Unprocessable("send either asset file(s) or 'asset_ref', not both")
        if ref:
            asset = await run_in_threadpool(partial(asset_by_ref, session, client=client, ref=ref, any_urdf=urdf is not None))
            if urdf is not None:
                asset = await asset_with_urdf(asset, urdf, session=session, storage=storage, client=client, settings=settings)
        else:
            asset, _ = await store_upload(files, work=folder, session=session, storage=storage, client=client,
                                          settings=settings, urdf=urdf)
    plan_options = {} if spec.plan is None else await run_in_threadpool(accept_plan, spec.plan, asset, storage, settings)
    job = await run_in_threadpool(_queue_job, session, client, asset, spec, enqueue, settings, plan_options)
    url = job_url(request, job.id)
    response.headers["Location"] = url
    logger.info("job %s queued for client %s", job.id, client.name)
    return JobAccepted(id=job.id, url=url, status=JobStatus(job.status))


@router.get("", response_model=JobsPublic, responses=ERRORS)
def list_animations(
    request: Request, client: ClientDep, session: SessionDep,
    limit: Annotated[int, Query(ge=1, le=crud_jobs.MAX_PAGE_SIZE)] = 50,
    offset: Annotated[int, Query(ge=0, le=MAX_OFFSET)] = 0,
    status_filter: Annotated[JobStatus | None, Query(alias="status")] = None,
) -> JobsPublic:
    """This client's jobs, newest first."""
    jobs, count = crud_jobs.list_jobs(session, client=client, limit=limit, offset=offset, status=status_filter)
    return JobsPublic(data=[job_public(request, job) for job in jobs], count=count, limit=limit, offset=offset)


@router.get("/{job_id}", response_model=JobPublic, responses=ERRORS)
async def get_animation(request: Request, job_id: uuid.UUID, client: ClientDep, session: SessionDep) -> JobPublic:
    """Status, stage, progress, timings, error and output links of one job."""
    job = await run_in_threadpool(_job_or_404, session, job_id, client)  # the one blocking step of a status poll
    return job_public(request, job)


@router.delete(
    "/{job_id}",
    response_model=JobPublic,
    responses={**error_responses(401, 404, 409, 429),
               202: {"model": JobPublic, "description": "running: it stops at its next stage"}},
)
def cancel_animation(request: Request, response: Response, job_id: uuid.UUID, client: ClientDep, session: SessionDep) -> JobPublic:
    """Cancel: a queued job at once (200), a running one at its next stage (202)."""
    job = _job_or_404(session, job_id, client)
    if job.status in (JobStatus.succeeded, JobStatus.failed):
        raise Conflict(f"job {job_id} already {job.status}; nothing to cancel", status=str(job.status))
    crud_jobs.request_cancel(session, job=job)
    if job.status == JobStatus.running:
        response.status_code = status.HTTP_202_ACCEPTED
    elif job.status in (JobStatus.succeeded, JobStatus.failed):  # it finished while we asked
        raise Conflict(f"job {job_id} already {job.status}; nothing to cancel", status=str(job.status))
    return job_public(request, job)
