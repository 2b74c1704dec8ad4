"""An httpx transport that sends requests to a FastAPI ``TestClient`` (which runs on httpx2).

``app.client.ArtimoClient`` speaks httpx; starlette's TestClient speaks httpx2. This adapter
lets the client library be tested against the app in process.
"""

from __future__ import annotations

import httpx
from fastapi.testclient import TestClient


class TestClientTransport(httpx.BaseTransport):
    __test__ = False  # not a test class

    def __init__(self, client: TestClient) -> None:
        self.client = client

    def handle_request(self, request: httpx.Request) -> httpx.Response:
        answer = self.client.request(request.method, str(request.url), headers=list(request.headers.multi_items()),
                                     content=request.read(), follow_redirects=False)
        return httpx.Response(answer.status_code, headers=list(answer.headers.multi_items()), content=answer.content,
                              request=request)
