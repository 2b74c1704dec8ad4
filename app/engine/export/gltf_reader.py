"""Read GLB / glTF files from any producer: node tree, node meshes, animation by time.

``read_glb(path)`` accepts binary GLB or ``.gltf`` JSON (embedded data URIs or files
next to it). Frames: all transforms are in glTF world (whatever up-axis the producer
used; ours is +Y up, see :data:`app.engine.export.rotations.Z_UP_TO_Y_UP`); a node's
world transform maps node-local points to world. Errors are :class:`MetricError`.
"""

from __future__ import annotations

import logging
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.errors import MetricError
from app.engine.export.gltf_container import MAX_FILE_BYTES, AccessorReader, load_buffers, parse_json, split_glb
from app.engine.export.gltf_sampling import Channel, read_channels
from app.engine.export.rotations import compose_trs
from app.engine.types import FloatArray, IntArray

logger = logging.getLogger(__name__)

TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN = 4, 5, 6
NodeMesh = tuple[FloatArray, IntArray]
"""(vertices (n, 3) float in the node frame, faces (m, 3) int)."""


def read_glb(path: str | Path) -> GltfScene:
    """Parse a ``.glb`` or ``.gltf`` file (format detected from its first bytes).

    Raises
    ------
    MetricError
        Unreadable, too large, or malformed file (the message names the file and the problem).
    """
    source = Path(path)
    try:
        size = source.stat().st_size
        if size > MAX_FILE_BYTES:
            raise MetricError(f"{source.name}: {size} bytes is larger than the {MAX_FILE_BYTES}-byte limit")
        data = source.read_bytes()
    except OSError as exc:
        raise MetricError(f"cannot read glTF file {source}: {exc}") from exc
    return parse_gltf(data, base_dir=source.parent, source=source.name)


def parse_gltf(data: bytes, *, base_dir: Path | None = None, source: str = "<bytes>") -> GltfScene:
    """Parse GLB or glTF JSON bytes; ``base_dir`` resolves external buffer URIs."""
    if data[:4] == b"glTF":
        document, binary = split_glb(data, source)
    elif data.lstrip(b" \t\r\n\xef\xbb\xbf")[:1] == b"{":
        document, binary = parse_json(data, source), None
    else:
        raise MetricError(f"{source}: neither a GLB file (bad magic) nor glTF JSON")
    return GltfScene(document, load_buffers(document, binary, base_dir, source), source)


def _static_local(node: dict[str, Any], where: str) -> FloatArray:
    """(4, 4) node-local transform from ``matrix`` (column-major) or TRS."""
    try:
        if "matrix" in node:
            matrix = np.asarray(node["matrix"], dtype=np.float64).reshape(4, 4).T
        else:
            translation = np.asarray(node.get("translation", [0.0, 0.0, 0.0]), dtype=np.float64).reshape(1, 3)
            rotation = np.asarray(node.get("rotation", [0.0, 0.0, 0.0, 1.0]), dtype=np.float64).reshape(1, 4)
            scale = np.asarray(node.get("scale", [1.0, 1.0, 1.0]), dtype=np.float64).reshape(1, 3)
            matrix = compose_trs(translation, rotation, scale)[0]
    except (TypeError, ValueError) as exc:
        raise MetricError(f"{where}: bad matrix/translation/rotation/scale ({exc})") from exc
    if not np.all(np.isfinite(matrix)):
        raise MetricError(f"{where}: transform holds a non-finite value")
    return matrix


