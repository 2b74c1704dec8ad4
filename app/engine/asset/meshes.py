"""Visual geometry of URDF links -> :class:`MeshPart` in the link frame.

Mesh files go through trimesh with a resolver confined to the asset directory, so
an MTL or texture reference cannot read outside it. Primitives (box, cylinder,
sphere) are built with trimesh.creation.
"""

from __future__ import annotations

import io
import logging
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import trimesh
import trimesh.resolvers
from PIL import Image

from app.engine.asset.face_count import least_faces
from app.engine.asset.model import Material, MeshPart
from app.engine.asset.safety import AssetLimits, check_image, confine
from app.engine.errors import AssetError
from app.engine.types import FloatArray, Transform

logger = logging.getLogger(__name__)

CYLINDER_SECTIONS = 48
SPHERE_SUBDIVISIONS = 3
MESH_SUFFIXES = frozenset({".obj", ".stl", ".dae", ".glb", ".gltf", ".ply", ".off"})
NORMAL_EPS = 1e-12
DEFAULT_RGBA = (0.8, 0.8, 0.8, 1.0)


class _ConfinedResolver(trimesh.resolvers.Resolver):
    """Resolve names relative to a mesh file's folder, never outside ``root``."""

    def __init__(self, mesh_file: Path, root: Path, report: list[str], limits: AssetLimits | None = None) -> None:
        self.parent = mesh_file.parent
        self.root = root
        self.report = report
        self.limits = limits or AssetLimits()
        self.refused: list[AssetError] = []
        """Files refused here; trimesh swallows errors while reading textures, so the caller re-raises these."""

    def get(self, name: str) -> bytes:
        candidate = (self.parent / name.strip().replace("\\", "/")).resolve()
        if not candidate.is_relative_to(self.root):
            self.report.append(f"'{name}' escapes the asset directory")
            raise FileNotFoundError(name)
        if not candidate.is_file():
            self.report.append(f"'{name}' is missing")
            raise FileNotFoundError(name)
        data = candidate.read_bytes()
        try:
            check_image(data, str(candidate.relative_to(self.root)), self.limits)  # a texture under any name: header first
        except AssetError as exc:
            self.refused.append(exc)
            raise
        return data

    def write(self, name: str, data: bytes | str) -> None:  # noqa: ARG002 - trimesh's Resolver signature
        raise PermissionError("the asset resolver is read-only")

    def namespaced(self, namespace: str) -> _ConfinedResolver:
        nested = _ConfinedResolver(self.parent / namespace / "_", self.root, self.report, self.limits)
        nested.refused = self.refused
        return nested

    def keys(self) -> Iterator[str]:  # pragma: no cover - trimesh only uses it for zips
        return iter(())


@dataclass
class GeometryBudget:
    """Running face count over one asset (zip-bomb style guard for meshes)."""

    max_faces: int
    faces: int = 0
    warnings: list[str] = field(default_factory=list)
    limits: AssetLimits = field(default_factory=AssetLimits)

    def spend(self, faces: int, file: str) -> None:
        self.faces += faces
        if self.faces > self.max_faces:
            raise AssetError(f"asset has more than {self.max_faces} triangles", file=file)

    def check_ahead(self, at_least: int, file: str) -> None:
        """Refuse a mesh before reading it when its header or lines already say it has too many faces."""
        if self.faces + at_least > self.max_faces:
            raise AssetError(f"asset has more than {self.max_faces} triangles ({file} alone has at least {at_least})", file=file)


def resolve_mesh_path(filename: str, urdf_dir: Path, root: Path, *, urdf_name: str, element: str) -> Path:
    """Map a URDF mesh ``filename`` to a file inside the asset directory.

    ``package://NAME/rest`` resolves to ``root/rest`` (or ``root/NAME/rest``);
    ``file://`` and plain paths resolve relative to the URDF's folder.

    Raises
    ------
    AssetError
        Path outside the asset directory, or missing file.
    """
    name = filename.strip()
    candidates: list[Path]
    if name.startswith("package://"):
        rest = name[len("package://") :]
        package, _, inner = rest.partition("/")
        candidates = [root / inner, root / package / inner, urdf_dir / inner]
    else:
        if name.startswith("file://"):
            name = name[len("file://") :]
        path = Path(name)
        candidates = [path if path.is_absolute() else urdf_dir / path]
    for candidate in candidates:
        resolved = confine(candidate, root, file=urdf_name, element=element, shown=filename)
        if resolved.is_file():
            return resolved
    raise AssetError(f"mesh file '{filename}' does not exist", file=urdf_name, element=element)


