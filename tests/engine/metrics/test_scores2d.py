"""2D variants: rasterised per-link masks (EGL), perfect == 1/1/0, degradations worse."""

from __future__ import annotations

import pytest

from app.engine.metrics.compiler import compile_case
from app.engine.metrics.results import METRICS_2D
from app.engine.metrics.scores2d import MASK_SIZE_PX, add_2d_scores, mask_camera
from app.engine.metrics.scoring import ground_truth_sequence, score_case
from app.engine.metrics.sequence import empty_sequence, trajectory_sequence
from benchmark.synthetic import degraded_trajectories


@pytest.fixture(scope="module")
def safe(smoke_cases, partnet_assets, geometries):
    case = smoke_cases["safe_101593_open_door"]
    asset = partnet_assets[case.asset]
    return asset, geometries[case.asset], compile_case(case, asset)


def _scores(safe, sequence):
    asset, geometry, truth = safe
    return add_2d_scores(asset, geometry, truth, sequence, score_case(asset, geometry, truth, sequence))


def test_the_camera_is_fixed_at_256_px_azimuth_0_elevation_20_fov_35(safe):
    asset, geometry, truth = safe
    camera = mask_camera(asset, geometry, ground_truth_sequence(asset, truth))
    assert (camera.width, camera.height, camera.fov_deg) == (MASK_SIZE_PX, MASK_SIZE_PX, 35.0)
    direction = (camera.eye - camera.target) / ((camera.eye - camera.target) ** 2).sum() ** 0.5
    assert direction[1] == pytest.approx(0.0, abs=1e-12) and direction[2] == pytest.approx(0.3420201433, abs=1e-9)


def test_perfect_prediction_scores_one_one_zero(safe):
    asset, _, truth = safe
    values = _scores(safe, trajectory_sequence(asset, truth.trajectory, "gt")).values
    assert [values[m] for m in METRICS_2D] == [1.0, 1.0, 0.0]


def test_half_way_prediction_scores_worse_on_every_2d_metric(safe):
    asset, _, truth = safe
    scores = _scores(safe, trajectory_sequence(asset, degraded_trajectories(asset, truth)["half_way"], "half"))
    assert (
        scores.values["P_MaskIoU"] < 1.0 and scores.values["P_BoundaryF1"] < 1.0 and scores.values["P_ContourCD"] > 0.0
    )
    door = [link for state in scores.states for link in state.links if link.link == "link_0"]
    assert door[-1].values["P_MaskIoU"] < 0.9  # the door ends half open


def test_missing_prediction_scores_worst_in_2d(safe):
    asset, _, _ = safe
    values = _scores(safe, empty_sequence(asset, "none", "nothing")).values
    assert [values[m] for m in METRICS_2D] == [0.0, 0.0, 1.0]
