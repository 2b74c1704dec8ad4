"""OpenAI-compatible Chat Completions over httpx (OpenAI, Azure-compatible gateways, vLLM, local servers)."""

from __future__ import annotations

import base64
from typing import Any

from app.engine.errors import ProviderResponseError
from app.engine.providers.base import Message, ModelRequest, ModelResponse
from app.engine.providers.http import make_client, post_json
from app.engine.report import TokenUsage


def _content(message: Message) -> str | list[dict[str, Any]]:
    if not message.images:
        return message.text
    parts: list[dict[str, Any]] = [{"type": "text", "text": message.text}]
    for image in message.images:
        parts.append({"type": "text", "text": f"[IMAGE] {image.name}"})
        parts.append({"type": "image_url", "image_url": {"url": "data:image/png;base64," + base64.b64encode(image.png).decode()}})
    return parts


class OpenAICompatibleModel:
    provider = "openai"

    def __init__(self, model: str, *, api_key: str | None, base_url: str, timeout_s: float = 120.0, attempts: int = 4) -> None:
        self.model = model
        self._key = api_key
        self._url = base_url.rstrip("/") + "/chat/completions"
        self._attempts = attempts
        self._timeout = timeout_s
        self._client: Any = None  # created inside the running event loop

    async def complete(self, request: ModelRequest) -> ModelResponse:
        messages: list[dict[str, Any]] = [{"role": "system", "content": request.system}]
        messages += [{"role": m.role, "content": _content(m)} for m in request.messages]
        payload: dict[str, Any] = {"model": self.model, "messages": messages, "temperature": request.temperature, "max_tokens": request.max_output_tokens}
        if request.json_mode:
            payload["response_format"] = {"type": "json_object"}
        headers = {"Authorization": f"Bearer {self._key}"} if self._key else {}
        if self._client is None:
            self._client = make_client(self._timeout)
        data, seconds = await post_json(self._client, self._url, payload, headers, provider=self.provider, attempts=self._attempts)
        try:
            text = data["choices"][0]["message"]["content"]
        except (KeyError, IndexError, TypeError) as exc:
            raise ProviderResponseError(f"{self.provider}: reply has no choices[0].message.content") from exc
        if not isinstance(text, str):
            raise ProviderResponseError(f"{self.provider}: message content is not text")
        usage = data.get("usage") or {}
        tokens = TokenUsage(input_tokens=int(usage.get("prompt_tokens") or 0), output_tokens=int(usage.get("completion_tokens") or 0))
        return ModelResponse(text=text, model=str(data.get("model") or self.model), usage=tokens, seconds=seconds)

    async def aclose(self) -> None:
        if self._client is not None:
            await self._client.aclose()
            self._client = None
