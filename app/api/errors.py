"""The one place that maps failures to HTTP responses.

Routes raise :class:`ApiError` subclasses (or let an :class:`EngineError` escape); the
handlers registered by :func:`install_error_handlers` turn them into JSON bodies
``{"detail": message, "kind": name, ...context}``. Nothing else in the API chooses a status
code for an error.
"""

from __future__ import annotations

import json
import logging
from typing import Any

from fastapi import FastAPI, Request
from fastapi.encoders import jsonable_encoder
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from sqlalchemy.exc import DataError, OperationalError

from app.api.guards import BodyRefused
from app.core.storage import StorageError
from app.engine.errors import AssetError, EngineError, PlanValidationError, ProviderError
from app.schemas.common import ErrorPublic

logger = logging.getLogger(__name__)


class ApiError(Exception):
    """An error with a fixed HTTP status; ``headers`` are added to the response."""

    status_code = 400

    def __init__(self, detail: str, *, headers: dict[str, str] | None = None, **context: Any) -> None:
        super().__init__(detail)
        self.detail = detail
        self.headers = headers or {}
        self.context = context


class BadRequest(ApiError):
    status_code = 400


class Unauthorized(ApiError):
    status_code = 401

    def __init__(self, detail: str = "missing or invalid API key (send 'Authorization: Bearer KEY')") -> None:
        super().__init__(detail, headers={"WWW-Authenticate": "Bearer"})


class NotFound(ApiError):
    status_code = 404


class Conflict(ApiError):
    status_code = 409


class PayloadTooLarge(ApiError):
    status_code = 413


class UnsupportedMediaType(ApiError):
    status_code = 415


class Unprocessable(ApiError):
    status_code = 422


class RateLimited(ApiError):
    status_code = 429

    def __init__(self, limit: int, retry_after_s: int) -> None:
        super().__init__(
            f"rate limit of {limit} requests per minute exceeded; retry in {retry_after_s} s",
            headers={"Retry-After": str(retry_after_s)}, limit=limit, retry_after_s=retry_after_s,
        )


class TooManyJobs(ApiError):
    status_code = 429

    def __init__(self, active: int, adding: int, limit: int, *, retry_after_s: int = 30) -> None:
        super().__init__(
            f"you have {active} jobs queued or running and asked for {adding} more; the limit is {limit} per API key: "
            "wait for some to finish (or cancel them)",
            headers={"Retry-After": str(retry_after_s)}, active=active, limit=limit,
        )


class Forbidden(ApiError):
    status_code = 403


class DamagedData(ApiError):
    """Stored bytes that no longer match their record: the server's fault, said plainly."""

    status_code = 500


class ServiceUnavailable(ApiError):
    status_code = 503

    def __init__(self, detail: str, *, retry_after_s: int = 5) -> None:
        super().__init__(detail, headers={"Retry-After": str(retry_after_s)})


ENGINE_STATUS: tuple[tuple[type[EngineError], int], ...] = (
    (AssetError, 422),
    (PlanValidationError, 422),
    (ProviderError, 422),
    (EngineError, 422),
)
"""Engine errors reaching the API come from validating the caller's input: all 422."""


def error_responses(*codes: int) -> dict[int | str, dict[str, Any]]:
    """OpenAPI ``responses`` entries documenting error bodies for ``codes``."""
    return {code: {"model": ErrorPublic} for code in codes}


class ErrorResponse(JSONResponse):
    """JSON rendered as ASCII: an echoed input holding a lone surrogate cannot break the response."""

    def render(self, content: Any) -> bytes:
        return json.dumps(content, ensure_ascii=True, allow_nan=False, separators=(",", ":")).encode("ascii")


def _body(detail: str, kind: str, context: dict[str, Any]) -> dict[str, Any]:
    body: dict[str, Any] = {"detail": detail, "kind": kind}
    body.update({key: value for key, value in context.items() if value is not None})
    return body


async def _api_error(_request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, ApiError)
    return ErrorResponse(_body(exc.detail, type(exc).__name__, exc.context), status_code=exc.status_code, headers=exc.headers)


async def _engine_error(_request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, EngineError)
    status = next(code for kind, code in ENGINE_STATUS if isinstance(exc, kind))
    context = {key: value for key, value in exc.context.items() if isinstance(value, str | int | float | list)}
    return ErrorResponse(_body(str(exc), type(exc).__name__, context), status_code=status)


async def _database_unavailable(_request: Request, exc: Exception) -> JSONResponse:
    logger.error("database unavailable: %s", exc)
    return ErrorResponse(_body("database unavailable, retry later", "ServiceUnavailable", {}), status_code=503,
                        headers={"Retry-After": "5"})


async def _database_refused_value(_request: Request, exc: Exception) -> JSONResponse:
    """Backstop: a value the schemas let through but the database cannot store (a bug to fix there)."""
    logger.warning("database refused a value: %s", exc)
    return ErrorResponse(_body("a value in the request cannot be stored", "InvalidValue", {}), status_code=422)


async def _body_refused(_request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, BodyRefused)
    return ErrorResponse(_body(str(exc.detail), exc.kind, {}), status_code=exc.status_code, headers={"Connection": "close"})


async def _storage_error(_request: Request, exc: Exception) -> JSONResponse:
    """Stored bytes missing or damaged: the server's fault, not the caller's input."""
    logger.error("storage: %s", exc)
    detail = f"{exc}; if it is an asset, upload the same file again to restore it"
    return ErrorResponse(_body(detail, "StorageError", {}), status_code=500)


MAX_ECHO_CHARS = 100
UUID_EXAMPLE = "123e4567-e89b-12d3-a456-426614174000"


def _validation_error(error: dict[str, Any]) -> dict[str, Any]:
    """One validation error without the rejected input (never echoed back), with a plain message for ids."""
    loc = [part if isinstance(part, int) else str(part)[:MAX_ECHO_CHARS] for part in error.get("loc", ())]
    message = str(error.get("msg", "invalid value"))[:500]
    if error.get("type") == "uuid_parsing" and loc[:1] == ["path"]:
        message = f"{loc[-1]} must be a UUID such as {UUID_EXAMPLE}"
    context = {k: v for k, v in (error.get("ctx") or {}).items() if isinstance(v, str | int | float) and k != "input"}
    cleaned: dict[str, Any] = {"type": str(error.get("type", "value_error")), "loc": loc, "msg": message}
    if context:
        cleaned["ctx"] = {k: (v[:MAX_ECHO_CHARS] if isinstance(v, str) else v) for k, v in context.items()}
    return cleaned


async def _invalid_request(_request: Request, exc: Exception) -> JSONResponse:
    """FastAPI's 422 body (``detail`` = list of errors), without echoing the input, rendered safely."""
    assert isinstance(exc, RequestValidationError)
    return ErrorResponse({"detail": jsonable_encoder([_validation_error(dict(e)) for e in exc.errors()])}, status_code=422)


def install_error_handlers(app: FastAPI) -> None:
    app.add_exception_handler(RequestValidationError, _invalid_request)
    app.add_exception_handler(ApiError, _api_error)
    app.add_exception_handler(EngineError, _engine_error)
    app.add_exception_handler(OperationalError, _database_unavailable)
    app.add_exception_handler(DataError, _database_refused_value)
    app.add_exception_handler(StorageError, _storage_error)
    app.add_exception_handler(BodyRefused, _body_refused)
