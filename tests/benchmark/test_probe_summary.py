"""``benchmark.probe.summarize``: outcomes per prompt, with wrong answers split by warning and right answers that warned counted."""

from __future__ import annotations

import json

from benchmark.probe import summarize

ROWS = [("p1", "RIGHT", 0, []), ("p2", "RIGHT", 0, ["loose match"]), ("p3", "WRONG", 0, ["check the result"]),
        ("p4", "WRONG", 0, []), ("p5", "WRONG", 1, []), ("p6", "RIGHT", 1, [])]


def test_summary_counts_each_outcome(tmp_path):
    expect = tmp_path / "expect.jsonl"
    expect.write_text("".join(json.dumps({"id": i, "type": "single", "expect": {"refuse": i == "p6"}}) + "\n" for i, *_ in ROWS))
    verdicts = []
    for rid, verdict, rc, warnings in ROWS:
        verdicts.append({"id": rid, "type": "single", "verdict": verdict, "rc": rc, "prompt": rid, "errs": []})
        (tmp_path / "runs" / rid).mkdir(parents=True)
        (tmp_path / "runs" / rid / "report.json").write_text(json.dumps({"warnings": warnings}))
    (tmp_path / "auto_verdicts.json").write_text(json.dumps(verdicts))
    summary = summarize(tmp_path, expect)
    assert summary["types"]["all"] == {"n": 6, "right": 3, "rate": 0.5, "right_warned": 1, "wrong_warned": 1, "wrong_refusal": 1, "wrong_silent": 1}
    assert [c["outcome"] for c in summary["cases"]] == ["right", "right", "wrong_warned", "wrong_silent", "wrong_refusal", "right"]


def test_a_range_missed_at_a_rounded_limit_is_told_apart() -> None:
    from benchmark.probe import bound_slip

    assert bound_slip(["joint_0 final 2.96706 not in [2.2,2.967]"])
    assert not bound_slip(["joint_0 final 2.5 not in [2.6,2.967]"])
    assert not bound_slip(["joint_0 final 2.96706 not in [2.2,2.967]", "joint_1 did not move"])
    assert not bound_slip([])
