"""Every rejection of SPEC §1 is an ``AssetError`` naming the file and the element."""

from __future__ import annotations

import io
import os
import stat
import zipfile
from pathlib import Path

import pytest
from PIL import Image
from support.primitive_assets import TRIANGLE_OBJ, box, joint, link, mesh, robot, two_link_urdf, write_asset

from app.engine.asset.loader import load_asset
from app.engine.asset.safety import AssetLimits
from app.engine.errors import AssetError

URDF = "mobility.urdf"
HINGE = two_link_urdf(joint("hinge", "revolute", "base", "part", limit=(0.0, 1.0)))


def rejected(
    path: Path, file: str, element: str, *, limits: AssetLimits | None = None, says: str = "", urdf: str | None = None
) -> AssetError:
    """Load ``path``, expect an AssetError whose message names ``file`` and ``element``."""
    with pytest.raises(AssetError) as caught:
        load_asset(path, limits=limits, urdf=urdf)
    error = caught.value
    message = str(error)
    assert error.file == file, message
    assert error.element is not None and element in error.element, message
    assert f"file {file}" in message and element in message, message
    assert says in message, message
    return error


def urdf_asset(tmp_path: Path, urdf: str, files: dict[str, str | bytes] | None = None) -> Path:
    return write_asset(tmp_path / "asset", urdf, files)


# --- zip archives ---------------------------------------------------------------------------


def make_zip(tmp_path: Path, members: list[tuple[str | zipfile.ZipInfo, bytes | str]], *, stored: bool = False) -> Path:
    archive = tmp_path / "upload.zip"
    with zipfile.ZipFile(archive, "w", compression=zipfile.ZIP_STORED if stored else zipfile.ZIP_DEFLATED) as zf:
        for name, data in members:
            zf.writestr(name, data)
    return archive


def test_zip_member_with_parent_reference(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [(URDF, HINGE), ("../evil.obj", TRIANGLE_OBJ)])
    rejected(archive, "upload.zip", "../evil.obj", says="'..'")
    assert not (tmp_path / "evil.obj").exists()


def test_zip_member_with_absolute_path(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [(URDF, HINGE), ("/tmp/artimo_evil.obj", TRIANGLE_OBJ)])
    rejected(archive, "upload.zip", "/tmp/artimo_evil.obj", says="absolute path")


def test_zip_symlink_member(tmp_path: Path) -> None:
    info = zipfile.ZipInfo("meshes/part.obj")
    info.external_attr = (stat.S_IFLNK | 0o777) << 16
    archive = make_zip(tmp_path, [(URDF, HINGE), (info, "/etc/passwd")])
    rejected(archive, "upload.zip", "meshes/part.obj", says="symbolic link")


def test_zip_with_too_many_members(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [(URDF, HINGE), ("a.txt", "a"), ("b.txt", "b")])
    rejected(archive, "upload.zip", "b.txt", limits=AssetLimits(max_files=2), says="3 members")


def test_zip_over_the_total_size_cap(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [(URDF, HINGE), ("noise.bin", os.urandom(3000))], stored=True)
    rejected(archive, "upload.zip", "noise.bin", limits=AssetLimits(max_total_bytes=3000), says="3000 bytes")


def test_zip_member_with_implausible_compression_ratio(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [(URDF, HINGE), ("zeros.obj", b"\0" * 4000)])
    rejected(archive, "upload.zip", "zeros.obj", limits=AssetLimits(max_compression_ratio=20.0), says="20x")


def test_broken_zip(tmp_path: Path) -> None:
    archive = tmp_path / "upload.zip"
    archive.write_bytes(b"PK\x03\x04 not really a zip archive")
    rejected(archive, "upload.zip", "central directory", says="not a readable zip")


def test_truncated_zip(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [(URDF, HINGE)])
    archive.write_bytes(archive.read_bytes()[:-30])
    rejected(archive, "upload.zip", "central directory")


# --- XML ----------------------------------------------------------------------------------

