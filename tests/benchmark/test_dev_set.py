"""The annotated dev set (benchmark/cases/dev.jsonl on PartNet-Mobility, dev_examples.jsonl on examples/).

Checks the files themselves (parse, unique ids, coverage), each case against its asset
(subjects, limits, self-return rests, compilation into K >= 1 key states), rolling without
slipping for wheeled objects, and that the GT trajectory itself, written as a
trajectory.jsonl and read back, scores exactly 1 on the three 3D metrics.
"""

from __future__ import annotations

import functools
import math
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

from app.engine.asset.kinematics import link_poses
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.export.jsonl import write_trajectory_jsonl
from app.engine.metrics.annotation import BASE_SUBJECT, MOTION_TYPES, Case
from app.engine.metrics.compiler import GroundTruth, compile_case
from app.engine.metrics.evaluate import evaluate_case
from app.engine.metrics.geometry import AssetGeometry, build_geometry
from app.engine.metrics.results import METRICS_3D
from app.engine.metrics.subjects import resolve_subject
from benchmark.cases import read_cases
from tests.conftest import EXAMPLES, REPO, partnet_root

CASES_DIR = REPO / "benchmark" / "cases"
MIN_CASES = 60
MIN_PER_TYPE = 8
MIN_ASSETS = 15
LIMIT_TOLERANCE = 1e-6
"""Targets may sit on a limit up to this much outside it (rounding of the written numbers)."""
NO_SLIP_FRACTION = 0.05
"""A rolling wheel's contact point may move at most this fraction of the base speed."""
SLIP_STEP_S = 1e-4
PERFECT_TOLERANCE = 1e-9
SYMMETRIC_TURNS = (
    "toy_car_spin_front_left_wheel",
    "cabinet_knob_pops_door",
    "cabinet_unlatch_open_overlap",
    "cabinet_unlatch_open_90",
    "cabinet_open_cupboard",
    "microwave_button_then_turntable",
)
"""Cases with a key state whose only change is a part turning about its own symmetry axis
(a wheel, a latch knob, a turntable): its box does not change, so the gIoU similarity ties over
the whole hold; the alignment's point-pose tie-break must still pick the right frame."""


def _files() -> list[tuple[Path, Path]]:
    """(cases file, assets root) of every dev file."""
    return [(CASES_DIR / "dev.jsonl", partnet_root()), (CASES_DIR / "dev_examples.jsonl", EXAMPLES)]


@functools.cache
def _all_cases() -> tuple[tuple[Case, str], ...]:
    """Every dev case with the folder of its asset."""
    return tuple((case, str(root / case.asset)) for path, root in _files() for case in read_cases(path))


@functools.cache
def _asset(folder: str) -> ArticulatedAsset:
    return load_asset(folder)


@functools.cache
def _geometry(folder: str) -> AssetGeometry:
    return build_geometry(_asset(folder))


@functools.cache
def _truth(case_id: str) -> GroundTruth:
    case, folder = _case(case_id)
    return compile_case(case, _asset(folder))


def _case(case_id: str) -> tuple[Case, str]:
    return next((c, f) for c, f in _all_cases() if c.case_id == case_id)


CASE_IDS = [case.case_id for case, _ in _all_cases()]


def test_files_parse_with_unique_ids() -> None:
    ids = [case.case_id for case, _ in _all_cases()]
    assert len(ids) == len(set(ids)), [i for i, n in Counter(ids).items() if n > 1]


def test_coverage() -> None:
    cases = [case for case, _ in _all_cases()]
    assert len(cases) >= MIN_CASES
    per_type = Counter(case.motion_type for case in cases)
    assert set(per_type) == set(MOTION_TYPES)
    assert min(per_type.values()) >= MIN_PER_TYPE, per_type
    assert len({folder for _, folder in _all_cases()}) >= MIN_ASSETS


@pytest.mark.parametrize("case_id", CASE_IDS)
def test_case_fits_its_asset(case_id: str) -> None:
    case, folder = _case(case_id)
    asset = _asset(folder)
    assert case.prompt.strip()
    driven = {c.phase for c in case.constraints}
    assert driven == {p.id for p in case.phases}, "every phase must constrain something"
    for number, constraint in enumerate(case.constraints):
        fields = constraint.constraints
        subject = resolve_subject(asset, constraint.subject, f"constraints[{number}]")
        if subject.joint is None:
            assert constraint.subject == BASE_SUBJECT
            assert fields.displacement_m is not None and fields.direction_axis_world is not None
            continue
        joint = asset.joints[subject.joint]
        assert joint.movable and joint.mimic is None
        drives = [v for v in (fields.target_q, fields.omega_radps, fields.return_mode) if v is not None]
        assert len(drives) == 1, f"constraints[{number}] must drive exactly one way"
        if fields.target_q is not None and joint.lower is not None and joint.upper is not None:
            assert joint.lower - LIMIT_TOLERANCE <= fields.target_q <= joint.upper + LIMIT_TOLERANCE
        if fields.return_mode is not None:
            assert fields.rest_position_q == pytest.approx(joint.rest)


