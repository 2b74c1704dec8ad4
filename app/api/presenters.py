"""ORM rows -> API schemas, with absolute URLs built from the request."""

from __future__ import annotations

import uuid
from collections import Counter
from collections.abc import Iterable
from urllib.parse import quote

from fastapi import Request

from app.db.models import TERMINAL, Artifact, Asset, Batch, Job, JobStatus
from app.schemas.assets import AssetPublic
from app.schemas.batches import BatchCasePublic, BatchPublic
from app.schemas.jobs import ArtifactPublic, JobPublic

ANIMATIONS = "/v1/animations"
NAMED_ARTIFACTS = ("animation.glb", "trajectory.jsonl", "plan.json", "causal.json", "report.json")
"""Outputs with their own route ``/v1/animations/{id}/<name>``."""
KEYFRAME_FOLDERS = ("keyframes/", "images/")
"""Images are served by ``/v1/animations/{id}/keyframes/<file>``."""


def _base(request: Request) -> str:
    """The server's base URL (scheme, host, root path) without the trailing slash.

    URLs are formatted from the fixed route paths instead of ``url_for``, which walks the
    route table on every call (it dominated the cost of a status poll).
    """
    return str(request.base_url).rstrip("/")


def job_url(request: Request, job_id: uuid.UUID) -> str:
    return f"{_base(request)}{ANIMATIONS}/{job_id}"


def artifact_url(request: Request, job_id: uuid.UUID, name: str) -> str:
    prefix = f"{_base(request)}{ANIMATIONS}/{job_id}"
    if name in NAMED_ARTIFACTS:
        return f"{prefix}/{quote(name)}"
    for folder in KEYFRAME_FOLDERS:
        rest = name[len(folder):]
        if name.startswith(folder) and rest and "/" not in rest:
            return f"{prefix}/keyframes/{quote(rest)}"
    return f"{prefix}/files/{quote(name)}"


def keyframe_names(name: str) -> list[str]:
    """Artifact names a keyframe file name may be stored under."""
    return [folder + name for folder in KEYFRAME_FOLDERS]


def visible_artifacts(job: Job) -> list[Artifact]:
    """Outputs are published only once the job has finished (no half-written run)."""
    return list(job.artifacts) if JobStatus(job.status) in TERMINAL else []


def _artifacts(request: Request, job: Job) -> list[ArtifactPublic]:
    return [
        ArtifactPublic(name=a.name, url=artifact_url(request, job.id, a.name), content_type=a.content_type,
                       size_bytes=a.size_bytes, sha256=a.sha256)
        for a in visible_artifacts(job)
    ]


def job_public(request: Request, job: Job) -> JobPublic:
    return JobPublic(
        id=job.id, url=job_url(request, job.id), status=JobStatus(job.status), stage=job.stage,
        progress=min(max(job.progress, 0), 100), cancel_requested=job.cancel_requested, prompt=job.prompt,
        options=dict(job.options or {}), asset_id=job.asset_id, batch_id=job.batch_id, case_id=job.case_id,
        error=job.error, error_kind=job.error_kind, timings=dict(job.timings or {}), attempts=job.attempts,
        created_at=job.created_at, started_at=job.started_at, finished_at=job.finished_at,
        artifacts=_artifacts(request, job),
    )


def asset_public(request: Request, asset: Asset, *, created: bool = False) -> AssetPublic:
    return AssetPublic(
        id=asset.id, sha256=asset.sha256, filename=asset.filename, urdf=asset.urdf, size_bytes=asset.size_bytes,
        created_at=asset.created_at, created=created,
        url=str(request.url_for("get_asset", ref=str(asset.id))),
        summary_url=str(request.url_for("get_asset_summary", ref=str(asset.id))),
    )


def _status_counts(jobs: Iterable[Job]) -> dict[str, int]:
    counts = Counter(str(job.status) for job in jobs)
    return {status.value: counts.get(status.value, 0) for status in JobStatus}


def batch_public(request: Request, batch: Batch) -> BatchPublic:
    jobs = list(batch.jobs)
    cases = [
        BatchCasePublic(
            case_id=job.case_id, job_id=job.id, url=job_url(request, job.id), status=JobStatus(job.status),
            stage=job.stage, progress=job.progress, error=job.error, error_kind=job.error_kind,
            artifacts=_artifacts(request, job),
        )
        for job in jobs
    ]
    return BatchPublic(
        id=batch.id, url=str(request.url_for("get_batch", batch_id=str(batch.id))), name=batch.name,
        created_at=batch.created_at, count=len(jobs), status_counts=_status_counts(jobs),
        done=all(JobStatus(job.status) in TERMINAL for job in jobs), cases=cases,
    )
