"""Gemini ``generateContent`` over httpx (API key header, inline PNG parts, structured output).

Structured output: ``responseMimeType: application/json`` plus ``responseSchema`` (mode
``json_schema``), the MIME type alone (``json_object``) or neither (``text``); a 400 that
names the schema falls back to the next mode. Thinking models get the profile's
``thinkingConfig.thinkingBudget``; thinking counts against ``maxOutputTokens``, so a reply
that stops at ``MAX_TOKENS`` (with or without parts) is a :class:`ReplyTruncated` and is
asked again with more room. ``promptFeedback.blockReason`` and safety finish reasons
become :class:`ProviderBlocked` with the reason; thought parts are skipped.
"""

from __future__ import annotations

import base64
import json
import logging
from typing import Any
from urllib.parse import quote

from app.engine.errors import ProviderBlocked, ProviderError, ProviderResponseError, ReplyTruncated
from app.engine.providers.base import Message, ModelRequest, ModelResponse
from app.engine.providers.http import Exchange, Timeouts, make_client, post_json
from app.engine.providers.names import valid_model_name
from app.engine.providers.profiles import OUTPUT_MODES, ModelProfile, OutputMode
from app.engine.providers.schemas import gemini_schema
from app.engine.report import TokenUsage

logger = logging.getLogger(__name__)

BLOCKING_FINISH = {"SAFETY", "RECITATION", "BLOCKLIST", "PROHIBITED_CONTENT", "SPII", "LANGUAGE", "IMAGE_SAFETY", "OTHER"}
MAX_ADAPTATIONS = 3


def _parts(message: Message) -> list[dict[str, Any]]:
    parts: list[dict[str, Any]] = [{"text": message.text}]
    for image in message.images:
        parts.append({"text": f"[IMAGE] {image.name}"})
        parts.append({"inlineData": {"mimeType": "image/png", "data": base64.b64encode(image.png).decode()}})
    return parts


def _usage(data: dict[str, Any]) -> TokenUsage:
    usage: dict[str, Any] = data["usageMetadata"] if isinstance(data.get("usageMetadata"), dict) else {}
    output = int(usage.get("candidatesTokenCount") or 0) + int(usage.get("thoughtsTokenCount") or 0)
    return TokenUsage(input_tokens=int(usage.get("promptTokenCount") or 0), output_tokens=output)


def _text(parts: list[Any]) -> str:
    """Answer text of the parts (thought parts skipped; a function call's args when that is all there is)."""
    text = "".join(str(p.get("text", "")) for p in parts if isinstance(p, dict) and not p.get("thought"))
    if text.strip():
        return text
    for part in parts:
        call = part.get("functionCall") if isinstance(part, dict) else None
        if isinstance(call, dict) and isinstance(call.get("args"), dict):
            return json.dumps(call["args"])
    return text


