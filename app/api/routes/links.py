"""Share links: a signed, expiring URL for one output file of a job, usable without a header.

``POST /v1/animations/{id}/links`` (with the key) returns ``/v1/shared/{id}/{name}?token=...``
URLs; anyone holding one can download that file until it expires. An altered or expired
token is 403.
"""

from __future__ import annotations

import uuid
from datetime import UTC, datetime
from typing import Annotated
from urllib.parse import quote

from fastapi import APIRouter, Path, Query, Request
from fastapi.concurrency import run_in_threadpool
from fastapi.responses import FileResponse
from pydantic import BaseModel, Field
from sqlalchemy.orm import Session

from app.api.deps import ClientDep, SessionDep, SettingsDep, StorageDep
from app.api.errors import NotFound, Unprocessable, error_responses
from app.api.presenters import visible_artifacts
from app.api.signing import Forbidden, expiry, link_secret, sign, verify
from app.core.storage import Storage, StorageError
from app.crud import jobs as crud_jobs
from app.db.models import ApiClient, Artifact

router = APIRouter(tags=["share"])

DEFAULT_TTL_S = 24 * 3600
MAX_TTL_S = 30 * 24 * 3600
MIN_TTL_S = 1
LINK_KIND = "file"


class LinksCreate(BaseModel):
    names: list[str] | None = Field(default=None, max_length=500, description="output names; default every output")
    expires_in_s: int = Field(default=DEFAULT_TTL_S, ge=MIN_TTL_S, le=MAX_TTL_S)


class SharedLink(BaseModel):
    name: str
    url: str
    content_type: str
    size_bytes: int


class SharedLinks(BaseModel):
    expires_at: datetime
    links: list[SharedLink]


def _artifacts(session: Session, client: ApiClient, job_id: uuid.UUID) -> dict[str, Artifact]:
    job = crud_jobs.get_job_for_client(session, job_id=job_id, client=client)
    if job is None:
        raise NotFound(f"no animation job {job_id}")
    return {artifact.name: artifact for artifact in visible_artifacts(job)}


@router.post("/v1/animations/{job_id}/links", response_model=SharedLinks, responses=error_responses(401, 404, 422, 429))
async def create_links(
    request: Request, job_id: uuid.UUID, body: LinksCreate, client: ClientDep, session: SessionDep, settings: SettingsDep,
) -> SharedLinks:
    """Signed download links for the job's outputs, valid for ``expires_in_s`` seconds."""
    artifacts = await run_in_threadpool(_artifacts, session, client, job_id)
    names = sorted(artifacts) if body.names is None else body.names
    missing = [name for name in names if name not in artifacts]
    if missing:
        raise Unprocessable(f"job {job_id} has no output named {missing[0]!r}", names=sorted(artifacts))
    secret = link_secret(settings)
    base = str(request.base_url).rstrip("/")
    links = []
    for name in names:
        token = sign(secret, LINK_KIND, body.expires_in_s, j=str(job_id), n=name, c=str(client.id))
        artifact = artifacts[name]
        links.append(SharedLink(name=name, url=f"{base}/v1/shared/{job_id}/{quote(name)}?token={token}",
                                content_type=artifact.content_type, size_bytes=artifact.size_bytes))
    expires = datetime.fromtimestamp(expiry(body.expires_in_s), UTC)
    return SharedLinks(expires_at=expires, links=links)


def _shared_file(session: Session, storage: Storage, job_id: uuid.UUID, name: str, client_id: str) -> FileResponse:
    job = crud_jobs.get_job(session, job_id=job_id)
    if job is None or str(job.client_id) != client_id:
        raise NotFound(f"no animation job {job_id}")
    owner = session.get(ApiClient, job.client_id)
    if owner is None or owner.disabled:
        raise Forbidden("the key that shared this link is disabled")
    artifact = next((a for a in visible_artifacts(job) if a.name == name), None)
    if artifact is None:
        raise NotFound(f"{name} is no longer available")
    try:
        path = storage.local_path(artifact.storage_key)
    except StorageError as exc:
        raise NotFound(f"{name} is missing from storage") from exc
    if not path.is_file():
        raise NotFound(f"{name} is missing from storage")
    return FileResponse(path, media_type=artifact.content_type, filename=name.rsplit("/", 1)[-1],
                        headers={"ETag": f'"{artifact.sha256}"', "Cache-Control": "private, max-age=300",
                                 "Access-Control-Allow-Origin": "*"},
                        content_disposition_type="inline")


@router.get("/v1/shared/{job_id}/{name:path}", response_class=FileResponse, responses=error_responses(403, 404, 422))
async def get_shared(
    job_id: uuid.UUID, session: SessionDep, settings: SettingsDep, storage: StorageDep,
    name: Annotated[str, Path(min_length=1, max_length=300)],
    token: Annotated[str, Query(min_length=1, max_length=2000, description="from POST /v1/animations/{id}/links")],
) -> FileResponse:
    """Download a shared output with its ``token`` (no ``Authorization`` header needed)."""
    claims = verify(link_secret(settings), token, LINK_KIND)
    if claims.fields.get("j") != str(job_id) or claims.fields.get("n") != name:
        raise Forbidden("this token was issued for another file")
    return await run_in_threadpool(_shared_file, session, storage, job_id, name, str(claims.fields.get("c")))
