"""Defences for untrusted uploads: zip extraction and URDF XML pre-checks."""

from __future__ import annotations

import io
import stat
import zipfile
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

import defusedxml.ElementTree as safe_et
from defusedxml import DefusedXmlException

from app.engine.errors import AssetError


@dataclass(frozen=True)
class AssetLimits:
    """Caps applied to every asset (defaults suit PartNet-Mobility with room to spare)."""

    max_total_bytes: int = 512 * 1024 * 1024
    """Largest total uncompressed size of a zip, bytes."""
    max_files: int = 5000
    """Most members a zip may hold."""
    max_compression_ratio: float = 200.0
    """Largest uncompressed/compressed ratio of one member (zip-bomb guard)."""
    max_urdf_bytes: int = 16 * 1024 * 1024
    max_faces: int = 2_000_000
    """Most triangles over all visual meshes of the asset (PartNet-Mobility's largest: ~11k)."""
    max_xml_depth: int = 64
    max_links: int = 257
    """Most ``<link>`` elements (PartNet-Mobility's largest: 15; a keyboard has ~100)."""
    max_joints: int = 256
    max_texture_pixels: int = 4096 * 4096
    """Largest texture image, width x height, checked from its header before it is decoded."""


def _member_problem(info: zipfile.ZipInfo) -> str | None:
    name = info.filename
    path = PurePosixPath(name.replace("\\", "/"))
    if name.startswith(("/", "\\")) or (len(name) > 1 and name[1] == ":"):
        return "absolute path"
    if ".." in path.parts:
        return "path escapes the archive root ('..')"
    mode = info.external_attr >> 16
    if stat.S_ISLNK(mode):
        return "symbolic link"
    return None


def extract_zip(archive: Path, target: Path, limits: AssetLimits, *, shown: str | None = None) -> None:
    """Extract ``archive`` into the empty directory ``target`` after checking every member.

    ``shown`` names the archive in error messages (default: its file name).

    Raises
    ------
    AssetError
        Broken zip, zip slip (``..``, absolute paths, symlinks), too many files,
        too large in total or a member with an implausible compression ratio.
    """
    shown = shown or archive.name
    try:
        zf = zipfile.ZipFile(archive)
    except (zipfile.BadZipFile, OSError) as exc:
        raise AssetError(f"not a readable zip archive: {exc}", file=shown, element="central directory") from exc
    with zf:
        infos = zf.infolist()
        if len(infos) > limits.max_files:
            raise AssetError(
                f"zip holds {len(infos)} members, more than the limit of {limits.max_files}",
                file=shown,
                element=infos[limits.max_files].filename,
            )
        total = 0
        for info in infos:
            problem = _member_problem(info)
            if problem:
                raise AssetError(f"unsafe zip member: {problem}", file=shown, element=info.filename)
            total += info.file_size
            if total > limits.max_total_bytes:
                raise AssetError(
                    f"zip expands to more than the limit of {limits.max_total_bytes} bytes",
                    file=shown,
                    element=info.filename,
                )
            if info.compress_size > 0 and info.file_size / info.compress_size > limits.max_compression_ratio:
                raise AssetError(
                    "zip member expands more than "
                    f"{limits.max_compression_ratio:.0f}x (zip bomb?)",
                    file=shown,
                    element=info.filename,
                )
        root = target.resolve()
        written = 0
        for info in infos:
            dest = (root / info.filename).resolve()
            if not dest.is_relative_to(root):
                raise AssetError("unsafe zip member: path escapes the archive root", file=shown, element=info.filename)
            if info.is_dir():
                dest.mkdir(parents=True, exist_ok=True)
                continue
            dest.parent.mkdir(parents=True, exist_ok=True)
            try:
                with zf.open(info) as src, open(dest, "wb") as out:
                    while chunk := src.read(1 << 20):
                        written += len(chunk)
                        if written > limits.max_total_bytes:
                            raise AssetError("zip expands beyond its declared size", file=shown, element=info.filename)
                        out.write(chunk)
            except (zipfile.BadZipFile, OSError, EOFError) as exc:
                raise AssetError(f"corrupt zip member: {exc}", file=shown, element=info.filename) from exc


