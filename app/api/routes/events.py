"""``GET /v1/animations/{id}/events``: a job's progress as server-sent events.

Each change of status, stage or progress is one ``event: job`` whose data is the job's
status record (as ``GET /v1/animations/{id}`` minus the output list); the stream ends with
``event: end`` once the job has finished, or after :data:`STREAM_S` seconds (the client
reconnects: ``retry`` tells it when). The stream holds no database connection between
its polls (one short session per poll), and the admission limit does not count it.
"""

from __future__ import annotations

import asyncio
import json
import time
import uuid
from collections.abc import AsyncIterator
from typing import Any

from fastapi import APIRouter, Request
from fastapi.concurrency import run_in_threadpool
from fastapi.responses import StreamingResponse
from sqlalchemy.orm import Session

from app.api.deps import ClientDep, SessionDep, SettingsDep
from app.api.errors import NotFound, error_responses
from app.crud import jobs as crud_jobs
from app.db.models import TERMINAL, ApiClient, Job, JobStatus
from app.db.session import session_factory

router = APIRouter(prefix="/v1/animations", tags=["animations"])

POLL_S = 0.25
HEARTBEAT_S = 10.0
STREAM_S = 25.0
RETRY_MS = 500
STATE_FIELDS = ("status", "stage", "progress", "cancel_requested", "error", "error_kind")


def _state(job: Job) -> dict[str, Any]:
    return {
        "id": str(job.id), "status": str(JobStatus(job.status)), "stage": job.stage,
        "progress": min(max(job.progress, 0), 100), "cancel_requested": job.cancel_requested,
        "error": job.error, "error_kind": job.error_kind, "timings": dict(job.timings or {}),
    }


def _owned_state(session: Session, job_id: uuid.UUID, client: ApiClient) -> dict[str, Any]:
    job = crud_jobs.get_job_for_client(session, job_id=job_id, client=client)
    if job is None:
        raise NotFound(f"no animation job {job_id}")
    state = _state(job)
    session.close()  # the stream polls with its own short sessions
    return state


def _read_state(url: str, job_id: uuid.UUID) -> dict[str, Any] | None:
    with session_factory(url)() as session:
        job = crud_jobs.get_job(session, job_id=job_id)
        return None if job is None else _state(job)


def _event(name: str, data: dict[str, Any]) -> str:
    return f"event: {name}\ndata: {json.dumps(data, separators=(',', ':'))}\n\n"


async def _stream(request: Request, url: str, job_id: uuid.UUID, first: dict[str, Any]) -> AsyncIterator[str]:
    yield f"retry: {RETRY_MS}\n\n"
    state: dict[str, Any] | None = first
    sent: tuple[Any, ...] | None = None
    began = last_write = time.monotonic()
    while state is not None:
        key = tuple(state[name] for name in STATE_FIELDS)
        if key != sent:
            sent, last_write = key, time.monotonic()
            yield _event("job", state)
        if JobStatus(state["status"]) in TERMINAL:
            yield _event("end", {"status": state["status"]})
            return
        now = time.monotonic()
        if now - began > STREAM_S or await request.is_disconnected():
            return
        if now - last_write > HEARTBEAT_S:
            last_write = now
            yield ": keep-alive\n\n"
        await asyncio.sleep(POLL_S)
        state = await run_in_threadpool(_read_state, url, job_id)
    yield _event("end", {"status": "gone"})


@router.get(
    "/{job_id}/events",
    response_class=StreamingResponse,
    responses={200: {"content": {"text/event-stream": {}}, "description": "job events"}, **error_responses(401, 404, 429)},
)
async def job_events(request: Request, job_id: uuid.UUID, client: ClientDep, session: SessionDep, settings: SettingsDep) -> StreamingResponse:
    """Server-sent events with the job's status, stage and progress until it finishes."""
    first = await run_in_threadpool(_owned_state, session, job_id, client)
    return StreamingResponse(
        _stream(request, settings.sqlalchemy_url, job_id, first), media_type="text/event-stream",
        headers={"Cache-Control": "no-store", "X-Accel-Buffering": "no"},
    )
