"""3D case scores on real PartNet assets: perfect == 1 exactly, every degradation strictly lower."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from app.engine.export.glb import export_glb
from app.engine.export.jsonl import read_trajectory_jsonl, write_trajectory_jsonl
from app.engine.metrics.compiler import compile_case
from app.engine.metrics.prediction import NodeMap, load_prediction
from app.engine.metrics.results import METRICS_3D
from app.engine.metrics.scoring import score_case, weighted
from app.engine.metrics.sequence import empty_sequence, trajectory_sequence
from benchmark.synthetic import degraded_trajectories, deleted_link_glb, with_values

DEGRADATIONS = ("half_way", "wrong_joint", "reversed", "static", "missing_part")
ORDER_BLIND = {("microwave_7119_open_door", "reversed"), ("microwave_7119_turn_tray", "reversed")}
"""Reversing these sequences keeps every key state in order (K states all reached at once), so
only the terminal check can tell them apart."""


@pytest.fixture(scope="module")
def compiled(smoke_cases, partnet_assets, geometries):
    out = {}
    for case_id, case in smoke_cases.items():
        asset = partnet_assets[case.asset]
        out[case_id] = (asset, geometries[case.asset], compile_case(case, asset))
    return out


def _score(entry, trajectory, **options):
    asset, geometry, truth = entry
    return score_case(asset, geometry, truth, trajectory_sequence(asset, trajectory, "test"), **options)


def test_weighting_renormalises_only_when_a_group_is_empty():
    assert weighted([1.0, 0.0, 0.5], [True, True, False]) == pytest.approx(0.8 * 0.5 + 0.2 * 0.5)
    assert weighted([1.0, 0.0], [True, True]) == 0.5
    assert weighted([0.25, 0.75], [False, False]) == 0.5


@pytest.mark.parametrize(
    "case_id",
    [
        "safe_101593_open_door",
        "microwave_7119_open_door",
        "microwave_7119_turn_tray",
        "toaster_103477_press_lever",
        "storage_19179_lift",
    ],
)
def test_a_perfect_jsonl_prediction_scores_exactly_one(compiled, case_id, tmp_path):
    asset, geometry, truth = compiled[case_id]
    path = write_trajectory_jsonl(truth.trajectory, tmp_path / "trajectory.jsonl")
    scores = score_case(asset, geometry, truth, load_prediction(path, asset))
    assert scores.values == {"P_gIoU": 1.0, "P_PC": 1.0, "P_OccF1": 1.0}
    assert all(link.values == dict.fromkeys(METRICS_3D, 1.0) for state in scores.states for link in state.links)
    assert scores.matched_frames is not None and not scores.padded


@pytest.mark.parametrize(
    "case_id", ["safe_101593_open_door", "microwave_7119_open_door", "toaster_103477_press_lever", "storage_19179_lift"]
)
@pytest.mark.parametrize("degradation", DEGRADATIONS)
def test_degraded_predictions_score_strictly_lower(compiled, case_id, degradation):
    asset, _, truth = compiled[case_id]
    trajectories = degraded_trajectories(asset, truth)
    if degradation not in trajectories:
        pytest.skip(f"{case_id} has no spare joint for {degradation}")
    values = _score(compiled[case_id], trajectories[degradation]).values
    assert all(values[m] <= 1.0 for m in METRICS_3D)
    if (case_id, degradation) in ORDER_BLIND:
        values = _score(compiled[case_id], trajectories[degradation], terminal_check=True).values
    assert sum(values.values()) < 3.0
    if case_id in ("safe_101593_open_door", "storage_19179_lift"):
        assert all(values[m] < 1.0 for m in METRICS_3D), values


def test_reversed_order_needs_the_terminal_check_when_every_state_is_reached_at_once(compiled):
    entry = compiled["microwave_7119_open_door"]
    reversed_motion = degraded_trajectories(entry[0], entry[2])["reversed"]
    assert _score(entry, reversed_motion).values["P_gIoU"] == 1.0
    assert _score(entry, reversed_motion, terminal_check=True).values["P_gIoU"] < 0.5
    assert _score(entry, entry[2].trajectory, terminal_check=True).values["P_gIoU"] == 1.0


def test_a_deleted_link_scores_worst_and_is_never_dropped(compiled, tmp_path):
    asset, geometry, truth = compiled["safe_101593_open_door"]
    full = score_case(
        asset, geometry, truth, load_prediction(export_glb(asset, truth.trajectory, tmp_path / "a.glb"), asset)
    )
    cut = score_case(
        asset,
        geometry,
        truth,
        load_prediction(deleted_link_glb(asset, truth.trajectory, "link_0", tmp_path / "b.glb"), asset),
    )
    assert all(cut.values[m] < full.values[m] for m in METRICS_3D)
    door = [link for state in cut.states for link in state.links if link.link == "link_0"]
    assert len(door) == len(truth.key_states)
    assert all(link.missing and link.values == {"P_gIoU": -1.0, "P_PC": 0.0, "P_OccF1": 0.0} for link in door)


def test_a_glb_prediction_scores_one_up_to_float32(compiled, tmp_path):
    asset, geometry, truth = compiled["storage_19179_lift"]
    glb = export_glb(asset, truth.trajectory, tmp_path / "animation.glb")
    scores = score_case(asset, geometry, truth, load_prediction(glb, asset))
    assert all(scores.values[m] > 0.9999 for m in METRICS_3D)
    exact = score_case(asset, geometry, truth, trajectory_sequence(asset, truth.trajectory, "gt"))
    assert scores.matched_frames == exact.matched_frames


def test_a_glbwith_values_foreign_node_names_is_read_through_a_node_map(compiled, tmp_path):
    asset, geometry, truth = compiled["safe_101593_open_door"]
    glb = deleted_link_glb(asset, truth.trajectory, "link_0", tmp_path / "renamed.glb")
    mapped = load_prediction(glb, asset, node_map=NodeMap(nodes={"renamed_link_0": "link_0"}))
    assert mapped.missing == ()
    assert score_case(asset, geometry, truth, mapped).values["P_gIoU"] > 0.9999


def test_glb_frames_are_brought_back_to_z_up(compiled, tmp_path):
    asset, _, truth = compiled["storage_19179_lift"]
    glb = load_prediction(export_glb(asset, truth.trajectory, tmp_path / "animation.glb"), asset)
    reference = trajectory_sequence(asset, truth.trajectory, "gt")
    for link in asset.visual_links:
        assert np.allclose(glb.poses[link], reference.poses[link], atol=1e-5)
    as_is = load_prediction(
        export_glb(asset, truth.trajectory, tmp_path / "b.glb"), asset, node_map=NodeMap(up_axis="Z")
    )
    assert not np.allclose(as_is.poses["link_2"], reference.poses["link_2"], atol=1e-3)


def test_no_prediction_scores_worst(compiled):
    asset, geometry, truth = compiled["toaster_103477_press_lever"]
    scores = score_case(asset, geometry, truth, empty_sequence(asset, "none", "nothing"))
    assert scores.values == {"P_gIoU": -1.0, "P_PC": 0.0, "P_OccF1": 0.0}


def test_predicted_values_are_clamped_to_the_limits(compiled, tmp_path):
    asset, _, truth = compiled["microwave_7119_open_door"]
    trajectory = degraded_trajectories(asset, truth)["half_way"]
    over = trajectory.q.copy()
    column = trajectory.joint_names.index("joint_0")
    over[:, column] = np.where(over[:, column] > 0.5, 7.0, over[:, column])  # far past the upper limit
    clamped = over.copy()
    clamped[:, column] = np.minimum(clamped[:, column], asset.joints["joint_0"].upper)
    first = _score(compiled["microwave_7119_open_door"], with_values(trajectory, over))
    second = _score(compiled["microwave_7119_open_door"], with_values(trajectory, clamped))
    assert first.values == second.values
    assert any("clamped" in note for note in trajectory_sequence(asset, with_values(trajectory, over), "x").notes)


def test_scores_are_deterministic(compiled, tmp_path):
    entry = compiled["safe_101593_open_door"]
    trajectory = degraded_trajectories(entry[0], entry[2])["half_way"]
    assert _score(entry, trajectory).model_dump_json() == _score(entry, trajectory).model_dump_json()


def test_a_jsonl_written_by_another_toolwith_valuesout_mimic_or_time_fields_loads(compiled, tmp_path: Path):
    asset, geometry, truth = compiled["microwave_7119_open_door"]
    lines = [f'{{"joint_angles": {{"joint_0": {q}}}}}' for q in truth.trajectory.joint("joint_0")]
    path = tmp_path / "trajectory.jsonl"
    path.write_text("\n".join(lines) + "\n")
    trajectory, _ = read_trajectory_jsonl(path, asset)
    scores = score_case(asset, geometry, truth, load_prediction(path, asset))
    assert trajectory.frame_count == truth.trajectory.frame_count
    assert scores.values["P_gIoU"] == 1.0
