"""``load_asset``: a directory or ``.zip`` (SPEC §1) -> :class:`ArticulatedAsset`."""

from __future__ import annotations

import dataclasses
import hashlib
import logging
import re
import tempfile
import zipfile
from pathlib import Path

import numpy as np

from app.engine.asset.meshes import GeometryBudget, load_mesh_file, primitive_parts, resolve_mesh_path
from app.engine.asset.model import ArticulatedAsset, LinkSemantics, LinkSpec, MeshPart
from app.engine.asset.safety import AssetLimits, check_images, check_urdf_xml, extract_zip
from app.engine.asset.urdf import check_transform, finite_numbers, parse_urdf
from app.engine.asset.urdf_choice import MACOS_METADATA_DIR, find_urdf
from app.engine.asset.urdf_reader import UrdfLink, UrdfRobot, UrdfVisual
from app.engine.errors import AssetError
from app.engine.types import FloatArray

logger = logging.getLogger(__name__)

SEMANTICS_FILE = "semantics.txt"
_VISUAL_SUFFIX = re.compile(r"[-_]?\d+$")


def load_asset(
    path: str | Path, *, limits: AssetLimits | None = None, name: str | None = None, urdf: str | None = None
) -> ArticulatedAsset:
    """Load an asset directory or ``.zip`` archive.

    Parameters
    ----------
    path
        Directory holding one ``.urdf`` and its meshes, or a ``.zip`` of such a directory.
    limits
        Size caps; defaults to :class:`AssetLimits`.
    name
        Asset name; defaults to the directory name or zip stem. A zip is called ``<name>.zip``
        in error messages (the service passes the client's name for its stored file).
    urdf
        Which ``.urdf`` to load when the folder holds several (its path inside the asset,
        or its file name when that is unique); see :func:`find_urdf`.

    Raises
    ------
    AssetError
        For every rejection of SPEC §1, naming the file and element.
    """
    limits = limits or AssetLimits()
    source = Path(path)
    if not source.exists():
        raise AssetError("asset path does not exist", file=str(source))
    if source.is_file():
        shown = source.name if name is None else f"{name}.zip"
        if source.suffix.lower() != ".zip" and not zipfile.is_zipfile(source):
            raise AssetError("an asset must be a directory or a .zip archive", file=shown)
        with tempfile.TemporaryDirectory(prefix="artimo-asset-") as tmp:
            extract_zip(source, Path(tmp), limits, shown=shown)
            return _load_directory(_archive_root(Path(tmp)), name or source.stem, limits, shown=shown, urdf=urdf)
    return _load_directory(source, name or source.resolve().name, limits, shown=source.resolve().name, urdf=urdf)


def _archive_root(extracted: Path) -> Path:
    """The asset directory inside an extracted zip: its single top-level folder, if it has one.

    A zip "of a directory" usually holds ``folder/mobility.urdf ...``; using ``folder``
    as the root makes the zip load exactly like the directory (same ``urdf_file``,
    same ``content_hash``).
    """
    entries = [p for p in extracted.iterdir() if p.name != MACOS_METADATA_DIR]
    if len(entries) == 1 and entries[0].is_dir() and not entries[0].is_symlink():
        return entries[0]
    return extracted


def _load_directory(root: Path, name: str, limits: AssetLimits, *, shown: str, urdf: str | None = None) -> ArticulatedAsset:
    root = root.resolve()
    urdf_path = find_urdf(root, shown=shown, requested=urdf)
    urdf_name = urdf_path.relative_to(root).as_posix()
    data = urdf_path.read_bytes()
    check_urdf_xml(data, urdf_name, limits)
    check_images(root, limits)
    parsed = parse_urdf(data, urdf_name)
    digest = hashlib.sha256(data)
    semantics = _read_semantics(urdf_path.parent, root)
    budget = GeometryBudget(max_faces=limits.max_faces, limits=limits)
    links: dict[str, LinkSpec] = {}
    for link in parsed.robot.links:
        parts = _link_parts(link, parsed.robot, urdf_path.parent, root, urdf_name, budget, digest)
        visual_names = tuple(v.name for v in link.visuals if v.name)
        links[link.name] = LinkSpec(name=link.name, parts=tuple(parts), semantics=_semantics_for(link.name, visual_names, semantics))
    if not any(link.has_geometry for link in links.values()):
        raise AssetError("no link has visual geometry", file=urdf_name)
    warnings = tuple(budget.warnings)
    for message in warnings:
        logger.warning("asset %s: %s", name, message)
    return ArticulatedAsset(
        name=name,
        urdf_file=urdf_name,
        root_link=parsed.root_link,
        links=links,
        joints=parsed.joints,
        joint_order=parsed.joint_order,
        link_order=parsed.link_order,
        warnings=warnings,
        content_hash=digest.hexdigest(),
    )


