"""POST /v1/benchmarks and GET /v1/batches/{id}/scores: annotated cases run as a batch, scored by the
benchmark's evaluator (same numbers as ``artimo bench``), with GT-vs-prediction key states."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.engine.asset.loader import load_asset
from app.engine.metrics.annotation import Case
from app.engine.metrics.evaluate import evaluate_case
from app.engine.metrics.geometry import build_geometry

tasks = pytest.importorskip("workers.tasks")

REPO = Path(__file__).resolve().parents[3]
CASES = [json.loads(line) for line in (REPO / "benchmark" / "cases" / "dev_examples.jsonl").read_text().splitlines() if '"asset": "pedal_bin"' in line][:2]


def _upload_pedal_bin(http, headers) -> str:  # type: ignore[no-untyped-def]
    urdf = (REPO / "examples" / "pedal_bin" / "pedal_bin.urdf").read_bytes()
    response = http.post("/v1/assets", headers=headers, files=[("asset", ("pedal_bin/pedal_bin.urdf", urdf))])
    assert response.status_code in (200, 201), response.text
    return str(response.json()["id"])


def test_benchmark_batch_is_scored_like_the_benchmark(http, alice, settings, sent, tmp_path) -> None:
    asset_id = _upload_pedal_bin(http, alice.headers)
    body = {"name": "pedal bin", "cases": [{**case, "asset": asset_id} for case in CASES]}
    response = http.post("/v1/benchmarks", headers=alice.headers, json=body)
    assert response.status_code == 202, response.text
    batch = response.json()
    scores_url = f"/v1/batches/{batch['id']}/scores"
    pending = http.get(scores_url, headers=alice.headers).json()
    assert [c["note"] for c in pending["cases"]] == ["not finished"] * 2 and pending["summary"]["scored"] == 0
    first, second = sent
    assert tasks.execute_job(str(first), settings=settings, worker="inline").value == "succeeded"
    http.delete(f"/v1/animations/{second}", headers=alice.headers)  # a cancelled case scores as missing
    scores = http.get(scores_url, headers=alice.headers).json()
    by_case = {c["case_id"]: c for c in scores["cases"]}
    done, cancelled = by_case[CASES[0]["case_id"]], by_case[CASES[1]["case_id"]]
    assert done["status"] == "succeeded" and cancelled["status"] == "cancelled"
    assert cancelled["values"]["P_gIoU"] == -1.0 and "missing" in cancelled["note"]
    # the same numbers as the evaluator on the downloaded prediction
    prediction = tmp_path / "trajectory.jsonl"
    prediction.write_bytes(http.get(f"/v1/animations/{first}/trajectory.jsonl", headers=alice.headers).content)
    asset = load_asset(REPO / "examples" / "pedal_bin", name="pedal_bin")
    expected = evaluate_case(Case.model_validate(CASES[0]), asset, build_geometry(asset), prediction).scores
    assert expected is not None and done["values"] == pytest.approx(expected.values)
    assert done["values"]["P_gIoU"] > 0.9
    state = done["states"][0]
    assert set(state["gt_joints"]) == {"lid_hinge", "pedal_pivot"} and set(state["pred_joints"]) == set(state["gt_joints"])
    assert scores["summary"]["scored"] == 2
    assert scores["summary"]["P_gIoU"] == pytest.approx((done["values"]["P_gIoU"] - 1.0) / 2)
    again = http.get(scores_url, headers=alice.headers).json()  # kept, not recomputed
    assert again == scores


def test_scores_of_a_plain_batch_or_another_client_are_404(http, alice, bob) -> None:
    asset_id = _upload_pedal_bin(http, alice.headers)
    plain = http.post("/v1/batches", headers=alice.headers, json={"cases": [{"asset": asset_id, "prompt": "open the lid"}]}).json()
    response = http.get(f"/v1/batches/{plain['id']}/scores", headers=alice.headers)
    assert response.status_code == 404 and "not a benchmark batch" in response.json()["detail"]
    bench = http.post("/v1/benchmarks", headers=alice.headers, json={"cases": [{**CASES[0], "asset": asset_id}]}).json()
    assert http.get(f"/v1/batches/{bench['id']}/scores", headers=bob.headers).status_code == 404


@pytest.mark.parametrize(("change", "where"), [
    ({"asset": "0" * 64}, "cases[0].asset"),
    ({"phases": []}, "phases"),
    ({"motion_type": "teleport"}, "motion_type"),
])
def test_bad_benchmark_cases_are_422(http, alice, sent, change, where) -> None:
    asset_id = _upload_pedal_bin(http, alice.headers)
    response = http.post("/v1/benchmarks", headers=alice.headers, json={"cases": [{**CASES[0], "asset": asset_id, **change}]})
    assert response.status_code == 422 and where in json.dumps(response.json()), response.text
    assert sent == []
