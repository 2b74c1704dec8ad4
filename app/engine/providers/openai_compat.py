"""OpenAI-compatible Chat Completions over httpx (OpenAI, gateways, vLLM, LM Studio, Ollama, local servers).

The request follows the model's profile (token-limit field, temperature, structured output)
and adapts when the endpoint rejects a parameter with HTTP 400: ``param: max_tokens`` ->
``max_completion_tokens``; ``param: temperature`` -> the model's default; a rejected
``response_format`` -> the next output mode (json_schema, json_object, text). What worked
is kept for the model's later calls. The reply's text comes from string or list-form
content, or from a tool call's arguments; ``finish_reason`` ``length`` and
``content_filter`` and a ``refusal`` become typed errors.
"""

from __future__ import annotations

import base64
import json
import logging
from typing import Any

from app.engine.errors import ProviderBlocked, ProviderError, ProviderResponseError, ReplyTruncated
from app.engine.providers.base import Message, ModelRequest, ModelResponse
from app.engine.providers.http import Exchange, Timeouts, make_client, post_json
from app.engine.providers.profiles import OUTPUT_MODES, ModelProfile, OutputMode
from app.engine.providers.schemas import json_schema
from app.engine.report import TokenUsage

logger = logging.getLogger(__name__)

MAX_ADAPTATIONS = 4


def _content(message: Message) -> str | list[dict[str, Any]]:
    if not message.images:
        return message.text
    parts: list[dict[str, Any]] = [{"type": "text", "text": message.text}]
    for image in message.images:
        parts.append({"type": "text", "text": f"[IMAGE] {image.name}"})
        parts.append({"type": "image_url", "image_url": {"url": "data:image/png;base64," + base64.b64encode(image.png).decode()}})
    return parts


def _text(message: dict[str, Any]) -> str:
    """String content, list-form content (text parts joined), or the first tool call's arguments."""
    content = message.get("content")
    if isinstance(content, list):
        content = "".join(str(p.get("text", "")) for p in content if isinstance(p, dict) and p.get("type") in ("text", "output_text", None))
    text = content if isinstance(content, str) else ""
    if not text.strip():
        for call in message.get("tool_calls") or []:
            arguments = (call.get("function") or {}).get("arguments") if isinstance(call, dict) else None
            if isinstance(arguments, str) and arguments.strip():
                return arguments
            if isinstance(arguments, dict):
                return json.dumps(arguments)
    return text


def _usage(data: dict[str, Any]) -> TokenUsage:
    usage: dict[str, Any] = data["usage"] if isinstance(data.get("usage"), dict) else {}
    return TokenUsage(input_tokens=int(usage.get("prompt_tokens") or 0), output_tokens=int(usage.get("completion_tokens") or 0))


