"""``trajectory.npz``: the same table as ``trajectory.csv`` as named numpy arrays.

Arrays: ``time`` (f,) seconds; one (f,) array per moving joint, named as in the URDF
(radians or metres); ``base_translation`` (f, 3) metres and ``base_rotation_xyzw`` (f, 4)
unit quaternions (root link in the world frame); ``joint_names`` (m,) the moving joints in
column order; ``fps`` () int. Load with ``numpy.load(path)`` (no pickles). The archive is
byte-identical for identical input (fixed zip timestamps).
"""

from __future__ import annotations

import io
import zipfile
from pathlib import Path

import numpy as np

from app.engine.errors import ExportError
from app.engine.export.track import ExportTrack
from app.engine.files import atomic_write_bytes

NPZ_FILE = "trajectory.npz"
FIXED_ARRAYS = ("time", "base_translation", "base_rotation_xyzw", "joint_names", "fps")
ZIP_EPOCH = (1980, 1, 1, 0, 0, 0)


def npz_arrays(track: ExportTrack) -> dict[str, np.ndarray]:
    """{name: array} in file order.

    Raises
    ------
    ExportError
        A joint is named like one of the fixed arrays.
    """
    clash = sorted(set(track.moving_joints) & set(FIXED_ARRAYS))
    if clash:
        raise ExportError(f"joint name(s) {clash} clash with the fixed arrays of {NPZ_FILE} ({', '.join(FIXED_ARRAYS)})")
    trajectory = track.trajectory
    arrays: dict[str, np.ndarray] = {"time": np.asarray(trajectory.times, dtype=np.float64)}
    arrays.update({name: np.asarray(track.values[name], dtype=np.float64) for name in track.moving_joints})
    arrays["base_translation"] = np.asarray(trajectory.base_translation, dtype=np.float64)
    arrays["base_rotation_xyzw"] = np.asarray(trajectory.base_rotation_xyzw, dtype=np.float64)
    arrays["joint_names"] = np.array(track.moving_joints, dtype=np.str_)
    arrays["fps"] = np.array(track.fps, dtype=np.int64)
    return arrays


def npz_bytes(arrays: dict[str, np.ndarray]) -> bytes:
    """An ``.npz`` archive (what ``numpy.savez`` writes) with fixed entry timestamps."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=zipfile.ZIP_STORED) as archive:
        for name, array in arrays.items():
            entry = zipfile.ZipInfo(f"{name}.npy", date_time=ZIP_EPOCH)
            with archive.open(entry, "w", force_zip64=True) as handle:
                np.lib.format.write_array(handle, np.asarray(array), allow_pickle=False)
    return buffer.getvalue()


def write_npz(track: ExportTrack, out_dir: Path) -> str:
    """Write ``trajectory.npz`` into ``out_dir``; returns its file name."""
    atomic_write_bytes(out_dir / NPZ_FILE, npz_bytes(npz_arrays(track)))
    return NPZ_FILE
