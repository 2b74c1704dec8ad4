"""The run's extra outputs: ``interaction.json`` (always) and the exports asked for.

Export names (CLI ``--export``, job option ``exports``): ``usd`` -> ``animation.usda``,
``mjcf`` -> ``scene.xml``, ``ros`` -> ``joint_trajectory.json``, ``csv`` ->
``trajectory.csv``, ``npz`` -> ``trajectory.npz``. All read one :class:`ExportTrack`
built from the same asset and trajectory.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Literal, get_args

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.causal import CausalDocument
from app.engine.errors import ExportError
from app.engine.execute.trajectory import Trajectory
from app.engine.export.track import ExportTrack, build_track
from app.engine.plan.schema import Plan

ExportName = Literal["usd", "mjcf", "ros", "csv", "npz"]
EXPORT_NAMES: tuple[ExportName, ...] = get_args(ExportName)
REQUIRES: dict[str, str] = {"usd": "pxr.Usd"}
"""Exports that need an optional package to be written (named with its extra by ``optional.require``).
``scene.xml`` is plain XML: the ``mjcf`` extra (mujoco) is for opening and simulating it."""


def parse_exports(value: str | Iterable[str] | None) -> tuple[ExportName, ...]:
    """Export names from ``"usd,mjcf"`` or a list, deduplicated, in :data:`EXPORT_NAMES` order.

    Raises
    ------
    ExportError
        An unknown name (the message lists the known ones).
    """
    if value is None:
        return ()
    items = value.split(",") if isinstance(value, str) else list(value)
    names = {item.strip().lower() for item in items if item.strip()}
    unknown = sorted(names - set(EXPORT_NAMES))
    if unknown:
        raise ExportError(f"unknown export(s) {', '.join(unknown)}: choose from {', '.join(EXPORT_NAMES)}")
    return tuple(name for name in EXPORT_NAMES if name in names)


def require_exports(names: Iterable[str]) -> None:
    """Import the optional packages the exports need, so a missing one fails before any work.

    Raises
    ------
    ExportError
        Naming the extra to install.
    """
    from app.engine.export.optional import require

    for name in names:
        if name in REQUIRES:
            require(REQUIRES[name])


def _writers(phase_ends: Sequence[tuple[str, float]]) -> dict[str, Callable[[ExportTrack, Path], str]]:
    from app.engine.export.csv_table import write_csv
    from app.engine.export.mjcf import write_mjcf
    from app.engine.export.npz_arrays import write_npz
    from app.engine.export.ros import write_ros
    from app.engine.export.usd import write_usd

    return {
        "usd": write_usd,
        "mjcf": lambda track, out_dir: write_mjcf(track, out_dir, phase_ends),
        "ros": write_ros,
        "csv": write_csv,
        "npz": write_npz,
    }


def write_exports(track: ExportTrack, out_dir: Path, names: Iterable[str], phase_ends: Sequence[tuple[str, float]] = ()) -> dict[str, str]:
    """Write the named exports into ``out_dir``; returns ``{name: file name}``.

    Raises
    ------
    ExportError
        Unknown name, missing optional package, or content a format cannot hold.
    """
    chosen = parse_exports(names)
    require_exports(chosen)
    writers = _writers(phase_ends)
    return {name: writers[name](track, out_dir) for name in chosen}


def write_run_outputs(out_dir: Path, asset: ArticulatedAsset, plan: Plan, trajectory: Trajectory,
                      causal: CausalDocument | None = None, exports: Iterable[str] = ()) -> dict[str, str]:
    """Write ``interaction.json`` and the asked-for exports; returns ``{kind: file name}``."""
    from app.engine.interaction.phases import actuated_phases
    from app.engine.interaction.targets import interaction_targets, write_interactions

    track = build_track(asset, trajectory)
    document = interaction_targets(asset, trajectory, actuated_phases(asset, plan, causal), track)
    written = {"interaction": write_interactions(out_dir, document)}
    written.update(write_exports(track, out_dir, exports, [(segment.name, segment.t1) for segment in plan.timeline]))
    return written
