"""``benchmark.runner.evaluate``: statuses, worst scores, summary, byte-determinism, jobs."""

from __future__ import annotations

import json

import pytest

from app.engine.errors import MetricError
from benchmark.cases import read_cases
from benchmark.runner import evaluate, timing_path


@pytest.fixture(scope="module")
def result(bench, tmp_path_factory):
    out = tmp_path_factory.mktemp("out") / "results.json"
    document = evaluate(bench["cases"], bench["assets"], bench["pred"], out, jobs=1)
    return out, document


def _case(document, case_id):
    return next(c for c in document["cases"] if c["case_id"] == case_id)


def test_statuses_and_scores(result):
    _, document = result
    assert [c["status"] for c in document["cases"]] == [
        "scored",
        "scored",
        "no_prediction",
        "scored",
        "prediction_error",
        "case_error",
    ]
    perfect = _case(document, "safe_101593_open_door")
    assert (perfect["P_gIoU"], perfect["P_PC"], perfect["P_OccF1"]) == (1.0, 1.0, 1.0)
    assert perfect["matched_frames"] == [15, 42, 45, 46] and perfect["prediction"] == "trajectory.jsonl"
    half = _case(document, "microwave_7119_open_door")
    assert all(half[m] < 1.0 for m in ("P_gIoU", "P_PC", "P_OccF1"))
    glb = _case(document, "toaster_103477_press_lever")
    assert glb["prediction"] == "animation.glb" and glb["P_gIoU"] > 0.9999


def test_cases_without_a_usable_prediction_score_worst_and_count(result):
    _, document = result
    for case_id in ("microwave_7119_turn_tray", "storage_19179_lift"):
        case = _case(document, case_id)
        assert (case["P_gIoU"], case["P_PC"], case["P_OccF1"]) == (-1.0, 0.0, 0.0)
        assert case["matched_frames"] is None and case["states"]
    assert "joint 'joint_0' value is not a finite number" in _case(document, "storage_19179_lift")["error"]
    summary = document["summary"]
    assert summary["counted"] == 5 and summary["by_status"]["case_error"] == 1
    assert summary["overall"]["n"] == 5
    gious = [c["P_gIoU"] for c in document["cases"] if c["status"] != "case_error"]
    assert summary["overall"]["P_gIoU"]["mean"] == pytest.approx(sum(gious) / 5)
    assert summary["by_motion_type"]["independent"]["n"] == 2


def test_a_broken_case_is_reported_not_scored(result):
    _, document = result
    broken = _case(document, "broken_subject")
    assert broken["P_gIoU"] is None and "constraints[0].subject" in broken["error"]


def test_per_state_and_per_link_detail(result):
    _, document = result
    states = _case(document, "safe_101593_open_door")["states"]
    assert [s["phase"] for s in states] == ["knob_turn_unlatch", "knob_self_return", "door_open", "hold_end_state"]
    assert states[2]["dynamic_links"] == ["link_0", "link_1", "link_2"]
    assert {link["link"] for link in states[0]["links"]} == {"link_3", "link_0", "link_1", "link_2"}


def test_output_is_byte_identical_across_runs_and_jobs(bench, result, tmp_path):
    out, _ = result
    again = tmp_path / "again.json"
    parallel = tmp_path / "parallel.json"
    evaluate(bench["cases"], bench["assets"], bench["pred"], again, jobs=1)
    evaluate(bench["cases"], bench["assets"], bench["pred"], parallel, jobs=2)
    assert again.read_bytes() == out.read_bytes()
    assert parallel.read_bytes() == out.read_bytes()
    timing = json.loads(timing_path(parallel).read_text())
    assert timing["jobs"] == 2 and len(timing["cases"]) == 6 and timing["cases"][0]["timing_s"]["total"] > 0


def test_node_map_option_reads_foreign_glbs(bench, tmp_path, partnet):
    from app.engine.asset.loader import load_asset
    from app.engine.metrics.compiler import compile_case
    from benchmark.synthetic import deleted_link_glb

    case = read_cases(bench["cases"])[0]
    asset = load_asset(partnet / case.asset)
    pred = tmp_path / "pred"
    deleted_link_glb(asset, compile_case(case, asset).trajectory, "link_0", pred / case.case_id / "animation.glb")
    cases = tmp_path / "one.jsonl"
    cases.write_text(bench["cases"].read_text().splitlines()[0] + "\n")
    plain = evaluate(cases, bench["assets"], pred, tmp_path / "plain.json")
    node_map = tmp_path / "map.json"
    node_map.write_text(json.dumps({"nodes": {"renamed_link_0": "link_0"}, "up_axis": "Y"}))
    mapped = evaluate(cases, bench["assets"], pred, tmp_path / "mapped.json", node_map=node_map)
    assert plain["cases"][0]["P_gIoU"] < 0.9 < 0.9999 < mapped["cases"][0]["P_gIoU"]
    assert any("scored worst" in note for note in plain["cases"][0]["notes"])


def test_with_2d_adds_the_mask_metrics(bench, tmp_path):
    cases = tmp_path / "two.jsonl"
    cases.write_text("\n".join(bench["cases"].read_text().splitlines()[:2]) + "\n")
    document = evaluate(cases, bench["assets"], bench["pred"], tmp_path / "2d.json", with_2d=True)
    perfect, half = document["cases"]
    assert (perfect["P_MaskIoU"], perfect["P_BoundaryF1"], perfect["P_ContourCD"]) == (1.0, 1.0, 0.0)
    assert half["P_MaskIoU"] < 1.0 and half["P_ContourCD"] > 0.0
    assert document["summary"]["metrics"][-3:] == ["P_MaskIoU", "P_BoundaryF1", "P_ContourCD"]


@pytest.mark.parametrize(
    ("content", "message"),
    [
        ("not json\n", "line 1: not JSON"),
        (
            '{"case_id": "a", "asset": "x", "prompt": "p", "motion_type": "funny", "phases": [{"id": "p", "order": 0}]}\n',
            "line 1 (case a): motion_type",
        ),
        (
            '{"case_id": "a/b", "asset": "x", "prompt": "p", "motion_type": "independent", "phases": [{"id": "p", "order": 0}]}\n',
            "cannot name a prediction folder",
        ),
        (
            '{"case_id": "a", "asset": "../x", "prompt": "p", "motion_type": "independent", "phases": [{"id": "p", "order": 0}]}\n',
            "must be a folder name",
        ),
        ("\n", "no cases"),
    ],
)
def test_bad_cases_files_name_the_line_and_field(tmp_path, content, message):
    path = tmp_path / "cases.jsonl"
    path.write_text(content)
    with pytest.raises(MetricError, match=message.replace("(", r"\(").replace(")", r"\)")):
        read_cases(path)


def test_duplicate_case_ids_are_rejected(bench, tmp_path):
    line = bench["cases"].read_text().splitlines()[0]
    path = tmp_path / "dup.jsonl"
    path.write_text(line + "\n" + line + "\n")
    with pytest.raises(MetricError, match="repeats line 1"):
        read_cases(path)
