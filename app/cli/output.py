"""Terminal output for the CLI (the only place that writes to stdout/stderr directly)."""

from __future__ import annotations

import json
import sys
from typing import Any


def out(text: str = "") -> None:
    sys.stdout.write(text + "\n")


def err(text: str) -> None:
    sys.stderr.write(text + "\n")


def out_json(value: Any) -> None:
    out(json.dumps(value, indent=2, sort_keys=False))
