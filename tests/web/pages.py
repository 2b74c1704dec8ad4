"""Helpers shared by the browser tests: waiting for a job's status on the page, moving the
scrubber, reading pixels and trajectories, and opening a job signed in."""

from __future__ import annotations

import io
import json
import time
from typing import Any

import numpy as np
from PIL import Image

from tests.web.conftest import REPO, PageProbe, Served

PEDAL_URDF = REPO / "examples" / "pedal_bin" / "pedal_bin.urdf"
PROMPT = "press the pedal to open the bin"
FAILING_PROMPT = "spin the propeller"
"""The pedal bin has no propeller: the job fails (GroundingError)."""
JOB_TIMEOUT_MS = 90_000
BACKGROUND = np.array([0xE9, 0xED, 0xF3])


def pixels(png: bytes) -> np.ndarray:
    """(height, width, 3) int RGB of a PNG screenshot."""
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


def status_is(page: Any, word: str, timeout: int = JOB_TIMEOUT_MS) -> None:
    page.wait_for_function(
        "word => (document.querySelector('[data-testid=job-status]')?.textContent || '').trim().endsWith(word)",
        arg=word, timeout=timeout,
    )


def set_time(page: Any, t: float) -> None:
    page.eval_on_selector(
        "[data-testid=scrubber]",
        "(el, t) => { el.value = String(t); el.dispatchEvent(new Event('input', {bubbles: true})); }", t,
    )
    page.evaluate("() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)))")  # drawn


def trajectory(served: Served, job_id: str) -> list[dict[str, Any]]:
    with served.client() as client:
        text = client.get(f"/v1/animations/{job_id}/trajectory.jsonl").raise_for_status().text
    return [json.loads(line) for line in text.splitlines() if line.strip()]


def submit_job(served: Served, prompt: str) -> dict[str, Any]:
    """Submit the pedal bin with ``prompt`` through the API (not the page)."""
    with served.client() as client:
        files = [("asset", ("pedal_bin/pedal_bin.urdf", PEDAL_URDF.read_bytes()))]
        return client.post("/v1/animations", data={"prompt": prompt}, files=files).raise_for_status().json()


def wait_finished(served: Served, job_id: str) -> dict[str, Any]:
    deadline = time.monotonic() + JOB_TIMEOUT_MS / 1000
    with served.client() as client:
        while True:
            job = client.get(f"/v1/animations/{job_id}").raise_for_status().json()
            if job["status"] in ("succeeded", "failed", "cancelled"):
                return job
            assert time.monotonic() < deadline, f"job {job_id} still {job['status']}"
            time.sleep(0.3)


def sign_in(probe: PageProbe) -> None:
    """Open the page by the link ``artimo serve`` printed."""
    probe.page.goto(probe.served.page_url)
    probe.page.wait_for_function("() => document.querySelector('#key-state').textContent === 'signed in (link)'")


def open_job(probe: PageProbe, job_id: str, status: str = "succeeded") -> None:
    """Show a finished job on the (signed-in) page and wait until its results are drawn."""
    probe.page.evaluate("delete document.querySelector('#main').dataset.loaded")  # not the previous view's
    probe.page.goto(f"{probe.served.url}/#/jobs/{job_id}")
    status_is(probe.page, status)
    probe.page.wait_for_selector("#main[data-loaded=true]", timeout=JOB_TIMEOUT_MS)
