"""Link geometry -> glTF meshes: one mesh per link, one primitive per :class:`MeshPart`.

Vertices stay in the link frame (the link's node carries the pose). The encoded
geometry of an asset is cached per asset object, so exporting several trajectories
of one asset (the refinement loop) encodes its meshes once.
"""

from __future__ import annotations

import logging
import threading
import weakref
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from app.engine.asset.model import ArticulatedAsset, MeshPart
from app.engine.errors import ExportError
from app.engine.export.gltf_builder import ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, GltfBuilder
from app.engine.types import FloatArray, IntArray

logger = logging.getLogger(__name__)

TRIANGLES = 4
MAX_UINT16_VERTICES = 65535
"""Parts with at most this many vertices use 16-bit indices (65535 itself is reserved)."""
NORMAL_EPS = 1e-12
FALLBACK_NORMAL = (0.0, 0.0, 1.0)


@dataclass(frozen=True)
class GeometryBlock:
    """Encoded meshes of one asset; ``builder`` is never mutated (callers copy it)."""

    builder: GltfBuilder
    mesh_of_link: Mapping[str, int]


_CACHE: weakref.WeakKeyDictionary[ArticulatedAsset, GeometryBlock] = weakref.WeakKeyDictionary()
_CACHE_LOCK = threading.Lock()


def vertex_normals(vertices: FloatArray, faces: IntArray) -> FloatArray:
    """(n, 3) area-weighted unit vertex normals of a triangle mesh (vertices (n, 3), faces (m, 3))."""
    corners = vertices[faces]
    face_normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    flat = faces.reshape(-1)
    count = vertices.shape[0]
    summed: FloatArray = np.stack(
        [np.bincount(flat, weights=np.repeat(face_normals[:, axis], 3), minlength=count) for axis in range(3)], axis=1
    )
    return unit_rows(summed)


def unit_rows(vectors: FloatArray) -> FloatArray:
    """(n, 3) rows scaled to unit length; zero or non-finite rows become +Z."""
    out = np.array(vectors, dtype=np.float64, copy=True)
    length = np.linalg.norm(out, axis=1)
    bad = ~np.isfinite(length) | (length < NORMAL_EPS)
    out[bad] = FALLBACK_NORMAL
    length[bad] = 1.0
    result: FloatArray = out / length[:, None]
    return result


@dataclass(frozen=True, eq=False)
class _LinkArrays:
    """Per-link concatenation of the parts' arrays, converted once (vectorised)."""

    starts: IntArray
    """(p + 1,) vertex offsets of the parts."""
    vertices: np.ndarray
    """(n, 3) float32."""
    normals: np.ndarray
    """(n, 3) float32, unit length."""
    lows: np.ndarray
    highs: np.ndarray
    """(p, 3) float32 per-part POSITION bounds."""


def _check_shapes(part: MeshPart, where: str) -> None:
    if part.vertices.ndim != 2 or part.vertices.shape[1] != 3:
        raise ExportError(f"{where}: vertices must be (n, 3), got {part.vertices.shape}")
    if part.faces.ndim != 2 or part.faces.shape[1] != 3:
        raise ExportError(f"{where}: faces must be (m, 3), got {part.faces.shape}")
    if part.uv is not None and part.uv.shape != (part.vertices.shape[0], 2):
        raise ExportError(f"{where}: uv must be ({part.vertices.shape[0]}, 2), got {part.uv.shape}")


