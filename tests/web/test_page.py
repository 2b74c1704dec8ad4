"""The page end to end in Chromium: sign in by the printed link, upload and submit, follow the
job, look at the animation (pixels), scrub, check the joint panel against the trajectory,
hover a link, read "what happened", correct the plan and run it, open the docs offline.

The tests share one page and run in order (each step builds on the one before).
"""

from __future__ import annotations

import json
import os
import shutil
import time
from typing import Any

import httpx
import numpy as np
import pytest

from tests.web.conftest import REPO, PageProbe, Served
from tests.web.pages import BACKGROUND, JOB_TIMEOUT_MS, PEDAL_URDF, PROMPT, pixels, set_time, status_is, trajectory

NEW_LID_TARGET = -0.7
DOCS_SCREENSHOT = REPO / "docs" / "page.png"
UPDATE_DOCS_SCREENSHOT = "ARTIMO_UPDATE_DOCS_SCREENSHOT"
"""Set to 1 to copy the page's screenshot over docs/page.png, the README's picture (it is
left alone otherwise): ``ARTIMO_UPDATE_DOCS_SCREENSHOT=1 pytest tests/web``."""
state: dict[str, Any] = {}


def test_sign_in_upload_submit_and_follow_progress(probe: PageProbe, served: Served) -> None:
    page = probe.page
    page.goto(served.page_url)
    page.wait_for_function("() => document.querySelector('#key-state').textContent === 'signed in (link)'")
    assert "#login=" not in page.url, "the sign-in token stays in the address bar"
    assert page.evaluate("localStorage.getItem('artimo.apiKey')").startswith("artimo-page.")
    page.set_input_files("[data-testid=asset-file]", [str(PEDAL_URDF)])
    page.fill("[data-testid=prompt]", PROMPT)
    page.click("[data-testid=submit]")
    page.wait_for_function("() => location.hash.startsWith('#/jobs/')")
    state["job_id"] = page.url.rsplit("/", 1)[1]
    status_is(page, "running")
    probe.shot("01-running")
    status_is(page, "succeeded")
    page.wait_for_selector("#main[data-loaded=true]", timeout=JOB_TIMEOUT_MS)
    assert "(events)" in page.text_content("[data-testid=job-status]"), "progress did not come from the event stream"
    assert PROMPT in page.text_content("[data-testid=jobs-list]")
    probe.shot("02-succeeded")


def test_canvas_shows_the_asset_and_the_scrubber_changes_it(probe: PageProbe) -> None:
    page = probe.page
    canvas = page.locator("[data-testid=viewer-canvas]")
    set_time(page, 0.0)
    start = pixels(canvas.screenshot())
    probe.shot("03-canvas-start", canvas)
    drawn = np.abs(start - BACKGROUND).sum(axis=2) > 30
    assert drawn.mean() > 0.05, f"the canvas is almost blank ({drawn.mean():.3f} of its pixels drawn)"
    end_time = float(page.get_attribute("[data-testid=scrubber]", "max"))
    set_time(page, end_time)
    end = pixels(canvas.screenshot())
    probe.shot("04-canvas-end", canvas)
    changed = np.abs(end - start).sum(axis=2) > 30
    assert changed.mean() > 0.005, f"moving the scrubber to the end changed only {changed.mean():.4f} of the picture"


def test_joint_panel_follows_thetrajectory(probe: PageProbe, served: Served) -> None:
    page = probe.page
    frames = trajectory(served, state["job_id"])
    step = frames[1]["time_s"] - frames[0]["time_s"]
    for t in (0.2, 0.45, 0.9, frames[-1]["time_s"]):
        set_time(page, t)
        expected = frames[min(round(t / step), len(frames) - 1)]
        assert page.get_attribute("[data-testid=joint-panel]", "data-frame") == str(expected["frame_idx"])
        rows = page.eval_on_selector_all("[data-testid=joint-panel] tr[data-joint]", "rows => rows.map(r => [r.dataset.joint, Number(r.dataset.value)])")
        assert dict(rows) == pytest.approx(expected["joint_angles"], abs=1e-12), t
    assert page.text_content("[data-testid=joint-panel]").count("[") == 2  # both joints show their limits


