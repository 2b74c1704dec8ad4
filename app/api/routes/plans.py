"""``POST /v1/assets/{ref}/plan-check``: would this Plan.json run on this asset? (the page's editor)"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Path
from fastapi.concurrency import run_in_threadpool

from app.api.deps import ClientDep, SessionDep, SettingsDep, StorageDep
from app.api.errors import error_responses
from app.api.intake import asset_by_ref
from app.api.plan_jobs import PlanCheck, check_plan

router = APIRouter(prefix="/v1/assets", tags=["assets"])


@router.post("/{ref}/plan-check", response_model=PlanCheck, responses=error_responses(401, 404, 422, 429))
async def plan_check(
    client: ClientDep, session: SessionDep, settings: SettingsDep, storage: StorageDep,
    document: Annotated[Any, Body(description="a Plan.json document")],
    ref: Annotated[str, Path(min_length=1, max_length=100, description="asset id or sha256")],
) -> PlanCheck:
    """Check a plan against the asset without running it: schema and asset problems (each naming
    its field) and the warnings the executor would give."""
    asset = await run_in_threadpool(asset_by_ref, session, client=client, ref=ref)
    return await run_in_threadpool(check_plan, document, asset, storage, settings)