@pytest.mark.parametrize("case_id", CASE_IDS)
def test_case_compiles_to_key_states(case_id: str) -> None:
    truth = _truth(case_id)
    case, _ = _case(case_id)
    assert len(truth.key_states) == len(case.phases) >= 1
    assert not [n for n in truth.notes if "ignored" in n]
    for state in truth.key_states:
        assert state.dynamic_links, f"key state {state.phase} moves nothing"


def _wheel_joints(asset: ArticulatedAsset) -> set[str]:
    return {j.name for j in asset.joints.values() if (asset.links[j.child].semantics.label or "") == "wheel"}


def _rolling_phases(case: Case, asset: ArticulatedAsset) -> set[str]:
    """Phases that move the base and drive wheel joints (sideways skids drive no wheel)."""
    wheels = _wheel_joints(asset)
    moved = {c.phase for c in case.constraints if c.subject == BASE_SUBJECT}
    return {c.phase for c in case.constraints if c.subject in wheels and c.phase in moved}


def _wheel_cases() -> list[str]:
    return [case.case_id for case, folder in _all_cases() if _rolling_phases(case, _asset(folder))]


def _contact_speeds(asset: ArticulatedAsset, truth: GroundTruth, frame: int) -> tuple[float, list[float]]:
    """(base speed, horizontal speed of each wheel's lowest point) at ``frame``, from a tiny step at the frame's velocities."""
    trajectory = truth.trajectory
    dt = float(trajectory.times[frame + 1] - trajectory.times[frame])
    q0, q1 = trajectory.q[frame], trajectory.q[frame + 1]
    b0, b1 = trajectory.base_translation[frame], trajectory.base_translation[frame + 1]
    values = {
        name: np.array([q0[i], q0[i] + SLIP_STEP_S * (q1[i] - q0[i]) / dt])
        for i, name in enumerate(trajectory.joint_names)
    }
    base = np.tile(np.eye(4), (2, 1, 1))
    base[0, :3, 3] = b0
    base[1, :3, 3] = b0 + SLIP_STEP_S * (b1 - b0) / dt
    poses = link_poses(asset, values, base=base)
    speeds = []
    for link in asset.visual_links:
        if (asset.links[link].semantics.label or "") != "wheel":
            continue
        vertices = np.concatenate([part.vertices for part in asset.links[link].parts], axis=0)
        start = vertices @ poses[link][0, :3, :3].T + poses[link][0, :3, 3]
        lowest = vertices[int(np.argmin(start[:, 2]))]
        moved = poses[link][1, :3, :3] @ lowest + poses[link][1, :3, 3]
        slip = (moved - start[int(np.argmin(start[:, 2]))])[:2]  # horizontal: a polygonal rim's lowest vertex also bobs
        speeds.append(float(np.linalg.norm(slip)) / SLIP_STEP_S)
    return float(np.linalg.norm(b1 - b0)) / dt, speeds


@pytest.mark.parametrize("case_id", _wheel_cases())
def test_wheels_roll_without_slipping(case_id: str) -> None:
    case, folder = _case(case_id)
    asset = _asset(folder)
    truth = _truth(case_id)
    rolling = _rolling_phases(case, asset)
    for timing in truth.timings:
        if timing.phase not in rolling:
            continue
        middle = (timing.start_frame + timing.end_frame) // 2
        speed, contacts = _contact_speeds(asset, truth, middle)
        assert speed > 0.0 and contacts
        assert max(contacts) <= NO_SLIP_FRACTION * speed, (timing.phase, speed, contacts)


def test_wheel_cases_exist() -> None:
    assert len(_wheel_cases()) >= 5


def _perfect_params() -> list[object]:
    return list(CASE_IDS)


def test_tie_list_names_dev_cases() -> None:
    assert set(SYMMETRIC_TURNS) <= set(CASE_IDS)


@pytest.mark.parametrize("case_id", CASE_IDS)
def test_ground_truth_giou_is_one(case_id: str, tmp_path: Path) -> None:
    case, folder = _case(case_id)
    prediction = write_trajectory_jsonl(_truth(case_id).trajectory, tmp_path / "trajectory.jsonl")
    outcome = evaluate_case(case, _asset(folder), _geometry(folder), prediction)
    assert outcome.status == "scored", outcome.error
    assert outcome.scores is not None
    assert math.isclose(outcome.scores.values["P_gIoU"], 1.0, abs_tol=PERFECT_TOLERANCE)


@pytest.mark.parametrize("case_id", _perfect_params())
def test_ground_truth_scores_one(case_id: str, tmp_path: Path) -> None:
    case, folder = _case(case_id)
    prediction = write_trajectory_jsonl(_truth(case_id).trajectory, tmp_path / "trajectory.jsonl")
    outcome = evaluate_case(case, _asset(folder), _geometry(folder), prediction)
    assert outcome.status == "scored", outcome.error
    assert outcome.scores is not None
    for metric in METRICS_3D:
        assert math.isclose(outcome.scores.values[metric], 1.0, abs_tol=PERFECT_TOLERANCE), (
            metric,
            outcome.scores.values,
        )
