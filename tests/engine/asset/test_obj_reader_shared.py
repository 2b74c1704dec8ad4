"""Every OBJ file of the shared PartNet-Mobility assets: the built-in reader takes it and gives the
trimesh path's parts (vertices, faces, uv bit for bit; normals within 1e-12; materials, texture
images, warnings).

The assets are the folders beside the repository (``tests/conftest.py``: ``partnet`` and its
sibling ``partnet-extra``); without them these tests are skipped.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from support.obj_compare import assert_same_parts, load_both

from app.engine.asset.confined_files import ConfinedFiles
from app.engine.asset.obj_reader import NotInSubset, read_obj
from tests.conftest import partnet_root

EXPECTED_FALLBACKS: dict[str, str] = {}
"""Shared OBJ files the built-in reader leaves to trimesh (path under the assets root -> why): none."""
PNG_SAMPLE_ASSETS = 6
"""Textured assets whose textures are really PNG-encoded by both readers (the others compare fingerprints)."""


def _roots() -> list[Path]:
    try:
        partnet = partnet_root()
    except RuntimeError:
        return []
    return [root for root in (partnet, partnet.parent / "partnet-extra") if root.is_dir()]


ROOTS = _roots()
ASSETS = [folder for root in ROOTS for folder in sorted(root.iterdir()) if (folder / "mobility.urdf").is_file()]
needs_assets = pytest.mark.skipif(not ASSETS, reason="the shared PartNet-Mobility assets are not here (set ARTIMO_PARTNET_ROOT)")


def _objs(folder: Path) -> list[Path]:
    return sorted(folder.resolve().rglob("*.obj"))


def _textured(folder: Path) -> bool:
    return any("map_Kd" in mtl.read_text(errors="replace") for mtl in folder.rglob("*.mtl"))


@needs_assets
def test_every_shared_obj_is_in_the_subset() -> None:
    fallbacks: dict[str, str] = {}
    count = 0
    for folder in ASSETS:
        root = folder.resolve()
        for path in _objs(folder):
            count += 1
            try:
                read_obj(path, ConfinedFiles.beside(path, root))
            except NotInSubset as exc:
                fallbacks[f"{folder.parent.name}/{path.relative_to(root.parent)}"] = str(exc)
    assert count > 1000
    assert set(fallbacks) == set(EXPECTED_FALLBACKS), fallbacks
    for name, reason in fallbacks.items():
        assert EXPECTED_FALLBACKS[name] in reason


@needs_assets
@pytest.mark.slow
@pytest.mark.parametrize("folder", ASSETS, ids=[f"{f.parent.name}/{f.name}" for f in ASSETS])
def test_shared_obj_files_give_the_trimesh_parts(folder: Path) -> None:
    root = folder.resolve()
    for path in _objs(folder):
        built_in, trimesh_path = load_both(path, root)
        try:
            assert_same_parts(built_in, trimesh_path)
        except AssertionError as exc:
            raise AssertionError(f"{path.relative_to(root)}: {exc}") from exc


SAMPLED = [folder for folder in ASSETS if _textured(folder)][:PNG_SAMPLE_ASSETS]


@needs_assets
@pytest.mark.slow
@pytest.mark.parametrize("folder", SAMPLED, ids=[f"{f.parent.name}/{f.name}" for f in SAMPLED])
def test_shared_textures_give_the_same_png_bytes(folder: Path) -> None:
    root = folder.resolve()
    textured = 0
    for path in _objs(folder):
        built_in, trimesh_path = load_both(path, root, real_png=True)
        assert_same_parts(built_in, trimesh_path)
        textured += sum(part.material.image_png is not None for part in getattr(built_in, "parts", []))
    assert textured > 0
