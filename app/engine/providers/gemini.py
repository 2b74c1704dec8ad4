"""Gemini ``generateContent`` over httpx (API key header, inline PNG parts, JSON response mode)."""

from __future__ import annotations

import base64
from typing import Any

from app.engine.errors import ProviderResponseError
from app.engine.providers.base import Message, ModelRequest, ModelResponse
from app.engine.providers.http import make_client, post_json
from app.engine.report import TokenUsage


def _parts(message: Message) -> list[dict[str, Any]]:
    parts: list[dict[str, Any]] = [{"text": message.text}]
    for image in message.images:
        parts.append({"text": f"[IMAGE] {image.name}"})
        parts.append({"inlineData": {"mimeType": "image/png", "data": base64.b64encode(image.png).decode()}})
    return parts


class GeminiModel:
    provider = "gemini"

    def __init__(self, model: str, *, api_key: str | None, base_url: str, timeout_s: float = 120.0, attempts: int = 4) -> None:
        self.model = model
        self._key = api_key
        self._url = f"{base_url.rstrip('/')}/models/{model}:generateContent"
        self._attempts = attempts
        self._timeout = timeout_s
        self._client: Any = None  # created inside the running event loop

    async def complete(self, request: ModelRequest) -> ModelResponse:
        config: dict[str, Any] = {"temperature": request.temperature, "maxOutputTokens": request.max_output_tokens}
        if request.json_mode:
            config["responseMimeType"] = "application/json"
        payload = {
            "systemInstruction": {"parts": [{"text": request.system}]},
            "contents": [{"role": "model" if m.role == "assistant" else "user", "parts": _parts(m)} for m in request.messages],
            "generationConfig": config,
        }
        headers = {"x-goog-api-key": self._key} if self._key else {}
        if self._client is None:
            self._client = make_client(self._timeout)
        data, seconds = await post_json(self._client, self._url, payload, headers, provider=self.provider, attempts=self._attempts)
        try:
            parts = data["candidates"][0]["content"]["parts"]
            text = "".join(p.get("text", "") for p in parts)
        except (KeyError, IndexError, TypeError, AttributeError) as exc:
            raise ProviderResponseError(f"{self.provider}: reply has no candidates[0].content.parts") from exc
        usage = data.get("usageMetadata") or {}
        tokens = TokenUsage(input_tokens=int(usage.get("promptTokenCount") or 0), output_tokens=int(usage.get("candidatesTokenCount") or 0))
        return ModelResponse(text=text, model=self.model, usage=tokens, seconds=seconds)

    async def aclose(self) -> None:
        if self._client is not None:
            await self._client.aclose()
            self._client = None
