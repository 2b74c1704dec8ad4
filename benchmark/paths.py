"""Where the benchmark's assets are: the PartNet-Mobility root, and checks that a root holds a file's assets.

The PartNet-Mobility assets are research data kept outside the repository. Their folder is
``$ARTIMO_PARTNET_ROOT``, else ``../shared/assets/partnet`` next to this repository (relative to
the repository, not to the working directory), else an error that says how to set it.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterable
from pathlib import Path

from app.engine.errors import MetricError
from app.engine.metrics.annotation import Case
from benchmark.cases import read_cases

REPOSITORY = Path(__file__).resolve().parents[1]
ENV_VARIABLE = "ARTIMO_PARTNET_ROOT"
BESIDE_REPOSITORY = REPOSITORY.parent / "shared" / "assets" / "partnet"
MAX_LISTED = 5


def partnet_root(environ: dict[str, str] | None = None) -> Path:
    """The PartNet-Mobility folder.

    Raises
    ------
    MetricError
        ``$ARTIMO_PARTNET_ROOT`` names no folder, or it is unset and the default does not exist.
    """
    environ = dict(os.environ) if environ is None else environ
    configured = environ.get(ENV_VARIABLE)
    if configured:
        root = Path(configured).expanduser()
        if not root.is_dir():
            raise MetricError(f"${ENV_VARIABLE} is {configured!r}, which is not a folder; point it at the folder holding "
                              "the PartNet-Mobility asset folders (safe_101593/, ...)")
        return root
    if BESIDE_REPOSITORY.is_dir():
        return BESIDE_REPOSITORY
    raise MetricError(f"no PartNet-Mobility folder: set ${ENV_VARIABLE} to the folder holding its asset folders "
                      f"(safe_101593/, ...), or put them at {BESIDE_REPOSITORY}; or pass --assets ROOT")


def check_assets_root(root: Path, assets: Iterable[str], what: str) -> list[str]:
    """The assets of ``what`` missing under ``root`` (names); an error when ``root`` holds none of them.

    Raises
    ------
    MetricError
        ``root`` is not a folder, or not one of the assets is there (a wrong root).
    """
    names = sorted(set(assets))
    if not root.is_dir():
        raise MetricError(f"assets root {root} is not a folder")
    missing = [name for name in names if not (root / name).is_dir()]
    if names and len(missing) == len(names):
        listed = ", ".join(missing[:MAX_LISTED]) + (f" and {len(missing) - MAX_LISTED} more" if len(missing) > MAX_LISTED else "")
        raise MetricError(f"assets root {root} holds none of the {len(names)} assets of {what} ({listed}): wrong --assets?")
    return missing


def assets_or_partnet(value: Path | None) -> Path:
    """``--assets`` when given, else :func:`partnet_root` (for the scripts' defaults)."""
    return value if value is not None else partnet_root()


def script_root(value: Path | None) -> Path | None:
    """:func:`assets_or_partnet` for a benchmark script: ``None`` after printing the error (the script exits 2)."""
    try:
        return assets_or_partnet(value)
    except MetricError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return None


def script_cases(cases_file: Path, assets: Path | None, limit: int) -> tuple[list[Case], Path] | None:
    """The first ``limit`` cases of ``cases_file`` and the root holding their assets, for a benchmark script:
    ``None`` after printing the error (a bad file, no root, or a root holding none of the cases' assets)."""
    try:
        cases = read_cases(cases_file)[:limit]
        root = assets_or_partnet(assets)
        check_assets_root(root, (case.asset for case in cases), str(cases_file))
    except MetricError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return None
    return cases, root
