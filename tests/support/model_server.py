"""A local model server that answers the way real models do, good days and bad (the only fake we use).

Speaks both wire formats: OpenAI Chat Completions (``POST /v1/chat/completions``) and
Gemini ``generateContent`` (``POST /v1beta/models/<model>:generateContent``). The role is
read from the system prompt ("You are the perceiver ..."). Replies come from a script:
a list of items per role, consumed in order (the last repeats); an item
``{"match": s, ...}`` is used once, for the first request whose body contains ``s``.

An item is a reply text (sent as is) or a dict:

- ``{"text": T, "shape": S}``: T wrapped like real models wrap JSON. Shapes: ``plain``,
  ``fenced`` (Markdown fence), ``prose`` (a sentence before and after a fence),
  ``think`` (a ``<think>`` block first, with a stray brace in it), ``comments``
  (``//`` comments and trailing commas), ``list`` (OpenAI list-form content),
  ``tool`` (the JSON as a tool call's arguments, no content);
- ``{"text": T, "needs_tokens": N}``: the model needs N output tokens; a request whose
  output limit (``max_tokens`` / ``max_completion_tokens`` / ``maxOutputTokens``) is
  smaller gets the first part of T and ``finish_reason: length`` / ``MAX_TOKENS`` (for a
  Gemini thinking model with ``thinking_tokens``, no parts at all);
- ``{"status": 429}`` (rate limit, ``Retry-After: 0``), ``{"status": 429, "quota": true}``
  (OpenAI ``insufficient_quota`` / Gemini per-day ``QuotaFailure``), ``{"status": 500}``,
  ``{"status": 400, "body": {...}}``;
- ``{"stall_s": x, ...}``: wait x seconds, then answer with the rest of the item;
- ``{"block": R}``: OpenAI ``finish_reason: content_filter`` / Gemini ``promptFeedback.blockReason: R``;
  ``{"refusal": text}``: an OpenAI structured-output refusal.

Server-wide behaviour (constructor flags): ``reasoning_models`` answer HTTP 400 to
``max_tokens`` and to a temperature other than 1 (as gpt-5 / o-series do);
``rejects_json_object`` answers 400 to ``response_format: json_object`` (as LM Studio does);
``thinking_tokens`` is what a Gemini 2.5 model spends thinking (counted against
``maxOutputTokens``). Every request is recorded (role, path, payload, auth header).
"""

from __future__ import annotations

import json
import re
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

ROLES = ("perceiver", "planner", "critic", "coverage")
FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "responses"
CHARS_PER_TOKEN = 4


def shaped(text: str, shape: str) -> tuple[str | list[dict[str, Any]] | None, list[dict[str, Any]] | None]:
    """(content, tool_calls) of ``text`` in a real model's ``shape``."""
    fence = f"```json\n{text.strip()}\n```"
    if shape == "fenced":
        return fence, None
    if shape == "prose":
        return f"Sure! Here is the JSON object for this object and action:\n\n{fence}\n\nLet me know if you need changes.", None
    if shape == "think":
        return f"<think>\nThe user wants JSON like {{\"a\": 1 ... I should check the limits first.\n</think>\n\n{text}", None
    if shape == "comments":
        body = text.strip()
        body = body[:1] + "\n  // answer follows\n" + body[1:-1].rstrip() + ",\n}"
        return f"```json\n{body}\n```", None
    if shape == "list":
        middle = len(text) // 2
        return [{"type": "text", "text": text[:middle]}, {"type": "text", "text": text[middle:]}], None
    if shape == "tool":
        return None, [{"id": "call_1", "type": "function", "function": {"name": "reply", "arguments": text}}]
    return text, None


@dataclass
class Script:
    replies: dict[str, list[Any]]
    reasoning_models: frozenset[str] = frozenset()
    rejects_json_object: bool = False
    thinking_tokens: int = 0
    requests: list[dict[str, Any]] = field(default_factory=list)
    cursor: dict[str, int] = field(default_factory=dict)
    used: set[int] = field(default_factory=set)
    lock: threading.Lock = field(default_factory=threading.Lock)

    def next(self, role: str, text: str) -> Any:
        with self.lock:
            items = self.replies.get(role) or ['{"error": "no recorded reply for ' + role + '"}']
            for item in items:
                if isinstance(item, dict) and "match" in item and id(item) not in self.used and item["match"] in text:
                    self.used.add(id(item))
                    return {k: v for k, v in item.items() if k != "match"} if "reply" not in item else item["reply"]
            plain = [item for item in items if not (isinstance(item, dict) and "match" in item)] or ["{}"]
            index = self.cursor.get(role, 0)
            self.cursor[role] = index + 1
            return plain[min(index, len(plain) - 1)]

    def of(self, role: str) -> list[dict[str, Any]]:
        return [r for r in self.requests if r["role"] == role]


