"""``/v1/animations/{id}/...``: the output files of a finished job."""

from __future__ import annotations

import uuid
from typing import Annotated, Any, Literal

from fastapi import APIRouter, Path
from fastapi.responses import FileResponse
from sqlalchemy.orm import Session

from app.api.deps import ClientDep, SessionDep, StorageDep
from app.api.errors import DamagedData, NotFound, error_responses
from app.api.presenters import keyframe_names, visible_artifacts
from app.core.storage import Storage, StorageError, intact_local_path
from app.crud import jobs as crud_jobs
from app.db.models import ApiClient

router = APIRouter(prefix="/v1/animations", tags=["results"])

ArtifactName = Literal[
    "animation.glb", "trajectory.jsonl", "plan.json", "causal.json", "report.json", "interaction.json",
    "animation.usda", "scene.xml", "joint_trajectory.json", "trajectory.csv", "trajectory.npz",
]
FILE_RESPONSES: dict[int | str, dict[str, Any]] = {
    200: {"content": {"application/octet-stream": {}}, "description": "the file, with its own content type"},
    **error_responses(401, 404, 422, 429, 500),
}


def _serve(session: Session, storage: Storage, client: ApiClient, job_id: uuid.UUID, names: list[str]) -> FileResponse:
    job = crud_jobs.get_job_for_client(session, job_id=job_id, client=client)
    if job is None:
        raise NotFound(f"no animation job {job_id}")
    if any("\x00" in name for name in names):
        raise NotFound("no output with that name")
    artifacts = {a.name: a for a in visible_artifacts(job)}
    artifact = next((artifacts[name] for name in names if name in artifacts), None)
    if artifact is None:
        state = "has not finished" if not artifacts and not crud_jobs.is_terminal(job) else "has no such output"
        raise NotFound(f"{names[0]} is not available: job {job_id} is {job.status} and {state}", status=str(job.status))
    try:
        present = storage.local_path(artifact.storage_key).is_file()
    except StorageError as exc:
        raise NotFound(f"{artifact.name} is missing from storage") from exc
    if not present:
        raise NotFound(f"{artifact.name} is missing from storage")
    try:  # verified on read: a file changed on disk is never served under its old sha256 ETag
        path = intact_local_path(storage, artifact.storage_key, artifact.sha256, artifact.size_bytes)
    except StorageError as exc:
        raise DamagedData(f"{artifact.name} of job {job_id} is damaged in storage ({exc}); submit the job again") from exc
    filename = artifact.name.rsplit("/", 1)[-1]
    return FileResponse(path, media_type=artifact.content_type, filename=filename,
                        headers={"ETag": f'"{artifact.sha256}"', "Cache-Control": "private, max-age=3600"},
                        content_disposition_type="inline")


@router.get("/{job_id}/keyframes/{name}", response_class=FileResponse, responses=FILE_RESPONSES)
def get_keyframe(
    job_id: uuid.UUID, client: ClientDep, session: SessionDep, storage: StorageDep,
    name: Annotated[str, Path(min_length=1, max_length=200, pattern=r"^[^/\\]+$")],
) -> FileResponse:
    """A rendered keyframe/reference image of a finished job (PNG)."""
    return _serve(session, storage, client, job_id, keyframe_names(name))


@router.get("/{job_id}/files/{name:path}", response_class=FileResponse, responses=FILE_RESPONSES)
def get_file(
    job_id: uuid.UUID, client: ClientDep, session: SessionDep, storage: StorageDep,
    name: Annotated[str, Path(min_length=1, max_length=300)],
) -> FileResponse:
    """Any output file of a finished job, by its name in ``artifacts``."""
    return _serve(session, storage, client, job_id, [name])


@router.get("/{job_id}/{name}", response_class=FileResponse, responses=FILE_RESPONSES)
def get_artifact(job_id: uuid.UUID, name: ArtifactName, client: ClientDep, session: SessionDep, storage: StorageDep) -> FileResponse:
    """``animation.glb`` (model/gltf-binary), ``trajectory.jsonl``, ``plan.json``, ``causal.json``, ``report.json``,
    ``interaction.json``, and the exports asked for (``animation.usda``, ``scene.xml``, ``joint_trajectory.json``,
    ``trajectory.csv``, ``trajectory.npz``)."""
    return _serve(session, storage, client, job_id, [name])
