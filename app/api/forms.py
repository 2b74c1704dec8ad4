"""Multipart request plumbing shared by the upload routes: temp folder, form reading, OpenAPI body."""

from __future__ import annotations

import shutil
import tempfile
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Any, TypeVar

from fastapi import Request
from fastapi.concurrency import run_in_threadpool
from fastapi.exceptions import RequestValidationError
from pydantic import BaseModel, ValidationError

from app.api.uploads import MultipartForm, UploadLimits, read_multipart
from app.core.config import Settings

M = TypeVar("M", bound=BaseModel)

INT_FIELDS = ("fps", "max_critic_rounds")
"""Form fields that arrive as text but are integers in the schema."""


@asynccontextmanager
async def upload_folder(settings: Settings) -> AsyncIterator[Path]:
    """A private temporary folder on the data volume, removed afterwards."""
    root = settings.data_dir / "uploads"
    root.mkdir(parents=True, exist_ok=True)
    folder = Path(tempfile.mkdtemp(prefix="upload-", dir=root))
    try:
        yield folder
    finally:
        await run_in_threadpool(shutil.rmtree, folder, True)


async def read_form(request: Request, settings: Settings, folder: Path) -> MultipartForm:
    limits = UploadLimits(max_bytes=settings.max_upload_bytes, max_files=settings.max_upload_files)
    return await read_multipart(request, limits, folder)


def _coerce(name: str, value: str) -> str | int:
    if name in INT_FIELDS:
        try:
            return int(value.strip())
        except ValueError:
            return value
    return value


def validate_fields(model: type[M], form: MultipartForm, names: tuple[str, ...]) -> M:
    """Build ``model`` from the text fields ``names`` (empty values count as absent).

    Raises
    ------
    RequestValidationError
        Like FastAPI's own body validation (422, ``loc`` = ``["body", field]``).
    """
    data: dict[str, Any] = {}
    for name in names:
        value = form.value(name)
        if value is not None and value != "":
            data[name] = _coerce(name, value)
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        errors = exc.errors(include_url=False, include_context=False, include_input=False)
        raise RequestValidationError([{**e, "loc": ("body", *e["loc"])} for e in errors]) from exc


def multipart_openapi(properties: dict[str, Any], required: list[str]) -> dict[str, Any]:
    """``openapi_extra`` describing a multipart body the route reads itself (streaming)."""
    schema = {"type": "object", "properties": properties, "required": required}
    return {"requestBody": {"required": True, "content": {"multipart/form-data": {"schema": schema}}}}


MAX_URDF_FIELD_CHARS = 500
URDF_FIELD_SCHEMA: dict[str, Any] = {
    "type": "string", "maxLength": MAX_URDF_FIELD_CHARS,
    "description": "which URDF to use when the asset holds several: its path inside the asset, or its file name",
}


def urdf_field(form: MultipartForm) -> str | None:
    """The ``urdf`` text field (absent or blank: ``None``).

    Raises
    ------
    RequestValidationError
        Longer than :data:`MAX_URDF_FIELD_CHARS` or holding control characters.
    """
    value = (form.value("urdf") or "").strip()
    if not value:
        return None
    if len(value) > MAX_URDF_FIELD_CHARS or any(ord(char) < 32 for char in value):
        raise RequestValidationError([{"type": "value_error", "loc": ("body", "urdf"),
                                       "msg": f"a file path of at most {MAX_URDF_FIELD_CHARS} printable characters"}])
    return value


ASSET_FILES_SCHEMA: dict[str, Any] = {
    "type": "array",
    "items": {"type": "string", "format": "binary"},
    "description": "one .zip of the asset folder, or the URDF and its mesh files (names may hold sub-folders)",
}