BILLION_LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE robot [
 <!ENTITY lol "lol">
 <!ENTITY lol1 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol2 "&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
]>
<robot name="&lol3;"><link name="base"><visual><geometry><box size="1 1 1"/></geometry></visual></link></robot>
"""
EXTERNAL_ENTITY = """<?xml version="1.0"?>
<!DOCTYPE robot [<!ENTITY secret SYSTEM "file:///etc/passwd">]>
<robot name="r"><link name="&secret;"><visual><geometry><box size="1 1 1"/></geometry></visual></link></robot>
"""
EXTERNAL_DTD = """<?xml version="1.0"?>
<!DOCTYPE robot SYSTEM "http://example.invalid/robot.dtd">
<robot name="r"><link name="base"><visual><geometry><box size="1 1 1"/></geometry></visual></link></robot>
"""


@pytest.mark.parametrize(
    "text", [BILLION_LAUGHS, EXTERNAL_ENTITY, EXTERNAL_DTD], ids=["billion-laughs", "external-entity", "external-dtd"]
)
def test_xml_entities_and_dtds_are_refused(tmp_path: Path, text: str) -> None:
    rejected(urdf_asset(tmp_path, text), URDF, "<!DOCTYPE>", says="forbidden XML construct")


# --- mesh paths -----------------------------------------------------------------------------


def mesh_urdf(filename: str) -> str:
    return two_link_urdf(joint("hinge", "revolute", "base", "part", limit=(0.0, 1.0)), child_visual=mesh(filename))


def test_mesh_path_with_parent_reference(tmp_path: Path) -> None:
    (tmp_path / "x.obj").write_text(TRIANGLE_OBJ)  # exists, but outside the asset
    error = rejected(
        urdf_asset(tmp_path, mesh_urdf("../x.obj")), URDF, "link part visual 0", says="outside the asset directory"
    )
    assert "'../x.obj'" in str(error) and str(tmp_path) not in str(error)


def test_mesh_path_absolute(tmp_path: Path) -> None:
    outside = tmp_path / "x.obj"
    outside.write_text(TRIANGLE_OBJ)
    rejected(
        urdf_asset(tmp_path, mesh_urdf(str(outside))), URDF, "link part visual 0", says="outside the asset directory"
    )


def test_mesh_path_file_url_absolute(tmp_path: Path) -> None:
    outside = tmp_path / "x.obj"
    outside.write_text(TRIANGLE_OBJ)
    rejected(
        urdf_asset(tmp_path, mesh_urdf(f"file://{outside}")),
        URDF,
        "link part visual 0",
        says="outside the asset directory",
    )


def test_mesh_path_package_url_escaping(tmp_path: Path) -> None:
    (tmp_path / "x.obj").write_text(TRIANGLE_OBJ)
    asset = urdf_asset(tmp_path, mesh_urdf("package://asset/../../x.obj"), {"meshes/part.obj": TRIANGLE_OBJ})
    rejected(asset, URDF, "link part visual 0", says="outside the asset directory")


def test_mesh_symlink_leaving_the_asset(tmp_path: Path) -> None:
    outside = tmp_path / "x.obj"
    outside.write_text(TRIANGLE_OBJ)
    asset = urdf_asset(tmp_path, mesh_urdf("meshes/part.obj"))
    (asset / "meshes").mkdir()
    (asset / "meshes" / "part.obj").symlink_to(outside)
    rejected(asset, URDF, "link part visual 0", says="outside the asset directory")


def test_obj_mtllib_escaping(tmp_path: Path) -> None:
    (tmp_path / "evil.mtl").write_text("newmtl m\nKd 1 0 0\n")
    obj = "mtllib ../../evil.mtl\nusemtl m\n" + TRIANGLE_OBJ
    asset = urdf_asset(tmp_path, mesh_urdf("meshes/part.obj"), {"meshes/part.obj": obj})
    rejected(asset, "meshes/part.obj", "../../evil.mtl", says="outside the asset directory")


def _png() -> bytes:
    buffer = io.BytesIO()
    Image.new("RGB", (2, 2), (255, 0, 0)).save(buffer, format="PNG")
    return buffer.getvalue()


TEXTURED_OBJ = "mtllib part.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n"


def test_mtl_map_kd_escaping(tmp_path: Path) -> None:
    (tmp_path / "secret.png").write_bytes(_png())
    files = {"meshes/part.obj": TEXTURED_OBJ, "meshes/part.mtl": "newmtl m\nKd 1 1 1\nmap_Kd ../../secret.png\n"}
    rejected(urdf_asset(tmp_path, mesh_urdf("meshes/part.obj"), files), "meshes/part.obj", "../../secret.png")


def test_mtl_map_kd_inside_is_loaded(tmp_path: Path) -> None:
    files = {
        "meshes/part.obj": TEXTURED_OBJ,
        "meshes/part.mtl": "newmtl m\nKd 1 1 1\nmap_Kd tex.png\n",
        "meshes/tex.png": _png(),
    }
    part = load_asset(urdf_asset(tmp_path, mesh_urdf("meshes/part.obj"), files)).links["part"].parts[0]
    assert part.material.image_png is not None and part.material.image_png.startswith(b"\x89PNG")
    assert part.uv is not None and part.uv.shape == (3, 2)


def test_missing_mesh(tmp_path: Path) -> None:
    asset = urdf_asset(tmp_path, mesh_urdf("meshes/gone.obj"), {"meshes/part.obj": TRIANGLE_OBJ})
    rejected(asset, URDF, "link part visual 0", says="'meshes/gone.obj' does not exist")


# --- the joint tree ---------------------------------------------------------------------------

BOX = box((1.0, 1.0, 1.0))


def test_cycle_beside_the_root(tmp_path: Path) -> None:
    urdf = robot(
        link("base", BOX),
        link("a", BOX),
        link("b", BOX),
        joint("ab", "fixed", "a", "b"),
        joint("ba", "fixed", "b", "a"),
    )
    error = rejected(urdf_asset(tmp_path, urdf), URDF, "joint ", says="cycle")
    assert error.element in ("joint ab", "joint ba")


def test_cycle_without_a_root(tmp_path: Path) -> None:
    urdf = robot(link("a", BOX), link("b", BOX), joint("ab", "fixed", "a", "b"), joint("ba", "fixed", "b", "a"))
    error = rejected(urdf_asset(tmp_path, urdf), URDF, "joint ", says="cycle")
    assert error.element in ("joint ab", "joint ba")


def test_link_with_two_parents(tmp_path: Path) -> None:
    urdf = robot(
        link("base", BOX),
        link("a", BOX),
        link("b", BOX),
        joint("to_b", "fixed", "base", "b"),
        joint("again_b", "fixed", "a", "b"),
    )
    rejected(urdf_asset(tmp_path, urdf), URDF, "joint again_b", says="child of two joints")


def test_several_roots(tmp_path: Path) -> None:
    urdf = robot(link("base", BOX), link("island", BOX), link("part", BOX), joint("j", "fixed", "base", "part"))
    rejected(urdf_asset(tmp_path, urdf), URDF, "link island", says="2 root links")


def test_several_roots_with_joints_below_each(tmp_path: Path) -> None:
    urdf = robot(
        link("base", BOX), link("part", BOX), link("island", BOX), link("rock", BOX),
        joint("j", "fixed", "base", "part"), joint("k", "fixed", "island", "rock"),
    )  # fmt: skip
    rejected(urdf_asset(tmp_path, urdf), URDF, "link island", says="2 root links")


@pytest.mark.parametrize(
    ("joint_xml", "says"),
    [
        (joint("j", "floating", "base", "part"), "floating joints are not supported"),
        (joint("j", "planar", "base", "part"), "planar joints are not supported"),
        (joint("j", "revolute", "base", "part"), "revolute joint has no <limit>"),
        (joint("j", "prismatic", "base", "part"), "prismatic joint has no <limit>"),
        (joint("j", "revolute", "base", "part", limit=(1.0, 0.5)), "not a valid range"),
        (joint("j", "prismatic", "base", "part", limit=(0.0, 1.0), axis=(0.0, 0.0, 0.0)), "axis is zero"),
        (joint("j", "revolute", "ghost", "part", limit=(0.0, 1.0)), "parent link 'ghost' is not defined"),
        (joint("j", "revolute", "base", "ghost", limit=(0.0, 1.0)), "child link 'ghost' is not defined"),
        (
            joint("j", "revolute", "base", "part", limit=(0.0, 1.0), mimic=("ghost", 1.0, 0.0)),
            "mimics unknown joint 'ghost'",
        ),
    ],
    ids=[
        "floating",
        "planar",
        "revolute-no-limit",
        "prismatic-no-limit",
        "lower-above-upper",
        "zero-axis",
        "unknown-parent",
        "unknown-child",
        "mimic-unknown",
    ],
)
def test_bad_joint(tmp_path: Path, joint_xml: str, says: str) -> None:
    rejected(urdf_asset(tmp_path, two_link_urdf(joint_xml)), URDF, "joint j", says=says)


def test_duplicate_link_names(tmp_path: Path) -> None:
    urdf = robot(link("base", BOX), link("base", BOX))
    rejected(urdf_asset(tmp_path, urdf), URDF, "link base", says="duplicate link name")


def test_duplicate_joint_names(tmp_path: Path) -> None:
    urdf = robot(
        link("base", BOX),
        link("a", BOX),
        link("b", BOX),
        joint("j", "fixed", "base", "a"),
        joint("j", "fixed", "base", "b"),
    )
    rejected(urdf_asset(tmp_path, urdf), URDF, "joint j", says="duplicate joint name")


# --- which URDF -------------------------------------------------------------------------------


def test_several_urdfs_without_mobility(tmp_path: Path) -> None:
    asset = write_asset(tmp_path / "asset", HINGE, {"b.urdf": HINGE}, urdf_name="a.urdf")
    error = rejected(asset, "asset", "*.urdf", says="holds 2 URDF files (a.urdf, b.urdf)")
    assert str(error).count("b.urdf") == 1  # the list once (it was the element too)


def test_several_urdfs_in_a_zip_name_the_upload(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [("a.urdf", HINGE), ("b.urdf", HINGE)])
    rejected(archive, "upload.zip", "*.urdf", says="holds 2 URDF files (a.urdf, b.urdf)")


def test_no_urdf(tmp_path: Path) -> None:
    asset = write_asset(tmp_path / "asset", None, {"meshes/part.obj": TRIANGLE_OBJ})
    rejected(asset, "asset", "*.urdf", says="no .urdf file")


def test_several_urdfs_are_an_error_even_with_a_mobility_urdf(tmp_path: Path) -> None:
    """A folder of assets (or a zip of two) must not pick one silently."""
    other = robot(link("only", BOX))
    asset = write_asset(tmp_path / "asset", HINGE, {"extra/other.urdf": other, "zz.urdf": other})
    error = rejected(asset, "asset", "*.urdf", says="holds 3 URDF files (mobility.urdf, zz.urdf, extra/other.urdf)")
    assert "--urdf" in str(error) and "'urdf' field" in str(error)


def test_a_zip_of_two_assets_is_an_error(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [("cap/mobility.urdf", robot(link("only", BOX))), ("bin/mobility.urdf", HINGE)])
    rejected(archive, "upload.zip", "*.urdf", says="holds 2 URDF files (bin/mobility.urdf, cap/mobility.urdf)")


def test_the_chosen_urdf_is_loaded(tmp_path: Path) -> None:
    other = robot(link("only", BOX))
    asset = write_asset(tmp_path / "asset", HINGE, {"extra/other.urdf": other, "zz.urdf": other})
    assert load_asset(asset, urdf="mobility.urdf").joint_order == ("hinge",)
    chosen = load_asset(asset, urdf="extra/other.urdf")
    assert chosen.urdf_file == "extra/other.urdf" and chosen.joint_order == ()
    assert load_asset(asset, urdf="other.urdf").urdf_file == "extra/other.urdf"  # a unique file name is enough
    archive = make_zip(tmp_path, [("cap/mobility.urdf", robot(link("only", BOX))), ("bin/mobility.urdf", HINGE)])
    assert load_asset(archive, urdf="bin/mobility.urdf").joint_order == ("hinge",)


def test_a_chosen_urdf_that_is_not_there_lists_the_ones_that_are(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [("cap/mobility.urdf", robot(link("only", BOX))), ("bin/mobility.urdf", HINGE)])
    rejected(archive, "upload.zip", "lid.urdf", urdf="lid.urdf",
             says="matches none of the asset's URDF files (bin/mobility.urdf, cap/mobility.urdf)")
    rejected(archive, "upload.zip", "mobility.urdf", urdf="mobility.urdf", says="matches several")


def test_a_single_urdf_may_be_named_with_its_folder(tmp_path: Path) -> None:
    archive = make_zip(tmp_path, [("bin/mobility.urdf", HINGE)])  # the zip of a folder: the folder is the asset root
    assert load_asset(archive, urdf="bin/mobility.urdf").urdf_file == "mobility.urdf"


def test_urdf_in_zip_agrees_with_the_loader_without_extracting(tmp_path: Path) -> None:
    from app.engine.asset.urdf_choice import urdf_in_zip

    two = make_zip(tmp_path, [("cap/mobility.urdf", robot(link("only", BOX))), ("bin/mobility.urdf", HINGE)])
    assert urdf_in_zip(two, "bin/mobility.urdf") == load_asset(two, urdf="bin/mobility.urdf").urdf_file == "bin/mobility.urdf"
    with pytest.raises(AssetError, match="holds 2 URDF files"):
        urdf_in_zip(two)
    (tmp_path / "one").mkdir()
    one = make_zip(tmp_path / "one", [("bin/mobility.urdf", HINGE), ("__MACOSX/bin/._mobility.urdf", "junk")])
    assert urdf_in_zip(one) == load_asset(one).urdf_file == "mobility.urdf"


# --- every number is checked on load (NaN, infinity, absurd sizes, wrong counts) -----------------
def _with_joint(joint_xml: str) -> str:
    return robot(link("base", BOX), link("part", BOX), joint_xml)


def _with_visual(visual_xml: str) -> str:
    return robot(link("base", BOX), link("part", visual_xml), joint("j", "revolute", "base", "part", limit=(0.0, 1.0)))


_JOINT = '<joint name="j" type="revolute"><parent link="base"/><child link="part"/>{}</joint>'
_LIMIT = '<limit lower="0" upper="1" effort="1" velocity="1"/>'
BAD_NUMBERS = {
    "axis with two numbers": (_with_joint(_JOINT.format('<axis xyz="0 1"/>' + _LIMIT)), "joint j", "axis needs 3 numbers"),
    "NaN axis": (_with_joint(_JOINT.format('<axis xyz="0 nan 1"/>' + _LIMIT)), "joint j", "axis holds a NaN"),
    "1e308 joint origin": (_with_joint(_JOINT.format('<origin xyz="1e308 0 0"/><axis xyz="0 0 1"/>' + _LIMIT)), "joint j",
                           "larger than 10000"),
    "infinite limit": (_with_joint(_JOINT.format('<axis xyz="0 0 1"/><limit lower="0" upper="inf" effort="1" velocity="1"/>')),
                       "joint j", "limit lower/upper holds"),
    "NaN effort": (_with_joint(_JOINT.format('<axis xyz="0 0 1"/><limit lower="0" upper="1" effort="nan" velocity="1"/>')),
                   "joint j", "limit effort holds"),
    "NaN mimic multiplier": (robot(link("base", BOX), link("a", BOX), link("b", BOX),
                                   joint("ja", "revolute", "base", "a", limit=(0.0, 1.0)),
                                   joint("jb", "revolute", "base", "b", limit=(0.0, 1.0), mimic=("ja", float("nan"), 0.0))),
                             "joint jb", "mimic multiplier/offset holds"),
    "NaN visual origin": (_with_visual('<visual><origin xyz="nan 0 0"/><geometry><box size="1 1 1"/></geometry></visual>'),
                          "link part visual 0", "origin is not a finite transform"),
    "infinite visual rpy": (_with_visual('<visual><origin rpy="0 inf 0"/><geometry><box size="1 1 1"/></geometry></visual>'),
                            "link part visual 0", "origin is not a finite transform"),
    "box with two sizes": (_with_visual('<visual><geometry><box size="1 1"/></geometry></visual>'), "link part visual 0",
                           "box size needs 3 numbers"),
    "NaN box size": (_with_visual('<visual><geometry><box size="nan 1 1"/></geometry></visual>'), "link part visual 0",
                     "box size holds a NaN"),
    "infinite cylinder": (_with_visual('<visual><geometry><cylinder radius="inf" length="1"/></geometry></visual>'),
                          "link part visual 0", "cylinder radius/length holds"),
    "NaN mesh scale": (_with_visual(mesh("meshes/part.obj", scale=(float("nan"), 1.0, 1.0))), "link part visual 0",
                       "mesh scale holds a NaN"),
    "zero mesh scale": (_with_visual(mesh("meshes/part.obj", scale=(0.0, 1.0, 1.0))), "link part visual 0", "zero factor"),
}


@pytest.mark.parametrize("case", sorted(BAD_NUMBERS))
def test_bad_numbers_in_the_urdf_are_rejected_naming_the_element(tmp_path: Path, case: str) -> None:
    urdf, element, says = BAD_NUMBERS[case]
    rejected(urdf_asset(tmp_path, urdf, {"meshes/part.obj": TRIANGLE_OBJ}), URDF, element, says=says)


@pytest.mark.parametrize("vertex", ["nan 0 0", "inf 0 0", "1e300 0 0"])
def test_bad_numbers_in_obj_vertices_are_rejected(tmp_path: Path, vertex: str) -> None:
    obj = f"v 0 0 0\nv {vertex}\nv 0 1 0\nf 1 2 3\n"
    rejected(urdf_asset(tmp_path, _with_visual(mesh("meshes/part.obj")), {"meshes/part.obj": obj}), "meshes/part.obj", "vertex 1",
             says="NaN, infinite or farther")


# --- cheap uploads must not buy unbounded work: limits checked before the expensive parse -----------
def _png_header(width: int, height: int) -> bytes:
    """The first bytes of a PNG declaring ``width`` x ``height`` (enough for a header read; never decoded)."""
    import struct
    import zlib

    def chunk(kind: bytes, payload: bytes) -> bytes:
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))

    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(b"\0" * 1000))


def test_too_many_joints_are_refused_before_the_urdf_is_parsed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import app.engine.asset.loader as loader

    monkeypatch.setattr(loader, "parse_urdf", lambda *_: pytest.fail("parsed a URDF over the joint limit"))
    links = [link(f"l{i}", BOX) for i in range(301)]
    joints = [joint(f"j{i}", "revolute", f"l{i}", f"l{i + 1}", limit=(0.0, 1.0)) for i in range(300)]
    rejected(urdf_asset(tmp_path, robot(*links, *joints)), URDF, "link", says="301 <link> elements, more than the limit of 257")


@pytest.mark.filterwarnings("ignore::PIL.Image.DecompressionBombWarning")  # PIL warns on the header it just read
@pytest.mark.parametrize("texture_name", ["textures/huge.png", "textures/huge.dat"])
def test_a_huge_texture_is_refused_from_its_header(tmp_path: Path, texture_name: str) -> None:
    """13000 x 13000 pixels (~500 MB decoded) in a few bytes: refused before decoding, under any file name."""
    mtl = f"newmtl skin\nmap_Kd {texture_name}\n"
    obj = "mtllib part.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl skin\nf 1/1 2/2 3/3\n"
    files = {"meshes/part.obj": obj, "meshes/part.mtl": mtl, f"meshes/{texture_name}": _png_header(13000, 13000)}
    asset = urdf_asset(tmp_path, two_link_urdf(joint("hinge", "revolute", "base", "part", limit=(0.0, 1.0)),
                                               child_visual=mesh("meshes/part.obj")), files)
    rejected(asset, f"meshes/{texture_name}", "texture", says="13000 x 13000 pixels")


def test_an_obj_over_the_triangle_budget_is_refused_before_it_is_parsed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import trimesh

    monkeypatch.setattr(trimesh, "load", lambda *_a, **_k: pytest.fail("parsed a mesh over the triangle budget"))
    obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\n" + b"f 1 2 3\n" * 2_000_001
    asset = urdf_asset(tmp_path, two_link_urdf(joint("hinge", "revolute", "base", "part", limit=(0.0, 1.0)),
                                               child_visual=mesh("meshes/part.obj")), {"meshes/part.obj": obj})
    with pytest.raises(AssetError, match="more than 2000000 triangles") as caught:
        load_asset(asset)
    assert caught.value.file == "meshes/part.obj"
