"""``benchmark.report.write_report``: markdown, CSV tables and charts from an evaluation."""

from __future__ import annotations

import csv

from benchmark.report import write_report
from benchmark.runner import evaluate


def test_report_files(bench, tmp_path):
    out = tmp_path / "results.json"
    evaluate(bench["cases"], bench["assets"], bench["pred"], out)
    report = write_report(out, tmp_path / "report")
    folder = report.parent
    text = report.read_text()
    assert "| State-dependent | 1 | 1.000 ± 0.000 |" in text
    assert "| **Overall** | 5 |" in text
    assert (
        "| safe_101593_open_door | state_dependent | scored | 1.000 | 1.000 | 1.000 | 15 42 45 51 | 15 42 45 46 |"
        in text
    )
    assert "broken_subject` (case_error)" in text and "## Timing" in text
    for name in ("cases.csv", "states.csv", "links.csv", "by_motion_type.csv", "overall.csv", "timing.csv"):
        assert (folder / name).is_file()
    for name in ("by_motion_type.png", "distribution.png", "timing.png"):
        assert (folder / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    rows = list(csv.DictReader((folder / "by_motion_type.csv").open()))
    assert [r["group"] for r in rows] == [
        "independent",
        "mechanically_coupled",
        "state_dependent",
        "environment_mediated",
    ]
    cases = list(csv.DictReader((folder / "cases.csv").open()))
    assert cases[0]["matched_frames"] == "15 42 45 46" and cases[-1]["status"] == "case_error"
    states = list(csv.DictReader((folder / "states.csv").open()))
    assert len(states) == sum(1 for _ in states) and states[0]["phase"] == "knob_turn_unlatch"


def test_report_without_charts_or_timing(bench, tmp_path):
    out = tmp_path / "results.json"
    evaluate(bench["cases"], bench["assets"], bench["pred"], out)
    (tmp_path / "results.timing.json").unlink()
    report = write_report(out, charts=False)
    assert report.parent == tmp_path / "report"
    assert "## Timing" not in report.read_text() and not (tmp_path / "report" / "timing.csv").exists()


def test_contact_sheets_show_gt_above_the_matched_frames(bench, tmp_path):
    from PIL import Image

    out = tmp_path / "results.json"
    evaluate(bench["cases"], bench["assets"], bench["pred"], out)
    report = write_report(
        out,
        charts=False,
        contact_sheets=True,
        cases_file=bench["cases"],
        assets_root=bench["assets"],
        pred_root=bench["pred"],
    )
    sheets = report.parent / "sheets"
    assert sorted(p.stem for p in sheets.glob("*.png")) == sorted(
        [
            "safe_101593_open_door",
            "microwave_7119_open_door",
            "microwave_7119_turn_tray",
            "toaster_103477_press_lever",
            "storage_19179_lift",
        ]
    )
    with Image.open(sheets / "safe_101593_open_door.png") as sheet:
        assert sheet.size[0] > 4 * 240 and sheet.size[1] > 2 * 240  # 4 key states, GT row + prediction row
    assert "[sheet](sheets/safe_101593_open_door.png)" in report.read_text()