def _visual_rgba(visual: UrdfVisual, robot: UrdfRobot) -> tuple[float, float, float, float] | None:
    material = visual.material
    if material is None:
        return None
    rgba = material.rgba
    if rgba is None and material.name:
        named = next((m for m in robot.materials if m.name == material.name), None)
        rgba = named.rgba if named is not None else None
    if rgba is None:
        return None
    clipped = np.clip(np.asarray(rgba, dtype=np.float64).reshape(-1)[:4], 0.0, 1.0)
    if clipped.size != 4:
        return None
    return (float(clipped[0]), float(clipped[1]), float(clipped[2]), float(clipped[3]))


def _link_parts(
    link: UrdfLink,
    robot: UrdfRobot,
    urdf_dir: Path,
    root: Path,
    urdf_name: str,
    budget: GeometryBudget,
    digest: hashlib._Hash,
) -> list[MeshPart]:
    parts: list[MeshPart] = []
    for index, visual in enumerate(link.visuals):
        element = f"link {link.name} visual {visual.name or index}"
        origin = np.eye(4) if visual.origin is None else check_transform(visual.origin, "origin", file=urdf_name, element=element)
        rgba = _visual_rgba(visual, robot)
        geometry = visual.geometry
        label = f"{link.name}_{index}"
        if geometry.kind == "mesh":
            mesh_path = resolve_mesh_path(geometry.filename or "", urdf_dir, root, urdf_name=urdf_name, element=element)
            scale = _mesh_scale(geometry.scale, urdf_name, element)
            transform = origin @ np.diag([*scale, 1.0])
            digest.update(str(mesh_path.relative_to(root)).encode())
            digest.update(mesh_path.read_bytes())
            parts.extend(_named(load_mesh_file(mesh_path, root, transform, rgba, budget, label=label), visual.name or ""))
            continue
        if geometry.kind == "box":
            size = finite_numbers(geometry.size, 3, "box size", file=urdf_name, element=element)
        elif geometry.kind == "cylinder":
            size = finite_numbers([geometry.radius, geometry.length], 2, "cylinder radius/length", file=urdf_name, element=element)
        else:
            size = finite_numbers([geometry.radius], 1, "sphere radius", file=urdf_name, element=element)
        parts.extend(_named(primitive_parts(geometry.kind, size, origin, rgba, budget, label=label, urdf_name=urdf_name), visual.name or ""))
    return parts


def _named(parts: list[MeshPart], visual: str) -> list[MeshPart]:
    return [dataclasses.replace(part, visual=visual) for part in parts]


MIN_SCALE = 1e-9


def _mesh_scale(raw: object, urdf_name: str, element: str) -> FloatArray:
    """A mesh's ``scale`` as three finite, non-zero factors (one number means all three)."""
    if raw is None:
        return np.ones(3)
    values = np.asarray(raw, dtype=np.float64).reshape(-1)
    scale = finite_numbers(values if values.size != 1 else np.repeat(values, 3), 3, "mesh scale", file=urdf_name, element=element)
    if np.any(np.abs(scale) < MIN_SCALE):
        raise AssetError(f"mesh scale {scale.tolist()} has a zero factor", file=urdf_name, element=element)
    return scale


def _read_semantics(urdf_dir: Path, root: Path) -> dict[str, tuple[str, str]]:
    """``semantics.txt`` as {link: (joint kind, label)}; missing file -> {}."""
    for folder in (urdf_dir, root):
        path = folder / SEMANTICS_FILE
        if path.is_file() and not path.is_symlink():
            result: dict[str, tuple[str, str]] = {}
            for line in path.read_text(encoding="utf-8", errors="replace").splitlines():
                fields = line.split()
                if len(fields) >= 3:
                    result[fields[0]] = (fields[1], " ".join(fields[2:]))
            return result
    return {}


def _semantics_for(link: str, visual_names: tuple[str, ...], table: dict[str, tuple[str, str]]) -> LinkSemantics:
    if link in table:
        kind, label = table[link]
        return LinkSemantics(label=label, joint_kind=kind, visual_names=visual_names, source="semantics.txt")
    cleaned = [_VISUAL_SUFFIX.sub("", v) for v in visual_names]
    cleaned = [c for c in cleaned if c]
    if cleaned:
        label = max(set(cleaned), key=lambda c: (cleaned.count(c), -cleaned.index(c)))
        return LinkSemantics(label=label, visual_names=visual_names, source="urdf")
    return LinkSemantics(visual_names=visual_names)
