"""The jobs list (filter by text and status, open a job from it) and the view of a batch that
is not a benchmark batch (its cases with their status, no scores)."""

from __future__ import annotations

from typing import Any

import pytest

from tests.web.conftest import PageProbe, Served
from tests.web.pages import FAILING_PROMPT, PEDAL_URDF, PROMPT, open_job, sign_in, submit_job, wait_finished

BATCH_NAME = "two plain cases"


def _rows(page: Any) -> list[dict[str, str]]:
    """The jobs list as shown: id, status word and prompt of each row."""
    return page.eval_on_selector_all("[data-testid=jobs-list] li[data-job-id]", """rows => rows.map((row) => ({
        id: row.dataset.jobId, status: row.querySelector('.badge').textContent, prompt: row.querySelector('.prompt').title,
        selected: row.classList.contains('selected')}))""")


def _api_jobs(served: Served, status: str = "") -> list[dict[str, Any]]:
    with served.client() as client:
        return client.get("/v1/animations", params={"limit": 100, **({"status": status} if status else {})}).json()["data"]


@pytest.fixture(scope="module")
def failed_job(served: Served) -> dict[str, Any]:
    job = wait_finished(served, submit_job(served, FAILING_PROMPT)["id"])
    assert job["status"] == "failed", job
    return job


def test_jobs_list_filters_by_text_and_status(probe: PageProbe, served: Served, finished_job: dict[str, Any],
                                              failed_job: dict[str, Any]) -> None:
    page = probe.page
    sign_in(probe)
    page.wait_for_selector(f"[data-testid=jobs-list] li[data-job-id='{failed_job['id']}']")
    everything = _rows(page)
    assert {row["id"] for row in everything} == {job["id"] for job in _api_jobs(served)}
    assert {finished_job["id"], failed_job["id"]} <= {row["id"] for row in everything}
    text = page.get_by_placeholder("filter prompt or asset")
    text.fill("PROPELLER")  # case-insensitive, part of the prompt
    shown = _rows(page)
    assert failed_job["id"] in {row["id"] for row in shown} and finished_job["id"] not in {row["id"] for row in shown}
    assert shown and all("propeller" in row["prompt"].lower() for row in shown)
    assert len(shown) < len(everything)
    text.fill("no prompt says this")
    assert _rows(page) == [] and page.text_content("[data-testid=jobs-list]") == "no job matches"
    text.fill("")
    assert len(_rows(page)) == len(everything)
    status = page.locator("#jobs-panel select")
    for word, inside, outside in (("failed", failed_job, finished_job), ("succeeded", finished_job, failed_job)):
        status.select_option(word)
        page.wait_for_function("""word => {  // the list is fetched again with the status
            const badges = [...document.querySelectorAll('[data-testid=jobs-list] li[data-job-id] .badge')];
            return badges.length > 0 && badges.every((badge) => badge.textContent === word);
        }""", arg=word)
        shown = _rows(page)
        assert {row["status"] for row in shown} == {word}
        assert {row["id"] for row in shown} == {job["id"] for job in _api_jobs(served, word)}
        assert inside["id"] in {row["id"] for row in shown} and outside["id"] not in {row["id"] for row in shown}
    text.fill("propeller")  # both filters at once: a succeeded job about a propeller does not exist
    assert _rows(page) == [] and page.text_content("[data-testid=jobs-list]") == "no job matches"
    probe.shot("10-jobs-filtered", page.locator("#jobs-panel"))
    text.fill("")
    status.select_option("")
    page.wait_for_function("n => document.querySelectorAll('[data-testid=jobs-list] li[data-job-id]').length === n", arg=len(everything))


def test_clicking_a_row_opens_that_job(probe: PageProbe, finished_job: dict[str, Any], failed_job: dict[str, Any]) -> None:
    page = probe.page
    for job, word in ((failed_job, "failed"), (finished_job, "succeeded")):
        page.click(f"[data-testid=jobs-list] li[data-job-id='{job['id']}']")
        page.wait_for_function("id => location.hash === `#/jobs/${id}`", arg=job["id"])
        page.wait_for_function("prompt => document.querySelector('#job-title')?.textContent === prompt", arg=job["prompt"])
        page.wait_for_function("() => document.querySelector('#main').dataset.loaded === 'true'")
        assert page.text_content("[data-testid=job-status]").strip().endswith(word)
        assert [row["id"] for row in _rows(page) if row["selected"]] == [job["id"]]
    assert page.locator("[data-testid=viewer-canvas]").count() == 1  # the succeeded one shows its animation
    assert page.text_content("#job-title") == PROMPT


def test_a_plain_batch_lists_its_cases_with_status(probe: PageProbe, served: Served) -> None:
    page = probe.page
    with served.client() as client:
        asset = client.post("/v1/assets", files=[("asset", ("pedal_bin/pedal_bin.urdf", PEDAL_URDF.read_bytes()))]).json()
        cases = [{"asset": asset["id"], "prompt": PROMPT, "case_id": "opens"},
                 {"asset": asset["id"], "prompt": FAILING_PROMPT, "case_id": "no-propeller"}]
        batch = client.post("/v1/batches", json={"name": BATCH_NAME, "cases": cases}).raise_for_status().json()
    for case in batch["cases"]:
        wait_finished(served, case["job_id"])
    with served.client() as client:
        batch = client.get(f"/v1/batches/{batch['id']}").json()
        assert client.get(f"/v1/batches/{batch['id']}/scores").status_code == 404  # not a benchmark batch
    assert {case["case_id"]: case["status"] for case in batch["cases"]} == {"opens": "succeeded", "no-propeller": "failed"}
    open_job(probe, batch["cases"][0]["job_id"])  # anywhere else first: the batch view must replace it
    page.goto(f"{served.url}/#/batches")
    page.wait_for_selector(f"[data-testid=batches] a[href='#/batches/{batch['id']}']")
    page.click(f"[data-testid=batches] a[href='#/batches/{batch['id']}']")
    page.wait_for_selector("[data-testid=batch] table")
    view = page.locator("[data-testid=batch]")
    assert view.locator("h2").text_content() == BATCH_NAME
    assert "2 cases: 1 succeeded, 1 failed" in view.text_content()
    assert "not a benchmark batch" in view.text_content() and page.locator("[data-testid=batch-scores]").count() == 0
    assert view.locator("thead th").all_text_contents() == ["case", "status", "job"]
    for case in batch["cases"]:
        row = view.locator(f"tbody tr[data-case='{case['case_id']}']")
        assert row.locator("td").nth(0).text_content() == case["case_id"]
        assert row.locator("td").nth(1).locator(".badge").text_content() == case["status"]
        assert row.locator("a", has_text="open").get_attribute("href") == f"#/jobs/{case['job_id']}"
    failed = next(case for case in batch["cases"] if case["status"] == "failed")
    assert "propeller" in view.locator(f"tbody tr[data-case='{failed['case_id']}'] td").nth(1).text_content()  # why it failed
    probe.shot("11-plain-batch", view)
    view.locator(f"tbody tr[data-case='{failed['case_id']}'] a", has_text="open").click()
    page.wait_for_function("id => location.hash === `#/jobs/${id}`", arg=failed["job_id"])
    page.wait_for_function("() => document.querySelector('#main').dataset.loaded === 'true'")
    assert page.text_content("[data-testid=job-status]").strip().endswith("failed")
