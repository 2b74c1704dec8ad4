"""Jobs through the real stack: uvicorn API -> Redis -> a real Celery worker -> Postgres + storage."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from app.client import ArtimoClient
from tests.support.gltf_validator import assert_valid
from tests.workers import stack
from tests.workers.conftest import TEST_API_KEY
from tests.workers.jobs import PEDAL_BIN, PEDAL_PROMPT

JOB_TIMEOUT_S = 60.0
POLL_S = 0.05


@pytest.fixture(scope="module")
def worker(service_env: dict[str, str], log_dir: Path, api: str) -> Iterator[stack.Service]:
    """One worker (concurrency 1) for the module; started after the API so it finds the schema."""
    started = stack.start_worker("w-life", service_env, log_dir)
    yield started
    started.stop()


@pytest.fixture()
def client(api: str, worker: stack.Service) -> Iterator[ArtimoClient]:
    with ArtimoClient(api, TEST_API_KEY) as http:
        yield http


def _wait_for(client: ArtimoClient, job_id: str, predicate: Any, what: str) -> dict[str, Any]:
    def check() -> dict[str, Any] | None:
        job = client.get(job_id)
        return job if predicate(job) else None

    return stack.wait_until(check, JOB_TIMEOUT_S, POLL_S, what)  # type: ignore[no-any-return]


def test_submit_run_succeed_download(client: ArtimoClient, tmp_path: Path) -> None:
    accepted = client.submit(PEDAL_BIN, PEDAL_PROMPT)
    assert accepted["status"] == "queued"
    running = _wait_for(client, accepted["id"], lambda j: j["status"] == "running" and 0 < j["progress"] < 100, "running with progress")
    assert running["stage"] in {"load_asset", "preprocess", "perceive", "plan", "refine", "export"}
    assert running["attempts"] == 1
    done = client.wait(accepted["id"], timeout=JOB_TIMEOUT_S, poll=POLL_S)
    assert done["status"] == "succeeded" and done["progress"] == 100 and done["error"] is None
    assert {"load_asset", "perceive", "plan", "refine", "export", "total"} <= set(done["timings"])
    names = sorted(a["name"] for a in done["artifacts"])
    assert names == ["animation.glb", "causal.json", "interaction.json", "plan.json", "report.json", "trajectory.jsonl"]
    written = client.download(accepted["id"], tmp_path)
    assert sorted(p.name for p in written) == names
    glb = tmp_path / "animation.glb"
    assert glb.read_bytes()[:4] == b"glTF"
    assert_valid([glb])
    lines = (tmp_path / "trajectory.jsonl").read_text().splitlines()
    assert len(lines) > 10 and '"lid_hinge"' in lines[-1]


def test_preview_option_adds_a_gif_artifact(client: ArtimoClient, tmp_path: Path) -> None:
    accepted = client.submit(PEDAL_BIN, PEDAL_PROMPT, preview=True)
    done = client.wait(accepted["id"], timeout=JOB_TIMEOUT_S, poll=POLL_S)
    assert done["status"] == "succeeded" and done["options"]["preview"] is True and "preview" in done["timings"]
    (gif,) = [a for a in done["artifacts"] if a["name"] == "preview.gif"]
    assert gif["content_type"] == "image/gif" and gif["url"].endswith("/files/preview.gif")
    (written,) = client.download(accepted["id"], tmp_path, names=["preview.gif"])
    assert written.read_bytes()[:6] == b"GIF89a"


def test_exports_option_adds_artifacts_each_ecosystem_reads(client: ArtimoClient, tmp_path: Path) -> None:
    import mujoco
    import numpy as np
    from pxr import Usd, UsdGeom

    accepted = client.submit(PEDAL_BIN, PEDAL_PROMPT, exports=["usd", "mjcf", "ros", "csv", "npz"])
    done = client.wait(accepted["id"], timeout=JOB_TIMEOUT_S, poll=POLL_S)
    assert done["status"] == "succeeded" and done["options"]["exports"] == ["usd", "mjcf", "ros", "csv", "npz"]
    types = {a["name"]: a["content_type"] for a in done["artifacts"]}
    assert types["animation.usda"] == "model/vnd.usda" and types["scene.xml"] == "application/xml"
    assert {"joint_trajectory.json", "trajectory.csv", "trajectory.npz", "interaction.json"} <= set(types)
    names = ["animation.usda", "scene.xml", "joint_trajectory.json", "trajectory.csv", "trajectory.npz", "interaction.json"]
    client.download(accepted["id"], tmp_path, names=names)
    stage = Usd.Stage.Open(str(tmp_path / "animation.usda"))
    assert UsdGeom.GetStageUpAxis(stage) == "Z" and stage.GetPrimAtPath("/pedal_bin/body/lid").IsValid()
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "scene.xml"))
    assert model.nkey >= 2 and mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, "lid_hinge") >= 0
    with np.load(tmp_path / "trajectory.npz", allow_pickle=False) as arrays:
        assert "lid_hinge" in arrays.files
    interactions = json.loads((tmp_path / "interaction.json").read_text())["interactions"]
    assert [(i["link"], i["action"]) for i in interactions] == [("pedal", "push")]
    response = client._request("GET", f"/v1/animations/{accepted['id']}/scene.xml")
    assert response.content == (tmp_path / "scene.xml").read_bytes()


def test_ungroundable_prompt_fails_with_engine_message(client: ArtimoClient) -> None:
    accepted = client.submit(PEDAL_BIN, "fly to the moon")
    done = client.wait(accepted["id"], timeout=JOB_TIMEOUT_S, poll=POLL_S)
    assert done["status"] == "failed" and done["error_kind"] == "GroundingError"
    assert "Movable parts of pedal_bin" in done["error"] and "lid_hinge" in done["error"]
    assert [a["name"] for a in done["artifacts"]] == ["report.json"]


def test_cancel_queued_job(client: ArtimoClient, worker: stack.Service) -> None:
    busy = client.submit(PEDAL_BIN, PEDAL_PROMPT)  # occupies the single worker
    _wait_for(client, busy["id"], lambda j: j["status"] == "running", "first job running")
    waiting = client.submit(PEDAL_BIN, PEDAL_PROMPT)
    assert client.get(waiting["id"])["status"] == "queued"
    cancelled = client.cancel(waiting["id"])
    assert cancelled["status"] == "cancelled"
    assert client.wait(busy["id"], timeout=JOB_TIMEOUT_S, poll=POLL_S)["status"] == "succeeded"
    dropped = f"job {waiting['id']} is already cancelled; redelivery skipped"
    stack.wait_until(lambda: dropped in worker.text(), JOB_TIMEOUT_S, what="the worker to drop the cancelled job")
    later = client.get(waiting["id"])
    assert later["status"] == "cancelled" and later["attempts"] == 0 and later["artifacts"] == []


def test_cancel_running_job(client: ArtimoClient) -> None:
    accepted = client.submit(PEDAL_BIN, PEDAL_PROMPT)
    _wait_for(client, accepted["id"], lambda j: j["status"] == "running" and j["stage"] is not None, "running")
    client.cancel(accepted["id"])
    done = client.wait(accepted["id"], timeout=JOB_TIMEOUT_S, poll=POLL_S)
    assert done["status"] == "cancelled" and done["cancel_requested"]
    assert "animation.glb" not in {a["name"] for a in done["artifacts"]}


def test_benchmark_submit_runs_cases_through_the_service(api: str, worker: stack.Service, tmp_path: Path) -> None:
    """``python -m benchmark.submit``: upload once, one batch, downloads under OUT/<case_id>/, evaluation."""
    from benchmark.submit import main as submit_main

    source = stack.REPO / "benchmark" / "cases" / "dev_examples.jsonl"
    picked = [line for line in source.read_text().splitlines() if '"asset": "pedal_bin"' in line][:2]
    assert len(picked) == 2
    cases = tmp_path / "cases.jsonl"
    cases.write_text("\n".join(picked) + "\n")
    out = tmp_path / "out"
    code = submit_main(["--server", api, "--key", TEST_API_KEY, "--cases", str(cases), "--assets", str(stack.REPO / "examples"),
                        "--out", str(out), "--poll", "0.1", "--jobs", "1"])
    assert code == 0
    runs = json.loads((out / "service_runs.json").read_text())
    assert [c["status"] for c in runs["cases"]] == ["succeeded", "succeeded"] and len(runs["batches"]) == 1
    for record in runs["cases"]:
        assert sorted(p.name for p in (out / record["case_id"]).iterdir()) == ["animation.glb", "trajectory.jsonl"]
    summary = json.loads((out / "evaluation.json").read_text())["summary"]
    assert summary["by_status"]["scored"] == 2
