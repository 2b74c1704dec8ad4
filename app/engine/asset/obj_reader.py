"""The built-in OBJ reader: an OBJ file in the common subset -> meshes, without importing trimesh.

For a file in the subset (see :mod:`app.engine.asset.obj_text` and :mod:`app.engine.asset.mtl_reader`)
it gives the meshes the trimesh path gives, array for array: the same vertices in the same order,
faces, normals, texture coordinates and materials. A file outside the subset raises
:class:`NotInSubset` before anything is kept, and the caller reads it with trimesh instead.

Like trimesh (``process=False``, ``group_material=True``), a mesh per material keeps only the
vertices its faces use; where faces give texture or normal indices, every distinct
(vertex, texture, normal) triple becomes a vertex, ordered by vertex index as trimesh orders them.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from app.engine.asset.confined_files import ConfinedFiles
from app.engine.asset.mesh_data import DEFAULT_RGBA, RGBA, gltf_uv, png, rgba
from app.engine.asset.model import Material
from app.engine.asset.mtl_reader import MtlMaterial, NotInSubset, read_mtl
from app.engine.asset.obj_text import FaceGroup, ObjText, parse_obj
from app.engine.asset.vertex_normals import angle_weighted_normals
from app.engine.errors import AssetError
from app.engine.types import FloatArray, IntArray, Transform

__all__ = ["NotInSubset", "ObjMesh", "read_obj"]


@dataclass(frozen=True, eq=False)
class ObjMesh:
    """One material's triangles of an OBJ file (a :class:`~app.engine.asset.mesh_data.SourceMesh`).

    Attributes
    ----------
    normals : (n, 3) float or None
        The file's ``vn`` per vertex (as written, not normalised); None when the faces give none.
    uv : (n, 2) float or None
        The file's ``vt`` per vertex (OBJ convention, v up).
    material : MtlMaterial or None
        The ``usemtl`` material, None when the file names none or the MTL lacks it.
    """

    vertices: FloatArray
    faces: IntArray
    normals: FloatArray | None
    uv: FloatArray | None
    material: MtlMaterial | None

    @property
    def transform(self) -> Transform:
        return np.eye(4)

    def vertex_normals(self) -> FloatArray:
        if self.normals is not None:
            return self.normals
        return angle_weighted_normals(self.vertices, self.faces)

    def appearance(self, fallback: RGBA | None, name: str) -> tuple[Material, FloatArray | None]:
        material = self.material
        if material is None:
            return Material(name=name, base_color=fallback or DEFAULT_RGBA), None
        image = material.image
        uv = gltf_uv(self.uv) if self.uv is not None and image is not None else None
        texture = png(image) if image is not None and uv is not None else None
        return Material(name=material.name or name, base_color=rgba(material.diffuse), image_png=texture), uv


def _unmerge(columns: list[IntArray]) -> tuple[IntArray, list[IntArray]]:
    """Faces over the distinct index tuples of their corners, and per kind the index each new vertex takes.

    The tuples are sorted with the last kind most significant, then by vertex index with numpy's
    default (unstable) sort, on the same array trimesh's ``unmerge_faces`` sorts: ties among tuples
    of one vertex then fall the same way, and both readers give the same vertex order.
    """
    stack = np.column_stack([column.reshape(-1) for column in columns])
    base = int(stack.max()) + 1 if stack.size else 1
    key = np.zeros(len(stack), dtype=np.int64)
    for position in reversed(range(stack.shape[1])):
        key = key * base + stack[:, position]
    _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
    tuples = stack[first]
    order = tuples[:, 0].argsort()
    tuples = tuples[order]
    remap = np.zeros(len(order), dtype=np.int64)
    remap[order] = np.arange(len(order))
    return remap[inverse].reshape((-1, 3)), list(tuples.T)


def _mesh(obj: ObjText, group: FaceGroup, material: MtlMaterial | None) -> ObjMesh:
    if group.texture is not None and obj.uv is not None:  # parse_obj checked every index has its entry
        columns = [group.vertex, group.texture] + ([] if group.normal is None else [group.normal])
        faces, picks = _unmerge(columns)
        normals = None if group.normal is None or obj.normals is None else obj.normals[picks[2]]
        return ObjMesh(vertices=obj.vertices[picks[0]].copy(), faces=faces, normals=normals, uv=obj.uv[picks[1]], material=material)
    if group.normal is not None and obj.normals is not None:
        faces, picks = _unmerge([group.vertex, group.normal])
        return ObjMesh(vertices=obj.vertices[picks[0]].copy(), faces=faces, normals=obj.normals[picks[1]], uv=None, material=material)
    used = np.zeros(len(obj.vertices), dtype=bool)
    used[group.vertex] = True
    renumber = np.zeros(len(obj.vertices), dtype=np.int64)
    renumber[used] = np.arange(used.sum())
    return ObjMesh(vertices=obj.vertices[used].copy(), faces=renumber[group.vertex], normals=None, uv=None, material=material)


def _materials(mtllib: str | None, files: ConfinedFiles) -> dict[str, MtlMaterial]:
    if mtllib is None:
        return {}
    try:
        data = files.get(mtllib)
    except (FileNotFoundError, AssetError):  # recorded in files.report / files.refused, raised by the caller
        return {}
    return read_mtl(data, files)


def read_obj(path: Path, files: ConfinedFiles) -> list[ObjMesh]:
    """The meshes of the OBJ file ``path``, in the order trimesh lists them.

    Files named by the OBJ (its MTL, the MTL's textures) are read through ``files``; refusals and
    missing files are left in ``files`` for the caller.

    Raises
    ------
    NotInSubset
        The file (or its MTL) is outside the subset; whatever was read through ``files`` is to be discarded.
    """
    obj = parse_obj(path.read_bytes())
    materials = _materials(obj.mtllib, files)
    meshes = []
    for group in obj.groups:
        material = materials.get(group.material) if group.material is not None else None
        if material is None and group.texture is not None:
            raise NotInSubset(f"faces with texture coordinates use material {group.material!r}, which the MTL does not define")
        meshes.append(_mesh(obj, group, material))
    return meshes
