"""Admission control: at most ``max_in_flight`` HTTP requests doing work inside the app per process.

Why: a sync route hops between threadpool threads (a dependency, the endpoint, the
response validation) while its database session keeps a pooled connection checked out.
With more requests in flight than pooled connections, every threadpool thread can end up
waiting for a connection held by a request that itself waits for a thread: a deadlock that
only the pool timeout (30 s) breaks, failing every request of the burst. Keeping the
requests in flight at or below the pool's capacity means a checkout never waits; the
others queue here, in the event loop, holding neither a thread nor a connection.

A request gives its slot back while it waits for body bytes from the client (an upload
arriving slowly holds no slot; it takes one again when the bytes are there), so slow
clients cannot freeze the API. Health routes never queue here.
"""

from __future__ import annotations

import asyncio

from starlette.types import ASGIApp, Message, Receive, Scope, Send

EXEMPT_PATHS = frozenset({"/healthz", "/readyz", "/metrics"})
"""Cheap routes a load balancer or monitor must always reach."""

STREAM_SUFFIX = "/events"
"""Server-sent event streams (app/api/routes/events.py) stay open for seconds while holding neither
a thread nor a database connection between polls: they are not counted (else a few open pages
would take every slot)."""


class AdmissionMiddleware:
    """Pure ASGI middleware: a semaphore around the work of every HTTP request (lifespan passes through)."""

    def __init__(self, app: ASGIApp, max_in_flight: int) -> None:
        self.app = app
        self.max_in_flight = max(1, int(max_in_flight))
        self._slots: asyncio.Semaphore | None = None

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or scope.get("path") in EXEMPT_PATHS or str(scope.get("path", "")).endswith(STREAM_SUFFIX):  # see STREAM_SUFFIX
            await self.app(scope, receive, send)
            return
        if self._slots is None:  # created inside the server's event loop
            self._slots = asyncio.Semaphore(self.max_in_flight)
        slots = self._slots
        held = False
        body_done = False

        async def receive_without_slot() -> Message:
            """Wait for body bytes without a slot; take one back before the app handles them."""
            nonlocal held, body_done
            if body_done or not held:
                return await receive()
            slots.release()
            held = False
            message = await receive()  # raising here (refused, cancelled) leaves the request without a slot
            await slots.acquire()
            held = True
            body_done = message["type"] != "http.request" or not message.get("more_body", False)
            return message

        await slots.acquire()
        held = True
        try:
            await self.app(scope, receive_without_slot, send)
        finally:
            if held:
                slots.release()
                held = False
