"""Order-preserving matching of GT key states to predicted frames (SPEC §6).

Choose frames ``t_1 <= ... <= t_K`` maximising ``sum_k S[k, t_k]``; consecutive states
must use strictly increasing frames unless ``allow_equal`` says otherwise. Exact dynamic
programming over a similarity quantised to ``SCORE_QUANTUM`` (integer sums make ties
exact). Exact ties of the similarity are broken by an optional secondary score (summed
the same way, it can never outweigh one quantum of the primary); remaining ties go to
the earliest frame. When the prediction has fewer frames than the strict steps
need, its last frame is repeated.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from app.engine.errors import MetricError
from app.engine.types import FloatArray

SCORE_QUANTUM = 1e-9
"""Similarities are compared at this resolution (ties closer than this are ties)."""
TIE_LEVELS = 100_000
"""Resolution of the tie-break score in [0, 1]."""
TIE_WEIGHT = 10_000_000
"""One primary quantum outweighs the tie-break of up to TIE_WEIGHT / TIE_LEVELS states."""
_INFEASIBLE = -(2**62)


@dataclass(frozen=True)
class Alignment:
    """Matched frames: ``frames[k]`` indexes the prediction (repeats of its last frame included)."""

    frames: tuple[int, ...]
    padded: bool
    """True when some state had to use a repeated last frame."""
    total: float
    """Sum of the similarity over the matched pairs."""


def _quantised(similarity: FloatArray, tie_break: FloatArray | None) -> np.ndarray:
    if not np.all(np.isfinite(similarity)):
        raise MetricError("alignment similarity holds a non-finite value")
    primary = np.round(similarity / SCORE_QUANTUM).astype(np.int64)
    if tie_break is None:
        return primary
    secondary = np.round(np.clip(tie_break, 0.0, 1.0) * (TIE_LEVELS - 1)).astype(np.int64)
    return primary * TIE_WEIGHT + secondary


def align(similarity: FloatArray, allow_equal: Sequence[bool], tie_break: FloatArray | None = None) -> Alignment:
    """Best order-preserving assignment of K states to T frames.

    Parameters
    ----------
    similarity : (K, T) float
        ``S[k, t]``; higher is better.
    allow_equal : (K - 1,) bool
        Whether states ``k`` and ``k + 1`` may share a frame.
    tie_break : (K, T) float in [0, 1], optional
        Orders assignments whose similarity sums tie exactly.

    Raises
    ------
    MetricError
        Empty or non-finite similarity, or ``allow_equal`` of the wrong length.
    """
    states, count = similarity.shape
    if states == 0 or count == 0:
        raise MetricError("alignment needs at least one state and one frame")
    if len(allow_equal) != states - 1:
        raise MetricError(f"allow_equal has {len(allow_equal)} entries for {states} states")
    needed = 1 + sum(1 for equal in allow_equal if not equal)
    scores = _quantised(similarity, tie_break)
    if count < needed:
        scores = np.concatenate([scores, np.repeat(scores[:, -1:], needed - count, axis=1)], axis=1)
    width = scores.shape[1]
    value = np.zeros((states, width), dtype=np.int64)
    value[-1] = scores[-1]
    for k in range(states - 2, -1, -1):
        suffix = np.maximum.accumulate(value[k + 1][::-1])[::-1]
        following = suffix if allow_equal[k] else np.concatenate([suffix[1:], [_INFEASIBLE]])
        value[k] = np.where(following <= _INFEASIBLE // 2, _INFEASIBLE, scores[k] + following)
    frames = [int(np.argmax(value[0]))]
    for k in range(1, states):
        low = frames[-1] if allow_equal[k - 1] else frames[-1] + 1
        frames.append(low + int(np.argmax(value[k][low:])))
    total = float(sum(similarity[k, min(f, count - 1)] for k, f in enumerate(frames)))
    return Alignment(frames=tuple(frames), padded=frames[-1] >= count, total=total)