class GltfScene:
    """A parsed glTF document: node tree, meshes and animations.

    Node names are the glTF names; unnamed nodes are ``node_<index>`` and repeated
    names get ``#<k>`` appended from the second occurrence on (recorded in ``warnings``).
    """

    def __init__(self, document: dict[str, Any], buffers: list[bytes], source: str) -> None:
        self.document = document
        self.source = source
        self.accessors = AccessorReader(document, buffers, source)
        self._nodes = self._node_list()
        self.warnings: list[str] = []
        self.node_names: tuple[str, ...] = self._names()
        self._index = {name: i for i, name in enumerate(self.node_names)}
        self.parents: tuple[int | None, ...] = self._parents()
        self._order = self._topological()
        self._static = (
            np.stack([_static_local(n, f"{source}: node {i}") for i, n in enumerate(self._nodes)])
            if self._nodes
            else np.zeros((0, 4, 4))
        )
        self._trs = [self._static_trs(i) for i in range(len(self._nodes))]
        self._channels: dict[int, list[Channel]] = {}
        self._geometry: dict[int, list[NodeMesh]] = {}

    # -- structure -------------------------------------------------------------------------
    def _node_list(self) -> list[dict[str, Any]]:
        for key in ("nodes", "meshes", "animations"):
            value = self.document.get(key, [])
            if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
                raise MetricError(f"{self.source}: '{key}' must be a list of objects")
        return list(self.document.get("nodes", []))

    def _names(self) -> tuple[str, ...]:
        seen: dict[str, int] = {}
        names = []
        for i, node in enumerate(self._nodes):
            raw = node.get("name")
            base = raw if isinstance(raw, str) and raw else f"node_{i}"
            count = seen.get(base, 0)
            seen[base] = count + 1
            names.append(base if count == 0 else f"{base}#{count}")
            if count:
                self.warnings.append(
                    f"{self.source}: node name '{base}' is repeated; node {i} is read as '{names[-1]}'"
                )
        for note in self.warnings:
            logger.warning(note)
        return tuple(names)

    def _parents(self) -> tuple[int | None, ...]:
        parents: list[int | None] = [None] * len(self._nodes)
        for i, node in enumerate(self._nodes):
            children = node.get("children", [])
            if not isinstance(children, list):
                raise MetricError(f"{self.source}: node {i} children must be a list")
            for child in children:
                if not isinstance(child, int) or not 0 <= child < len(self._nodes) or child == i:
                    raise MetricError(f"{self.source}: node {i} has an invalid child {child}")
                if parents[child] is not None:
                    raise MetricError(f"{self.source}: node {child} has two parents ({parents[child]} and {i})")
                parents[child] = i
        return tuple(parents)

    def _topological(self) -> list[int]:
        children: list[list[int]] = [[] for _ in self._nodes]
        for child, parent in enumerate(self.parents):
            if parent is not None:
                children[parent].append(child)
        order = [i for i, parent in enumerate(self.parents) if parent is None]
        for i in order:  # the list grows while iterating: breadth-first
            order.extend(children[i])
        if len(order) != len(self._nodes):
            raise MetricError(f"{self.source}: the node hierarchy has a cycle")
        return order

    def _static_trs(self, index: int) -> tuple[FloatArray, FloatArray, FloatArray] | None:
        node = self._nodes[index]
        if "matrix" in node:
            return None
        return (
            np.asarray(node.get("translation", [0.0, 0.0, 0.0]), dtype=np.float64),
            np.asarray(node.get("rotation", [0.0, 0.0, 0.0, 1.0]), dtype=np.float64),
            np.asarray(node.get("scale", [1.0, 1.0, 1.0]), dtype=np.float64),
        )

    def node_index(self, name: str) -> int:
        """Index of the node called ``name``.

        Raises
        ------
        MetricError
            No such node.
        """
        if name not in self._index:
            raise MetricError(f"{self.source}: no node named '{name}'")
        return self._index[name]

    def parent(self, name: str) -> str | None:
        """Name of the parent node (None for a root node)."""
        parent = self.parents[self.node_index(name)]
        return None if parent is None else self.node_names[parent]

    def children(self, name: str) -> tuple[str, ...]:
        index = self.node_index(name)
        return tuple(self.node_names[i] for i, p in enumerate(self.parents) if p == index)

    def node_extras(self, name: str) -> Any:
        """The node's ``extras`` value (None when absent)."""
        return self._nodes[self.node_index(name)].get("extras")

    # -- animation -------------------------------------------------------------------------
    @property
    def animation_names(self) -> tuple[str, ...]:
        animations = self.document.get("animations", [])
        return tuple(str(a.get("name") or f"animation_{i}") for i, a in enumerate(animations))

    def _animation_index(self, animation: int | str) -> int | None:
        names = self.animation_names
        if not names:
            return None
        if isinstance(animation, str):
            if animation not in names:
                raise MetricError(f"{self.source}: no animation named '{animation}' (have {', '.join(names)})")
            return names.index(animation)
        if not 0 <= animation < len(names):
            raise MetricError(f"{self.source}: no animation {animation} (the file has {len(names)})")
        return animation

    def channels(self, animation: int | str = 0) -> list[Channel]:
        """Decoded node channels of an animation ([] when the file has none)."""
        index = self._animation_index(animation)
        if index is None:
            return []
        if index not in self._channels:
            where = f"{self.source}: animation {index}"
            self._channels[index] = read_channels(
                self.document["animations"][index], self.accessors, len(self._nodes), where
            )
        return self._channels[index]

    def animation_times(self, animation: int | str = 0) -> FloatArray:
        """(k,) sorted distinct key times of all channels; ``[0.0]`` for a file without animation."""
        channels = self.channels(animation)
        if not channels:
            return np.zeros(1)
        return np.unique(np.concatenate([c.times for c in channels]))

    def local_transforms(self, times: Sequence[float] | FloatArray, animation: int | str = 0) -> FloatArray:
        """(nodes, m, 4, 4) node-local transforms at ``times`` (m,)."""
        query = np.atleast_1d(np.asarray(times, dtype=np.float64))
        if not np.all(np.isfinite(query)):
            raise MetricError("sample times must be finite")
        local = np.repeat(self._static[:, None], query.shape[0], axis=1)
        by_node: dict[int, dict[str, FloatArray]] = {}
        for channel in self.channels(animation):
            by_node.setdefault(channel.node, {})[channel.path] = channel.sample(query)
        for node, paths in sorted(by_node.items()):
            trs = self._trs[node]
            if trs is None:
                logger.warning("%s: node %d has a matrix; its animation channels are ignored", self.source, node)
                continue
            count = query.shape[0]
            translation = paths.get("translation", np.broadcast_to(trs[0], (count, 3)))
            rotation = paths.get("rotation", np.broadcast_to(trs[1], (count, 4)))
            scale = paths.get("scale", np.broadcast_to(trs[2], (count, 3)))
            local[node] = compose_trs(np.asarray(translation), np.asarray(rotation), np.asarray(scale))
        return local

    def world_transform_tracks(
        self, times: Sequence[float] | FloatArray, animation: int | str = 0
    ) -> dict[str, FloatArray]:
        """{node name: (m, 4, 4) node-to-world transforms at ``times`` (m,)}."""
        local = self.local_transforms(times, animation)
        world = np.zeros_like(local)
        for index in self._order:
            parent = self.parents[index]
            world[index] = local[index] if parent is None else world[parent] @ local[index]
        return {name: world[i] for i, name in enumerate(self.node_names)}

    def world_transforms(self, t: float, animation: int | str = 0) -> dict[str, FloatArray]:
        """{node name: (4, 4) node-to-world transform at time ``t`` seconds}."""
        return {name: track[0] for name, track in self.world_transform_tracks([t], animation).items()}

    # -- geometry --------------------------------------------------------------------------
    def node_geometry(self, name: str) -> list[NodeMesh]:
        """Triangle primitives of the node's mesh in the node frame ([] without a mesh).

        Primitives that are not triangles (points, lines) are skipped.
        """
        index = self.node_index(name)
        if index not in self._geometry:
            self._geometry[index] = self._read_mesh(index)
        return self._geometry[index]

    def _read_mesh(self, node_index: int) -> list[NodeMesh]:
        mesh_index = self._nodes[node_index].get("mesh")
        if mesh_index is None:
            return []
        meshes = self.document.get("meshes", [])
        if not isinstance(mesh_index, int) or not isinstance(meshes, list) or not 0 <= mesh_index < len(meshes):
            raise MetricError(f"{self.source}: node {node_index} refers to missing mesh {mesh_index}")
        primitives = meshes[mesh_index].get("primitives", [])
        if not isinstance(primitives, list) or not all(isinstance(p, dict) for p in primitives):
            raise MetricError(f"{self.source}: mesh {mesh_index} primitives must be a list of objects")
        out = []
        for number, primitive in enumerate(primitives):
            where = f"mesh {mesh_index} primitive {number}"
            read = _primitive(primitive, self.accessors, where, self.source)
            if read is not None:
                out.append(read)
        return out


