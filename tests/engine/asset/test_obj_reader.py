"""The built-in OBJ reader gives what the trimesh path gives, and hands trimesh what it does not take.

Small files cover the corners of the subset (grouping, index forms, materials, textures, missing and
escaping references) and files just outside it; each is loaded through both readers and the parts,
warnings and errors compared. The shared PartNet-Mobility files are compared in
``test_obj_reader_shared.py``.
"""

from __future__ import annotations

import io
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from support.obj_compare import assert_same_parts, load_both

from app.engine.asset.confined_files import ConfinedFiles
from app.engine.asset.obj_reader import NotInSubset, read_obj
from app.engine.errors import AssetError

REPO = Path(__file__).resolve().parents[3]
TRIANGLES = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\n"
UVS = "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
NORMALS = "vn 0 0 1\nvn 0 0.5 0.5\nvn 1 0 0\n"


def _png(color: tuple[int, int, int] = (200, 10, 10), size: tuple[int, int] = (4, 2)) -> bytes:
    buffer = io.BytesIO()
    Image.new("RGB", size, color).save(buffer, format="PNG")
    return buffer.getvalue()


def _jpeg() -> bytes:
    buffer = io.BytesIO()
    Image.new("RGB", (8, 8), (10, 120, 200)).save(buffer, format="JPEG")
    return buffer.getvalue()


MTL = "newmtl red\nKd 0.9 0.1 0.1\nKs 0.1 0.1 0.1\nNs 10\nillum 2\nd 1\n\nnewmtl skin\nKd 1 1 1\nmap_Kd tex.png\n\nnewmtl grey\n"
IN_SUBSET = {
    "plain": TRIANGLES + "f 1 2 3\nf 2 4 3\n",
    "normals": TRIANGLES + NORMALS + "f 1//1 2//2 3//3\nf 2//1 4//1 3//3\nf 1//3 2//2 5//1\n",
    "uv only": "mtllib part.mtl\n" + TRIANGLES + UVS + "usemtl skin\nf 1/1 2/2 3/3\nf 2/2 4/4 3/3\nf 1/4 2/2 3/1\n",
    "uv and normals": "mtllib part.mtl\n" + TRIANGLES + UVS + NORMALS + "usemtl skin\nf 1/1/1 2/2/2 3/3/3\nf 2/2/1 4/4/2 3/3/3\n"
                      "f 1/1/2 2/2/2 3/3/3\nf 3/1/1 1/4/3 5/2/2\n",
    "uvw": "mtllib part.mtl\n" + TRIANGLES + "vt 0 0 0\nvt 1 0 0\nvt 0 1 0\nusemtl skin\nf 1/1 2/2 3/3\n",
    "materials interleaved": "mtllib part.mtl\n" + TRIANGLES + "usemtl red\nf 1 2 3\nusemtl grey\nf 2 4 3\nusemtl red\nf 1 2 5\n"
                             "usemtl grey\nf 3 4 5\n",
    "faces before usemtl": "mtllib part.mtl\no thing\n" + TRIANGLES + "f 1 2 3\ng side\ns 1\nusemtl red\nf 2 4 3\n",
    "unknown usemtl": "mtllib part.mtl\n" + TRIANGLES + "usemtl nowhere\nf 1 2 3\nusemtl red\nf 2 4 3\n",
    "vertices after faces": "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n",
    "comments and blank lines": "# header\n\n" + TRIANGLES + "# faces\nf 1 2 3   \nf  2 4 3\r\n",
    "sliver and degenerate faces": TRIANGLES + "v 2 0 0\nf 1 2 3\nf 1 2 6\nf 1 1 2\nf 2 3 4\n",
    "non-ascii object name": "o Façade\n" + TRIANGLES + "f 1 2 3\n",
}
OUTSIDE = {
    "quads": (TRIANGLES + "f 1 2 4 3\n", "not all triangles"),
    "vertex colours": ("v 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 0 1 0 1 0 0\nf 1 2 3\n", "v line"),
    "negative indices": (TRIANGLES + "f -1 -2 -3\n", "positive indices"),
    "mixed forms in one material": (TRIANGLES + NORMALS + "f 1//1 2//2 3//3\nf 1 2 3\n", "in the form v//vn"),
    "index past the end": (TRIANGLES + "f 1 2 9\n", "refers to v"),
    "tabs": (TRIANGLES.replace(" ", "\t") + "f 1 2 3\n", "tabs"),
    "unknown statement": (TRIANGLES + "l 1 2\nf 1 2 3\n", "statement 'l'"),
    "usemtl in a comment": ("# usemtl red\n" + TRIANGLES + "f 1 2 3\n", "'usemtl' appears"),
    "two mtllib": ("mtllib part.mtl\nmtllib other.mtl\n" + TRIANGLES + "f 1 2 3\n", "more than one mtllib"),
    "uv without its material": ("mtllib part.mtl\n" + TRIANGLES + UVS + "usemtl nowhere\nf 1/1 2/2 3/3\n", "does not define"),
    "nan": ("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "plain numbers"),
    "no faces": (TRIANGLES, "no faces"),
}


def _asset(tmp_path: Path, obj: str, files: dict[str, str | bytes] | None = None) -> tuple[Path, Path]:
    root = tmp_path / "asset"
    (root / "meshes").mkdir(parents=True)
    path = root / "meshes" / "part.obj"
    path.write_text(obj, encoding="utf-8", newline="")
    default = {"meshes/part.mtl": MTL, "meshes/tex.png": _png()}
    for name, data in (default if files is None else files).items():
        target = root / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data if isinstance(data, bytes) else data.encode())
    return path, root.resolve()