def test_play_pause_and_speed(probe: PageProbe) -> None:
    page = probe.page
    set_time(page, 0.0)
    page.select_option("[data-testid=speed]", "0.5")
    ratio, playing = page.evaluate("""async () => {
        const button = document.querySelector('[data-testid=play]');
        button.click();
        const wall = performance.now(), start = artimoPlayer.time;
        await new Promise((resolve) => setTimeout(resolve, 1500));
        const rate = (artimoPlayer.time - start) / ((performance.now() - wall) / 1000);
        const playing = button.dataset.playing;
        button.click();
        return [rate, playing];
    }""")
    assert playing == "true" and 0.15 < ratio < 0.6, ratio  # half speed (slow frames only lower it: steps are capped)
    assert page.get_attribute("[data-testid=play]", "data-playing") == "false"
    paused_at = float(page.get_attribute("[data-testid=scrubber]", "data-time"))
    page.wait_for_timeout(300)
    assert float(page.get_attribute("[data-testid=scrubber]", "data-time")) == paused_at > 0


def test_hover_names_and_highlights_a_link(probe: PageProbe) -> None:
    page = probe.page
    set_time(page, 1.0)
    canvas = page.locator("[data-testid=viewer-canvas]")
    box = canvas.bounding_box()
    page.mouse.move(box["x"] + 2, box["y"] + 2)
    page.wait_for_timeout(200)
    before = pixels(canvas.screenshot())
    spot = page.evaluate("artimoPlayer.linkScreenPosition('pedal')")
    page.mouse.move(box["x"] + spot["x"], box["y"] + spot["y"])
    page.wait_for_function("() => document.querySelector('.viewer').dataset.hoveredLink === 'pedal'")
    assert "pedal_pivot" in page.text_content(".viewer .tip")
    after = pixels(canvas.screenshot())
    probe.shot("05-hover-pedal", canvas)
    page.evaluate("window.scrollTo(0, 0)")
    shot = probe.shot("page", full_page=False)  # the README's picture
    if os.environ.get(UPDATE_DOCS_SCREENSHOT) == "1":
        shutil.copyfile(shot, DOCS_SCREENSHOT)
        assert DOCS_SCREENSHOT.read_bytes() == shot.read_bytes()
    assert (np.abs(after - before).sum(axis=2) > 30).mean() > 0.001, "the hovered link is not highlighted"
    page.mouse.move(box["x"] + 2, box["y"] + 2)


def test_what_happened(probe: PageProbe, served: Served) -> None:
    page = probe.page
    with served.client() as client:
        plan = client.get(f"/v1/animations/{state['job_id']}/plan.json").json()
    bands = page.locator("[data-testid=phase-timeline] .band")
    assert bands.count() == len(plan["timeline"])
    first = bands.nth(0)
    assert first.text_content() == plan["timeline"][0]["name"]
    explain = page.locator("[data-testid=explain]")
    with served.client() as client:
        causal = client.get(f"/v1/animations/{state['job_id']}/causal.json").json()
    action = causal["causal"]["action"]
    control = explain.locator(".chain .node.control").first.text_content()
    assert action["target_role"] == "control" and control.startswith(f"{action['primitive']} {action['target_link']}")
    for target in causal["causal"]["effects"]["joint_targets"]:
        assert f"{target['joint']} → {target['to']}" in explain.text_content()
    with served.client() as client:
        report = client.get(f"/v1/animations/{state['job_id']}/report.json").json()
    understood = page.text_content("[data-testid=understanding]")
    if report.get("understanding"):  # one row per clause, nested steps and moves as tables
        assert page.locator("table[data-testid=understanding] > tbody > tr").count() == len(report["understanding"])
        assert "pedal_pivot" in understood and "lid_hinge" in understood
    else:
        assert "no per-clause explanation in this report" in understood
    assert "accepted" in page.text_content("[data-testid=critic-rounds]")
    assert "perceive" in page.text_content("[data-testid=timings]")
    links = page.eval_on_selector_all("[data-testid=artifact-links] a", "as => as.map(a => [a.dataset.name, a.href])")
    names = dict(links)
    assert {"animation.glb", "trajectory.jsonl", "plan.json", "causal.json", "report.json"} <= set(names)
    glb = httpx.get(names["animation.glb"], timeout=30)  # no header: the signed link is enough
    assert glb.status_code == 200 and glb.content[:4] == b"glTF"
    probe.shot("06-what-happened", explain)


