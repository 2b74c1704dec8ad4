"""The engine is a pure library: importing it pulls in no web, queue, DB or CLI code.

Two checks: every ``app.engine`` module is imported in a fresh interpreter and
``sys.modules`` is inspected (catches indirect imports too); and import-linter's
contracts from ``pyproject.toml`` are run when ``lint-imports`` is installed.
"""

from __future__ import annotations

import importlib.util
import json
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
FORBIDDEN = (
    "fastapi",
    "starlette",
    "celery",
    "redis",
    "sqlalchemy",
    "alembic",
    "app.api",
    "app.core",
    "app.db",
    "app.crud",
    "app.schemas",
    "app.main",
    "app.client",
    "app.cli",
    "workers",
    "benchmark",
)
TIMEOUT_S = 120

PROBE = """
import importlib, json, pkgutil, sys
import app.engine
names = sorted(m.name for m in pkgutil.walk_packages(app.engine.__path__, prefix="app.engine."))
for name in names:
    importlib.import_module(name)
forbidden = {forbidden!r}
found = sorted(m for m in sys.modules if any(m == f or m.startswith(f + ".") for f in forbidden))
print(json.dumps({{"imported": names, "forbidden": found}}))
"""


def test_engine_imports_no_service_code() -> None:
    result = subprocess.run(
        [sys.executable, "-c", PROBE.format(forbidden=FORBIDDEN)],
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=TIMEOUT_S,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout.strip().splitlines()[-1])
    for expected in (
        "app.engine.asset.loader",
        "app.engine.plan.checks",
        "app.engine.execute.executor",
        "app.engine.export.jsonl",
    ):
        assert expected in report["imported"]
    assert report["forbidden"] == [], f"app.engine pulled in {report['forbidden']}"


def _ini_config(tmp_path: Path) -> tuple[Path, list[str]]:
    """pyproject's import-linter contracts as an INI file, minus internal modules that do not exist yet.

    import-linter refuses a forbidden *internal* module that is absent from the graph;
    the service layer (``app.api``, ``app.db``, ...) may not be written yet, and a
    module that does not exist cannot be imported by the engine anyway.
    """
    config = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["importlinter"]
    roots = config["root_packages"]
    lines = ["[importlinter]", "root_packages =", *(f"    {r}" for r in roots), "include_external_packages = True"]
    if config.get("exclude_type_checking_imports"):
        lines.append("exclude_type_checking_imports = True")
    lines.append("")
    skipped: list[str] = []
    for number, contract in enumerate(config["contracts"], start=1):
        lines += [f"[importlinter:contract:{number}]", f"name = {contract['name']}", f"type = {contract['type']}"]
        for key, value in contract.items():
            if key in ("name", "type"):
                continue
            if isinstance(value, list):
                if key == "forbidden_modules":
                    internal_missing = [
                        m for m in value if m.split(".")[0] in roots and importlib.util.find_spec(m) is None
                    ]
                    skipped += [m for m in internal_missing if m not in skipped]
                    value = [m for m in value if m not in internal_missing]
                lines += [f"{key} =", *(f"    {v}" for v in value)]
            else:
                lines.append(f"{key} = {value}")
        lines.append("")
    path = tmp_path / "importlinter.ini"
    path.write_text("\n".join(lines), encoding="utf-8")
    return path, skipped


def test_import_contracts(tmp_path: Path) -> None:
    executable = shutil.which("lint-imports") or str(Path(sys.executable).with_name("lint-imports"))
    if not Path(executable).exists():
        pytest.skip("import-linter is not installed (pip install -e '.[dev]')")
    config, skipped = _ini_config(tmp_path)
    result = subprocess.run(
        [executable, "--config", str(config), "--no-cache", "--no-logo"],
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=TIMEOUT_S,
        check=False,
    )
    assert result.returncode == 0, (
        f"lint-imports failed (not yet existing modules skipped: {skipped}):\n{result.stdout}\n{result.stderr}"
    )
    assert "BROKEN" not in result.stdout and "KEPT" in result.stdout
