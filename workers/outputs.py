"""A job's outputs: output files to storage + Artifact rows (and the asset's name for the engine)."""

from __future__ import annotations

import logging
import re
from pathlib import Path, PurePosixPath

from sqlalchemy.orm import Session

from app.core.storage import Storage
from app.crud import jobs as crud_jobs
from app.db.models import Artifact, Job

logger = logging.getLogger(__name__)

CONTENT_TYPES = {
    ".glb": "model/gltf-binary",
    ".json": "application/json",
    ".jsonl": "application/jsonl",
    ".png": "image/png",
    ".gif": "image/gif",
    ".jpg": "image/jpeg",
    ".txt": "text/plain",
    ".usda": "model/vnd.usda",
    ".xml": "application/xml",
    ".csv": "text/csv",
    ".npz": "application/zip",
}
DEFAULT_CONTENT_TYPE = "application/octet-stream"
SAFE_NAME = re.compile(r"[^A-Za-z0-9._-]+")
DEFAULT_ASSET_NAME = "asset"


def job_prefix(job: Job) -> str:
    return f"jobs/{job.id}"


def content_type(name: str) -> str:
    return CONTENT_TYPES.get(PurePosixPath(name).suffix.lower(), DEFAULT_CONTENT_TYPE)


def asset_name(filename: str) -> str:
    """The asset's name for the engine (messages, GLB root) from the uploaded file name."""
    stem = PurePosixPath(filename.replace("\\", "/")).name
    stem = stem[: -len(".zip")] if stem.lower().endswith(".zip") else stem
    return SAFE_NAME.sub("_", stem).strip("._") or DEFAULT_ASSET_NAME


def clear_outputs(session: Session, storage: Storage, job: Job) -> None:
    """Forget a previous (partial) run of the job: its Artifact rows and its storage prefix."""
    crud_jobs.delete_artifacts(session, job=job)
    storage.delete_prefix(job_prefix(job))


def publish_outputs(session: Session, storage: Storage, job: Job, out_dir: Path) -> list[Artifact]:
    """Store every file under ``out_dir`` as ``jobs/<id>/<relative path>`` and record an Artifact each.

    Files are taken in sorted order; a name that already has a row is replaced (a re-run).
    """
    artifacts = []
    for path in sorted(p for p in out_dir.rglob("*") if p.is_file() and not p.name.startswith(".")):
        name = path.relative_to(out_dir).as_posix()
        stored = storage.put_file(f"{job_prefix(job)}/{name}", path)
        artifacts.append(
            crud_jobs.add_artifact(
                session, job=job, name=name, storage_key=stored.key, sha256=stored.sha256,
                size_bytes=stored.size, content_type=content_type(name),
            )
        )
    logger.info("job %s: stored %d artifacts", job.id, len(artifacts))
    return artifacts