def test_plan_editor_shows_errors_inline(probe: PageProbe) -> None:
    page = probe.page
    t1 = page.locator('[data-testid=plan-editor] [data-path="timeline[0].t1"]')
    good = t1.input_value()
    t1.fill("-1")
    t1.press("Tab")
    page.wait_for_selector('[data-path="timeline[0].t1"].invalid')
    assert "t1" in page.text_content("[data-testid=plan-issues]")
    assert page.is_disabled("[data-testid=run-plan]")
    message = t1.locator("xpath=..").locator(".field-error").text_content()
    assert message, "no message next to the field"
    raw = page.locator("[data-testid=plan-json]")
    text = raw.input_value()
    raw.fill(text.replace('"meta"', '"meta" "', 1))
    page.wait_for_function("() => document.querySelector('[data-testid=plan-issues]').textContent.includes('not valid JSON')")
    assert page.get_attribute("[data-testid=plan-issues] li.issue", "data-line") == "2"
    raw.fill(text)
    t1.fill(good)
    t1.press("Tab")
    page.wait_for_function("() => document.querySelector('[data-testid=plan-issues]').textContent.includes('valid: ready to run')")


def test_edit_a_target_and_run_it_as_a_new_job(probe: PageProbe, served: Served) -> None:
    page = probe.page
    with served.client() as client:
        plan = client.get(f"/v1/animations/{state['job_id']}/plan.json").json()
    where = next(f"timeline[{s}].controls[{c}]" for s, segment in enumerate(plan["timeline"])
                 for c, control in enumerate(segment["controls"]) if control.get("joint") == "lid_hinge" and control["mode"] == "joint_position")
    target = page.locator(f'[data-testid=plan-editor] [data-path="{where}.q_target_rad"]')
    target.fill(str(NEW_LID_TARGET))
    target.press("Tab")
    page.wait_for_function("() => !document.querySelector('[data-testid=run-plan]').disabled")
    assert "using q_target_rad" in page.text_content("[data-testid=plan-issues]")  # differs from its expression: said so
    probe.shot("07-plan-editor", page.locator("[data-testid=plan-editor]"))
    page.click("[data-testid=run-plan]")
    with served.client() as client:
        page.wait_for_function("old => location.hash.startsWith('#/jobs/') && !location.hash.includes(old)", arg=state["job_id"])
    new_id = page.url.rsplit("/", 1)[1]
    status_is(page, "succeeded")
    page.wait_for_selector("#main[data-loaded=true]", timeout=JOB_TIMEOUT_MS)
    frames = trajectory(served, new_id)
    assert frames[-1]["joint_angles"]["lid_hinge"] == pytest.approx(NEW_LID_TARGET)
    assert trajectory(served, state["job_id"])[-1]["joint_angles"]["lid_hinge"] != pytest.approx(NEW_LID_TARGET)
    with served.client() as client:
        report = client.get(f"/v1/animations/{new_id}/report.json").json()
    assert report["provider"] == "plan" and "no perceiver" in report["final_state"]
    assert "a plan job skips the perceiver" in page.text_content("[data-testid=explain]")
    set_time(page, frames[-1]["time_s"])
    probe.shot("08-plan-job")


