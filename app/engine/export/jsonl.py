"""``trajectory.jsonl`` (SPEC §4): one JSON object per frame, the authors' field names."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import ExportError, MetricError
from app.engine.execute.trajectory import Trajectory
from app.engine.files import atomic_write_text

MAX_FRAMES = 100_000
UNIT_TOLERANCE = 1e-12
"""Base quaternions this close to unit length are kept bit-exact (no renormalisation)."""


def trajectory_records(trajectory: Trajectory) -> list[dict[str, Any]]:
    """The per-frame records, in frame order."""
    records = []
    names = trajectory.joint_names
    for i in range(trajectory.frame_count):
        records.append(
            {
                "frame_idx": i,
                "time_s": float(trajectory.times[i]),
                "joint_angles": {name: float(trajectory.q[i, j]) for j, name in enumerate(names)},
                "base_pose": {
                    "translation": [float(v) for v in trajectory.base_translation[i]],
                    "rotation_xyzw": [float(v) for v in trajectory.base_rotation_xyzw[i]],
                },
                "modes": dict(trajectory.modes[i]) if trajectory.modes else {},
            }
        )
    return records


def dumps_trajectory(trajectory: Trajectory) -> str:
    try:
        lines = [json.dumps(r, allow_nan=False) for r in trajectory_records(trajectory)]
    except ValueError as exc:
        raise ExportError(f"trajectory holds a non-finite value: {exc}") from exc
    return "\n".join(lines) + "\n"


def write_trajectory_jsonl(trajectory: Trajectory, path: str | Path) -> Path:
    """Write ``trajectory`` atomically to ``path``."""
    return atomic_write_text(path, dumps_trajectory(trajectory))


def _frame(line: str, number: int, source: str) -> dict[str, Any]:
    try:
        record = json.loads(line)
    except json.JSONDecodeError as exc:
        raise MetricError(f"{source} line {number}: not JSON ({exc.msg})") from exc
    if not isinstance(record, dict):
        raise MetricError(f"{source} line {number}: expected an object")
    return record


def _floats(values: Any, size: int, what: str) -> list[float] | None:
    if values is None:
        return None
    if not isinstance(values, list) or len(values) != size or not all(_number(v) for v in values):
        raise MetricError(f"{what} must be {size} finite numbers")
    return [float(v) for v in values]


def read_trajectory_jsonl(path: str | Path, asset: ArticulatedAsset, *, fps: int | None = None) -> tuple[Trajectory, list[str]]:
    """Read a trajectory file written by us or another tool, aligned to ``asset``.

    Joints missing from a frame keep their rest value; unknown joints are ignored
    (reported in the returned notes). ``time_s`` defaults to ``frame_idx / fps``.

    Raises
    ------
    MetricError
        Unreadable file, no frames, or malformed values.
    """
    source = Path(path)
    try:
        text = source.read_text(encoding="utf-8")
    except OSError as exc:
        raise MetricError(f"cannot read trajectory {source}: {exc}") from exc
    lines = [(n, line) for n, line in enumerate(text.splitlines(), start=1) if line.strip()]
    if not lines:
        raise MetricError(f"{source.name}: no frames")
    if len(lines) > MAX_FRAMES:
        raise MetricError(f"{source.name}: more than {MAX_FRAMES} frames")
    names = asset.movable_joints
    q = np.tile(asset.rest_vector(), (len(lines), 1))
    times = np.zeros(len(lines))
    translation = np.zeros((len(lines), 3))
    rotation = np.tile([0.0, 0.0, 0.0, 1.0], (len(lines), 1))
    unknown: set[str] = set()
    modes: list[dict[str, bool]] = []
    rate = fps or 30
    for row, (number, line) in enumerate(lines):
        record = _frame(line, number, source.name)
        where = f"{source.name} line {number}"
        _joint_row(record, asset, q[row], unknown, where)
        times[row] = _time(record, row, rate, where)
        modes.append(_modes(record.get("modes"), where))
        _base_row(record, translation[row], rotation[row], where)
    notes = [f"{source.name}: unknown joints ignored: {', '.join(sorted(unknown))}"] if unknown else []
    estimated = rate if fps else _estimate_fps(times)
    trajectory = Trajectory(
        fps=estimated,
        times=times,
        joint_names=names,
        q=q,
        base_translation=translation,
        base_rotation_xyzw=rotation,
        modes=tuple(modes),
    )
    return trajectory, notes


def _joint_row(record: dict[str, Any], asset: ArticulatedAsset, q_row: np.ndarray, unknown: set[str], where: str) -> None:
    """Fill ``q_row`` (j,) from ``joint_angles`` (or ``joint_pos``); collect unknown joint names."""
    names = asset.movable_joints
    angles = record.get("joint_angles", record.get("joint_pos", {}))
    if not isinstance(angles, dict):
        raise MetricError(f"{where}: joint_angles must be an object")
    for name, value in angles.items():
        if name in names:
            if not _number(value):
                raise MetricError(f"{where}: joint '{name}' value is not a finite number")
            q_row[names.index(name)] = float(value)
        elif name not in asset.joints:
            unknown.add(str(name))


def _base_row(record: dict[str, Any], translation_row: np.ndarray, rotation_row: np.ndarray, where: str) -> None:
    """Fill the (3,) translation and (4,) unit quaternion rows from ``base_pose`` when present."""
    pose = record.get("base_pose") or {}
    if not isinstance(pose, dict):
        raise MetricError(f"{where}: base_pose must be an object")
    moved = _floats(pose.get("translation"), 3, f"{where}: base_pose.translation")
    turned = _floats(pose.get("rotation_xyzw"), 4, f"{where}: base_pose.rotation_xyzw")
    if moved is not None:
        translation_row[:] = moved
    if turned is not None and np.linalg.norm(turned) > 1e-9:
        length = float(np.linalg.norm(turned))
        rotation_row[:] = turned if abs(length - 1.0) <= UNIT_TOLERANCE else np.asarray(turned) / length


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)


def _time(record: dict[str, Any], row: int, rate: int, where: str) -> float:
    """``time_s``, else ``frame_idx / rate``, else ``row / rate``."""
    if "time_s" in record:
        if not _number(record["time_s"]):
            raise MetricError(f"{where}: time_s must be a finite number")
        return float(record["time_s"])
    index = record.get("frame_idx", row)
    if not _number(index):
        raise MetricError(f"{where}: frame_idx must be a number")
    return float(index) / rate


def _modes(value: Any, where: str) -> dict[str, bool]:
    if value is None:
        return {}
    if not isinstance(value, dict) or not all(isinstance(v, bool) for v in value.values()):
        raise MetricError(f"{where}: modes must map names to true/false")
    return {str(k): bool(v) for k, v in value.items()}


def _estimate_fps(times: np.ndarray) -> int:
    steps = np.diff(times)
    steps = steps[steps > 0]
    return round(1.0 / float(np.median(steps))) if steps.size else 30