def _primitive(primitive: dict[str, Any], accessors: AccessorReader, where: str, source: str) -> NodeMesh | None:
    mode = primitive.get("mode", TRIANGLES)
    if mode not in (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN):
        return None
    attributes = primitive.get("attributes")
    if not isinstance(attributes, dict):
        raise MetricError(f"{source}: {where} has no attributes object")
    position = attributes.get("POSITION")
    if position is None:
        return None
    vertices = accessors.read(position, what=f"{where} POSITION").astype(np.float64)
    if vertices.shape[1] != 3 or not np.all(np.isfinite(vertices)):
        raise MetricError(f"{source}: {where} POSITION must be finite VEC3")
    count = vertices.shape[0]
    if "indices" in primitive:
        indices = accessors.read(primitive["indices"], what=f"{where} indices").reshape(-1).astype(np.int64)
    else:
        indices = np.arange(count, dtype=np.int64)
    if indices.size and (indices.min() < 0 or indices.max() >= count):
        raise MetricError(f"{source}: {where} has an index outside 0..{count - 1}")
    return vertices, _faces(indices, mode)


def _faces(indices: IntArray, mode: int) -> IntArray:
    """(m, 3) triangles from an index list in TRIANGLES / TRIANGLE_STRIP / TRIANGLE_FAN order."""
    if mode == TRIANGLES:
        usable = indices.shape[0] - indices.shape[0] % 3
        return indices[:usable].reshape(-1, 3)
    if indices.shape[0] < 3:
        return np.zeros((0, 3), dtype=np.int64)
    k = np.arange(indices.shape[0] - 2)
    if mode == TRIANGLE_FAN:
        return np.stack([np.full(k.shape, indices[0]), indices[k + 1], indices[k + 2]], axis=1)
    odd = (k % 2).astype(bool)
    first = np.where(odd, indices[k + 1], indices[k])
    second = np.where(odd, indices[k], indices[k + 1])
    return np.stack([first, second, indices[k + 2]], axis=1)