def test_batches_view_with_benchmark_scores(probe: PageProbe, served: Served) -> None:
    page = probe.page
    cases = [json.loads(line) for line in (REPO / "benchmark" / "cases" / "dev_examples.jsonl").read_text().splitlines()
             if '"asset": "pedal_bin"' in line][:2]
    with served.client() as client:
        files = [("asset", ("pedal_bin/pedal_bin.urdf", PEDAL_URDF.read_bytes()))]
        asset = client.post("/v1/assets", files=files).json()  # its own upload (201), or the same content stored by another test (200)
        batch = client.post("/v1/benchmarks", json={"name": "pedal bench", "cases": [{**c, "asset": asset["id"]} for c in cases]}).json()
        deadline = time.monotonic() + JOB_TIMEOUT_MS / 1000
        while not client.get(f"/v1/batches/{batch['id']}").json()["done"]:
            assert time.monotonic() < deadline, "benchmark jobs did not finish"
            time.sleep(0.3)
    page.goto(f"{served.url}/#/batches")
    page.wait_for_selector("[data-testid=batches] a")
    page.click("text=pedal bench")
    page.wait_for_selector("[data-testid=batch-scores]")
    assert page.url.endswith(batch["id"])
    assert "P_gIoU" in page.text_content("[data-testid=batch-scores]")
    first = cases[0]["case_id"]
    row = page.locator(f"[data-testid=batch] tr[data-case={first}]")
    assert float(row.locator("td").nth(2).text_content()) > 0.9  # P_gIoU of a case the offline agent gets right
    row.locator("a").first.click()
    page.wait_for_selector("text=key states of")
    assert "lid_hinge" in page.text_content("[data-testid=batch]")
    probe.shot("09-benchmark-batch", page.locator("[data-testid=batch]"))


def test_docs_render_from_local_files(probe: PageProbe, served: Served) -> None:
    page = probe.page
    page.goto(f"{served.url}/docs")
    page.wait_for_selector(".swagger-ui .info .title", timeout=30_000)
    assert "ArtiMo" in page.text_content(".swagger-ui .info .title")
    page.goto(f"{served.url}/redoc")
    page.wait_for_selector("h1", timeout=30_000)
    assert "ArtiMo" in page.text_content("h1")


def test_a_failed_job_says_why(probe: PageProbe, served: Served) -> None:
    page = probe.page
    with served.client() as client:
        files = [("asset", ("pedal_bin/pedal_bin.urdf", PEDAL_URDF.read_bytes()))]
        job = client.post("/v1/animations", data={"prompt": "spin the propeller"}, files=files).json()
    page.goto(f"{served.url}/#/jobs/{job['id']}")
    status_is(page, "failed")
    page.wait_for_selector("#main[data-loaded=true]", timeout=JOB_TIMEOUT_MS)
    error = page.text_content("#main .error")
    assert "GroundingError" in error and "propeller" in error
    assert "propeller" in page.text_content("[data-testid=warnings]")  # report.json of the failed run
    assert page.locator("[data-testid=viewer-canvas]").count() == 0 and page.locator("[data-testid=plan-editor]").count() == 0


def test_progress_falls_back_to_polling_without_the_event_stream(browser: Any, served: Served) -> None:
    probe = PageProbe(browser, served)
    try:
        page = probe.page
        page.route("**/events", lambda route: route.fulfill(status=503, body="no streams here"))
        page.goto(served.page_url)
        page.wait_for_function("() => document.querySelector('#key-state').textContent === 'signed in (link)'")
        with served.client() as client:
            files = [("asset", ("pedal_bin/pedal_bin.urdf", PEDAL_URDF.read_bytes()))]
            job = client.post("/v1/animations", data={"prompt": PROMPT}, files=files).json()
        page.goto(f"{served.url}/#/jobs/{job['id']}")
        status_is(page, "succeeded")
        assert "(polling)" in page.text_content("[data-testid=job-status]")
        page.wait_for_selector("#main[data-loaded=true]", timeout=JOB_TIMEOUT_MS)
    finally:
        probe.context.close()
    probe.check_clean()
