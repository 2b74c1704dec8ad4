"""Typed seams: execution events, patches (and undoing), staged outputs."""

from __future__ import annotations

from pathlib import Path

import pytest

from app.engine.agents.actor import repair
from app.engine.agents.critique import Critique, FixHint
from app.engine.asset.loader import load_asset
from app.engine.execute.executor import execute
from app.engine.plan.schema import Plan
from app.engine.staging import PARTIAL_PREFIX, Staging


def _plan(joint: str, **control: object) -> Plan:
    return Plan.model_validate({"meta": {"fps": 30, "duration_s": 1.0}, "timeline": [
        {"name": "a", "phase_type": "effect_motion", "t0": 0.0, "t1": 1.0, "controls": [{"mode": "joint_position", "joint": joint, **control}]}]})


def test_execution_events_are_typed(examples_dir: Path) -> None:
    asset = load_asset(examples_dir / "oven")
    trajectory = execute(_plan("door_hinge", q_target_rad=9.0), asset)
    warning, event = trajectory.events
    assert warning.kind == "plan_warning" and "will be clamped" in warning.message
    assert event.kind == "target_clamped" and event.joint == "door_hinge" and event.where == "timeline[0].controls[0]"
    assert event.value == pytest.approx(asset.joints["door_hinge"].upper) and trajectory.event_messages == [warning.message, event.message]


def test_patches_are_typed_and_an_undo_is_recognised(examples_dir: Path) -> None:
    asset = load_asset(examples_dir / "oven")
    plan = _plan("door_hinge", q_target_rad=0.5)
    hint = FixHint(type="adjust_joint_target", joint="door_hinge", segment_index=0, phase_type="effect_motion", direction="increase", strength="medium")
    bigger, (first,) = repair(plan, Critique(param_fix_hints=[hint]), asset, execute(plan, asset))
    assert first.change == "target" and first.value_before == pytest.approx(0.5) and first.value_after == pytest.approx(0.6)
    assert isinstance(bigger, Plan) and bigger.timeline[0].controls[0].q_target_rad == pytest.approx(0.6)  # type: ignore[union-attr]
    back = hint.model_copy(update={"direction": "decrease"})
    _, (second,) = repair(bigger, Critique(param_fix_hints=[back]), asset, execute(bigger, asset))
    assert second.undoes(first) and not first.undoes(second.model_copy(update={"segment_index": 1}))
    exact = hint.model_copy(update={"factor": 1.5})
    _, (third,) = repair(plan, Critique(param_fix_hints=[exact]), asset, execute(plan, asset))
    assert third.value_after == pytest.approx(0.75)


def test_staging_replaces_previous_outputs_and_keeps_other_files(tmp_path: Path) -> None:
    for name in ("animation.glb", "plan.json", "report.json", "mine.txt"):
        (tmp_path / name).write_text("old")
    (tmp_path / "images").mkdir()
    (tmp_path / "images" / "old.png").write_text("old")
    with Staging(tmp_path) as staging:
        (staging.path / "report.json").write_text("new")
        (staging.path / "animation.glb").write_text("new")
        staging.publish(only=("report.json",))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine.txt", "report.json"]
    assert (tmp_path / "report.json").read_text() == "new" and not any(p.name.startswith(PARTIAL_PREFIX) for p in tmp_path.iterdir())
