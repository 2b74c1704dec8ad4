"""What a mesh reader hands the loader: triangles, and on demand their normals and appearance.

Both readers (the built-in OBJ reader and the trimesh path) return :class:`SourceMesh` objects in
the mesh file's frame; :func:`app.engine.asset.meshes.load_mesh_file` checks them and moves them
into the link frame. Normals and appearance are computed only when asked for, after the face budget
and the vertex checks (a texture is not decoded for a mesh that is refused anyway).
"""

from __future__ import annotations

import io
import threading
from collections import OrderedDict
from typing import TYPE_CHECKING, Protocol

import numpy as np

from app.engine.asset.model import Material
from app.engine.types import FloatArray, IntArray, Transform

if TYPE_CHECKING:
    from PIL import Image

DEFAULT_RGBA = (0.8, 0.8, 0.8, 1.0)
RGBA = tuple[float, float, float, float]


class SourceMesh(Protocol):
    """One triangle mesh of a mesh file (file frame, before scale and origin)."""

    @property
    def vertices(self) -> FloatArray:
        """(n, 3) float."""
        ...

    @property
    def faces(self) -> IntArray:
        """(m, 3) int."""
        ...

    @property
    def transform(self) -> Transform:
        """(4, 4) the mesh's placement in the file (a scene node's transform; identity for OBJ)."""
        ...

    def vertex_normals(self) -> FloatArray:
        """(n, 3) float, not necessarily unit length."""
        ...

    def appearance(self, fallback: RGBA | None, name: str) -> tuple[Material, FloatArray | None]:
        """The mesh's material and (n, 2) glTF uv (v down), or no uv.

        ``fallback`` is the URDF colour, used when the file gives none; ``name`` names a material
        the file leaves unnamed.
        """
        ...


def rgba(values: object) -> RGBA:
    """An RGB(A) colour as four floats in [0, 1]; values above 1 are read as 0-255."""
    arr = np.asarray(values, dtype=np.float64).reshape(-1)
    if arr.size == 3:
        arr = np.append(arr, 1.0)
    if arr.size != 4:
        return DEFAULT_RGBA
    if arr.max() > 1.0:
        arr = arr / 255.0
    clipped = np.clip(arr, 0.0, 1.0)
    return (float(clipped[0]), float(clipped[1]), float(clipped[2]), float(clipped[3]))


SOURCE_KEY = "artimo_source_sha256"
"""Key of ``Image.info`` holding the digest of the file an image was opened from (set by the MTL reader)."""

_ENCODED: OrderedDict[tuple[str, str], bytes] = OrderedDict()
_ENCODED_MAX = 32
_ENCODED_LOCK = threading.Lock()


def png(image: Image.Image) -> bytes:
    """``image`` as PNG bytes (RGBA when it has transparency or a palette, else RGB). An image opened from a file
    is encoded once per file content: PartNet assets share one texture among many OBJ files (150 encodings, 13 s,
    for one safe before)."""
    mode = "RGBA" if image.mode in ("RGBA", "LA", "P") else "RGB"
    source = image.info.get(SOURCE_KEY)
    key = (source, mode) if isinstance(source, str) else None
    if key is not None:
        with _ENCODED_LOCK:  # the service may load assets on several threads
            if key in _ENCODED:
                _ENCODED.move_to_end(key)
                return _ENCODED[key]
    buffer = io.BytesIO()
    image.convert(mode).save(buffer, format="PNG", optimize=False, compress_level=6)
    data = buffer.getvalue()
    if key is not None:
        with _ENCODED_LOCK:
            _ENCODED[key] = data
            while len(_ENCODED) > _ENCODED_MAX:
                _ENCODED.popitem(last=False)
    return data


def gltf_uv(raw: FloatArray) -> FloatArray:
    """(n, 2) glTF uv (v down) from OBJ-style texture coordinates (v up; extra columns dropped)."""
    values = np.asarray(raw, dtype=np.float64)[:, :2]
    return np.column_stack([values[:, 0], 1.0 - values[:, 1]])
