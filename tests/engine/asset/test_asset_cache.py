"""The asset disk cache returns exactly what load_asset returns, and notices changes."""

from __future__ import annotations

import dataclasses
import os
import shutil
from pathlib import Path

import numpy as np

from app.engine.asset.cache import cache_key, load_asset_cached
from app.engine.asset.loader import load_asset
from app.engine.execute.executor import execute
from app.engine.export.glb import glb_bytes
from app.engine.plan.schema import Plan


def _same(a, b) -> None:  # type: ignore[no-untyped-def]
    assert (a.name, a.urdf_file, a.root_link, a.joint_order, a.link_order, a.content_hash) == (b.name, b.urdf_file, b.root_link, b.joint_order, b.link_order, b.content_hash)
    for name in a.joints:
        ja, jb = a.joints[name], b.joints[name]
        assert (ja.type, ja.parent, ja.child, ja.lower, ja.upper, ja.mimic) == (jb.type, jb.parent, jb.child, jb.lower, jb.upper, jb.mimic)
        assert np.array_equal(ja.origin, jb.origin) and np.array_equal(ja.axis, jb.axis)
    for name in a.links:
        la, lb = a.links[name], b.links[name]
        assert la.semantics == lb.semantics and len(la.parts) == len(lb.parts)
        for pa, pb in zip(la.parts, lb.parts, strict=True):
            assert pa.material == pb.material and pa.source == pb.source and pa.visual == pb.visual
            for field in ("vertices", "faces", "normals", "uv"):
                x, y = getattr(pa, field), getattr(pb, field)
                assert (x is None and y is None) or np.array_equal(x, y)


def test_cache_round_trip_is_exact(partnet: Path, tmp_path: Path) -> None:
    source = partnet / "safe_102387"  # textured
    fresh = load_asset(source)
    first = load_asset_cached(source, tmp_path)
    assert len(list(tmp_path.glob("*.npz"))) == 1
    second = load_asset_cached(source, tmp_path)
    _same(fresh, first)
    _same(fresh, second)
    plan = Plan.model_validate({"meta": {"fps": 30, "duration_s": 1.0}, "timeline": [{"name": "o", "phase_type": "effect_motion", "t0": 0, "t1": 1,
                                "controls": [{"mode": "joint_position", "joint": "joint_0", "q_target_expr": "upper_limit"}]}]})
    assert glb_bytes(fresh, execute(plan, fresh)) == glb_bytes(second, execute(plan, second))


def test_cache_key_changes_with_the_files(tmp_path: Path, examples_dir: Path) -> None:
    copy = tmp_path / "bin"
    shutil.copytree(examples_dir / "pedal_bin", copy)
    before = cache_key(copy)
    urdf = next(copy.glob("*.urdf"))
    os.utime(urdf, ns=(urdf.stat().st_atime_ns, urdf.stat().st_mtime_ns + 1_000_000))
    assert cache_key(copy) != before
    assert cache_key(copy, urdf="other.urdf") != cache_key(copy)
    assert cache_key(copy, content_hash="ab" * 32) == cache_key(tmp_path / "elsewhere", content_hash="ab" * 32)


def test_a_known_content_hash_finds_the_entry_without_reading_and_names_the_asset(tmp_path: Path, examples_dir: Path) -> None:
    import zipfile

    archive = tmp_path / "bin.zip"
    with zipfile.ZipFile(archive, "w") as zf:
        for file in sorted((examples_dir / "pedal_bin").rglob("*")):
            zf.write(file, f"pedal_bin/{file.relative_to(examples_dir / 'pedal_bin')}")
    cache = tmp_path / "cache"
    first = load_asset_cached(archive, cache, name="alice-bin", content_hash="cd" * 32)
    archive.write_bytes(b"not read on a hit")
    second = load_asset_cached(archive, cache, name="bob-bin", content_hash="cd" * 32)
    assert (first.name, second.name) == ("alice-bin", "bob-bin")
    _same(first, dataclasses.replace(second, name="alice-bin"))


def test_corrupt_entry_is_ignored(tmp_path: Path, examples_dir: Path) -> None:
    cache = tmp_path / "cache"
    asset = load_asset_cached(examples_dir / "oven", cache)
    entry = next(cache.glob("*.npz"))
    entry.write_bytes(b"not a zip")
    again = load_asset_cached(examples_dir / "oven", cache)
    _same(asset, again)


def test_no_cache_dir_means_plain_loading(examples_dir: Path) -> None:
    assert load_asset_cached(examples_dir / "oven", None).name == "oven"


def test_parts_keep_their_urdf_visual_names(partnet: Path, tmp_path: Path) -> None:
    """Interaction targets find handles by the URDF visual name; the cache keeps it."""
    for asset in (load_asset(partnet / "storage_19179"), load_asset_cached(partnet / "storage_19179", tmp_path),
                  load_asset_cached(partnet / "storage_19179", tmp_path)):
        names = {part.visual for part in asset.links["link_0"].parts}
        assert names == {"drawer_front-28", "handle-27"}
