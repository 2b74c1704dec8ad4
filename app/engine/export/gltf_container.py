"""Reading glTF 2.0 containers: GLB or ``.gltf`` JSON, their buffers, and accessors.

Used by :mod:`app.engine.export.gltf_reader`. Every malformed input raises
:class:`MetricError` whose message starts with the source name.
"""

from __future__ import annotations

import base64
import binascii
import json
import struct
import urllib.parse
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.errors import MetricError

GLB_MAGIC = b"glTF"
GLB_HEADER = 12
CHUNK_HEADER = 8
CHUNK_JSON = 0x4E4F534A
CHUNK_BIN = 0x004E4942
MAX_FILE_BYTES = 1 << 30
"""Refuse inputs above 1 GiB."""

COMPONENT_DTYPES: dict[int, np.dtype[Any]] = {
    5120: np.dtype("<i1"),
    5121: np.dtype("<u1"),
    5122: np.dtype("<i2"),
    5123: np.dtype("<u2"),
    5125: np.dtype("<u4"),
    5126: np.dtype("<f4"),
}
ELEMENT_WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
UNSUPPORTED_EXTENSIONS = frozenset({"KHR_draco_mesh_compression", "EXT_meshopt_compression"})


def split_glb(data: bytes, source: str) -> tuple[dict[str, Any], bytes | None]:
    """(JSON document, BIN chunk or None) of a GLB byte string."""
    if len(data) < GLB_HEADER:
        raise MetricError(f"{source}: too short to be a GLB file ({len(data)} bytes)")
    magic, version, length = struct.unpack("<4sII", data[:GLB_HEADER])
    if magic != GLB_MAGIC:
        raise MetricError(f"{source}: not a GLB file (bad magic)")
    if version != 2:
        raise MetricError(f"{source}: GLB version {version} is not supported (only 2)")
    if length > len(data):
        raise MetricError(f"{source}: truncated GLB (header says {length} bytes, file has {len(data)})")
    offset = GLB_HEADER
    chunks: list[tuple[int, bytes]] = []
    while offset + CHUNK_HEADER <= length:
        size, kind = struct.unpack("<II", data[offset : offset + CHUNK_HEADER])
        start = offset + CHUNK_HEADER
        if start + size > length:
            raise MetricError(f"{source}: GLB chunk {len(chunks)} runs past the end of the file")
        chunks.append((kind, data[start : start + size]))
        offset = start + size + (-size % 4)
    if not chunks or chunks[0][0] != CHUNK_JSON:
        raise MetricError(f"{source}: the first GLB chunk is not JSON")
    binary = chunks[1][1] if len(chunks) > 1 and chunks[1][0] == CHUNK_BIN else None
    return parse_json(chunks[0][1], source), binary


