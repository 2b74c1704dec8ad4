"""``trajectory.csv``: one row per frame, a ``time`` column, one column per moving joint, the base pose.

Columns: ``time`` (s), then each joint of :attr:`ExportTrack.moving_joints` named as in
the URDF (radians or metres), then ``base_x, base_y, base_z`` (metres, world) and
``base_qx, base_qy, base_qz, base_qw`` (unit quaternion of the root link in the world).
Numbers are written as Python's shortest round-trip repr, so reading them back gives the
exact float64 values. Opens in any spreadsheet, pandas or ``numpy.genfromtxt``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from app.engine.errors import ExportError
from app.engine.export.track import ExportTrack
from app.engine.files import atomic_write_text
from app.engine.types import FloatArray

CSV_FILE = "trajectory.csv"
BASE_COLUMNS = ("base_x", "base_y", "base_z", "base_qx", "base_qy", "base_qz", "base_qw")


def table_columns(track: ExportTrack) -> tuple[str, ...]:
    """Column names: ``time``, the moving joints, the base pose.

    Raises
    ------
    ExportError
        A joint is named like one of the fixed columns.
    """
    columns = ("time", *track.moving_joints, *BASE_COLUMNS)
    if len(set(columns)) != len(columns):
        clash = sorted({c for c in track.moving_joints if c == "time" or c in BASE_COLUMNS})
        raise ExportError(f"joint name(s) {clash} clash with the table's fixed columns (time, base_*)")
    return columns


def table_values(track: ExportTrack) -> FloatArray:
    """(f, 1 + m + 7) values in the order of :func:`table_columns`."""
    trajectory = track.trajectory
    return np.column_stack([
        np.asarray(trajectory.times, dtype=np.float64),
        track.joint_matrix(),
        np.asarray(trajectory.base_translation, dtype=np.float64),
        np.asarray(trajectory.base_rotation_xyzw, dtype=np.float64),
    ])


def write_csv(track: ExportTrack, out_dir: Path) -> str:
    """Write ``trajectory.csv`` into ``out_dir``; returns its file name."""
    lines = [",".join(table_columns(track))]
    lines.extend(",".join(map(repr, row)) for row in table_values(track).tolist())
    atomic_write_text(out_dir / CSV_FILE, "\n".join(lines) + "\n")
    return CSV_FILE
