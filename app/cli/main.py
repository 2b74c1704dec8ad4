"""``artimo`` console script: subcommands live in one module each."""

from __future__ import annotations

import argparse
import logging
import sys
from collections.abc import Sequence

from app.cli import (
    animate_cmd,
    asset_cmds,
    bench_cmd,
    jobs_cmd,
    keys_cmd,
    plan_cmd,
    serve_cmd,
    submit_cmd,
    validate_glb_cmd,
)
from app.cli.output import err
from app.engine.errors import EngineError

COMMAND_MODULES = (asset_cmds, animate_cmd, plan_cmd, validate_glb_cmd, bench_cmd, serve_cmd, keys_cmd, submit_cmd, jobs_cmd)


def version() -> str:
    """The installed package's version (the source tree's when not installed)."""
    from importlib.metadata import PackageNotFoundError
    from importlib.metadata import version as installed

    try:
        return installed("artimo")
    except PackageNotFoundError:
        return "unknown (not installed: pip install -e .)"


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="artimo", description="Text-driven articulated mesh animation.")
    parser.add_argument("--version", action="version", version=f"artimo {version()}")
    parser.add_argument("-v", "--verbose", action="count", default=0, help="more logging (-vv for debug)")
    parser.add_argument("--no-cache", action="store_true", help="do not use the asset cache ($ARTIMO_CACHE_DIR, default ~/.cache/artimo)")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for module in COMMAND_MODULES:
        module.register(commands)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    level = logging.WARNING - 10 * min(args.verbose, 2)
    logging.basicConfig(level=level, format="%(levelname)s %(name)s: %(message)s")
    try:
        return int(args.handler(args) or 0)
    except EngineError as exc:
        err(f"error: {exc}")
        return 1
    except KeyboardInterrupt:
        err("interrupted")
        return 130


if __name__ == "__main__":
    sys.exit(main())
