"""Terminal output for the CLI (the only place that writes to stdout/stderr directly)."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path
from typing import Any


def out(text: str = "") -> None:
    sys.stdout.write(text + "\n")


def err(text: str) -> None:
    sys.stderr.write(text + "\n")


def out_json(value: Any) -> None:
    out(json.dumps(value, indent=2, sort_keys=False))


def cache_dir(args: object) -> Path | None:
    """The asset cache folder for this invocation (None with --no-cache)."""
    if getattr(args, "no_cache", False):
        return None
    root = os.environ.get("ARTIMO_CACHE_DIR") or str(Path.home() / ".cache" / "artimo")
    return Path(root) / "assets"
