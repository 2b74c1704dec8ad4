"""A disk cache of loaded assets, so a repeated run skips URDF parsing and mesh decoding.

Entries are keyed by the asset's files (name, size, modification time of every file in a
folder; the bytes of a zip) or by a content hash the caller already knows (the service's
stored sha256), plus the chosen URDF, and stored as one ``.npz`` (arrays plus a JSON header, read with
``allow_pickle=False``). Reading an entry skips parsing the URDF and the meshes, and the imports
they need (lxml, PIL; trimesh for meshes outside the built-in OBJ reader's subset).
"""

from __future__ import annotations

import dataclasses
import hashlib
import io
import json
import logging
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.asset.model import ArticulatedAsset, JointSpec, LinkSemantics, LinkSpec, Material, MeshPart, Mimic
from app.engine.asset.safety import AssetLimits
from app.engine.files import atomic_write_bytes

logger = logging.getLogger(__name__)

CACHE_VERSION = 4
HEADER = "header"


def cache_key(path: Path, urdf: str | None = None, content_hash: str | None = None) -> str:
    """Fingerprint of an asset folder (file names, sizes, mtimes) or zip (its bytes), or of
    ``content_hash`` when the caller knows it (then nothing is read); plus the chosen URDF."""
    digest = hashlib.sha256(f"artimo-asset-cache:{CACHE_VERSION}:{urdf or ''}".encode())
    if content_hash is not None:
        digest.update(f"content:{content_hash}".encode())
        return digest.hexdigest()
    source = path.resolve()
    if source.is_file():
        digest.update(source.read_bytes())
    else:
        for file in sorted(p for p in source.rglob("*") if p.is_file()):
            stat = file.stat()
            digest.update(f"{file.relative_to(source)}\0{stat.st_size}\0{stat.st_mtime_ns}\n".encode())
    return digest.hexdigest()


def _joint_record(joint: JointSpec) -> dict[str, Any]:
    return {
        "name": joint.name, "type": joint.type, "parent": joint.parent, "child": joint.child,
        "origin": joint.origin.reshape(-1).tolist(), "axis": joint.axis.tolist(), "lower": joint.lower, "upper": joint.upper,
        "effort": joint.effort, "velocity": joint.velocity,
        "mimic": None if joint.mimic is None else [joint.mimic.joint, joint.mimic.multiplier, joint.mimic.offset],
    }


_PACKED = {"v": ("vertices", np.float64, 3), "f": ("faces", np.int64, 3), "n": ("normals", np.float64, 3), "u": ("uv", np.float64, 2)}
"""Every part's array of one kind goes into one packed array (a few arrays per entry, whatever the part count:
an npz member costs ~0.2 ms to open, and a PartNet pot has over a thousand parts)."""


def _dump(asset: ArticulatedAsset) -> bytes:
    arrays: dict[str, np.ndarray] = {}
    chunks: dict[str, list[np.ndarray]] = {key: [] for key in _PACKED}
    images: dict[bytes, int] = {}
    links = []
    for name in asset.link_order:
        link = asset.links[name]
        parts = []
        for part in link.parts:
            image = -1
            if part.material.image_png is not None:
                image = images.setdefault(part.material.image_png, len(images))
            material = part.material
            parts.append({"source": part.source, "visual": part.visual, "normals": part.normals is not None, "uv": part.uv is not None,
                          "counts": [len(part.vertices), len(part.faces)],
                          "material": [material.name, list(material.base_color), material.metallic, material.roughness, material.double_sided, image]})
            for key, (field, _, _) in _PACKED.items():
                value = getattr(part, field)
                if value is not None:
                    chunks[key].append(value)
        semantics = link.semantics
        links.append({"name": name, "parts": parts, "semantics": [semantics.label, semantics.joint_kind, list(semantics.visual_names), semantics.source]})
    for key, (_, dtype, width) in _PACKED.items():
        arrays[key] = np.concatenate(chunks[key]).astype(dtype, copy=False) if chunks[key] else np.zeros((0, width), dtype=dtype)
    for data, number in images.items():
        arrays[f"img{number}"] = np.frombuffer(data, dtype=np.uint8)
    header = {
        "version": CACHE_VERSION, "name": asset.name, "urdf_file": asset.urdf_file, "root_link": asset.root_link,
        "joint_order": list(asset.joint_order), "link_order": list(asset.link_order), "warnings": list(asset.warnings),
        "content_hash": asset.content_hash, "joints": [_joint_record(asset.joints[j]) for j in asset.joint_order], "links": links,
    }
    arrays[HEADER] = np.frombuffer(json.dumps(header).encode(), dtype=np.uint8)
    buffer = io.BytesIO()
    np.savez(buffer, **arrays)  # type: ignore[arg-type]  # numpy's stub types the first keyword as allow_pickle
    return buffer.getvalue()


