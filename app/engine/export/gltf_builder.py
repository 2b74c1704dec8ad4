"""Low-level glTF 2.0 document assembly: one binary buffer, bufferViews, accessors,
images, textures and materials, and the GLB container.

Every bufferView starts on a 4-byte boundary and holds exactly one accessor or image
(no byteStride is needed). Images and materials are deduplicated by content, so the
same input always gives the same indices and bytes.
"""

from __future__ import annotations

import json
import struct
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from app.engine.asset.model import Material
from app.engine.errors import ExportError

ALIGNMENT = 4
FLOAT = 5126
UNSIGNED_SHORT = 5123
UNSIGNED_INT = 5125
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963
LINEAR_FILTER = 9729
LINEAR_MIPMAP_LINEAR = 9987
REPEAT = 10497
ALPHA_OPAQUE = 0.999
"""baseColorFactor alpha below this makes the material ``BLEND``."""

GLB_MAGIC = b"glTF"
GLB_VERSION = 2
CHUNK_JSON = 0x4E4F534A
CHUNK_BIN = 0x004E4942

_COMPONENT_TYPES = {np.dtype(np.float32): FLOAT, np.dtype(np.uint16): UNSIGNED_SHORT, np.dtype(np.uint32): UNSIGNED_INT}
_ELEMENT_TYPES = {1: "SCALAR", 2: "VEC2", 3: "VEC3", 4: "VEC4"}
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
PNG_KEPT_CHUNKS = frozenset({b"IHDR", b"PLTE", b"tRNS", b"IDAT", b"IEND"})
"""Chunks kept in embedded PNGs; colour-space chunks (iCCP, gAMA, sRGB, cHRM) and pHYs
make the Khronos validator warn (IMAGE_FEATURES_UNSUPPORTED), and text is noise."""


def clean_png(data: bytes) -> bytes:
    """``data`` with only the chunks in :data:`PNG_KEPT_CHUNKS`.

    Raises
    ------
    ExportError
        If ``data`` is not a well-formed PNG stream.
    """
    if not data.startswith(PNG_SIGNATURE):
        raise ExportError("a material texture is not a PNG image")
    kept = [PNG_SIGNATURE]
    offset = len(PNG_SIGNATURE)
    while offset < len(data):
        if offset + 12 > len(data):
            raise ExportError("a material texture is a truncated PNG image")
        (length,) = struct.unpack(">I", data[offset : offset + 4])
        kind = data[offset + 4 : offset + 8]
        end = offset + 12 + length
        if end > len(data):
            raise ExportError("a material texture is a truncated PNG image")
        if kind in PNG_KEPT_CHUNKS:
            kept.append(data[offset:end])
        offset = end
        if kind == b"IEND":
            break
    return b"".join(kept)


def _unit_interval(value: float) -> float:
    """``value`` clamped to [0, 1] as a Python float (NaN is rejected)."""
    number = float(value)
    if number != number:
        raise ExportError("a material factor is NaN")
    return min(max(number, 0.0), 1.0)