class OpenAICompatibleModel:
    provider = "openai"

    def __init__(self, model: str, *, api_key: str | None, base_url: str, profile: ModelProfile | None = None,
                 timeouts: Timeouts | None = None, attempts: int = 4) -> None:
        self.model = model
        self.profile = profile or ModelProfile()
        self._key = api_key
        self._url = base_url.rstrip("/") + "/chat/completions"
        self._attempts = attempts
        self._timeouts = timeouts or Timeouts()
        self._token_param: str = self.profile.token_param
        self._temperature = self.profile.temperature
        self._mode: OutputMode = self.profile.output_mode
        self._client: Any = None  # created inside the running event loop

    def _payload(self, request: ModelRequest, mode: OutputMode) -> dict[str, Any]:
        messages: list[dict[str, Any]] = [{"role": "system", "content": request.system}]
        messages += [{"role": m.role, "content": _content(m)} for m in request.messages]
        payload: dict[str, Any] = {"model": self.model, "messages": messages,
                                   self._token_param: request.max_output_tokens or self.profile.max_output_tokens}
        if self._temperature is not None:
            payload["temperature"] = self._temperature
        if mode == "json_schema" and request.reply_model is not None:
            payload["response_format"] = {"type": "json_schema", "json_schema": {"name": request.reply_model.__name__,
                                                                                "schema": json_schema(request.reply_model), "strict": False}}
        elif mode in ("json_schema", "json_object"):
            payload["response_format"] = {"type": "json_object"}
        return payload

    def _adapt(self, error: ProviderResponseError, tried: list[OutputMode]) -> bool:
        """Change what the endpoint rejected (HTTP 400); False when there is nothing left to change."""
        if error.status != 400:
            return False
        if error.param == "max_tokens" and self._token_param == "max_tokens":
            self._token_param = "max_completion_tokens"
        elif error.param == "temperature" and self._temperature is not None:
            self._temperature = None
        elif error.param == "response_format" or "response_format" in error.message:  # servers without a structured 'param'
            remaining = [m for m in OUTPUT_MODES if m not in tried]
            if not remaining:
                return False
            self._mode = remaining[0]
        else:
            return False
        logger.warning("%s rejected a parameter (%s); retrying with %s=%s, temperature=%s, output=%s",
                       self.model, error.message[:120], "limit field", self._token_param, self._temperature, self._mode)
        return True

    async def complete(self, request: ModelRequest) -> ModelResponse:
        if self._client is None:
            self._client = make_client(self._timeouts)
        headers = {"Authorization": f"Bearer {self._key}"} if self._key else {}
        exchange = Exchange(url=self._url, headers=headers, provider=self.provider, secrets=(self._key,) if self._key else ())
        tried: list[OutputMode] = []
        for _ in range(MAX_ADAPTATIONS + 1):
            mode = self._mode
            tried.append(mode)
            try:
                data = await post_json(self._client, exchange, self._payload(request, mode), attempts=self._attempts, timeouts=self._timeouts)
                break
            except ProviderResponseError as exc:
                if not self._adapt(exc, tried):
                    raise
        else:  # pragma: no cover - each adaptation changes one of three settings
            raise ProviderError(f"{self.provider}: {self.model} rejected every request shape")
        try:
            return self._read(data, request, exchange, mode)
        except ProviderError as exc:
            exc.transport = tuple(exchange.attempts)
            exc.usage = _usage(data)
            raise

    def _read(self, data: dict[str, Any], request: ModelRequest, exchange: Exchange, mode: OutputMode) -> ModelResponse:
        try:
            choice = data["choices"][0]
            message = choice["message"]
        except (KeyError, IndexError, TypeError) as exc:
            raise ProviderResponseError(f"{self.provider}: reply has no choices[0].message") from exc
        finish = choice.get("finish_reason")
        tokens = _usage(data)
        text = _text(message if isinstance(message, dict) else {})
        limit = request.max_output_tokens or self.profile.max_output_tokens
        if finish == "length":
            raise ReplyTruncated(f"{self.provider}: {self.model} stopped at the output limit of {limit} tokens", limit=limit, partial=text)
        if finish == "content_filter":
            raise ProviderBlocked(f"{self.provider}: {self.model}'s reply was withheld by the content filter", reason="content_filter")
        refusal = message.get("refusal") if isinstance(message, dict) else None
        if isinstance(refusal, str) and refusal.strip():
            raise ProviderBlocked(f"{self.provider}: {self.model} refused: {refusal[:300]}", reason="refusal")
        if not text.strip():
            raise ProviderResponseError(f"{self.provider}: {self.model} sent an empty reply (finish_reason {finish!r})")
        seconds = sum(a.seconds for a in exchange.attempts if a.outcome == "ok")
        return ModelResponse(text=text, model=str(data.get("model") or self.model), usage=tokens, seconds=round(seconds, 6),
                             finish_reason=finish, output_mode=mode, transport=tuple(exchange.attempts))

    async def aclose(self) -> None:
        if self._client is not None:
            await self._client.aclose()
            self._client = None