@pytest.mark.parametrize("case", sorted(IN_SUBSET))
def test_a_file_in_the_subset_gives_the_trimesh_parts(tmp_path: Path, case: str) -> None:
    path, root = _asset(tmp_path, IN_SUBSET[case])
    read_obj(path, ConfinedFiles.beside(path, root))  # taken by the built-in reader
    assert_same_parts(*load_both(path, root))


@pytest.mark.parametrize("case", sorted(OUTSIDE))
def test_a_file_outside_the_subset_goes_to_trimesh(tmp_path: Path, case: str) -> None:
    obj, reason = OUTSIDE[case]
    path, root = _asset(tmp_path, obj)
    files = ConfinedFiles.beside(path, root)
    with pytest.raises(NotInSubset, match=reason):
        read_obj(path, files)
    built_in, trimesh_path = load_both(path, root)
    assert_same_parts(built_in, trimesh_path)


def test_textures_give_the_same_png_bytes(tmp_path: Path) -> None:
    mtl = "newmtl a\nKd 1 1 1\nmap_Kd a.jpg\nnewmtl b\nKd 0.5 0.5 0.5\nmap_Kd b.png\n"
    obj = "mtllib part.mtl\n" + TRIANGLES + UVS + "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 2/2 4/4 3/3\n"
    path, root = _asset(tmp_path, obj, {"meshes/part.mtl": mtl, "meshes/a.jpg": _jpeg(), "meshes/b.png": _png((1, 2, 3), (3, 5))})
    built_in, trimesh_path = load_both(path, root, real_png=True)
    assert_same_parts(built_in, trimesh_path)
    assert all(part.material.image_png for part in built_in.parts)


