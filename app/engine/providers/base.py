"""The model interface every provider implements, and the request/response records."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

from app.engine.report import TokenUsage


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
    json_mode: bool = True
    temperature: float = 0.0
    max_output_tokens: int = 8192


@dataclass(frozen=True)
class ModelResponse:
    text: str
    model: str
    usage: TokenUsage = field(default_factory=TokenUsage)
    seconds: float = 0.0


class ChatModel(Protocol):
    """One model endpoint. ``complete`` raises ProviderRateLimited / ProviderTimeout / ProviderResponseError."""

    provider: str
    model: str

    async def complete(self, request: ModelRequest) -> ModelResponse: ...

    async def aclose(self) -> None: ...
