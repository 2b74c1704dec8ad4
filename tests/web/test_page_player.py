"""The player's joint curves and phase timeline against the scrubber, and share links.

The curves canvas is read back pixel by pixel: each joint's line passes through its
trajectory values, and the red playhead of the curves, the timeline's playhead and the
scrubber's thumb stand at the same x. Each phase band spans, on screen, the thumb's
positions at its start and end times.
"""

from __future__ import annotations

import base64
import json
import time
from typing import Any

import httpx
import numpy as np
import pytest

from tests.web.conftest import PageProbe, Served
from tests.web.pages import open_job, pixels, set_time, sign_in, trajectory

STRIP_PX = 64  # timeline.js: one strip of the curves canvas per joint
CURVE_COLORS = [(0x2F, 0x6F, 0xDE), (0xE6, 0x86, 0x3B), (0x1F, 0x8A, 0x4C), (0x8F, 0x7A, 0xD8)]
PLAYHEAD_COLOR = (0xDD, 0x33, 0x33)
THUMB_COLOR = (0x2F, 0x6F, 0xDE)  # --accent
ALIGN_PX = 2.0
EDGE_PX = 3
state: dict[str, Any] = {}


def _near(image: np.ndarray, color: tuple[int, int, int], tolerance: int = 40) -> np.ndarray:
    return np.abs(image - np.array(color)).sum(axis=2) < tolerance


def _thumb_x(page: Any) -> float:
    """Page x of the scrubber thumb's centre, found in its pixels."""
    scrubber = page.locator("[data-testid=scrubber]")
    columns = np.flatnonzero(_near(pixels(scrubber.screenshot()), THUMB_COLOR, 60).any(axis=0))
    assert columns.size and columns.size <= 16, f"no single thumb in the scrubber: {columns}"
    return scrubber.bounding_box()["x"] + (columns.min() + columns.max() + 1) / 2


def _curves_playhead_x(page: Any) -> float:
    """Page x of the curves' playhead: the column that is red over most of the canvas's height."""
    canvas = page.locator("[data-testid=joint-curves]")
    image = pixels(canvas.screenshot())
    red = (image[:, :, 0] - np.maximum(image[:, :, 1], image[:, :, 2])) > 60
    count = red.sum(axis=0)
    columns = np.flatnonzero(count > 0.7 * image.shape[0])
    assert columns.size, "no playhead line in the curves"
    return canvas.bounding_box()["x"] + (columns.min() + columns.max() + 1) / 2


@pytest.fixture(scope="module", autouse=True)
def job_on_page(probe: PageProbe, served: Served, finished_job: dict[str, Any]) -> None:
    sign_in(probe)
    open_job(probe, finished_job["id"])
    state["job_id"] = finished_job["id"]
    state["duration"] = float(probe.page.get_attribute("[data-testid=scrubber]", "max"))
    state["frames"] = trajectory(served, finished_job["id"])
    with served.client() as client:
        state["plan"] = client.get(f"/v1/animations/{finished_job['id']}/plan.json").json()


def test_joint_curves_trace_each_joint_and_its_limits(probe: PageProbe) -> None:
    page = probe.page
    set_time(page, 0.0)
    canvas = page.locator("[data-testid=joint-curves]")
    image = pixels(canvas.screenshot())
    probe.shot("12-joint-curves", canvas)
    joints = page.evaluate("artimoPlayer.joints()")
    frames, duration = state["frames"], state["duration"]
    shown = [joint for joint in joints if joint["name"] in frames[0]["joint_angles"]]
    assert len(shown) == 2 and abs(image.shape[0] - STRIP_PX * len(shown)) <= 1  # (a screenshot rounds outwards)
    width = image.shape[1]
    for index, joint in enumerate(shown):
        top, strip = index * STRIP_PX + 4, STRIP_PX - 10  # timeline.js; lines at the extremes are drawn on its edges
        band = image[top - EDGE_PX:top + strip + EDGE_PX]
        curve = _near(band, CURVE_COLORS[index])
        assert curve.any(axis=0).mean() > 0.9, f"{joint['name']}: its line does not run across the canvas"
        values = [frame["joint_angles"][joint["name"]] for frame in frames]
        low, high = min(*values, joint["lower"]), max(*values, joint["upper"])
        red, green, blue = band[:, :, 0], band[:, :, 1], band[:, :, 2]
        limit_red = (red - green > 30) & (np.abs(green - blue) < 25)  # the limits' red, also half-covered (not the orange curve)
        curve_rows = [np.flatnonzero(curve[:, x]) for x in range(width)]
        for limit in (joint["lower"], joint["upper"]):  # a dashed line at each limit, where the curve leaves it
            y = round(EDGE_PX + strip - (limit - low) / (high - low) * strip)
            free = [x for x, rows in enumerate(curve_rows) if rows.size and np.abs(rows - y).min() > 4]
            assert len(free) > 0.1 * width, (joint["name"], limit)
            dashed = limit_red[y - 2:y + 2, free].any(axis=0).mean()
            assert dashed > 0.4, (joint["name"], limit, dashed)
        for fraction in (0.35, 0.5, 0.65, 0.8, 0.95):
            frame = frames[round(fraction * (len(frames) - 1))]
            column = min(int(frame["time_s"] / duration * width), width - 1)
            y = EDGE_PX + strip - (frame["joint_angles"][joint["name"]] - low) / (high - low) * strip
            rows = np.flatnonzero(curve[:, max(column - 1, 0):column + 2].any(axis=1))
            assert rows.size and np.abs(rows - y).min() <= 3, (joint["name"], frame["time_s"], y, rows)


