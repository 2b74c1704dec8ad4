"""Visual geometry of URDF links -> :class:`MeshPart` in the link frame.

OBJ files in the common subset are read by the built-in reader (:mod:`app.engine.asset.obj_reader`);
every other mesh file, and the primitives (box, cylinder, sphere), go through trimesh, imported only
then (:mod:`app.engine.asset.mesh_trimesh`). Either way a reference inside a mesh file (MTL,
texture) is read only from inside the asset directory (:mod:`app.engine.asset.confined_files`).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from app.engine.asset.confined_files import ConfinedFiles
from app.engine.asset.face_count import least_faces
from app.engine.asset.mesh_data import DEFAULT_RGBA, RGBA, SourceMesh
from app.engine.asset.model import Material, MeshPart
from app.engine.asset.obj_reader import NotInSubset, read_obj
from app.engine.asset.safety import AssetLimits, confine
from app.engine.errors import AssetError
from app.engine.types import FloatArray, IntArray, Transform

logger = logging.getLogger(__name__)

MESH_SUFFIXES = frozenset({".obj", ".stl", ".dae", ".glb", ".gltf", ".ply", ".off"})
NORMAL_EPS = 1e-12


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


def _unit(vectors: FloatArray) -> FloatArray:
    length = np.linalg.norm(vectors, axis=1)
    bad = ~np.isfinite(length) | (length < NORMAL_EPS)
    vectors[bad] = (0.0, 0.0, 1.0)
    length[bad] = 1.0
    return vectors / length[:, None]


def _part(vertices: FloatArray, faces: IntArray, normals: FloatArray, transform: Transform, material: Material,
          uv: FloatArray | None, source: str) -> MeshPart:
    """Move a mesh by ``transform`` (rotation, translation, scale) into a link-frame part."""
    linear = transform[:3, :3]
    moved = np.asarray(vertices, dtype=np.float64) @ linear.T + transform[:3, 3]
    triangles = np.array(faces, dtype=np.int64)
    turned = np.array(normals, dtype=np.float64)
    determinant = float(np.linalg.det(linear))
    if abs(determinant) > NORMAL_EPS:
        turned = turned @ np.linalg.inv(linear)
    if determinant < 0:
        triangles = triangles[:, ::-1].copy()
    return MeshPart(vertices=moved, faces=triangles, normals=_unit(turned), uv=uv, material=material, source=source)


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


def read_source_meshes(path: Path, files: ConfinedFiles, relative: str, *, built_in: bool = True) -> list[SourceMesh]:
    """The meshes of ``path``: the built-in reader for an OBJ in its subset, else trimesh.

    ``built_in=False`` forces trimesh (to check that both readers agree). ``files`` collects what
    the reader that was kept read (a file the built-in reader gives up on is read again by trimesh).
    """
    if built_in and path.suffix.lower() == ".obj":
        trial = ConfinedFiles(parent=files.parent, root=files.root, limits=files.limits)
        try:
            meshes: list[SourceMesh] = list(read_obj(path, trial))
        except NotInSubset as exc:
            logger.debug("%s: read with trimesh (%s)", relative, exc)
        else:
            files.report.extend(trial.report)
            files.refused.extend(trial.refused)
            return meshes
    from app.engine.asset.mesh_trimesh import read_with_trimesh

    return list(read_with_trimesh(path, files, relative))


def load_mesh_file(
    path: Path,
    root: Path,
    transform: Transform,
    fallback_rgba: RGBA | None,
    budget: GeometryBudget,
    *,
    label: str,
    built_in: bool = True,
) -> list[MeshPart]:
    """Load one mesh file into link-frame parts (``transform`` = visual origin x scale).

    ``built_in=False`` reads OBJ files with trimesh too (see :func:`read_source_meshes`).

    Raises
    ------
    AssetError
        Unsupported format, unreadable file, no triangles, or references outside the asset.
    """
    relative = str(path.relative_to(root))
    if path.suffix.lower() not in MESH_SUFFIXES:
        raise AssetError(f"unsupported mesh format '{path.suffix}'", file=relative)
    budget.check_ahead(least_faces(path), relative)
    files = ConfinedFiles.beside(path, root, budget.limits)
    meshes = read_source_meshes(path, files, relative, built_in=built_in)
    budget.warnings.extend(files.raise_problems(relative))
    parts = []
    for index, mesh in enumerate(meshes):
        budget.spend(len(mesh.faces), relative)
        _check_vertices(mesh.vertices, relative)  # before any arithmetic on them
        material, uv = mesh.appearance(fallback_rgba, f"{label}_{index}")
        part = _part(mesh.vertices, mesh.faces, mesh.vertex_normals(), transform @ mesh.transform, material, uv, relative)
        _check_numbers(part, relative)
        parts.append(part)
    if not parts:
        raise AssetError("mesh has no triangles", file=relative)
    return parts


def primitive_parts(
    kind: str,
    size: FloatArray,
    transform: Transform,
    rgba: RGBA | None,
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
    from app.engine.asset.mesh_trimesh import primitive_mesh

    mesh = primitive_mesh(kind, size)
    budget.spend(len(mesh.faces), urdf_name)
    material = Material(name=f"{label}_{kind}", base_color=rgba or DEFAULT_RGBA)
    return [_part(mesh.vertices, mesh.faces, mesh.vertex_normals(), transform, material, None, f"primitive:{kind}")]
