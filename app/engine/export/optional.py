"""Lazy imports of the exporters' optional dependencies, with an error naming the extra."""

from __future__ import annotations

import importlib
from types import ModuleType

from app.engine.errors import ExportError

EXTRAS: dict[str, tuple[str, str]] = {
    "pxr": ("usd", "usd-core"),
}
"""import name -> (extra of the ``artimo`` package, PyPI package)."""


def require(module: str) -> ModuleType:
    """Import ``module`` (e.g. ``pxr.Usd``) or raise an :class:`ExportError` saying what to install.

    Raises
    ------
    ExportError
        The package is not installed.
    """
    top = module.split(".", 1)[0]
    extra, package = EXTRAS[top]
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise ExportError(
            f"the '{extra}' export needs the optional package {package}, which is not installed: "
            f"pip install 'artimo[{extra}]' (or pip install {package})"
        ) from exc

