"""A local OpenAI-compatible server that replays recorded model replies (the only fake we use).

Replies are picked by role (the system prompt names it: perceiver / planner / critic) from
a script: a list per role, consumed in order (the last one repeats). A script item is
either reply text or ``{"status": 429}`` / ``{"status": 500}`` / ``{"delay_s": x}`` to
simulate a rate limit, a server error or a slow answer. Every request is recorded.
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

ROLES = ("perceiver", "planner", "critic")
FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "responses"


@dataclass
class Script:
    replies: dict[str, list[Any]]
    requests: list[dict[str, Any]] = field(default_factory=list)
    cursor: dict[str, int] = field(default_factory=dict)

    used: set[int] = field(default_factory=set)
    lock: threading.Lock = field(default_factory=threading.Lock)

    def next(self, role: str, text: str) -> Any:
        """A ``{"match": s, "reply": r}`` item whose ``s`` occurs in the request (used once), else the next plain item."""
        with self.lock:
            items = self.replies.get(role) or ['{"error": "no recorded reply for ' + role + '"}']
            for item in items:
                if isinstance(item, dict) and "match" in item and id(item) not in self.used and item["match"] in text:
                    self.used.add(id(item))
                    return item["reply"]
            plain = [item for item in items if not (isinstance(item, dict) and "match" in item)] or ["{}"]
            index = self.cursor.get(role, 0)
            self.cursor[role] = index + 1
            return plain[min(index, len(plain) - 1)]


def _role(payload: dict[str, Any]) -> str:
    system = next((m.get("content", "") for m in payload.get("messages", []) if m.get("role") == "system"), "")
    system = system or json.dumps(payload.get("systemInstruction", ""))
    match = re.search(r"you are the (?:\w+ )?(perceiver|planner|critic)", str(system).lower())
    return match.group(1) if match else "unknown"


def _handler(script: Script) -> type[BaseHTTPRequestHandler]:
    class Handler(BaseHTTPRequestHandler):
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
            script.requests.append({"role": role, "path": self.path, "payload": payload,
                                    "auth": self.headers.get("Authorization") or self.headers.get("x-goog-api-key")})
            gemini = ":generateContent" in self.path
            if not (self.path.endswith("/chat/completions") or gemini):
                self._send(404, {"error": {"message": "unknown path"}})
                return
            item = script.next(role, json.dumps(payload))
            if isinstance(item, dict) and "status" in item:
                self._send(item["status"], {"error": {"message": "simulated"}}, {"Retry-After": "0"} if item["status"] == 429 else None)
                return
            if isinstance(item, dict) and "delay_s" in item:
                time.sleep(item["delay_s"])
                item = item.get("reply", "{}")
            text = item if isinstance(item, str) else json.dumps(item)
            if gemini:
                self._send(200, {"candidates": [{"content": {"role": "model", "parts": [{"text": text}]}}],
                                 "usageMetadata": {"promptTokenCount": len(json.dumps(payload)) // 4, "candidatesTokenCount": len(text) // 4}})
                return
            self._send(200, {"id": "replay", "model": payload.get("model", "replay"), "choices": [{"index": 0, "message": {"role": "assistant", "content": text}}],
                             "usage": {"prompt_tokens": len(json.dumps(payload)) // 4, "completion_tokens": len(text) // 4}})

    return Handler


@contextmanager
def replay_server(replies: dict[str, list[Any]]) -> Iterator[tuple[str, Script]]:
    """Serve ``replies`` on a free loopback port; yields (base_url ending in /v1, script)."""
    script = Script(replies=replies)
    server = ThreadingHTTPServer(("127.0.0.1", 0), _handler(script))
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
