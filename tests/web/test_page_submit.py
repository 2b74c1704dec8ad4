"""Submitting from the page with a .zip of an example folder, and again with that asset
chosen from the list of earlier ones, each at 24 fps (the planner's rate is 30): the plan,
the trajectory and the page's clock follow the chosen rate."""

from __future__ import annotations

import zipfile
from pathlib import Path
from typing import Any

import pytest

from tests.web.conftest import REPO, PageProbe, Served
from tests.web.pages import JOB_TIMEOUT_MS, set_time, sign_in, status_is, trajectory

EXAMPLE = REPO / "examples" / "pedal_bin"
FPS = 24
PLANNER_FPS = 30
state: dict[str, Any] = {}


@pytest.fixture(scope="module")
def example_zip(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The example's folder as a user zips it (the folder itself inside)."""
    path = tmp_path_factory.mktemp("zip") / "pedal_bin.zip"
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        for file in sorted(EXAMPLE.rglob("*")):
            archive.write(file, file.relative_to(EXAMPLE.parent).as_posix())
    return path


def _submit(probe: PageProbe, prompt: str) -> str:
    """Fill the prompt, open the options, set fps, submit; the id of the job that opens."""
    page = probe.page
    page.fill("[data-testid=prompt]", prompt)
    if not page.is_visible("#submit-panel select[name=fps]"):
        page.click("#submit-panel details summary")
    page.select_option("#submit-panel select[name=fps]", str(FPS))
    before = page.evaluate("location.hash")
    page.click("[data-testid=submit]")
    page.wait_for_function("old => location.hash.startsWith('#/jobs/') && location.hash !== old", arg=before)
    job_id = page.url.rsplit("/", 1)[1]
    status_is(page, "succeeded")
    page.wait_for_selector("#main[data-loaded=true]", timeout=JOB_TIMEOUT_MS)
    return job_id


def _check_rate(probe: PageProbe, served: Served, job_id: str) -> dict[str, Any]:
    """The job ran at FPS: its options, plan, trajectory steps and the page's frame numbers."""
    with served.client() as client:
        job = client.get(f"/v1/animations/{job_id}").json()
        plan = client.get(f"/v1/animations/{job_id}/plan.json").json()
    assert job["options"].get("fps") == FPS, job["options"]
    assert plan["meta"]["fps"] == FPS
    frames = trajectory(served, job_id)
    assert frames[1]["time_s"] - frames[0]["time_s"] == pytest.approx(1 / FPS)
    assert frames[-1]["frame_idx"] == round(frames[-1]["time_s"] * FPS) == len(frames) - 1
    set_time(probe.page, 1.0)  # one second in is frame 24, not 30
    assert probe.page.get_attribute("[data-testid=joint-panel]", "data-frame") == str(FPS)
    assert probe.page.text_content("[data-testid=time]").endswith(f"frame {FPS}")
    return job


def test_submit_a_zip_at_24_fps(probe: PageProbe, served: Served, example_zip: Path) -> None:
    page = probe.page
    sign_in(probe)
    page.set_input_files("[data-testid=asset-file]", [str(example_zip)])
    job_id = _submit(probe, "press the pedal to open the bin (zip)")
    job = _check_rate(probe, served, job_id)
    with served.client() as client:
        asset = client.get(f"/v1/assets/{job['asset_id']}").json()
        assert client.get(f"/v1/animations/{job_id}/report.json").json()["provider"] == "offline"
    assert asset["filename"].startswith("pedal_bin"), asset
    state["asset_id"] = job["asset_id"]
    probe.shot("15-zip-24fps")


def test_submit_an_earlier_asset_at_24_fps(probe: PageProbe, served: Served) -> None:
    page = probe.page
    asset_id = state["asset_id"]
    page.wait_for_selector(f"#earlier-asset option[value='{asset_id}']", state="attached")
    assert page.eval_on_selector("[data-testid=asset-file]", "input => input.files.length") == 0  # emptied after the upload
    page.select_option("#earlier-asset", asset_id)
    with served.client() as client:
        assets_before = {asset["id"] for asset in client.get("/v1/assets", params={"limit": 100}).json()["data"]}
    job_id = _submit(probe, "open the bin with the pedal, then let go (earlier asset)")
    job = _check_rate(probe, served, job_id)
    assert job["asset_id"] == asset_id
    with served.client() as client:
        after = {asset["id"] for asset in client.get("/v1/assets", params={"limit": 100}).json()["data"]}
    assert asset_id in after and after == assets_before  # nothing uploaded again
