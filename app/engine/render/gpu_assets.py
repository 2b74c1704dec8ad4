"""Per-asset GPU resources: one vertex/index buffer per link and one texture atlas.

Every :class:`MeshPart` of a link is concatenated into one interleaved buffer
(:data:`VERTEX_FORMAT`), so a link is one draw call whatever its part count
(``kitchen_pot_100038``: 1127 parts in 2 links -> 2 draws). Material colour and the
part's atlas rectangle travel as vertex attributes. Resources are cached per asset
object, weakly: when the asset is garbage-collected its resources are queued and
released at the next render (moderngl's own ``context_gc`` mode is not used: in
moderngl 5.13 it queues already-released objects and then fails on them). Everything
is created, used and released under the backend's lock with the context current.
"""

from __future__ import annotations

import threading
import weakref
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from app.engine.asset.model import ArticulatedAsset, MeshPart
from app.engine.render.atlas import Rect, TextureAtlas, build_atlas, texture_key
from app.engine.render.sampling import sample_link_points

VERTEX_FORMAT = "3f 3f 2f 4f 4f"
VERTEX_ATTRIBUTES = ("in_position", "in_normal", "in_uv", "in_color", "in_rect")
FLOATS_PER_VERTEX = 16
POSITION_ONLY_FORMAT = "3f 52x"
"""The same buffer read by the flat (ID/mask) program: position, then skip 13 floats."""
NO_RECT = (0.0, 0.0, 0.0, 0.0)


@dataclass
class LinkMesh:
    """GPU buffers of one link (``vao_shaded``/``vao_flat`` share ``vbo``/``ibo``)."""

    vbo: Any
    ibo: Any
    vao_shaded: Any
    vao_flat: Any
    index_count: int


@dataclass
class AssetResources:
    """Everything uploaded for one asset."""

    links: dict[str, LinkMesh]
    atlas: Any
    points: dict[tuple[str, int], tuple[Any, Any]] = field(default_factory=dict)

    def release(self) -> None:
        for mesh in self.links.values():
            for obj in (mesh.vao_shaded, mesh.vao_flat, mesh.vbo, mesh.ibo):
                obj.release()
        for vbo, vao in self.points.values():
            vao.release()
            vbo.release()
        self.atlas.release()
        self.links.clear()
        self.points.clear()


def _part_vertices(part: MeshPart, rects: dict[str, Rect]) -> np.ndarray:
    """(n, 16) float32 interleaved vertices of one part."""
    count = len(part.vertices)
    out = np.zeros((count, FLOATS_PER_VERTEX), dtype=np.float32)
    out[:, 0:3] = part.vertices
    if part.normals is not None:
        out[:, 3:6] = part.normals
    rect: tuple[float, ...] = NO_RECT
    if part.uv is not None and part.material.image_png is not None:
        out[:, 6:8] = part.uv
        rect = tuple(float(v) for v in rects[texture_key(part.material.image_png)])
    out[:, 8:12] = part.material.base_color
    out[:, 12:16] = rect
    return out


def pack_link(asset: ArticulatedAsset, link: str, rects: dict[str, Rect]) -> tuple[np.ndarray, np.ndarray]:
    """Interleaved (n, 16) float32 vertices and (m * 3,) uint32 indices of ``link``'s parts."""
    vertices, indices, offset = [], [], 0
    for part in asset.links[link].parts:
        vertices.append(_part_vertices(part, rects))
        indices.append((part.faces.reshape(-1) + offset).astype(np.uint32))
        offset += len(part.vertices)
    return np.concatenate(vertices, axis=0), np.concatenate(indices)


def build_asset_atlas(asset: ArticulatedAsset) -> TextureAtlas:
    """The atlas of every textured part (uv and image present) of ``asset``."""
    pngs = [
        p.material.image_png
        for link in asset.visual_links
        for p in asset.links[link].parts
        if p.material.image_png is not None and p.uv is not None
    ]
    return build_atlas(pngs)


def upload_asset(ctx: Any, programs: dict[str, Any], asset: ArticulatedAsset) -> AssetResources:
    """Create the buffers, vertex arrays and atlas texture of ``asset`` in ``ctx``."""
    atlas = build_asset_atlas(asset)
    height, width = atlas.pixels.shape[:2]
    texture = ctx.texture((width, height), 4, data=np.ascontiguousarray(atlas.pixels).tobytes())
    links: dict[str, LinkMesh] = {}
    for name in asset.visual_links:
        vertices, indices = pack_link(asset, name, atlas.rects)
        vbo = ctx.buffer(vertices.tobytes())
        ibo = ctx.buffer(indices.tobytes())
        shaded = ctx.vertex_array(
            programs["shaded"], [(vbo, VERTEX_FORMAT, *VERTEX_ATTRIBUTES)], index_buffer=ibo, index_element_size=4
        )
        flat = ctx.vertex_array(
            programs["flat"], [(vbo, POSITION_ONLY_FORMAT, "in_position")], index_buffer=ibo, index_element_size=4
        )
        links[name] = LinkMesh(vbo=vbo, ibo=ibo, vao_shaded=shaded, vao_flat=flat, index_count=int(indices.size))
    return AssetResources(links=links, atlas=texture)


def point_array(
    ctx: Any, programs: dict[str, Any], resources: AssetResources, asset: ArticulatedAsset, link: str, count: int
) -> Any:
    """The (cached) vertex array of ``count`` seeded surface points of ``link``."""
    key = (link, count)
    if key not in resources.points:
        points = sample_link_points(asset, link, count).astype(np.float32)
        vbo = ctx.buffer(points.tobytes())
        vao = ctx.vertex_array(programs["points"], [(vbo, "3f", "in_position")])
        resources.points[key] = (vbo, vao)
    return resources.points[key][1]


class AssetCache:
    """Weak per-asset cache of :class:`AssetResources` (callers hold the backend lock)."""

    def __init__(self) -> None:
        self._entries: weakref.WeakKeyDictionary[
            ArticulatedAsset, tuple[AssetResources, weakref.finalize[[AssetResources], ArticulatedAsset]]
        ] = weakref.WeakKeyDictionary()
        self._dead: list[AssetResources] = []
        self._lock = threading.Lock()

    def get(self, ctx: Any, programs: dict[str, Any], asset: ArticulatedAsset) -> AssetResources:
        with self._lock:
            found = self._entries.get(asset)
        if found is not None:
            return found[0]
        resources = upload_asset(ctx, programs, asset)
        finalizer = weakref.finalize(asset, self._queue, resources)
        with self._lock:
            self._entries[asset] = (resources, finalizer)
        return resources

    def _queue(self, resources: AssetResources) -> None:
        with self._lock:
            self._dead.append(resources)

    def collect(self) -> None:
        """Release the resources of collected assets (context current, backend lock held)."""
        with self._lock:
            dead, self._dead = self._dead, []
        for resources in dead:
            resources.release()

    def pop(self, asset: ArticulatedAsset) -> AssetResources | None:
        with self._lock:
            found = self._entries.pop(asset, None)
        if found is None:
            return None
        found[1].detach()
        return found[0]
