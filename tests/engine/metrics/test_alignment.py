"""Order-preserving DP matching: optimality, earliest ties, K > T, equal frames."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from app.engine.errors import MetricError
from app.engine.metrics.alignment import align


def _brute_force(similarity: np.ndarray, allow_equal: list[bool]) -> tuple[int, ...]:
    """Lexicographically earliest best assignment over every feasible frame sequence."""
    states, frames = similarity.shape
    best, choice = None, None
    for combo in itertools.product(range(frames), repeat=states):
        ok = all(b > a or (allow_equal[k] and b == a) for k, (a, b) in enumerate(itertools.pairwise(combo)))
        if not ok:
            continue
        total = round(sum(similarity[k, t] for k, t in enumerate(combo)) * 1e9)
        if best is None or total > best:
            best, choice = total, combo
    assert choice is not None
    return choice


@pytest.mark.parametrize("seed", range(40))
def test_matches_exhaustive_search_including_ties(seed):
    rng = np.random.default_rng(seed)
    states, frames = int(rng.integers(1, 4)), int(rng.integers(3, 7))
    similarity = rng.integers(-2, 3, size=(states, frames)) / 2.0  # many exact ties
    allow_equal = [bool(v) for v in rng.integers(0, 2, size=states - 1)]
    assert align(similarity, allow_equal).frames == _brute_force(similarity, allow_equal)


def test_ties_go_to_the_earliest_frames():
    flat = np.zeros((3, 6))
    assert align(flat, [False, False]).frames == (0, 1, 2)
    assert align(flat, [True, True]).frames == (0, 0, 0)
    plateau = np.array([[0.1, 0.5, 1.0, 1.0, 1.0, 1.0], [0.0, 0.0, 1.0, 1.0, 1.0, 1.0]])
    assert align(plateau, [False]).frames == (2, 3)


def test_order_is_kept_even_when_states_prefer_the_reverse():
    similarity = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]])
    assert align(similarity, [False]).frames == (0, 1)  # every order-keeping choice sums to 0


def test_fewer_frames_than_states_repeat_the_last_frame():
    similarity = np.array([[1.0, 0.0], [0.0, 1.0], [0.0, 1.0], [0.0, 1.0]])
    result = align(similarity, [False, False, False])
    assert result.frames == (0, 1, 2, 3) and result.padded
    assert result.total == pytest.approx(4.0)


def test_equal_frames_allowed_when_phases_end_together_or_overlap():
    similarity = np.array([[0.0, 1.0, 0.0], [0.0, 1.0, 0.0]])
    assert align(similarity, [True]).frames == (1, 1)
    assert align(similarity, [False]).frames == (0, 1)


def test_bad_input_is_rejected():
    with pytest.raises(MetricError):
        align(np.array([[np.nan]]), [])
    with pytest.raises(MetricError):
        align(np.zeros((2, 3)), [])