def _rgba(values: object) -> tuple[float, float, float, float]:
    arr = np.asarray(values, dtype=np.float64).reshape(-1)
    if arr.size == 3:
        arr = np.append(arr, 1.0)
    if arr.size != 4:
        return DEFAULT_RGBA
    if arr.max() > 1.0:
        arr = arr / 255.0
    clipped = np.clip(arr, 0.0, 1.0)
    return (float(clipped[0]), float(clipped[1]), float(clipped[2]), float(clipped[3]))


def _png(image: Image.Image) -> bytes:
    buffer = io.BytesIO()
    mode = "RGBA" if image.mode in ("RGBA", "LA", "P") else "RGB"
    image.convert(mode).save(buffer, format="PNG", optimize=False, compress_level=6)
    return buffer.getvalue()


def _material_of(mesh: trimesh.Trimesh, fallback: tuple[float, float, float, float] | None, name: str) -> tuple[Material, FloatArray | None]:
    """Material and (n, 2) glTF uv of a trimesh mesh."""
    visual = mesh.visual
    uv = None
    if isinstance(visual, trimesh.visual.TextureVisuals):
        material = visual.material
        image = None
        color: tuple[float, float, float, float] = fallback or DEFAULT_RGBA
        metallic, roughness = 0.0, 1.0
        if isinstance(material, trimesh.visual.material.PBRMaterial):
            image = material.baseColorTexture
            if material.baseColorFactor is not None:
                color = _rgba(material.baseColorFactor)
            metallic = float(material.metallicFactor if material.metallicFactor is not None else 0.0)
            roughness = float(material.roughnessFactor if material.roughnessFactor is not None else 1.0)
        elif isinstance(material, trimesh.visual.material.SimpleMaterial):
            image = material.image
            color = _rgba(material.diffuse)
        if visual.uv is not None and image is not None and len(visual.uv) == len(mesh.vertices):
            raw = np.asarray(visual.uv, dtype=np.float64)[:, :2]
            uv = np.column_stack([raw[:, 0], 1.0 - raw[:, 1]])
        texture = _png(image) if (image is not None and uv is not None) else None
        mat_name = getattr(material, "name", None) or name
        return Material(name=str(mat_name), base_color=color, image_png=texture, metallic=metallic, roughness=roughness), uv
    if isinstance(visual, trimesh.visual.ColorVisuals) and visual.kind is not None:
        colors = np.asarray(visual.face_colors, dtype=np.float64)
        return Material(name=name, base_color=_rgba(colors.mean(axis=0))), None
    return Material(name=name, base_color=fallback or DEFAULT_RGBA), None


def _unit(vectors: FloatArray) -> FloatArray:
    length = np.linalg.norm(vectors, axis=1)
    bad = ~np.isfinite(length) | (length < NORMAL_EPS)
    vectors[bad] = (0.0, 0.0, 1.0)
    length[bad] = 1.0
    return vectors / length[:, None]


def _part(mesh: trimesh.Trimesh, transform: Transform, material: Material, uv: FloatArray | None, source: str) -> MeshPart:
    """Move ``mesh`` by ``transform`` (rotation, translation, scale) into a link-frame part."""
    linear = transform[:3, :3]
    vertices = np.asarray(mesh.vertices, dtype=np.float64) @ linear.T + transform[:3, 3]
    faces = np.array(mesh.faces, dtype=np.int64)
    normals = np.array(mesh.vertex_normals, dtype=np.float64)
    determinant = float(np.linalg.det(linear))
    if abs(determinant) > NORMAL_EPS:
        normals = normals @ np.linalg.inv(linear)
    if determinant < 0:
        faces = faces[:, ::-1].copy()
    return MeshPart(vertices=vertices, faces=faces, normals=_unit(normals), uv=uv, material=material, source=source)


def _scene_meshes(scene: trimesh.Scene) -> Iterator[tuple[trimesh.Trimesh, Transform]]:
    for node in scene.graph.nodes_geometry:
        transform, geometry_name = scene.graph[node]
        geometry = scene.geometry[geometry_name]
        if isinstance(geometry, trimesh.Trimesh) and len(geometry.faces) > 0:
            yield geometry, np.asarray(transform, dtype=np.float64)


MAX_COORDINATE_M = 1e4
"""Largest |vertex coordinate| accepted in the link frame, metres (as URDF positions)."""