def check_urdf_xml(data: bytes, file_name: str, limits: AssetLimits) -> None:
    """Reject URDF text that is too large, declares a DTD/entities, or is not well formed.

    Raises
    ------
    AssetError
        Naming ``file_name`` and the offending construct.
    """
    if len(data) > limits.max_urdf_bytes:
        raise AssetError(f"URDF is {len(data)} bytes, more than {limits.max_urdf_bytes}", file=file_name)
    try:
        root = safe_et.fromstring(data, forbid_dtd=True, forbid_entities=True, forbid_external=True)
    except DefusedXmlException as exc:
        raise AssetError(f"URDF uses a forbidden XML construct ({type(exc).__name__}: {exc})", file=file_name, element="<!DOCTYPE>/<!ENTITY>") from exc
    except safe_et.ParseError as exc:
        raise AssetError(f"URDF is not well-formed XML: {exc}", file=file_name) from exc
    if root.tag != "robot":
        raise AssetError(f"URDF root element is <{root.tag}>, expected <robot>", file=file_name, element=root.tag)
    depth = _depth(root)
    if depth > limits.max_xml_depth:
        raise AssetError(f"URDF nests {depth} levels deep, more than {limits.max_xml_depth}", file=file_name)
    for tag, most in (("link", limits.max_links), ("joint", limits.max_joints)):
        count = len(root.findall(tag))
        if count > most:
            raise AssetError(f"URDF has {count} <{tag}> elements, more than the limit of {most}", file=file_name, element=tag)


IMAGE_SUFFIXES = frozenset({".png", ".jpg", ".jpeg", ".bmp", ".tga", ".gif", ".tif", ".tiff", ".webp"})


def check_image(data: bytes | Path, name: str, limits: AssetLimits) -> None:
    """Refuse an image larger than ``limits.max_texture_pixels`` from its header (nothing decoded).

    Data that is not an image passes (another reader will judge it).

    Raises
    ------
    AssetError
        Too many pixels.
    """
    from PIL import Image, UnidentifiedImageError

    try:
        with Image.open(io.BytesIO(data) if isinstance(data, bytes) else data) as image:
            width, height = image.size
    except Image.DecompressionBombError as exc:
        raise AssetError(f"image is far larger than the limit of {limits.max_texture_pixels} pixels ({exc})",
                         file=name, element="texture") from exc
    except (UnidentifiedImageError, OSError, ValueError):
        return
    if width * height > limits.max_texture_pixels:
        raise AssetError(f"image is {width} x {height} pixels, more than the limit of {limits.max_texture_pixels}",
                         file=name, element="texture")


def check_images(root: Path, limits: AssetLimits) -> None:
    """:func:`check_image` on every image file of an asset folder (by suffix), before any mesh is read."""
    for path in sorted(root.rglob("*")):
        if path.suffix.lower() in IMAGE_SUFFIXES and path.is_file() and not path.is_symlink():
            check_image(path, str(path.relative_to(root)), limits)


def _depth(element: object) -> int:
    stack = [(element, 1)]
    deepest = 0
    while stack:
        node, level = stack.pop()
        deepest = max(deepest, level)
        stack.extend((child, level + 1) for child in node)  # type: ignore[attr-defined]
    return deepest


def confine(path: Path, root: Path, *, file: str, element: str, shown: str | None = None) -> Path:
    """Resolve ``path`` and require it to stay inside ``root`` (symlinks resolved).

    ``shown`` is the name used in the error message (default ``path``); callers pass
    the path as written in the asset so that server paths do not leak into messages.

    Raises
    ------
    AssetError
        If the resolved path lies outside ``root``.
    """
    resolved = path.resolve()
    if not resolved.is_relative_to(root.resolve()):
        raise AssetError(f"path '{shown or path}' resolves outside the asset directory", file=file, element=element)
    return resolved