@dataclass
class GltfBuilder:
    """Accumulates the binary chunk and the JSON arrays that reference it."""

    chunks: list[bytes] = field(default_factory=list)
    length: int = 0
    buffer_views: list[dict[str, Any]] = field(default_factory=list)
    accessors: list[dict[str, Any]] = field(default_factory=list)
    images: list[dict[str, Any]] = field(default_factory=list)
    textures: list[dict[str, Any]] = field(default_factory=list)
    materials: list[dict[str, Any]] = field(default_factory=list)
    meshes: list[dict[str, Any]] = field(default_factory=list)
    _image_index: dict[bytes, int] = field(default_factory=dict)
    _material_index: dict[tuple[Any, ...], int] = field(default_factory=dict)

    def copy(self) -> GltfBuilder:
        """A builder that shares nothing mutable with this one (dict entries are never mutated)."""
        return GltfBuilder(
            chunks=list(self.chunks),
            length=self.length,
            buffer_views=list(self.buffer_views),
            accessors=list(self.accessors),
            images=list(self.images),
            textures=list(self.textures),
            materials=list(self.materials),
            meshes=list(self.meshes),
            _image_index=dict(self._image_index),
            _material_index=dict(self._material_index),
        )

    def add_view(self, data: bytes, target: int | None = None) -> int:
        """Append ``data`` as a new bufferView (4-byte aligned); returns its index."""
        view: dict[str, Any] = {"buffer": 0, "byteOffset": self.length, "byteLength": len(data)}
        if target is not None:
            view["target"] = target
        self.chunks.append(data)
        padding = -len(data) % ALIGNMENT
        if padding:
            self.chunks.append(b"\x00" * padding)
        self.length += len(data) + padding
        self.buffer_views.append(view)
        return len(self.buffer_views) - 1

    def add_accessor(
        self,
        array: np.ndarray,
        *,
        target: int | None = None,
        bounds: bool = False,
        limits: tuple[np.ndarray, np.ndarray] | None = None,
    ) -> int:
        """Append a (n,) or (n, c) float32/uint16/uint32 array as an accessor.

        ``bounds`` writes ``min``/``max`` (exactly the stored values); ``limits``
        passes them precomputed as ((c,), (c,)) arrays of the stored dtype.
        """
        component = _COMPONENT_TYPES.get(array.dtype)
        width = 1 if array.ndim == 1 else int(array.shape[1])
        if component is None or width not in _ELEMENT_TYPES or array.ndim > 2:
            raise ExportError(f"cannot store an array of dtype {array.dtype} and shape {array.shape}")
        data = np.ascontiguousarray(array)
        view = self.add_view(data.tobytes(), target)
        accessor: dict[str, Any] = {
            "bufferView": view,
            "componentType": component,
            "count": int(array.shape[0]),
            "type": _ELEMENT_TYPES[width],
        }
        if bounds and limits is None:
            table = data.reshape(array.shape[0], width)
            limits = (table.min(axis=0), table.max(axis=0))
        if limits is not None:
            accessor["min"] = np.atleast_1d(limits[0]).tolist()
            accessor["max"] = np.atleast_1d(limits[1]).tolist()
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def add_image(self, png: bytes) -> int:
        """Texture index of an embedded PNG (one texture per distinct image)."""
        found = self._image_index.get(png)
        if found is not None:
            return found
        view = self.add_view(clean_png(png))
        self.images.append({"bufferView": view, "mimeType": "image/png"})
        self.textures.append({"sampler": 0, "source": len(self.images) - 1})
        self._image_index[png] = len(self.textures) - 1
        return self._image_index[png]

    def add_material(self, material: Material, *, textured: bool) -> int:
        """Index of a glTF material for ``material`` (``textured`` uses its PNG)."""
        texture = self.add_image(material.image_png) if textured and material.image_png is not None else None
        color = [_unit_interval(c) for c in material.base_color]
        metallic = _unit_interval(material.metallic)
        roughness = _unit_interval(material.roughness)
        key = (*color, metallic, roughness, bool(material.double_sided), texture)
        found = self._material_index.get(key)
        if found is not None:
            return found
        pbr: dict[str, Any] = {"baseColorFactor": color, "metallicFactor": metallic, "roughnessFactor": roughness}
        if texture is not None:
            pbr["baseColorTexture"] = {"index": texture}
        entry: dict[str, Any] = {
            "name": material.name,
            "pbrMetallicRoughness": pbr,
            "doubleSided": bool(material.double_sided),
        }
        if color[3] < ALPHA_OPAQUE:
            entry["alphaMode"] = "BLEND"
        self.materials.append(entry)
        self._material_index[key] = len(self.materials) - 1
        return self._material_index[key]

    def add_mesh(self, name: str, primitives: list[dict[str, Any]]) -> int:
        self.meshes.append({"name": name, "primitives": primitives})
        return len(self.meshes) - 1

    def document(self, **top: Any) -> dict[str, Any]:
        """The full glTF JSON with ``top`` (asset, scene, scenes, nodes, animations, ...)."""
        doc: dict[str, Any] = dict(top)
        if self.length:
            doc["buffers"] = [{"byteLength": self.length}]
        for key, values in (
            ("bufferViews", self.buffer_views),
            ("accessors", self.accessors),
            ("images", self.images),
            ("textures", self.textures),
            ("materials", self.materials),
            ("meshes", self.meshes),
        ):
            if values:
                doc[key] = values
        if self.textures:
            doc["samplers"] = [
                {"magFilter": LINEAR_FILTER, "minFilter": LINEAR_MIPMAP_LINEAR, "wrapS": REPEAT, "wrapT": REPEAT}
            ]
        return doc

    def glb(self, document: dict[str, Any]) -> bytes:
        """Pack ``document`` and the binary chunk into a GLB container.

        Raises
        ------
        ExportError
            If the document holds a non-finite number.
        """
        try:
            text = json.dumps(document, separators=(",", ":"), allow_nan=False, ensure_ascii=True)
        except ValueError as exc:
            raise ExportError(f"the glTF document holds a non-finite number: {exc}") from exc
        json_bytes = text.encode("ascii")
        json_bytes += b" " * (-len(json_bytes) % ALIGNMENT)
        binary = b"".join(self.chunks)
        total = 12 + 8 + len(json_bytes) + (8 + len(binary) if binary else 0)
        parts = [
            struct.pack("<4sII", GLB_MAGIC, GLB_VERSION, total),
            struct.pack("<II", len(json_bytes), CHUNK_JSON),
            json_bytes,
        ]
        if binary:
            parts += [struct.pack("<II", len(binary), CHUNK_BIN), binary]
        return b"".join(parts)
