"""Options shared by the commands that talk to an ArtiMo server (``submit``, ``jobs``)."""

from __future__ import annotations

import argparse
import os
from typing import TYPE_CHECKING

from app.cli.output import err

if TYPE_CHECKING:
    from app.client import ArtimoClient

DEFAULT_SERVER = "http://127.0.0.1:8000"
ROLES = ("perceiver", "planner", "critic")


def add_server_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--server", default=os.environ.get("ARTIMO_SERVER", DEFAULT_SERVER), help=f"default $ARTIMO_SERVER or {DEFAULT_SERVER}")
    parser.add_argument("--key", default=None, help="API key (default $ARTIMO_API_KEY)")


def open_client(args: argparse.Namespace) -> ArtimoClient | None:
    """A client of ``--server`` with ``--key`` (or $ARTIMO_API_KEY); None (after saying why) without a key."""
    from app.client import ArtimoClient

    key = args.key or os.environ.get("ARTIMO_API_KEY")
    if not key:
        err("no API key: pass --key or set ARTIMO_API_KEY (artimo serve prints one; artimo keys create --name NAME makes one)")
        return None
    return ArtimoClient(args.server, key)


def model_options(items: list[str]) -> dict[str, str]:
    """``--model ROLE=NAME`` (repeatable) as the job's ``<role>_model`` fields.

    Raises
    ------
    ValueError
        Not ROLE=NAME with a known role.
    """
    models: dict[str, str] = {}
    for item in items:
        role, _, name = item.partition("=")
        if role not in ROLES or not name:
            raise ValueError(f"--model expects ROLE=NAME with ROLE one of {', '.join(ROLES)}, got {item!r}")
        models[f"{role}_model"] = name
    return models