def _role(payload: dict[str, Any]) -> str:
    system = next((m.get("content", "") for m in payload.get("messages", []) if m.get("role") == "system"), "")
    system = system or json.dumps(payload.get("systemInstruction", ""))
    match = re.search(r"you are the (?:\w+ )?(perceiver|planner|critic|coverage)", str(system).lower())
    return match.group(1) if match else "unknown"


def _limit(payload: dict[str, Any]) -> int | None:
    config = payload.get("generationConfig") or {}
    value = payload.get("max_completion_tokens", payload.get("max_tokens", config.get("maxOutputTokens")))
    return int(value) if value is not None else None


def _openai_error(script: Script, payload: dict[str, Any]) -> dict[str, Any] | None:
    model = str(payload.get("model", ""))
    if any(model.startswith(name) for name in script.reasoning_models):
        if "max_tokens" in payload:
            return {"error": {"message": "Unsupported parameter: 'max_tokens' is not supported with this model. Use 'max_completion_tokens' instead.",
                              "type": "invalid_request_error", "param": "max_tokens", "code": "unsupported_parameter"}}
        if payload.get("temperature", 1) != 1:
            return {"error": {"message": f"Unsupported value: 'temperature' does not support {payload['temperature']} with this model. Only the default (1) value is supported.",
                              "type": "invalid_request_error", "param": "temperature", "code": "unsupported_value"}}
    if script.rejects_json_object and (payload.get("response_format") or {}).get("type") == "json_object":
        return {"error": "'response_format.type' must be 'json_schema' or 'text'"}
    return None


