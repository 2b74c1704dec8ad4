"""Shared pieces of the API schemas."""

from __future__ import annotations

from datetime import UTC, datetime
from typing import Annotated, Any

from pydantic import AfterValidator, BaseModel


def _aware(value: datetime) -> datetime:
    """SQLite returns naive datetimes; every stored time is UTC."""
    return value if value.tzinfo is not None else value.replace(tzinfo=UTC)


UtcDatetime = Annotated[datetime, AfterValidator(_aware)]


def _no_nul(value: str) -> str:
    if "\x00" in value:
        raise ValueError("must not contain NUL characters")
    return value


def _no_control(value: str) -> str:
    if any(ord(char) < 32 or ord(char) == 127 for char in value):
        raise ValueError("must not contain control characters")
    return value


Text = Annotated[str, AfterValidator(_no_nul)]
"""Free text (prompts): anything a database can store (no NUL)."""
Name = Annotated[str, AfterValidator(_no_control)]
"""Identifiers and labels (model names, case ids): no control characters."""


class ErrorPublic(BaseModel):
    """Body of every error response (plus context fields such as ``file``/``element``)."""

    detail: str | list[dict[str, Any]]
    kind: str | None = None
