"""Easing curves of ``joint_position`` (SPEC §3): s in [0, 1] -> progress in [0, 1]."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from app.engine.types import FloatArray


def linear(s: FloatArray) -> FloatArray:
    return np.asarray(s, dtype=np.float64)


def ease_in(s: FloatArray) -> FloatArray:
    s = np.asarray(s, dtype=np.float64)
    return s * s


def ease_out(s: FloatArray) -> FloatArray:
    s = np.asarray(s, dtype=np.float64)
    return 1.0 - (1.0 - s) * (1.0 - s)


def ease_in_out(s: FloatArray) -> FloatArray:
    """Smoothstep 3s^2 - 2s^3."""
    s = np.asarray(s, dtype=np.float64)
    return s * s * (3.0 - 2.0 * s)


CURVES: dict[str, Callable[[FloatArray], FloatArray]] = {
    "linear": linear,
    "ease_in": ease_in,
    "ease_out": ease_out,
    "ease_in_out": ease_in_out,
}
