"""Which ``.urdf`` of an asset to load: the only one, or the one asked for (``--urdf`` / the API's ``urdf``).

Plain file and zip-member listing, nothing parsed or extracted: the loader, the upload route and
``artimo submit`` (before it uploads anything) apply the same rule.
"""

from __future__ import annotations

import zipfile
from pathlib import Path

from app.engine.errors import AssetError

MACOS_METADATA_DIR = "__MACOSX"


def find_urdf(root: Path, *, shown: str | None = None, requested: str | None = None) -> Path:
    """The asset's URDF: the only ``.urdf`` under ``root``, or the one ``requested``.

    ``requested`` is a path relative to ``root`` (``cap/mobility.urdf``), or a file name or
    path ending that matches exactly one URDF. ``shown`` names the asset in error messages
    (the upload's name; default ``root.name``).

    Raises
    ------
    AssetError
        No URDF; several and none requested (the message lists them); a requested one
        that matches none or several.
    """
    found = [p for p in root.rglob("*") if p.suffix.lower() == ".urdf" and p.is_file() and not p.is_symlink()]
    names = [p.relative_to(root).as_posix() for p in found]
    return root / choose_urdf(names, requested, shown or root.name)


def urdf_in_zip(archive: Path, requested: str | None = None) -> str:
    """:func:`find_urdf` on a zip's member list (nothing extracted): the chosen URDF's path inside the asset.

    Raises
    ------
    AssetError
        As :func:`find_urdf`, or an unreadable zip.
    """
    try:
        with zipfile.ZipFile(archive) as zf:
            members = [i.filename.replace("\\", "/") for i in zf.infolist() if not i.is_dir()]
    except (zipfile.BadZipFile, OSError) as exc:
        raise AssetError(f"not a readable zip archive: {exc}", file=archive.name, element="central directory") from exc
    members = [m.lstrip("/") for m in members if m.split("/", 1)[0] != MACOS_METADATA_DIR]
    tops = {m.split("/", 1)[0] for m in members}
    if len(tops) == 1 and all("/" in m for m in members):  # a zip of one folder: the folder is the asset root
        members = [m.split("/", 1)[1] for m in members]
    return choose_urdf([m for m in members if m.lower().endswith(".urdf")], requested, archive.name)


def choose_urdf(names: list[str], requested: str | None, shown: str) -> str:
    """One of ``names`` (URDF paths relative to the asset root): the only one, or the one ``requested``."""
    names = sorted((n for n in names if MACOS_METADATA_DIR not in n.split("/")), key=lambda n: (n.count("/"), n))
    if not names:
        raise AssetError("no .urdf file in the asset", file=shown, element="*.urdf")
    if requested is not None:
        return _match_urdf(names, requested, shown)
    if len(names) == 1:
        return names[0]
    raise AssetError(
        f"the asset holds {len(names)} URDF files ({urdf_list(names)}); choose one with --urdf NAME "
        "(artimo) or the 'urdf' field (API), or upload one asset at a time",
        file=shown, element="*.urdf",  # the list is in the message once
    )


MAX_LISTED_URDFS = 12


def urdf_list(names: list[str]) -> str:
    """``a.urdf, b.urdf`` (the first :data:`MAX_LISTED_URDFS`, then how many more)."""
    shown = ", ".join(names[:MAX_LISTED_URDFS])
    return shown if len(names) <= MAX_LISTED_URDFS else f"{shown} and {len(names) - MAX_LISTED_URDFS} more"


def _match_urdf(names: list[str], requested: str, shown: str) -> str:
    wanted = requested.strip().replace("\\", "/").strip("/")
    while wanted.startswith("./"):
        wanted = wanted[2:]
    if wanted in names:
        return wanted
    ending = [n for n in names if n.endswith("/" + wanted)]
    if len(ending) == 1:
        return ending[0]
    # the asset's own top folder named too (``bin/mobility.urdf`` for a zip of the folder ``bin``)
    inner = [n for n in names if wanted.endswith("/" + n)]
    if len(inner) == 1:
        return inner[0]
    problem = "matches several" if len(ending) > 1 or len(inner) > 1 else "matches none"
    raise AssetError(f"the requested URDF {requested!r} {problem} of the asset's URDF files ({urdf_list(names)})",
                     file=shown, element=requested[:200])
