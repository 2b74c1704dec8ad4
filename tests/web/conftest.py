"""The page in a real browser: ``artimo serve`` (embedded: SQLite database and broker, a real
Celery worker) in a temporary data folder, and Debian's Chromium driven by Playwright for
Python (``/usr/bin/chromium``, headless; never a downloaded browser build).

Every page must work offline: requests to any host but the server are aborted and fail the
test. Screenshots go to ``out/test-artifacts/web/`` (kept after the run);
``ARTIMO_UPDATE_DOCS_SCREENSHOT=1`` also copies the main one over ``docs/page.png`` (the
README's picture, left alone otherwise; see test_page.py).

One server and one browser serve the whole session (each module opens its own page), so
jobs, assets and batches made by one module are seen by the others: tests look for their
own by id or by a prompt or name of their own.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import httpx
import pytest

from benchmark.service_stack import free_port

REPO = Path(__file__).resolve().parents[2]
CHROMIUM = Path("/usr/bin/chromium")
BROWSER_ARGS = [
    "--no-sandbox", "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--no-first-run", "--disable-gpu",
]
ARTIFACTS = REPO / "out" / "test-artifacts" / "web"
SERVE_TIMEOUT_S = 60.0
STAGE_DELAY_S = "0.15"
"""Per-stage pause of the worker, so the page can be seen following a running job."""
SERVICE_VARIABLES = ("DATABASE_URL", "REDIS_URL", "ARTIMO_API_KEY", "CELERY_QUEUE", "ARTIMO_STORAGE_DIR", "ARTIMO_LINK_SECRET")
PAGE_LINE = re.compile(r"^Page: (http://\S+/#login=(\S+))$")
KEY_LINE = re.compile(r"API key \(shown once, stored hashed\): (\S+)")


@dataclass
class Served:
    url: str
    page_url: str
    key: str
    banner: list[str]

    def client(self) -> httpx.Client:
        return httpx.Client(base_url=self.url, headers={"Authorization": f"Bearer {self.key}"}, timeout=30)


def _read_banner(process: subprocess.Popen[str]) -> list[str]:
    assert process.stdout is not None
    lines: list[str] = []
    deadline = time.monotonic() + SERVE_TIMEOUT_S
    while time.monotonic() < deadline and not any(line.startswith("Page:") for line in lines):
        line = process.stdout.readline()
        if not line:
            break
        lines.append(line.rstrip("\n"))
    return lines


def _wait_ready(url: str, process: subprocess.Popen[str]) -> None:
    deadline = time.monotonic() + SERVE_TIMEOUT_S
    while time.monotonic() < deadline:
        if process.poll() is not None:
            raise AssertionError("artimo serve exited before it was ready")
        try:
            if httpx.get(f"{url}/readyz", timeout=2).status_code == 200:
                return
        except httpx.HTTPError:
            pass
        time.sleep(0.2)
    raise AssertionError(f"{url} not ready after {SERVE_TIMEOUT_S:.0f} s")


@pytest.fixture(scope="package")
def served(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Served]:
    """``artimo serve`` as a user starts it; the page link is read from what it prints."""
    data_dir = tmp_path_factory.mktemp("web-data")
    port = free_port()
    env = {k: v for k, v in os.environ.items() if k not in SERVICE_VARIABLES}
    env.update({"ARTIMO_DATA_DIR": str(data_dir), "JOB_STAGE_DELAY_S": STAGE_DELAY_S, "RATE_LIMIT_PER_MINUTE": "100000"})
    process = subprocess.Popen(
        [sys.executable, "-m", "app.cli.main", "serve", "--host", "127.0.0.1", "--port", str(port), "--workers", "1"],
        cwd=REPO, env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, start_new_session=True,
    )
    try:
        banner = _read_banner(process)
        key = next((m.group(1) for line in banner if (m := KEY_LINE.search(line))), None)
        page = next((m.group(1) for line in banner if (m := PAGE_LINE.match(line))), None)
        assert key and page, "\n".join(banner)
        url = f"http://127.0.0.1:{port}"
        _wait_ready(url, process)
        yield Served(url=url, page_url=page, key=key, banner=banner)
    finally:
        process.send_signal(signal.SIGTERM)
        try:
            process.wait(30)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait(10)


@pytest.fixture(scope="package")
def browser() -> Iterator[Any]:
    """One Chromium for the browser tests, closed after the last of them: Playwright's sync API keeps an event loop
    running while it is open, which would break ``asyncio.run`` in the test packages after this one."""
    if not CHROMIUM.is_file():
        pytest.fail("Debian's Chromium is missing: apt-get install chromium (make test installs it)")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        chromium = playwright.chromium.launch(executable_path=str(CHROMIUM), headless=True, args=BROWSER_ARGS)
        yield chromium
        chromium.close()


class PageProbe:
    """A page that refuses every request leaving the server, and records script errors."""

    def __init__(self, browser: Any, served: Served) -> None:
        self.context = browser.new_context(viewport={"width": 1400, "height": 1000})
        self.page = self.context.new_page()
        self.external: list[str] = []
        self.errors: list[str] = []
        self.page.route("**/*", self._route)
        self.page.on("pageerror", lambda error: self.errors.append(str(error)))
        self.served = served

    def _route(self, route: Any) -> None:
        url = route.request.url
        if url.startswith((self.served.url, "data:", "blob:")):
            route.continue_()
        else:
            self.external.append(url)
            route.abort()

    def shot(self, name: str, locator: Any = None, *, full_page: bool = True) -> Path:
        """Save a screenshot (of ``locator``, or the page) as a test artifact."""
        ARTIFACTS.mkdir(parents=True, exist_ok=True)
        path = ARTIFACTS / f"{name}.png"
        (locator or self.page).screenshot(path=str(path), **({} if locator else {"full_page": full_page}))
        return path

    def check_clean(self) -> None:
        assert self.external == [], f"the page asked other hosts: {self.external}"
        assert self.errors == [], f"script errors: {self.errors}"


@pytest.fixture(scope="module")
def probe(browser: Any, served: Served) -> Iterator[PageProbe]:
    probe = PageProbe(browser, served)
    yield probe
    probe.context.close()
    probe.check_clean()


@pytest.fixture(scope="package")
def finished_job(served: Served) -> dict[str, Any]:
    """A succeeded job of the pedal bin, submitted through the API (as the job's JSON)."""
    from tests.web.pages import PROMPT, submit_job, wait_finished

    job = wait_finished(served, submit_job(served, PROMPT)["id"])
    assert job["status"] == "succeeded", job
    return job
