"""``POST /v1/benchmarks``: a batch whose cases carry their annotation; ``GET /v1/batches/{id}/scores``."""

from __future__ import annotations

import uuid

from fastapi import APIRouter, Request, Response, status
from fastapi.concurrency import run_in_threadpool
from pydantic import BaseModel, ConfigDict, Field

from app.api.benchmark_scores import BatchScores, batch_scores, read_annotations, store_annotations
from app.api.deps import ClientDep, EnqueuerDep, SessionDep, SettingsDep, StorageDep
from app.api.errors import NotFound, PayloadTooLarge, Unprocessable, error_responses
from app.api.presenters import batch_public
from app.api.queue import dispatch_jobs
from app.crud.assets import find_assets_for_client
from app.crud.batches import BatchCase, create_batch, get_batch_for_client
from app.engine.metrics.annotation import Case
from app.schemas.batches import BatchPublic
from app.schemas.common import Name
from app.schemas.jobs import JobOptions

router = APIRouter(tags=["batches"])


class BenchmarkCreate(BaseModel):
    """Benchmark cases (``benchmark/cases/*.jsonl`` lines) whose ``asset`` is an uploaded asset's id or sha256."""

    model_config = ConfigDict(extra="forbid")

    name: Name | None = Field(default=None, max_length=200)
    options: JobOptions = Field(default_factory=JobOptions)
    cases: list[Case] = Field(min_length=1)


@router.post("/v1/benchmarks", status_code=status.HTTP_202_ACCEPTED, response_model=BatchPublic,
             responses=error_responses(401, 413, 422, 429, 503))
def create_benchmark(
    request: Request, response: Response, body: BenchmarkCreate, client: ClientDep, session: SessionDep,
    settings: SettingsDep, storage: StorageDep, enqueue: EnqueuerDep,
) -> BatchPublic:
    """Queue one job per case, keeping each case's annotation so the batch can be scored."""
    if len(body.cases) > settings.max_batch_cases:
        raise PayloadTooLarge(f"{len(body.cases)} cases, more than the limit of {settings.max_batch_cases}",
                              limit=settings.max_batch_cases)
    ids = [case.case_id for case in body.cases]
    if len(set(ids)) != len(ids):
        raise Unprocessable("case_id values must be unique within a benchmark")
    cases = []
    for index, case in enumerate(body.cases):
        found = find_assets_for_client(session, client=client, ref=case.asset)
        asset = found[0] if len(found) == 1 else None
        if asset is None:
            raise Unprocessable(f"cases[{index}].asset: no asset {case.asset!r} (upload it with POST /v1/assets first)", case=index)
        cases.append(BatchCase(asset=asset, prompt=case.prompt.strip(), case_id=case.case_id, options=body.options.stored()))
    batch = create_batch(session, client=client, cases=cases, name=body.name)
    store_annotations(storage, str(batch.id), body.cases)
    dispatch_jobs(session, batch.jobs, enqueue)
    session.refresh(batch)
    public = batch_public(request, batch)
    response.headers["Location"] = public.url
    return public


@router.get("/v1/batches/{batch_id}/scores", response_model=BatchScores, responses=error_responses(401, 404, 429))
async def get_batch_scores(
    batch_id: uuid.UUID, client: ClientDep, session: SessionDep, settings: SettingsDep, storage: StorageDep,
) -> BatchScores:
    """Per-case scores (P_gIoU, P_PC, P_OccF1) and key states, GT against the matched predicted frames."""
    batch = await run_in_threadpool(lambda: get_batch_for_client(session, batch_id=batch_id, client=client))
    if batch is None:
        raise NotFound(f"no batch {batch_id}")
    cases = await run_in_threadpool(read_annotations, storage, str(batch_id))
    if cases is None:
        raise NotFound(f"batch {batch_id} is not a benchmark batch (submit cases with POST /v1/benchmarks)")
    return await run_in_threadpool(batch_scores, batch, cases, storage, settings)