def _check_vertices(vertices: FloatArray, relative: str) -> None:
    """Every vertex finite and within :data:`MAX_COORDINATE_M` (NaN breaks everything downstream)."""
    if vertices.size and (not np.all(np.isfinite(vertices)) or float(np.abs(vertices).max()) > MAX_COORDINATE_M):
        bad = int(np.flatnonzero(~np.isfinite(vertices).all(axis=1) | (np.abs(vertices) > MAX_COORDINATE_M).any(axis=1))[0])
        raise AssetError(f"mesh vertex {bad} is NaN, infinite or farther than {MAX_COORDINATE_M:g} m "
                         f"({vertices[bad].tolist()})", file=relative, element=f"vertex {bad}")


def _check_numbers(part: MeshPart, relative: str) -> None:
    """The part's vertices (after scale and origin) and uvs: finite and bounded."""
    _check_vertices(part.vertices, relative)
    if part.uv is not None and not np.all(np.isfinite(part.uv)):
        raise AssetError("mesh texture coordinates hold NaN or infinite values", file=relative, element="vt")


def load_mesh_file(
    path: Path,
    root: Path,
    transform: Transform,
    fallback_rgba: tuple[float, float, float, float] | None,
    budget: GeometryBudget,
    *,
    label: str,
) -> list[MeshPart]:
    """Load one mesh file into link-frame parts (``transform`` = visual origin x scale).

    Raises
    ------
    AssetError
        Unsupported format, unreadable file, no triangles, or references outside the asset.
    """
    relative = str(path.relative_to(root))
    if path.suffix.lower() not in MESH_SUFFIXES:
        raise AssetError(f"unsupported mesh format '{path.suffix}'", file=relative)
    budget.check_ahead(least_faces(path), relative)
    report: list[str] = []
    resolver = _ConfinedResolver(path, root, report, budget.limits)
    try:
        with open(path, "rb") as handle:
            scene = trimesh.load(handle, file_type=path.suffix.lower().lstrip("."), resolver=resolver, force="scene", process=False)
    except AssetError:
        raise
    except Exception as exc:  # trimesh raises many unrelated types on corrupt files
        if resolver.refused:
            raise resolver.refused[0] from exc
        raise AssetError(f"cannot read mesh: {type(exc).__name__}: {exc}", file=relative) from exc
    if resolver.refused:
        raise resolver.refused[0]
    escapes = [r for r in report if "escapes" in r]
    if escapes:
        names = "; ".join(r.removesuffix(" escapes the asset directory") for r in escapes)
        raise AssetError("mesh references a file outside the asset directory: " + "; ".join(escapes), file=relative, element=f"reference {names}")
    budget.warnings.extend(f"{relative}: referenced file {r}" for r in report)
    parts = []
    if not isinstance(scene, trimesh.Scene):
        raise AssetError("mesh did not load as a scene", file=relative)
    for index, (mesh, node_transform) in enumerate(_scene_meshes(scene)):
        budget.spend(len(mesh.faces), relative)
        _check_vertices(np.asarray(mesh.vertices, dtype=np.float64), relative)  # before any arithmetic on them
        material, uv = _material_of(mesh, fallback_rgba, f"{label}_{index}")
        part = _part(mesh, transform @ node_transform, material, uv, relative)
        _check_numbers(part, relative)
        parts.append(part)
    if not parts:
        raise AssetError("mesh has no triangles", file=relative)
    return parts


def primitive_parts(
    kind: str,
    size: FloatArray,
    transform: Transform,
    rgba: tuple[float, float, float, float] | None,
    budget: GeometryBudget,
    *,
    label: str,
    urdf_name: str,
) -> list[MeshPart]:
    """Build a URDF primitive (``box`` size xyz; ``cylinder`` radius, length; ``sphere`` radius)."""
    if np.any(~np.isfinite(size)) or np.any(size <= 0):
        raise AssetError(f"{kind} has a non-positive size {size.tolist()}", file=urdf_name, element=label)
    if np.any(size > MAX_COORDINATE_M):
        raise AssetError(f"{kind} size {size.tolist()} is larger than {MAX_COORDINATE_M:g} m", file=urdf_name, element=label)
    if kind == "box":
        mesh = trimesh.creation.box(extents=size)
    elif kind == "cylinder":
        mesh = trimesh.creation.cylinder(radius=float(size[0]), height=float(size[1]), sections=CYLINDER_SECTIONS)
    else:
        mesh = trimesh.creation.icosphere(subdivisions=SPHERE_SUBDIVISIONS, radius=float(size[0]))
    budget.spend(len(mesh.faces), urdf_name)
    material = Material(name=f"{label}_{kind}", base_color=rgba or DEFAULT_RGBA)
    return [_part(mesh, transform, material, None, f"primitive:{kind}")]
