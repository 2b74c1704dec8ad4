"""Run the Khronos glTF-Validator (npm ``gltf-validator``, pinned in
``tests/tools/gltf_validator/package.json``) on glTF/GLB files.

Install once (``make setup`` / ``make validator`` does it):
    npm install --prefix tests/tools/gltf_validator --no-audit --no-fund

A missing ``node`` or package is an error naming the command to run (tests fail, never skip).
Users run it as ``artimo validate-glb FILE.glb ...``; the tests import it through
``tests.support.gltf_validator``.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

TOOL_DIR = Path(__file__).resolve().parents[1] / "tests" / "tools" / "gltf_validator"
"""The harness and its npm package, in this repository (``artimo validate-glb --tool-dir`` points elsewhere)."""
SCRIPT = TOOL_DIR / "validate.mjs"
PACKAGE = TOOL_DIR / "node_modules" / "gltf-validator" / "package.json"
INSTALL_COMMAND = "npm install --prefix tests/tools/gltf_validator --no-audit --no-fund"
TIMEOUT_S = 300.0
SHOWN_MESSAGES = 12


class ValidatorUnavailable(AssertionError):
    """node or the gltf-validator package is missing (tests must fail, not skip)."""


@dataclass(frozen=True)
class ValidationReport:
    """One file's validator result; ``messages`` are the validator's issue records."""

    path: str
    ok: bool
    num_errors: int
    num_warnings: int
    num_infos: int
    num_hints: int
    messages: tuple[dict[str, Any], ...]
    error: str | None = None
    validator_version: str = ""

    @property
    def clean(self) -> bool:
        """Parsed, with no errors and no warnings."""
        return self.ok and self.num_errors == 0 and self.num_warnings == 0

    def summary(self) -> str:
        if not self.ok:
            return f"{self.path}: unreadable ({self.error})"
        lines = [f"{self.path}: {self.num_errors} errors, {self.num_warnings} warnings, {self.num_infos} infos"]
        for message in [m for m in self.messages if m.get("severity", 9) <= 1][:SHOWN_MESSAGES]:
            lines.append(f"  [{message.get('code')}] {message.get('message')} at {message.get('pointer')}")
        return "\n".join(lines)


def _node(package: Path | None = None) -> str:
    node = shutil.which("node")
    if node is None:
        raise ValidatorUnavailable("node is not installed; install Node.js (>= 18), then run: " + INSTALL_COMMAND)
    if not (package or PACKAGE).is_file():
        raise ValidatorUnavailable(f"the gltf-validator npm package is not installed; run: {INSTALL_COMMAND}")
    return node


def _report(record: dict[str, Any]) -> ValidationReport:
    return ValidationReport(
        path=str(record.get("path")),
        ok=bool(record.get("ok")),
        num_errors=int(record.get("numErrors", 0)),
        num_warnings=int(record.get("numWarnings", 0)),
        num_infos=int(record.get("numInfos", 0)),
        num_hints=int(record.get("numHints", 0)),
        messages=tuple(record.get("messages", ())),
        error=record.get("error"),
        validator_version=str(record.get("validatorVersion", "")),
    )


def validate_glb(paths: Iterable[str | Path], *, tool_dir: Path | None = None) -> list[ValidationReport]:
    """Validate every file with one node process; reports in input order (``tool_dir``: another harness folder).

    Raises
    ------
    ValidatorUnavailable
        node or the npm package is missing (message names the install command).
    RuntimeError
        The harness crashed or printed something that is not one report per file.
    """
    files = [str(Path(p).resolve()) for p in paths]
    if not files:
        return []
    script = SCRIPT if tool_dir is None else tool_dir / "validate.mjs"
    node = _node(None if tool_dir is None else tool_dir / "node_modules" / "gltf-validator" / "package.json")
    done = subprocess.run([node, str(script), *files], capture_output=True, text=True, timeout=TIMEOUT_S, check=False)
    lines = [line for line in done.stdout.splitlines() if line.strip()]
    if done.returncode not in (0, 1) or len(lines) != len(files):
        raise RuntimeError(f"gltf-validator harness failed (exit {done.returncode}): {done.stderr.strip()[:2000]}")
    return [_report(json.loads(line)) for line in lines]


def assert_valid(paths: Iterable[str | Path]) -> list[ValidationReport]:
    """Fail unless every file validates with 0 errors and 0 warnings."""
    reports = validate_glb(paths)
    dirty = [r for r in reports if not r.clean]
    if dirty:
        raise AssertionError("glTF-Validator found problems:\n" + "\n".join(r.summary() for r in dirty))
    return reports


def main(argv: list[str]) -> int:
    """``python -m tests.support.gltf_validator FILE ...`` (the Makefile's demo): reports on stdout, 1 unless clean."""
    if not argv:
        sys.stderr.write("usage: python -m tests.support.gltf_validator FILE.glb [FILE ...]\n")
        return 2
    reports = validate_glb(argv)
    for report in reports:
        sys.stdout.write(report.summary() + "\n")
    return 0 if all(r.clean for r in reports) else 1
