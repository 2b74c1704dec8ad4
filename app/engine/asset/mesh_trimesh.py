"""The trimesh path: every mesh format trimesh reads, and the URDF primitives.

Imported only when needed (a mesh the built-in OBJ reader does not take, a primitive): importing
trimesh brings in scipy and networkx, most of a cold process's time. References inside a mesh
file (MTL, textures, glTF buffers) go through :class:`~app.engine.asset.confined_files.ConfinedFiles`.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh
import trimesh.resolvers

from app.engine.asset.confined_files import ConfinedFiles
from app.engine.asset.mesh_data import DEFAULT_RGBA, RGBA, gltf_uv, png, rgba
from app.engine.asset.model import Material
from app.engine.errors import AssetError
from app.engine.types import FloatArray, IntArray, Transform

CYLINDER_SECTIONS = 48
SPHERE_SUBDIVISIONS = 3


class _ConfinedResolver(trimesh.resolvers.Resolver):
    """trimesh's view of :class:`ConfinedFiles` (read-only)."""

    def __init__(self, files: ConfinedFiles) -> None:
        self.files = files

    def get(self, name: str) -> bytes:
        return self.files.get(name)

    def write(self, name: str, data: bytes | str) -> None:  # noqa: ARG002 - trimesh's Resolver signature
        raise PermissionError("the asset resolver is read-only")

    def namespaced(self, namespace: str) -> _ConfinedResolver:
        files = self.files
        nested = ConfinedFiles(parent=files.parent / namespace, root=files.root, limits=files.limits, report=files.report,
                               refused=files.refused)
        return _ConfinedResolver(nested)

    def keys(self) -> Iterator[str]:  # pragma: no cover - trimesh only uses it for zips
        return iter(())


@dataclass(frozen=True, eq=False)
class TrimeshMesh:
    """One trimesh mesh as a :class:`~app.engine.asset.mesh_data.SourceMesh` (``transform``: its scene node's)."""

    mesh: trimesh.Trimesh
    transform: Transform

    @property
    def vertices(self) -> FloatArray:
        return np.asarray(self.mesh.vertices, dtype=np.float64)

    @property
    def faces(self) -> IntArray:
        return np.asarray(self.mesh.faces, dtype=np.int64)

    def vertex_normals(self) -> FloatArray:
        return np.asarray(self.mesh.vertex_normals, dtype=np.float64)

    def appearance(self, fallback: RGBA | None, name: str) -> tuple[Material, FloatArray | None]:
        visual = self.mesh.visual
        if isinstance(visual, trimesh.visual.TextureVisuals):
            return _texture_appearance(visual, len(self.mesh.vertices), fallback, name)
        if isinstance(visual, trimesh.visual.ColorVisuals) and visual.kind is not None:
            colors = np.asarray(visual.face_colors, dtype=np.float64)
            return Material(name=name, base_color=rgba(colors.mean(axis=0))), None
        return Material(name=name, base_color=fallback or DEFAULT_RGBA), None


def _texture_appearance(visual: trimesh.visual.TextureVisuals, vertex_count: int, fallback: RGBA | None,
                        name: str) -> tuple[Material, FloatArray | None]:
    material = visual.material
    image = None
    color: RGBA = fallback or DEFAULT_RGBA
    metallic, roughness = 0.0, 1.0
    if isinstance(material, trimesh.visual.material.PBRMaterial):
        image = material.baseColorTexture
        if material.baseColorFactor is not None:
            color = rgba(material.baseColorFactor)
        metallic = float(material.metallicFactor if material.metallicFactor is not None else 0.0)
        roughness = float(material.roughnessFactor if material.roughnessFactor is not None else 1.0)
    elif isinstance(material, trimesh.visual.material.SimpleMaterial):
        image = material.image
        color = rgba(material.diffuse)
    uv = None
    if visual.uv is not None and image is not None and len(visual.uv) == vertex_count:
        uv = gltf_uv(visual.uv)
    texture = png(image) if (image is not None and uv is not None) else None
    material_name = getattr(material, "name", None) or name
    return Material(name=str(material_name), base_color=color, image_png=texture, metallic=metallic, roughness=roughness), uv


def read_with_trimesh(path: Path, files: ConfinedFiles, relative: str) -> list[TrimeshMesh]:
    """The triangle meshes of the mesh file ``path``, in scene order (references read through ``files``).

    Raises
    ------
    AssetError
        trimesh cannot read the file (or a referenced file was refused while it tried).
    """
    resolver = _ConfinedResolver(files)
    try:
        with open(path, "rb") as handle:
            scene = trimesh.load(handle, file_type=path.suffix.lower().lstrip("."), resolver=resolver, force="scene", process=False)
    except AssetError:
        raise
    except Exception as exc:  # trimesh raises many unrelated types on corrupt files
        if files.refused:
            raise files.refused[0] from exc
        raise AssetError(f"cannot read mesh: {type(exc).__name__}: {exc}", file=relative) from exc
    if not isinstance(scene, trimesh.Scene):
        raise AssetError("mesh did not load as a scene", file=relative)
    meshes = []
    for node in scene.graph.nodes_geometry:
        transform, geometry_name = scene.graph[node]
        geometry = scene.geometry[geometry_name]
        if isinstance(geometry, trimesh.Trimesh) and len(geometry.faces) > 0:
            meshes.append(TrimeshMesh(mesh=geometry, transform=np.asarray(transform, dtype=np.float64)))
    return meshes


def primitive_mesh(kind: str, size: FloatArray) -> TrimeshMesh:
    """A URDF primitive centred on its frame: ``box`` (size xyz), ``cylinder`` (radius, length along z), ``sphere`` (radius)."""
    if kind == "box":
        mesh = trimesh.creation.box(extents=size)
    elif kind == "cylinder":
        mesh = trimesh.creation.cylinder(radius=float(size[0]), height=float(size[1]), sections=CYLINDER_SECTIONS)
    else:
        mesh = trimesh.creation.icosphere(subdivisions=SPHERE_SUBDIVISIONS, radius=float(size[0]))
    return TrimeshMesh(mesh=mesh, transform=np.eye(4))
