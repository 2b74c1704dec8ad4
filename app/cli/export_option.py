"""``--export usd,mjcf,ros,csv,npz`` for ``artimo animate`` and ``artimo run-plan``."""

from __future__ import annotations

import argparse

from app.engine.export.outputs import EXPORT_NAMES, parse_exports, require_exports

WHERE = "usd: animation.usda, mjcf: scene.xml, ros: joint_trajectory.json, csv: trajectory.csv, npz: trajectory.npz"


def add_export_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--export", default="", metavar="NAMES",
                        help=f"also write these formats, comma-separated ({', '.join(EXPORT_NAMES)}; {WHERE})")


def exports_of(args: argparse.Namespace) -> tuple[str, ...]:
    """The asked-for exports, checked before any work (unknown name, missing optional package: ExportError)."""
    names = parse_exports(args.export)
    require_exports(names)
    return names