def _handler(script: Script) -> type[BaseHTTPRequestHandler]:
    class Handler(BaseHTTPRequestHandler):
        protocol_version = "HTTP/1.1"

        def log_message(self, *args: Any) -> None:
            pass

        def _send(self, status: int, body: dict[str, Any], headers: dict[str, str] | None = None) -> None:
            data = json.dumps(body).encode()
            self.send_response(status)
            self.send_header("Content-Type", "application/json")
            self.send_header("Content-Length", str(len(data)))
            for key, value in (headers or {}).items():
                self.send_header(key, value)
            self.end_headers()
            self.wfile.write(data)

        def do_POST(self) -> None:
            length = int(self.headers.get("Content-Length", 0))
            payload = json.loads(self.rfile.read(length) or b"{}")
            role = _role(payload)
            gemini = ":generateContent" in self.path
            script.requests.append({"role": role, "path": self.path, "payload": payload,
                                    "auth": self.headers.get("Authorization") or self.headers.get("x-goog-api-key")})
            if not (self.path.endswith("/chat/completions") or gemini):
                self._send(404, {"error": {"message": "unknown path"}})
                return
            if not gemini:
                rejected = _openai_error(script, payload)
                if rejected is not None:
                    self._send(400, rejected)
                    return
            item = script.next(role, json.dumps(payload))
            if isinstance(item, dict) and "stall_s" in item:
                time.sleep(item["stall_s"])
                item = item["reply"] if "reply" in item else {k: v for k, v in item.items() if k != "stall_s"}
            try:
                self._answer(item if isinstance(item, dict) else {"text": item}, payload, gemini)
            except (BrokenPipeError, ConnectionResetError):  # the client gave up waiting (a stall test)
                pass

        def _answer(self, item: dict[str, Any], payload: dict[str, Any], gemini: bool) -> None:
            if "status" in item:
                self._status(item, gemini)
                return
            tokens_in = len(json.dumps(payload)) // CHARS_PER_TOKEN
            if "block" in item or "refusal" in item:
                self._blocked(item, gemini, tokens_in)
                return
            text = str(item.get("text", "{}"))
            needs = int(item.get("needs_tokens", len(text) // CHARS_PER_TOKEN))
            limit = _limit(payload)
            thinking = script.thinking_tokens if gemini else 0
            cut = limit is not None and limit < needs + thinking
            if cut:
                room = max(0, (limit or 0) - thinking)
                text = text[: room * CHARS_PER_TOKEN // 2]
            content, tools = shaped(text, str(item.get("shape", "plain"))) if not cut else (text, None)
            used = min(needs, len(text) // CHARS_PER_TOKEN + 1)
            if gemini:
                self._gemini(content, tools, cut, tokens_in, used, thinking)
                return
            finish = "length" if cut else "tool_calls" if tools else "stop"
            message: dict[str, Any] = {"role": "assistant", "content": content}
            if tools:
                message["tool_calls"] = tools
            self._send(200, {"id": "chatcmpl-local", "object": "chat.completion", "model": payload.get("model", "local"),
                             "choices": [{"index": 0, "message": message, "finish_reason": finish}],
                             "usage": {"prompt_tokens": tokens_in, "completion_tokens": used, "total_tokens": tokens_in + used}})

        def _gemini(self, content: Any, tools: Any, cut: bool, tokens_in: int, used: int, thinking: int) -> None:
            if isinstance(content, list):
                content = "".join(p["text"] for p in content)
            parts: list[dict[str, Any]] = []
            if tools:
                parts = [{"functionCall": {"name": "reply", "args": json.loads(tools[0]["function"]["arguments"])}}]
            elif content and not (cut and thinking):
                parts = [{"text": content}]
            candidate: dict[str, Any] = {"content": {"role": "model", "parts": parts} if parts else {"role": "model"},
                                         "finishReason": "MAX_TOKENS" if cut else "STOP", "index": 0}
            self._send(200, {"candidates": [candidate], "modelVersion": "gemini-local",
                             "usageMetadata": {"promptTokenCount": tokens_in, "candidatesTokenCount": used if parts else 0,
                                               "thoughtsTokenCount": thinking, "totalTokenCount": tokens_in + used + thinking}})

        def _blocked(self, item: dict[str, Any], gemini: bool, tokens_in: int) -> None:
            if gemini:
                self._send(200, {"promptFeedback": {"blockReason": item.get("block", "SAFETY")},
                                 "usageMetadata": {"promptTokenCount": tokens_in, "totalTokenCount": tokens_in}})
                return
            refusal = item.get("refusal")
            message = {"role": "assistant", "content": None, "refusal": refusal} if refusal else {"role": "assistant", "content": ""}
            self._send(200, {"id": "chatcmpl-local", "model": "local", "choices": [{"index": 0, "message": message,
                             "finish_reason": "stop" if refusal else "content_filter"}], "usage": {"prompt_tokens": tokens_in, "completion_tokens": 0}})

        def _status(self, item: dict[str, Any], gemini: bool) -> None:
            status = int(item["status"])
            if "body" in item:
                self._send(status, item["body"])
            elif status == 429 and item.get("quota"):
                if gemini:
                    self._send(429, {"error": {"code": 429, "status": "RESOURCE_EXHAUSTED", "message": "You exceeded your current quota, please check your plan and billing details.",
                                               "details": [{"@type": "type.googleapis.com/google.rpc.QuotaFailure", "violations": [
                                                   {"quotaMetric": "generativelanguage.googleapis.com/generate_content_free_tier_requests",
                                                    "quotaId": "GenerateRequestsPerDayPerProjectPerModel-FreeTier"}]}]}})
                else:
                    self._send(429, {"error": {"message": "You exceeded your current quota, please check your plan and billing details.",
                                               "type": "insufficient_quota", "param": None, "code": "insufficient_quota"}})
            elif status == 429:
                body = ({"error": {"code": 429, "status": "RESOURCE_EXHAUSTED", "message": "Resource has been exhausted (e.g. check quota).",
                                   "details": [{"@type": "type.googleapis.com/google.rpc.RetryInfo", "retryDelay": "0s"}]}} if gemini else
                        {"error": {"message": "Rate limit reached for requests", "type": "requests", "code": "rate_limit_exceeded"}})
                self._send(429, body, {"Retry-After": "0"})
            else:
                self._send(status, {"error": {"message": "The server had an error while processing your request.", "type": "server_error"}})

    return Handler


@contextmanager
def model_server(replies: dict[str, list[Any]], **behaviour: Any) -> Iterator[tuple[str, Script]]:
    """Serve ``replies`` on a free loopback port; yields (base URL ending in /v1, script). Gemini: drop the /v1."""
    script = Script(replies=replies, **behaviour)
    server = ThreadingHTTPServer(("127.0.0.1", 0), _handler(script))
    server.daemon_threads = True
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/v1", script
    finally:
        server.shutdown()
        server.server_close()


def recorded(case: str) -> dict[str, list[Any]]:
    """The recorded replies of ``tests/fixtures/responses/<case>/<role>.json`` (one reply per file, text kept as is)."""
    folder = FIXTURES / case
    return {role: [(folder / f"{role}.json").read_text()] for role in ROLES if (folder / f"{role}.json").is_file()}
