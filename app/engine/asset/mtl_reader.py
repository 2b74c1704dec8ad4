"""The common subset of Wavefront MTL: named materials with a diffuse colour and a diffuse texture.

:func:`read_mtl` gives what the trimesh path takes from an MTL file (the colour of ``Kd`` as
8-bit RGBA, the ``map_Kd`` image opened with PIL) for files in the subset below, and raises
:class:`NotInSubset` for anything else, so the caller can hand the mesh to trimesh instead.

The subset: UTF-8 text without control characters; ``Kd``, ``Ka`` and ``Ks`` with three finite numbers, ``Ns`` with
one, each after a ``newmtl``; ``map_Kd`` after a ``newmtl``; other statements (``illum``, ``d``,
``Ni``, ...) are read and ignored, as trimesh ignores them.
"""

from __future__ import annotations

import hashlib
import io
import math
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from app.engine.asset.confined_files import ConfinedFiles
from app.engine.asset.mesh_data import SOURCE_KEY
from app.engine.errors import AssetError
from app.engine.types import IntArray

if TYPE_CHECKING:
    from PIL import Image

_CONTROL = re.compile(r"[\x00-\x08\x0b-\x0c\x0e-\x1f\x7f]")
"""ASCII control characters but tab, newline and carriage return."""
COLOUR_KEYS = frozenset({"kd", "ka", "ks"})
_SHADOWING = frozenset({"name", "image", "diffuse", "ambient", "specular", "glossiness"})
"""Statement names trimesh would take as a material's own fields (an MTL ``name`` line renames it)."""
DEFAULT_DIFFUSE = (102, 102, 102, 255)
"""The diffuse colour of a material without ``Kd`` (trimesh's default grey)."""


class NotInSubset(Exception):
    """The file uses something outside the built-in reader's subset (the message says what)."""


@dataclass(frozen=True)
class MtlMaterial:
    """One ``newmtl`` block.

    Attributes
    ----------
    diffuse : (4,) uint8
        ``Kd`` as 8-bit RGBA (opaque), or the default grey.
    image : PIL image or None
        The ``map_Kd`` texture, opened (not decoded); None when absent, missing or unreadable.
    """

    name: str
    diffuse: IntArray
    image: Image.Image | None = None


def _numbers(fields: list[str], count: int, line: str) -> list[float]:
    try:
        values = [float(x) for x in fields]
    except ValueError as exc:
        raise NotInSubset(f"unreadable number in {line!r}") from exc
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise NotInSubset(f"{line!r} does not have {count} finite numbers")
    return values


def _diffuse(kd: list[float] | None) -> IntArray:
    if kd is None:
        return np.array(DEFAULT_DIFFUSE, dtype=np.uint8)
    scaled = np.clip(np.asarray(kd, dtype=np.float64) * 255, 0.0, 255).round()
    return np.append(scaled, 255).astype(np.uint8)


def _open_image(data: bytes) -> Image.Image | None:
    from PIL import Image

    try:
        image = Image.open(io.BytesIO(data))
    except Exception:  # like trimesh: a texture PIL cannot open is no texture
        return None
    image.info[SOURCE_KEY] = hashlib.sha256(data).hexdigest()  # many OBJ files of one asset share a texture: encoded once
    return image


def _texture(files: ConfinedFiles, name: str) -> Image.Image | None:
    try:
        data = files.get(name)
    except (FileNotFoundError, AssetError):  # recorded in files.report / files.refused
        return None
    return _open_image(data)


@dataclass
class _Block:
    name: str
    kd: list[float] | None = None
    image: Image.Image | None = None


def read_mtl(data: bytes, files: ConfinedFiles) -> dict[str, MtlMaterial]:
    """Materials by name from MTL bytes, textures read through ``files``.

    A later ``newmtl`` of the same name replaces the earlier one; a ``map_Kd`` that cannot be read
    leaves the block's earlier texture, if any (as trimesh does).

    Raises
    ------
    NotInSubset
        The file is outside the subset (raised before any file is read through ``files``).
    """
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise NotInSubset("the MTL file is not UTF-8") from exc
    if _CONTROL.search(text):
        raise NotInSubset("the MTL file holds control characters")
    blocks: dict[str, _Block] = {}
    current: _Block | None = None
    textures: list[tuple[_Block, str]] = []
    for line in text.strip().splitlines():
        fields = line.strip().split()
        if len(fields) <= 1:
            continue
        key = fields[0].lower()
        if key == "newmtl":
            current = _Block(name=" ".join(fields[1:]))
            blocks[current.name] = current
        elif current is None:
            if key in COLOUR_KEYS or key in ("ns", "map_kd"):
                raise NotInSubset(f"{line!r} comes before any newmtl")
        elif key in _SHADOWING:
            raise NotInSubset(f"statement {fields[0]!r} would rename a material field")
        elif key in COLOUR_KEYS:
            values = _numbers(fields[1:], 3, line)
            if key == "kd":
                current.kd = values
        elif key == "ns":
            _numbers(fields[1:], 1, line)
        elif key == "map_kd":
            textures.append((current, line[line.lower().index("map_kd") + 6 :].strip()))
    for block, name in textures:  # read files only now, when the whole MTL is known to be in the subset
        image = _texture(files, name)
        if image is not None:
            block.image = image
    return {name: MtlMaterial(name=block.name, diffuse=_diffuse(block.kd), image=block.image) for name, block in blocks.items()}
