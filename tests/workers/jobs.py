"""Create and read jobs directly in the database (for tests that bypass the API)."""

from __future__ import annotations

import uuid
from pathlib import Path

from app.core.config import Settings
from app.core.storage import LocalStorage
from app.crud.assets import get_or_create_asset, get_or_create_content
from app.crud.clients import create_api_client
from app.crud.jobs import create_job
from app.db.models import Job
from app.db.session import session_factory
from tests.workers import stack

REPO = Path(__file__).resolve().parents[2]
PEDAL_BIN = REPO / "examples" / "pedal_bin"
PEDAL_PROMPT = "press the pedal to open the bin"


def make_job(settings: Settings, prompt: str = PEDAL_PROMPT, folder: Path = PEDAL_BIN, options: dict[str, object] | None = None) -> uuid.UUID:
    """A queued job on the asset ``folder`` (zipped into storage), owned by a new client."""
    storage = LocalStorage(settings.storage_dir)
    data = stack.zip_folder(folder)
    import hashlib

    digest = hashlib.sha256(data).hexdigest()
    stored = storage.put_bytes(f"assets/{digest}.zip", data)
    with session_factory(settings.sqlalchemy_url)() as session:
        client, _ = create_api_client(session, name=f"test-{uuid.uuid4().hex[:6]}")
        content = get_or_create_content(session, sha256=digest, size_bytes=stored.size, storage_key=stored.key)
        asset, _ = get_or_create_asset(session, client=client, content=content, filename=f"{folder.name}.zip", urdf="")
        job = create_job(session, client=client, asset=asset, prompt=prompt, options=options or {})
        return job.id


def load_job(settings: Settings, job_id: uuid.UUID) -> Job:
    """The job with its artifacts and events loaded (detached)."""
    with session_factory(settings.sqlalchemy_url)() as session:
        job = session.get(Job, job_id)
        assert job is not None
        _ = list(job.artifacts), list(job.events)
        session.expunge(job)
        return job
