"""The model interface every provider implements, and the request/response records."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

from pydantic import BaseModel

from app.engine.providers.profiles import ModelProfile, OutputMode
from app.engine.report import TokenUsage, TransportAttempt


@dataclass(frozen=True)
class Image:
    name: str
    png: bytes


@dataclass(frozen=True)
class Message:
    role: str
    """``user`` or ``assistant``."""
    text: str
    images: tuple[Image, ...] = ()


@dataclass(frozen=True)
class ModelRequest:
    system: str
    messages: tuple[Message, ...]
    reply_model: type[BaseModel] | None = None
    """Pydantic model of the expected reply (structured output: each provider writes its schema dialect); None for free text."""
    max_output_tokens: int | None = None
    """Output limit; None takes the model profile's."""


@dataclass(frozen=True)
class ModelResponse:
    text: str
    """The reply's text (list-form content joined; a tool call's arguments when the model answered with one)."""
    model: str
    usage: TokenUsage = field(default_factory=TokenUsage)
    seconds: float = 0.0
    finish_reason: str | None = None
    output_mode: OutputMode | None = None
    transport: tuple[TransportAttempt, ...] = ()


class ChatModel(Protocol):
    """One model endpoint.

    ``complete`` raises ProviderRateLimited / ProviderQuotaExceeded / ProviderTimeout /
    ProviderResponseError (ProviderBlocked for a refusal or block, ReplyTruncated at the
    output limit); each carries the transport attempts made.
    """

    provider: str
    model: str
    profile: ModelProfile

    async def complete(self, request: ModelRequest) -> ModelResponse: ...

    async def aclose(self) -> None: ...
