"""``artimo validate-glb FILE ...``: the Khronos glTF-Validator on GLB/glTF files (the tests' validator)."""

from __future__ import annotations

import argparse
import os
from pathlib import Path

from app.cli.output import err, out, out_json


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("validate-glb", help="check GLB/glTF files with the Khronos glTF-Validator (needs Node; make setup installs it)")
    parser.add_argument("files", nargs="+", type=Path)
    parser.add_argument("--json", action="store_true", help="every report with all its messages, as JSON")
    parser.add_argument("--tool-dir", type=Path, default=os.environ.get("ARTIMO_GLTF_VALIDATOR_DIR") or None,
                        help="folder of the validator harness (default $ARTIMO_GLTF_VALIDATOR_DIR or this repository's "
                             "tests/tools/gltf_validator)")
    parser.set_defaults(handler=_validate)


def _validate(args: argparse.Namespace) -> int:
    from app.gltf_validation import ValidatorUnavailable, validate_glb

    missing = [str(path) for path in args.files if not path.is_file()]
    if missing:
        err(f"error: no such file: {', '.join(missing)}")
        return 2
    try:
        reports = validate_glb(args.files, tool_dir=args.tool_dir)
    except ValidatorUnavailable as exc:
        err(f"error: {exc}")
        return 2
    if args.json:
        out_json([{**report.__dict__, "clean": report.clean} for report in reports])
    else:
        for report in reports:
            out(report.summary())
    return 0 if all(report.clean for report in reports) else 1