def _joint(record: dict[str, Any]) -> JointSpec:
    origin = np.asarray(record["origin"], dtype=np.float64).reshape(4, 4)
    axis = np.asarray(record["axis"], dtype=np.float64)
    origin.setflags(write=False)
    axis.setflags(write=False)
    mimic = None if record["mimic"] is None else Mimic(record["mimic"][0], float(record["mimic"][1]), float(record["mimic"][2]))
    return JointSpec(name=record["name"], type=record["type"], parent=record["parent"], child=record["child"], origin=origin, axis=axis,
                     lower=record["lower"], upper=record["upper"], effort=record["effort"], velocity=record["velocity"], mimic=mimic)


def _load(data: np.lib.npyio.NpzFile) -> ArticulatedAsset:
    header = json.loads(bytes(data[HEADER]).decode())
    if header.get("version") != CACHE_VERSION:
        raise ValueError("cache version mismatch")
    packed = {key: data[key] for key in _PACKED}
    offsets = dict.fromkeys(_PACKED, 0)
    links: dict[str, LinkSpec] = {}
    for record in header["links"]:
        parts = []
        for part in record["parts"]:
            name, color, metallic, roughness, double_sided, image = part["material"]
            png = bytes(data[f"img{image}"]) if image >= 0 else None
            material = Material(name=name, base_color=tuple(color), image_png=png, metallic=metallic, roughness=roughness, double_sided=double_sided)
            vertex_count, face_count = part["counts"]
            taken: dict[str, np.ndarray | None] = {}
            for key, count, present in (("v", vertex_count, True), ("f", face_count, True), ("n", vertex_count, part["normals"]),
                                        ("u", vertex_count, part["uv"])):
                taken[key] = packed[key][offsets[key]:offsets[key] + count] if present else None
                offsets[key] += count if present else 0
            vertices, faces = taken["v"], taken["f"]
            assert vertices is not None and faces is not None
            parts.append(MeshPart(vertices=vertices, faces=faces, normals=taken["n"], uv=taken["u"], material=material, source=part["source"],
                                  visual=part["visual"]))
        label, kind, visuals, source = record["semantics"]
        links[record["name"]] = LinkSpec(name=record["name"], parts=tuple(parts), semantics=LinkSemantics(label=label, joint_kind=kind, visual_names=tuple(visuals), source=source))
    joints = {r["name"]: _joint(r) for r in header["joints"]}
    return ArticulatedAsset(name=header["name"], urdf_file=header["urdf_file"], root_link=header["root_link"], links=links, joints=joints,
                            joint_order=tuple(header["joint_order"]), link_order=tuple(header["link_order"]),
                            warnings=tuple(header["warnings"]), content_hash=header["content_hash"])


def _fresh(source: Path, limits: AssetLimits | None, name: str | None, urdf: str | None) -> ArticulatedAsset:
    from app.engine.asset.loader import load_asset  # imports the mesh readers: only on a miss

    return load_asset(source, limits=limits, name=name, urdf=urdf)


def _default_name(source: Path) -> str:
    """The name :func:`load_asset` gives an asset when none is passed."""
    return source.stem if source.is_file() else source.resolve().name


def load_asset_cached(
    path: str | Path, cache_dir: Path | None, *, limits: AssetLimits | None = None, name: str | None = None,
    urdf: str | None = None, content_hash: str | None = None,
) -> ArticulatedAsset:
    """``load_asset`` through the cache in ``cache_dir`` (no cache when ``None``).

    ``content_hash``: the sha256 of ``path`` when the caller knows it (the entry is then found
    without reading the file). The entry does not depend on ``name``: a hit is renamed.

    Raises
    ------
    AssetError
        As ``load_asset`` (rejections are never cached).
    """
    source = Path(path)
    if cache_dir is None or not source.exists():
        return _fresh(source, limits, name, urdf)
    entry = cache_dir / f"{cache_key(source, urdf, content_hash)}.npz"
    wanted = name or _default_name(source)
    if entry.is_file():
        try:
            with np.load(entry, allow_pickle=False) as data:
                cached = _load(data)
            return cached if cached.name == wanted else dataclasses.replace(cached, name=wanted)
        except (OSError, ValueError, KeyError, json.JSONDecodeError) as exc:
            logger.warning("ignoring unreadable asset cache entry %s: %s", entry.name, exc)
    asset = _fresh(source, limits, name, urdf)
    try:
        atomic_write_bytes(entry, _dump(asset))
    except OSError as exc:
        logger.warning("cannot write the asset cache %s: %s", cache_dir, exc)
    return asset
