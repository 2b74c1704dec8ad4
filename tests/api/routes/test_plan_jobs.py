"""POST /v1/animations with ``plan``: checked at submission (422 naming the field), run by the
worker's task function with the executor and exporters only, report.json says so."""

from __future__ import annotations

import json
from typing import Any

import pytest

from app.engine.run import PLAN_STATE
from tests.support import upload_assets as assets

tasks = pytest.importorskip("workers.tasks")


def hinge_plan(target: float = 1.2, **changes: Any) -> dict[str, Any]:
    plan: dict[str, Any] = {
        "meta": {"fps": 30, "duration_s": 1.5},
        "timeline": [{"name": "open_lid", "phase_type": "effect_motion", "t0": 0.0, "t1": 1.0,
                      "controls": [{"mode": "joint_position", "joint": "lid_hinge", "q_target_rad": target, "curve": "ease_in_out"}]}],
    }
    plan.update(changes)
    return plan


def submit_plan(http, headers, plan: Any, upload=None, **fields):  # type: ignore[no-untyped-def]
    name, data = upload or assets.hinge_zip("-plan")
    text = plan if isinstance(plan, str) else json.dumps(plan)
    return http.post("/v1/animations", headers=headers, data={"plan": text, **fields}, files=[("asset", (name, data))])


def test_plan_job_runs_executor_and_exporters_only(http, alice, settings, sent) -> None:
    response = submit_plan(http, alice.headers, hinge_plan(1.2), prompt="lid to 1.2 rad")
    assert response.status_code == 202, response.text
    url = response.json()["url"]
    job = http.get(url, headers=alice.headers).json()
    assert job["prompt"] == "lid to 1.2 rad" and job["options"]["source"] == "plan"
    assert tasks.execute_job(str(sent[0]), settings=settings, worker="inline-test").value == "succeeded"
    job = http.get(url, headers=alice.headers).json()
    assert job["status"] == "succeeded", job
    names = {a["name"] for a in job["artifacts"]}
    assert {"animation.glb", "trajectory.jsonl", "plan.json", "report.json"} <= names and "causal.json" not in names
    report = http.get(f"{url}/report.json", headers=alice.headers).json()
    assert report["provider"] == "plan" and report["final_state"] == PLAN_STATE
    assert report["role_calls"] == [] and report["critic_rounds"] == []
    frames = [json.loads(line) for line in http.get(f"{url}/trajectory.jsonl", headers=alice.headers).text.splitlines()]
    assert frames[-1]["joint_angles"]["lid_hinge"] == pytest.approx(1.2)
    assert http.get(f"{url}/plan.json", headers=alice.headers).json()["timeline"][0]["controls"][0]["q_target_rad"] == 1.2


def test_plan_without_a_label_is_listed_as_plan(http, alice) -> None:
    url = submit_plan(http, alice.headers, hinge_plan()).json()["url"]
    assert http.get(url, headers=alice.headers).json()["prompt"] == "(plan)"


@pytest.mark.parametrize(
    ("plan", "field"),
    [
        (hinge_plan(timeline=[{"name": "x", "phase_type": "hold", "t0": 1.0, "t1": 0.5, "controls": []}]), "timeline[0].t1"),
        (hinge_plan(meta={"fps": 25, "duration_s": 1.0}), "meta.fps"),
        ({"meta": {"fps": 30, "duration_s": 1.0}, "timeline": [{"name": "a", "phase_type": "hold", "t0": 0, "t1": 1,
          "controls": [{"mode": "joint_position", "joint": "no_such_joint", "q_target_rad": 1.0}]}]}, "timeline[0].controls[0].joint"),
        ({"meta": {"fps": 30, "duration_s": 1.0}, "timeline": [{"name": "a", "phase_type": "hold", "t0": 0, "t1": 1,
          "controls": [{"mode": "joint_position", "joint": "lid_hinge", "q_target_expr": "upper_limit +"}]}]}, "timeline[0].controls[0].q_target_expr"),
        ({"meta": {"fps": 30, "duration_s": 1.0}, "timeline": [{"name": "a", "phase_type": "wiggle", "t0": 0, "t1": 1}]}, "timeline[0].phase_type"),
        ({"meta": {"fps": 30, "duration_s": 1.0}}, "timeline"),
    ],
)
def test_bad_plans_are_422_naming_the_field(http, alice, sent, plan, field) -> None:
    response = submit_plan(http, alice.headers, plan)
    assert response.status_code == 422, response.text
    body = response.json()
    assert body["field"] == "plan" and any(issue.startswith(field) for issue in body["issues"]), body
    assert field in body["detail"] or body["issues"][0] in body["detail"]
    assert sent == [] and http.get("/v1/animations", headers=alice.headers).json()["count"] == 0


def test_plan_that_is_not_json_names_line_and_column(http, alice, sent) -> None:
    response = submit_plan(http, alice.headers, '{"meta": {"fps": 30,\n "duration_s": }')
    assert response.status_code == 422
    assert "line 2 column" in response.json()["detail"] and sent == []


def test_plan_check_reports_issues_and_warnings(http, alice) -> None:
    asset = http.post("/v1/assets", headers=alice.headers, files=[("asset", assets.hinge_zip("-check"))]).json()
    url = f"/v1/assets/{asset['id']}/plan-check"
    good = http.post(url, headers=alice.headers, json=hinge_plan(1.0)).json()
    assert good == {"valid": True, "issues": [], "warnings": []}
    clamped = http.post(url, headers=alice.headers, json=hinge_plan(3.0)).json()
    assert clamped["valid"] and "clamped" in clamped["warnings"][0]
    bad = http.post(url, headers=alice.headers, json={"meta": {"fps": 30, "duration_s": 1}, "timeline": []}).json()
    assert not bad["valid"] and bad["issues"][0].startswith("timeline")
    assert http.post(url, headers={}, json=hinge_plan()).status_code == 401


def test_prompt_or_plan_is_required(http, alice) -> None:
    response = http.post("/v1/animations", headers=alice.headers, files=[("asset", assets.hinge_zip())])
    assert response.status_code == 422 and "plan" in json.dumps(response.json())


def test_plan_as_a_file_part(http, alice, sent) -> None:
    name, data = assets.hinge_zip("-planfile")
    files = [("asset", (name, data)), ("plan", ("plan.json", json.dumps(hinge_plan(0.5)).encode()))]
    response = http.post("/v1/animations", headers=alice.headers, files=files)
    assert response.status_code == 202, response.text
    twice = http.post("/v1/animations", headers=alice.headers, data={"plan": json.dumps(hinge_plan())},
                      files=[*files[:1], ("plan", ("plan.json", b"{}"))])
    assert twice.status_code == 422 and twice.json()["field"] == "plan"
    binary = http.post("/v1/animations", headers=alice.headers, files=[files[0], ("plan", ("plan.json", b"\xff\xfe\x00"))])
    assert binary.status_code == 422 and "UTF-8" in binary.json()["detail"]
