"""The executor's output: joint values and base pose per frame."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from app.engine.execute.events import ExecutionEvent
from app.engine.types import FloatArray, JointMatrix


@dataclass(frozen=True, eq=False)
class Trajectory:
    """Sampled animation.

    Attributes
    ----------
    fps : int
    times : (f,) float, seconds; ``times[i] = i / fps``
    joint_names : names of the columns of ``q`` (the asset's movable joints)
    q : (f, j) float, radians or metres
    base_translation : (f, 3) float, metres, world frame
    base_rotation_xyzw : (f, 4) float, unit quaternions
    modes : per-frame ``{name: set}`` flags from ``mode_set`` controls
    events : typed notes from execution (plan warnings, overlaps, limits reached, clamped targets)
    """

    fps: int
    times: FloatArray
    joint_names: tuple[str, ...]
    q: JointMatrix
    base_translation: FloatArray
    base_rotation_xyzw: FloatArray
    modes: tuple[Mapping[str, bool], ...] = ()
    events: tuple[ExecutionEvent, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        for array in (self.times, self.q, self.base_translation, self.base_rotation_xyzw):
            array.setflags(write=False)

    @property
    def frame_count(self) -> int:
        return int(self.times.shape[0])

    @property
    def duration_s(self) -> float:
        return float(self.times[-1]) if self.frame_count else 0.0

    @property
    def event_messages(self) -> list[str]:
        """The readable sentences of :attr:`events` (what report.json lists under ``events``)."""
        return [event.message for event in self.events]

    def joint(self, name: str) -> FloatArray:
        """(f,) values of one joint."""
        return self.q[:, self.joint_names.index(name)]

    def joint_values(self) -> dict[str, FloatArray]:
        """{joint: (f,) values} for every column."""
        return {name: self.q[:, i] for i, name in enumerate(self.joint_names)}

    def has_base_motion(self, tolerance: float = 1e-9) -> bool:
        return bool(np.abs(self.base_translation - self.base_translation[:1]).max(initial=0.0) > tolerance)
