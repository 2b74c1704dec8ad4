"""Request guards in front of the app: no key in URLs, bounded bodies, no body that trickles forever.

- A query string carrying a credential (``?api_key=``, ``?token=`` ...) is refused (400):
  keys travel only in the ``Authorization`` header, never in URLs (which land in logs). The one
  exception is a signed share link (``/v1/shared/...?token=``): its token is made for URLs.
- A body that is not ``multipart/form-data`` (JSON: ``/v1/batches``) may hold at most
  ``max_json_body_bytes`` (413); multipart uploads have their own, larger limits
  (:mod:`app.api.uploads`).
- Reading a body times out: no chunk for ``body_idle_timeout_s`` seconds, or more than
  ``body_timeout_s`` in all, answers 408. A client cannot hold a request open by sending a
  body slowly.

Pure ASGI (nothing buffered). The refusals are raised from the wrapped ``receive`` as
:class:`BodyRefused` (an ``HTTPException``, so FastAPI's body parsing passes it through)
and rendered like every other error.
"""

from __future__ import annotations

import asyncio
import json
import time
from urllib.parse import parse_qsl

from starlette.exceptions import HTTPException
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.core.logging import CREDENTIAL_PARAMETERS

SHARED_PREFIX = "/v1/shared/"
SHARED_LINK_PARAMETERS = frozenset({"token"})
"""A signed share link carries its own expiring, single-file token in the URL by design (it is still redacted from logs)."""

MULTIPART = b"multipart/form-data"


class BodyRefused(HTTPException):
    """A request body refused while it was being read (too large, too slow)."""

    def __init__(self, status_code: int, detail: str, kind: str) -> None:
        super().__init__(status_code=status_code, detail=detail)
        self.kind = kind


def _header(scope: Scope, name: bytes) -> bytes:
    return next((value for key, value in scope.get("headers", []) if key.lower() == name), b"")


async def _answer(send: Send, status: int, detail: str, kind: str) -> None:
    body = json.dumps({"detail": detail, "kind": kind}, ensure_ascii=True).encode()
    await send({"type": "http.response.start", "status": status,
                "headers": [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode())]})
    await send({"type": "http.response.body", "body": body})


class RequestGuardMiddleware:
    """Refuses credentials in URLs, caps non-multipart bodies and times out slow bodies."""

    def __init__(self, app: ASGIApp, *, max_json_body_bytes: int, body_idle_timeout_s: float, body_timeout_s: float) -> None:
        self.app = app
        self.max_json_body_bytes = max_json_body_bytes
        self.body_idle_timeout_s = body_idle_timeout_s
        self.body_timeout_s = body_timeout_s

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        query = scope.get("query_string", b"").decode("latin-1")
        allowed = SHARED_LINK_PARAMETERS if str(scope.get("path", "")).startswith(SHARED_PREFIX) else frozenset()
        if any(name.lower() in CREDENTIAL_PARAMETERS - allowed for name, _ in parse_qsl(query, keep_blank_values=True)):
            await _answer(send, 400, "send the API key in the 'Authorization: Bearer KEY' header, never in the URL "
                                     "(URLs are logged); this request was not processed", "CredentialInUrl")
            return
        limit = None if _header(scope, b"content-type").lower().startswith(MULTIPART) else self.max_json_body_bytes
        declared = _header(scope, b"content-length")
        if limit is not None and declared.isdigit() and int(declared) > limit:
            await _answer(send, 413, f"request body of {int(declared)} bytes is larger than the limit of {limit} bytes", "PayloadTooLarge")
            return
        await self.app(scope, self._guarded(receive, limit), send)

    def _guarded(self, receive: Receive, limit: int | None) -> Receive:
        started = time.monotonic()
        received = 0
        done = False

        async def guarded_receive() -> Message:
            nonlocal received, done
            if done:
                return await receive()  # after the body: waiting for a disconnect is not a slow body
            remaining = self.body_timeout_s - (time.monotonic() - started)
            try:
                message = await asyncio.wait_for(receive(), timeout=max(0.0, min(self.body_idle_timeout_s, remaining)))
            except TimeoutError:
                raise BodyRefused(408, f"the request body was not received in time (no data for {self.body_idle_timeout_s:g} s, "
                                       f"or more than {self.body_timeout_s:g} s in all)", "RequestTimeout") from None
            if message["type"] == "http.request":
                received += len(message.get("body", b""))
                done = not message.get("more_body", False)
                if limit is not None and received > limit:
                    raise BodyRefused(413, f"request body larger than the limit of {limit} bytes", "PayloadTooLarge")
            else:
                done = True
            return message

        return guarded_receive