class GeminiModel:
    provider = "gemini"

    def __init__(self, model: str, *, api_key: str | None, base_url: str, profile: ModelProfile | None = None,
                 timeouts: Timeouts | None = None, attempts: int = 4) -> None:
        if not valid_model_name(model):
            raise ProviderError(f"invalid Gemini model name {model[:100]!r}: letters, digits and . _ : @ + - in /-separated segments")
        self.model = model
        self.profile = profile or ModelProfile()
        self._key = api_key
        # one escaped path segment as well as checked above: nothing in a name can leave models/ or add a query
        self._url = f"{base_url.rstrip('/')}/models/{quote(model, safe='')}:generateContent"
        self._attempts = attempts
        self._timeouts = timeouts or Timeouts()
        self._mode: OutputMode = self.profile.output_mode
        self._client: Any = None  # created inside the running event loop

    def _payload(self, request: ModelRequest, mode: OutputMode) -> dict[str, Any]:
        config: dict[str, Any] = {"maxOutputTokens": request.max_output_tokens or self.profile.max_output_tokens}
        if self.profile.temperature is not None:
            config["temperature"] = self.profile.temperature
        if self.profile.thinking_budget is not None:
            config["thinkingConfig"] = {"thinkingBudget": self.profile.thinking_budget}
        if mode in ("json_schema", "json_object"):
            config["responseMimeType"] = "application/json"
        if mode == "json_schema" and request.reply_model is not None:
            config["responseSchema"] = gemini_schema(request.reply_model)
        return {
            "systemInstruction": {"parts": [{"text": request.system}]},
            "contents": [{"role": "model" if m.role == "assistant" else "user", "parts": _parts(m)} for m in request.messages],
            "generationConfig": config,
        }

    async def complete(self, request: ModelRequest) -> ModelResponse:
        if self._client is None:
            self._client = make_client(self._timeouts)
        headers = {"x-goog-api-key": self._key} if self._key else {}
        exchange = Exchange(url=self._url, headers=headers, provider=self.provider, secrets=(self._key,) if self._key else ())
        tried: list[OutputMode] = []
        for _ in range(MAX_ADAPTATIONS + 1):
            mode = self._mode
            tried.append(mode)
            try:
                data = await post_json(self._client, exchange, self._payload(request, mode), attempts=self._attempts, timeouts=self._timeouts)
                break
            except ProviderResponseError as exc:
                remaining = [m for m in OUTPUT_MODES if m not in tried]
                if exc.status != 400 or not remaining or not any(k in exc.message for k in ("responseSchema", "response_schema", "responseMimeType")):
                    raise
                logger.warning("%s rejected the output mode %s (%s); trying %s", self.model, mode, exc.message[:120], remaining[0])
                self._mode = remaining[0]
        else:  # pragma: no cover
            raise ProviderError(f"{self.provider}: {self.model} rejected every request shape")
        try:
            return self._read(data, request, exchange, mode)
        except ProviderError as exc:
            exc.transport = tuple(exchange.attempts)
            exc.usage = _usage(data)
            raise

    def _read(self, data: dict[str, Any], request: ModelRequest, exchange: Exchange, mode: OutputMode) -> ModelResponse:
        feedback: dict[str, Any] = data["promptFeedback"] if isinstance(data.get("promptFeedback"), dict) else {}
        if feedback.get("blockReason"):
            reason = str(feedback["blockReason"])
            raise ProviderBlocked(f"{self.provider}: the prompt was blocked ({reason})", reason=reason)
        candidates = data.get("candidates")
        if not isinstance(candidates, list) or not candidates or not isinstance(candidates[0], dict):
            raise ProviderResponseError(f"{self.provider}: reply has no candidates")
        candidate = candidates[0]
        finish = candidate.get("finishReason")
        parts = (candidate.get("content") or {}).get("parts") or []
        text = _text(parts if isinstance(parts, list) else [])
        limit = request.max_output_tokens or self.profile.max_output_tokens
        if finish == "MAX_TOKENS":
            why = "" if text.strip() else " (thinking used all of it; no answer parts)"
            raise ReplyTruncated(f"{self.provider}: {self.model} stopped at the output limit of {limit} tokens{why}", limit=limit, partial=text)
        if finish in BLOCKING_FINISH:
            raise ProviderBlocked(f"{self.provider}: {self.model} stopped: {finish}", reason=str(finish))
        if not text.strip():
            raise ProviderResponseError(f"{self.provider}: {self.model} sent no answer parts (finishReason {finish!r})")
        seconds = sum(a.seconds for a in exchange.attempts if a.outcome == "ok")
        return ModelResponse(text=text, model=str(data.get("modelVersion") or self.model), usage=_usage(data), seconds=round(seconds, 6),
                             finish_reason=finish, output_mode=mode, transport=tuple(exchange.attempts))

    async def aclose(self) -> None:
        if self._client is not None:
            await self._client.aclose()
            self._client = None