@pytest.mark.parametrize(
    ("mtl", "files", "warned"),
    [
        ("newmtl skin\nmap_Kd gone.png\n", {}, True),
        ("newmtl skin\nmap_Kd unreadable.png\n", {"meshes/unreadable.png": b"hello"}, False),
        (None, {}, True),
    ],
    ids=["missing texture", "unreadable texture", "missing mtl"],
)
def test_missing_references_are_the_same_warnings(tmp_path: Path, mtl: str | None, files: dict[str, str | bytes], warned: bool) -> None:
    obj = "mtllib part.mtl\n" + TRIANGLES + UVS + "usemtl skin\nf 1/1 2/2 3/3\n"
    path, root = _asset(tmp_path, obj, {**files, **({} if mtl is None else {"meshes/part.mtl": mtl})})
    if mtl is not None:
        read_obj(path, ConfinedFiles.beside(path, root))  # in the subset: the built-in reader's own warnings
    built_in, trimesh_path = load_both(path, root)
    assert_same_parts(built_in, trimesh_path)
    assert not isinstance(built_in, AssetError) and bool(built_in.warnings) == warned


@pytest.mark.parametrize(
    ("obj", "mtl", "says"),
    [
        ("mtllib ../../evil.mtl\n" + TRIANGLES + "usemtl m\nf 1 2 3\n", None, "outside the asset directory"),
        ("mtllib part.mtl\n" + TRIANGLES + UVS + "usemtl skin\nf 1/1 2/2 3/3\n", "newmtl skin\nmap_Kd ../../secret.png\n",
         "outside the asset directory"),
    ],
    ids=["mtl", "texture"],
)
def test_an_escaping_reference_is_the_same_error(tmp_path: Path, obj: str, mtl: str | None, says: str) -> None:
    (tmp_path / "evil.mtl").write_text("newmtl m\nKd 1 0 0\n")
    (tmp_path / "secret.png").write_bytes(_png())
    path, root = _asset(tmp_path, obj, {} if mtl is None else {"meshes/part.mtl": mtl})
    built_in, trimesh_path = load_both(path, root)
    assert isinstance(built_in, AssetError) and isinstance(trimesh_path, AssetError)
    assert str(built_in) == str(trimesh_path) and says in str(built_in)


def test_a_vertex_normal_from_faces_matches_trimesh_on_a_curved_mesh(tmp_path: Path) -> None:
    angles = np.linspace(0.0, np.pi, 9)
    rows = [f"v {np.cos(a)!r} {np.sin(a)!r} {z!r}" for a in angles for z in (0.0, 0.37)]
    faces = [f"f {2 * i + 1} {2 * i + 3} {2 * i + 2}\nf {2 * i + 2} {2 * i + 3} {2 * i + 4}" for i in range(8)]
    path, root = _asset(tmp_path, "\n".join(rows + faces) + "\n", {})
    assert_same_parts(*load_both(path, root))


def test_an_obj_only_asset_loads_without_trimesh_yourdfpy_scipy_or_networkx(tmp_path: Path) -> None:
    root = tmp_path / "asset"
    (root / "meshes").mkdir(parents=True)
    (root / "meshes" / "part.obj").write_text("mtllib part.mtl\n" + TRIANGLES + UVS + "usemtl skin\nf 1/1 2/2 3/3\n")
    (root / "meshes" / "part.mtl").write_text(MTL)
    (root / "meshes" / "tex.png").write_bytes(_png())
    (root / "mobility.urdf").write_text(
        '<robot name="r"><link name="base"/><link name="part"><visual><origin xyz="0 0 0" rpy="0 0.5 0"/>'
        '<geometry><mesh filename="meshes/part.obj" scale="2"/></geometry><material name="m"><color rgba="1 0 0 1"/></material>'
        '</visual></link><joint name="j" type="revolute"><parent link="base"/><child link="part"/><axis xyz="0 0 1"/>'
        '<limit lower="0" upper="1"/></joint></robot>'
    )
    code = textwrap.dedent(
        f"""
        import sys
        from app.engine.asset.loader import load_asset
        asset = load_asset({str(root)!r})
        assert asset.links["part"].parts[0].material.image_png is not None
        print(" ".join(sorted(m for m in ("trimesh", "yourdfpy", "scipy", "networkx") if m in sys.modules)))
        """
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=REPO, timeout=120)
    assert done.stdout.strip() == ""