def parse_json(text: bytes, source: str) -> dict[str, Any]:
    """The glTF JSON object (checks ``asset.version`` 2.x and required extensions)."""
    try:
        document = json.loads(text.decode("utf-8-sig"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise MetricError(f"{source}: the glTF JSON cannot be parsed: {exc}") from exc
    if not isinstance(document, dict):
        raise MetricError(f"{source}: the glTF JSON is not an object")
    version = str((document.get("asset") or {}).get("version", ""))
    if not version.startswith("2."):
        raise MetricError(f"{source}: glTF asset version '{version}' is not supported (only 2.x)")
    blocked = sorted(UNSUPPORTED_EXTENSIONS.intersection(document.get("extensionsRequired") or []))
    if blocked:
        raise MetricError(f"{source}: compressed geometry ({', '.join(blocked)}) is not supported")
    return document


def load_buffers(document: dict[str, Any], binary: bytes | None, base_dir: Path | None, source: str) -> list[bytes]:
    """Bytes of every ``buffers[i]``: GLB BIN chunk, data URI, or a file next to the source."""
    out = []
    for index, buffer in enumerate(_list(document, "buffers", source)):
        uri = buffer.get("uri")
        if uri is None:
            if index != 0 or binary is None:
                raise MetricError(f"{source}: buffer {index} has no uri and no GLB BIN chunk")
            data = binary
        elif uri.startswith("data:"):
            data = _data_uri(uri, f"{source}: buffer {index}")
        else:
            data = _external(uri, base_dir, f"{source}: buffer {index}")
        length = int(buffer.get("byteLength", len(data)))
        if len(data) < length:
            raise MetricError(f"{source}: buffer {index} holds {len(data)} bytes, byteLength says {length}")
        out.append(data)
    return out


def _data_uri(uri: str, where: str) -> bytes:
    header, _, payload = uri.partition(",")
    if not header.endswith(";base64"):
        raise MetricError(f"{where}: only base64 data URIs are supported")
    try:
        return base64.b64decode(payload, validate=True)
    except (binascii.Error, ValueError) as exc:
        raise MetricError(f"{where}: invalid base64 data URI") from exc


def _external(uri: str, base_dir: Path | None, where: str) -> bytes:
    if base_dir is None:
        raise MetricError(f"{where}: external uri '{uri}' cannot be resolved without a file path")
    folder = base_dir.resolve()
    target = (folder / urllib.parse.unquote(uri)).resolve()
    if not target.is_relative_to(folder):
        raise MetricError(f"{where}: uri '{uri}' points outside the glTF's folder")
    try:
        return target.read_bytes()
    except OSError as exc:
        raise MetricError(f"{where}: cannot read '{uri}': {exc}") from exc


def _list(document: dict[str, Any], key: str, source: str) -> list[dict[str, Any]]:
    value = document.get(key, [])
    if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
        raise MetricError(f"{source}: '{key}' must be a list of objects")
    return value


class AccessorReader:
    """Decodes accessors of one document (cached by index) into numpy arrays."""

    def __init__(self, document: dict[str, Any], buffers: list[bytes], source: str) -> None:
        self.accessors = _list(document, "accessors", source)
        self.views = _list(document, "bufferViews", source)
        self.buffers = buffers
        self.source = source
        self._cache: dict[int, np.ndarray] = {}

    def read(self, index: Any, *, what: str) -> np.ndarray:
        """(count, width) float64 array of accessor ``index`` (normalised integers -> [0, 1] / [-1, 1]);
        integer accessors that are not normalised keep int64."""
        if not isinstance(index, int) or not 0 <= index < len(self.accessors):
            raise MetricError(f"{self.source}: {what} refers to missing accessor {index}")
        if index not in self._cache:
            try:
                self._cache[index] = self._decode(index, what)
            except (TypeError, ValueError, KeyError) as exc:
                raise MetricError(f"{self.source}: accessor {index} ({what}) is malformed: {exc}") from exc
        return self._cache[index]

    def _decode(self, index: int, what: str) -> np.ndarray:
        accessor = self.accessors[index]
        where = f"{self.source}: accessor {index} ({what})"
        dtype = COMPONENT_DTYPES.get(accessor.get("componentType", -1))
        width = ELEMENT_WIDTHS.get(accessor.get("type", ""))
        count = accessor.get("count")
        if dtype is None or width is None or not isinstance(count, int) or count < 0:
            raise MetricError(f"{where}: bad componentType, type or count")
        if "bufferView" in accessor:
            raw = self._raw(accessor, dtype, width, count, where)
        else:
            raw = np.zeros((count, width), dtype=dtype)
        if "sparse" in accessor:
            raw = self._sparse(accessor["sparse"], raw, dtype, width, where)
        return _convert(raw, dtype, bool(accessor.get("normalized", False)))

    def _raw(self, accessor: dict[str, Any], dtype: np.dtype[Any], width: int, count: int, where: str) -> np.ndarray:
        return self._view_slice(accessor["bufferView"], int(accessor.get("byteOffset", 0)), dtype, width, count, where)

    def _view_slice(
        self, view_index: Any, offset: int, dtype: np.dtype[Any], width: int, count: int, where: str
    ) -> np.ndarray:
        if not isinstance(view_index, int) or not 0 <= view_index < len(self.views):
            raise MetricError(f"{where}: missing bufferView {view_index}")
        view = self.views[view_index]
        buffer_index = view.get("buffer", -1)
        if not isinstance(buffer_index, int) or not 0 <= buffer_index < len(self.buffers):
            raise MetricError(f"{where}: bufferView {view_index} refers to missing buffer {buffer_index}")
        element = dtype.itemsize * width
        stride = int(view.get("byteStride", element)) or element
        start = int(view.get("byteOffset", 0)) + offset
        needed = 0 if count == 0 else stride * (count - 1) + element
        if (
            stride < element
            or offset + needed > int(view.get("byteLength", 0))
            or start + needed > len(self.buffers[buffer_index])
        ):
            raise MetricError(f"{where}: data runs past its bufferView or buffer")
        flat = np.frombuffer(self.buffers[buffer_index], dtype=np.uint8, count=needed, offset=start)
        if stride != element:
            padded = np.zeros(stride * count, dtype=np.uint8)
            padded[:needed] = flat
            flat = padded.reshape(count, stride)[:, :element].reshape(-1)
        return flat.copy().view(dtype).reshape(count, width)

    def _sparse(
        self, sparse: dict[str, Any], raw: np.ndarray, dtype: np.dtype[Any], width: int, where: str
    ) -> np.ndarray:
        try:
            count = int(sparse["count"])
            indices_spec, values_spec = sparse["indices"], sparse["values"]
            index_dtype = COMPONENT_DTYPES[indices_spec["componentType"]]
            rows = self._view_slice(
                indices_spec["bufferView"], int(indices_spec.get("byteOffset", 0)), index_dtype, 1, count, where
            )
            values = self._view_slice(
                values_spec["bufferView"], int(values_spec.get("byteOffset", 0)), dtype, width, count, where
            )
        except (KeyError, TypeError, ValueError) as exc:
            raise MetricError(f"{where}: malformed sparse block ({exc})") from exc
        rows = rows.reshape(-1).astype(np.int64)
        if rows.size and (rows.min() < 0 or rows.max() >= raw.shape[0]):
            raise MetricError(f"{where}: sparse index out of range")
        out = raw.copy()
        out[rows] = values
        return out


def _convert(raw: np.ndarray, dtype: np.dtype[Any], normalized: bool) -> np.ndarray:
    if dtype.kind == "f":
        return raw.astype(np.float64)
    if not normalized:
        return raw.astype(np.int64)
    scale = float(np.iinfo(dtype).max)
    values = raw.astype(np.float64) / scale
    return np.maximum(values, -1.0) if dtype.kind == "i" else values
