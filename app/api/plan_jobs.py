"""Jobs that run a given Plan.json: check it against the asset at submission, store it for the worker.

A plan job skips the perceiver, planner and critic: the worker
(:mod:`workers.plan_jobs`) executes the stored plan and exports the usual outputs. A plan
that does not parse or does not fit the asset is refused with 422 before any job exists,
each problem naming its field (``timeline[0].controls[1].joint: unknown joint ...``).
"""

from __future__ import annotations

import hashlib
import json
from pathlib import PurePosixPath
from typing import Any

from pydantic import BaseModel

from app.api.errors import PayloadTooLarge, Unprocessable
from app.api.uploads import MultipartForm
from app.core.config import Settings
from app.core.storage import Storage
from app.db.models import Asset
from app.engine.asset.cache import load_asset_cached
from app.engine.errors import PlanValidationError
from app.engine.plan.checks import validate_plan
from app.schemas.jobs import MAX_PLAN_CHARS

PLAN_OPTION = "plan_sha256"
"""Job option holding the stored plan's sha256 (``plans/<sha256>.json`` in storage)."""
SOURCE_OPTION = "source"
PLAN_LABEL = "(plan)"
"""The job's prompt text when a plan is sent without a label."""


class PlanCheck(BaseModel):
    """What ``POST /v1/assets/{ref}/plan-check`` found."""

    valid: bool
    issues: list[str]
    """Problems that make the plan unusable, each ``field.path: message``."""
    warnings: list[str]
    """Things the executor will adjust (clamped targets, conflicting target fields, extended duration)."""


def take_plan_file(form: MultipartForm) -> None:
    """A ``plan`` sent as a file part (``curl -F plan=@plan.json``) becomes the ``plan`` text field.

    Raises
    ------
    PayloadTooLarge
        The file is longer than :data:`MAX_PLAN_CHARS` bytes.
    Unprocessable
        It is not UTF-8 text, or ``plan`` came twice.
    """
    files = form.files_of("plan")
    if not files:
        return
    if len(files) > 1 or form.value("plan") is not None:
        raise Unprocessable("send one 'plan'", field="plan")
    if files[0].path.stat().st_size > MAX_PLAN_CHARS:
        raise PayloadTooLarge(f"the plan file is longer than {MAX_PLAN_CHARS} bytes", field="plan")
    try:
        form.fields["plan"] = [files[0].path.read_text(encoding="utf-8")]
    except UnicodeDecodeError as exc:
        raise Unprocessable("plan: the file is not UTF-8 text", field="plan") from exc


def plan_key(sha256: str) -> str:
    return f"plans/{sha256}.json"


def parse_plan_text(text: str) -> dict[str, Any]:
    """JSON text -> object, or a PlanValidationError naming the line and column."""
    try:
        value = json.loads(text)
    except json.JSONDecodeError as exc:
        raise PlanValidationError("plan is not valid JSON", issues=[f"line {exc.lineno} column {exc.colno}: {exc.msg}"]) from exc
    if not isinstance(value, dict):
        raise PlanValidationError("plan must be a JSON object", issues=[f"(document): found {type(value).__name__}"])
    return value


def check_plan(document: Any, asset: Asset, storage: Storage, settings: Settings) -> PlanCheck:
    """Validate ``document`` (parsed JSON) against the stored ``asset`` (blocking: run in a thread)."""
    model = load_asset_cached(storage.local_path(asset.storage_key), settings.engine_config().asset_cache_dir,
                              name=PurePosixPath(asset.filename).stem)
    try:
        checked = validate_plan(document, model)
    except PlanValidationError as exc:
        return PlanCheck(valid=False, issues=exc.issues or [exc.message], warnings=[])
    return PlanCheck(valid=True, issues=[], warnings=list(checked.warnings))


def accept_plan(text: str, asset: Asset, storage: Storage, settings: Settings) -> dict[str, Any]:
    """Check and store a submitted plan; returns the job options that point the worker at it.

    Raises
    ------
    Unprocessable
        The plan is not JSON, violates the schema, or does not fit the asset.
    """
    try:
        document = parse_plan_text(text)
    except PlanValidationError as exc:
        raise Unprocessable(f"plan: {exc.message}: {exc.issues[0]}", field="plan", issues=exc.issues) from exc
    result = check_plan(document, asset, storage, settings)
    if not result.valid:
        raise Unprocessable(f"plan: {result.issues[0]}", field="plan", issues=result.issues)
    data = json.dumps(document, indent=2, sort_keys=False).encode("utf-8") + b"\n"
    digest = hashlib.sha256(data).hexdigest()
    if not storage.exists(plan_key(digest)):
        storage.put_bytes(plan_key(digest), data)
    return {PLAN_OPTION: digest, SOURCE_OPTION: "plan"}