def _link_arrays(parts: list[MeshPart], labels: list[str]) -> _LinkArrays:
    counts = np.array([p.vertices.shape[0] for p in parts], dtype=np.int64)
    starts = np.concatenate([[0], np.cumsum(counts)])
    vertices = np.concatenate([p.vertices for p in parts], axis=0)
    finite = np.isfinite(vertices).all(axis=1)
    if not finite.all():
        bad = int(np.searchsorted(starts, int(np.argmin(finite)), side="right")) - 1
        raise ExportError(f"{labels[bad]}: a vertex coordinate is not finite")
    faces = np.concatenate([p.faces for p in parts], axis=0)
    limit = np.repeat(counts, [p.faces.shape[0] for p in parts])
    outside = (faces.min(axis=1) < 0) | (faces.max(axis=1) >= limit)
    if outside.any():
        row = int(np.argmax(outside))
        bad = int(np.searchsorted(np.cumsum([p.faces.shape[0] for p in parts]), row, side="right"))
        raise ExportError(f"{labels[bad]}: a face index is outside 0..{counts[bad] - 1}")
    normals = np.concatenate(
        [
            p.normals
            if p.normals is not None and p.normals.shape == p.vertices.shape
            else vertex_normals(p.vertices, p.faces)
            for p in parts
        ],
        axis=0,
    )
    vertices32 = vertices.astype(np.float32)
    return _LinkArrays(
        starts=starts,
        vertices=vertices32,
        normals=unit_rows(normals).astype(np.float32),
        lows=np.minimum.reduceat(vertices32, starts[:-1], axis=0),
        highs=np.maximum.reduceat(vertices32, starts[:-1], axis=0),
    )


def _primitive(builder: GltfBuilder, part: MeshPart, arrays: _LinkArrays, index: int, where: str) -> dict[str, Any]:
    begin, end = int(arrays.starts[index]), int(arrays.starts[index + 1])
    limits = (arrays.lows[index], arrays.highs[index])
    attributes = {
        "POSITION": builder.add_accessor(arrays.vertices[begin:end], target=ARRAY_BUFFER, limits=limits),
        "NORMAL": builder.add_accessor(arrays.normals[begin:end], target=ARRAY_BUFFER),
    }
    uv = part.uv
    textured = part.material.image_png is not None and uv is not None
    if textured and uv is not None:
        if not np.isfinite(uv).all():
            raise ExportError(f"{where}: a texture coordinate is not finite")
        attributes["TEXCOORD_0"] = builder.add_accessor(uv.astype(np.float32), target=ARRAY_BUFFER)
    index_type = np.uint16 if end - begin <= MAX_UINT16_VERTICES else np.uint32
    indices = builder.add_accessor(part.faces.reshape(-1).astype(index_type), target=ELEMENT_ARRAY_BUFFER)
    material = builder.add_material(part.material, textured=textured)
    return {"attributes": attributes, "indices": indices, "material": material, "mode": TRIANGLES}


def encode_geometry(asset: ArticulatedAsset) -> GeometryBlock:
    """Encode every link's parts (parts without triangles are skipped).

    Raises
    ------
    ExportError
        Malformed part arrays (wrong shapes, non-finite values, bad face indices).
    """
    builder = GltfBuilder()
    mesh_of_link: dict[str, int] = {}
    for link_name in asset.link_order:
        parts, labels = [], []
        for index, part in enumerate(asset.links[link_name].parts):
            label = f"link {link_name} part {index} ({part.source})"
            _check_shapes(part, label)
            if part.faces.shape[0] == 0 or part.vertices.shape[0] == 0:
                logger.debug("asset %s: %s has no triangles; skipped", asset.name, label)
                continue
            parts.append(part)
            labels.append(label)
        if not parts:
            continue
        arrays = _link_arrays(parts, labels)
        primitives = [_primitive(builder, part, arrays, i, labels[i]) for i, part in enumerate(parts)]
        mesh_of_link[link_name] = builder.add_mesh(link_name, primitives)
    return GeometryBlock(builder=builder, mesh_of_link=mesh_of_link)


def geometry_block(asset: ArticulatedAsset) -> GeometryBlock:
    """Cached :func:`encode_geometry` (keyed by the asset object, dropped with it)."""
    with _CACHE_LOCK:
        block = _CACHE.get(asset)
    if block is None:
        block = encode_geometry(asset)
        with _CACHE_LOCK:
            _CACHE[asset] = block
    return block