def test_playheads_follow_the_scrubber_thumb(probe: PageProbe) -> None:
    page = probe.page
    for fraction in (0.1, 0.5, 0.9):
        set_time(page, fraction * state["duration"])
        thumb = _thumb_x(page)
        box = page.locator("[data-testid=phase-timeline] .playhead").bounding_box()
        assert abs(box["x"] + box["width"] / 2 - thumb) <= ALIGN_PX, (fraction, box, thumb)
        assert abs(_curves_playhead_x(page) - thumb) <= ALIGN_PX, fraction


def test_phase_bands_span_their_phase_on_the_scrubber(probe: PageProbe) -> None:
    page = probe.page
    segments, duration = state["plan"]["timeline"], state["duration"]
    bands = page.locator("[data-testid=phase-timeline] .band")
    assert bands.count() == len(segments) > 1
    for index, segment in enumerate(segments):
        band = page.locator(f"[data-testid=phase-timeline] .band[data-segment='{index}']")
        assert band.text_content() == segment["name"]
        assert band.locator("xpath=..").get_attribute("data-phase-type") == segment["phase_type"]
        box = band.bounding_box()
        set_time(page, segment["t0"])
        assert abs(_thumb_x(page) - box["x"]) <= ALIGN_PX, (segment["name"], "start")
        if (segment["t1"] - segment["t0"]) / duration > 0.01:  # shorter ones are drawn wider, to be seen
            set_time(page, min(segment["t1"], duration))
            assert abs(_thumb_x(page) - (box["x"] + box["width"])) <= ALIGN_PX, (segment["name"], "end")
    last = len(segments) - 1
    set_time(page, 0.0)
    page.click(f"[data-testid=phase-timeline] .band[data-segment='{last}']")  # a band seeks to its start
    assert float(page.get_attribute("[data-testid=scrubber]", "data-time")) == pytest.approx(segments[last]["t0"], abs=1e-3)
    probe.shot("13-timeline", page.locator("[data-testid=phase-timeline]"))


def _claims(url: str) -> dict[str, Any]:
    payload = httpx.URL(url).params["token"].split(".")[0]
    return json.loads(base64.urlsafe_b64decode(payload + "=" * (-len(payload) % 4)))


def _share(page: Any, name: str, expiry: str) -> str:
    links = page.locator("[data-testid=artifact-links]")
    links.locator("select").select_option(expiry)
    old = page.locator("[data-testid=share-url]").input_value() if page.locator("[data-testid=share-url]").count() else ""
    links.locator("li", has=page.locator(f"a[data-name='{name}']")).locator("button", has_text="share link").click()
    page.wait_for_function("old => (document.querySelector('[data-testid=share-url]')?.value || old) !== old", arg=old)
    return page.locator("[data-testid=share-url]").input_value()


def test_share_link_opens_the_glb_without_a_key(probe: PageProbe, served: Served) -> None:
    page = probe.page
    for seconds in (604800, 3600):  # the expiry chosen on the page is the token's
        url = _share(page, "animation.glb", str(seconds))
        assert url.startswith(f"{served.url}/v1/shared/{state['job_id']}/animation.glb?token=")
        assert _claims(url)["e"] == pytest.approx(time.time() + seconds, abs=120)
        assert "animation.glb, valid until" in page.text_content("[data-testid=artifact-links]")
    probe.shot("14-share-link", page.locator("[data-testid=artifact-links]"))
    glb = httpx.get(url, timeout=30)  # no Authorization header
    assert glb.status_code == 200 and glb.content[:4] == b"glTF"
    payload, signature = httpx.URL(url).params["token"].split(".")
    middle = len(signature) // 2
    flipped = signature[:middle] + ("A" if signature[middle] != "A" else "B") + signature[middle + 1:]
    claims = _claims(url) | {"e": _claims(url)["e"] + 3600}
    longer = base64.urlsafe_b64encode(json.dumps(claims, separators=(",", ":")).encode()).rstrip(b"=").decode()
    base = url.split("?")[0]
    for token in (f"{payload}.{flipped}", f"{longer}.{signature}"):
        assert httpx.get(base, params={"token": token}, timeout=30).status_code == 403
    other = base.replace("animation.glb", "trajectory.jsonl")  # a token names its one file
    assert httpx.get(other, params={"token": f"{payload}.{signature}"}, timeout=30).status_code == 403
    assert httpx.get(base, timeout=30).status_code in (401, 403, 422)  # no token at all
