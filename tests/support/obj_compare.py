"""Load a mesh file through the built-in OBJ reader and through trimesh, and compare what comes out.

``load_both`` gives each reader's parts and warnings (or the ``AssetError`` it raised). Unless
``real_png`` is set, a texture's PNG encoding is replaced, in both readers, by a fingerprint of the
image it would encode (format, mode, size and the file bytes it was opened from): the encoder is
the same function for both, and encoding the shared assets' thousands of JPEG textures twice
would take minutes.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from unittest import mock

import numpy as np

from app.engine.asset.meshes import GeometryBudget, load_mesh_file
from app.engine.asset.model import MeshPart
from app.engine.errors import AssetError

NORMAL_TOLERANCE = 1e-12
# a transform with rotation, non-uniform scale and translation, so the comparison covers the link-frame arithmetic
PLACEMENT = np.array([[0.0, -2.0, 0.0, 0.1], [1.5, 0.0, 0.0, -0.2], [0.0, 0.0, 0.5, 0.3], [0.0, 0.0, 0.0, 1.0]])


@dataclass(frozen=True)
class Loaded:
    parts: list[MeshPart]
    warnings: list[str]


def image_fingerprint(image: Any) -> bytes:
    """What identifies the PNG ``png(image)`` would give: the image's format, mode, size and source bytes."""
    source = image.fp.getvalue() if getattr(image, "fp", None) is not None else image.tobytes()
    header = f"{image.format}|{image.mode}|{image.size}|".encode()
    return b"fingerprint:" + hashlib.sha256(header + source).digest()


def _load(path: Path, root: Path, *, built_in: bool) -> Loaded | AssetError:
    budget = GeometryBudget(max_faces=10_000_000)
    try:
        parts = load_mesh_file(path, root, PLACEMENT, None, budget, label="link_0", built_in=built_in)
    except AssetError as exc:
        return exc
    return Loaded(parts=parts, warnings=list(budget.warnings))


def load_both(path: Path, root: Path, *, real_png: bool = False) -> tuple[Loaded | AssetError, Loaded | AssetError]:
    """(built-in reader, trimesh) results for the mesh file ``path`` of the asset ``root``."""
    if real_png:
        return _load(path, root, built_in=True), _load(path, root, built_in=False)
    with mock.patch("app.engine.asset.obj_reader.png", image_fingerprint), \
            mock.patch("app.engine.asset.mesh_trimesh.png", image_fingerprint):
        return _load(path, root, built_in=True), _load(path, root, built_in=False)


def _same_array(name: str, a: np.ndarray | None, b: np.ndarray | None) -> None:
    assert (a is None) == (b is None), f"{name}: one is None"
    if a is not None and b is not None:
        assert a.dtype == b.dtype and a.shape == b.shape, f"{name}: {a.dtype}{a.shape} != {b.dtype}{b.shape}"
        assert a.tobytes() == b.tobytes(), f"{name}: values differ"


def assert_same_parts(built_in: Loaded | AssetError, trimesh_path: Loaded | AssetError) -> None:
    """The two results are the same: equal errors, or the same warnings and parts (arrays bit for bit,
    normals within :data:`NORMAL_TOLERANCE`)."""
    if isinstance(built_in, AssetError) or isinstance(trimesh_path, AssetError):
        assert isinstance(built_in, AssetError) and isinstance(trimesh_path, AssetError), (built_in, trimesh_path)
        assert (str(built_in), built_in.file, built_in.element) == (str(trimesh_path), trimesh_path.file, trimesh_path.element)
        return
    assert built_in.warnings == trimesh_path.warnings
    assert len(built_in.parts) == len(trimesh_path.parts)
    for index, (a, b) in enumerate(zip(built_in.parts, trimesh_path.parts, strict=True)):
        for name in ("vertices", "faces", "uv"):
            _same_array(f"part {index} {name}", getattr(a, name), getattr(b, name))
        assert a.normals is not None and b.normals is not None
        assert a.normals.shape == b.normals.shape
        assert np.allclose(a.normals, b.normals, rtol=0.0, atol=NORMAL_TOLERANCE), f"part {index} normals"
        assert a.material == b.material, f"part {index}: {a.material} != {b.material}"
        assert (a.source, a.visual) == (b.source, b.visual)


def normals_bitwise_equal(built_in: Loaded, trimesh_path: Loaded) -> bool:
    """Whether every part's normals are equal bit for bit (not just within the tolerance)."""
    return all(a.normals is not None and b.normals is not None and a.normals.tobytes() == b.normals.tobytes()
               for a, b in zip(built_in.parts, trimesh_path.parts, strict=True))
