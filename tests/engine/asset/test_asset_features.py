"""What a valid asset turns into: zip = folder, package:// paths, axes, rest pose, mimics, geometry."""

from __future__ import annotations

import math
import zipfile
from pathlib import Path

import numpy as np
import pytest
from support.primitive_assets import (
    TRIANGLE_OBJ,
    box,
    cylinder,
    joint,
    link,
    mesh,
    robot,
    two_link_urdf,
    write_asset,
    write_cabinet,
)

from app.engine.asset.kinematics import link_poses, resolve_joint_values
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset


def zip_folder(folder: Path, archive: Path, prefix: str) -> Path:
    with zipfile.ZipFile(archive, "w", compression=zipfile.ZIP_DEFLATED) as zf:
        for path in sorted(folder.rglob("*")):
            zf.write(path, prefix + str(path.relative_to(folder)))
    return archive


def assert_same_asset(a: ArticulatedAsset, b: ArticulatedAsset) -> None:
    assert (a.name, a.urdf_file, a.root_link, a.content_hash) == (b.name, b.urdf_file, b.root_link, b.content_hash)
    assert a.joint_order == b.joint_order and a.link_order == b.link_order
    for name in a.joint_order:
        ja, jb = a.joints[name], b.joints[name]
        assert (ja.type, ja.parent, ja.child, ja.lower, ja.upper, ja.mimic) == (
            jb.type,
            jb.parent,
            jb.child,
            jb.lower,
            jb.upper,
            jb.mimic,
        )
        assert np.array_equal(ja.origin, jb.origin) and np.array_equal(ja.axis, jb.axis)
    for name in a.link_order:
        parts_a, parts_b = a.links[name].parts, b.links[name].parts
        assert len(parts_a) == len(parts_b)
        assert a.links[name].semantics == b.links[name].semantics
        for pa, pb in zip(parts_a, parts_b, strict=True):
            assert np.array_equal(pa.vertices, pb.vertices) and np.array_equal(pa.faces, pb.faces)
            assert pa.material == pb.material and pa.source == pb.source


def mesh_asset(root: Path) -> Path:
    urdf = robot(
        link("base", box((1.0, 1.0, 1.0))),
        link("part", mesh("meshes/part.obj", xyz=(0.0, 0.0, 1.0), scale=(2.0, 3.0, 4.0))),
        joint("hinge", "revolute", "base", "part", limit=(-1.0, 1.0)),
    )
    return write_asset(root, urdf, {"meshes/part.obj": TRIANGLE_OBJ, "semantics.txt": "part hinge door\n"})


@pytest.mark.parametrize("prefix", ["thing/", ""], ids=["top-level-folder", "flat"])
def test_zip_loads_like_the_folder(tmp_path: Path, prefix: str) -> None:
    folder = mesh_asset(tmp_path / "thing")
    archive = zip_folder(folder, tmp_path / "thing.zip", prefix)
    assert_same_asset(load_asset(archive), load_asset(folder))


def test_zip_with_macos_metadata_loads_like_the_folder(tmp_path: Path) -> None:
    folder = mesh_asset(tmp_path / "thing")
    archive = zip_folder(folder, tmp_path / "thing.zip", "thing/")
    with zipfile.ZipFile(archive, "a") as zf:
        zf.writestr("__MACOSX/thing/._mobility.urdf", b"\x00\x05\x16\x07 apple double")
    assert_same_asset(load_asset(archive), load_asset(folder))


def test_mesh_origin_scale_and_semantics(tmp_path: Path) -> None:
    asset = load_asset(mesh_asset(tmp_path / "thing"))
    (part,) = asset.links["part"].parts
    assert np.allclose(part.vertices, [[0, 0, 1], [2, 0, 1], [0, 3, 1]])
    assert part.source == "meshes/part.obj"
    assert np.allclose(part.normals, [[0, 0, 1]] * 3)
    assert asset.links["part"].semantics.label == "door" and asset.links["part"].semantics.joint_kind == "hinge"
    assert asset.links["part"].semantics.source == "semantics.txt"


@pytest.mark.parametrize(
    ("filename", "where"),
    [
        ("package://thing/meshes/part.obj", "meshes/part.obj"),
        ("package://thing/part.obj", "thing/part.obj"),
        ("file://meshes/part.obj", "meshes/part.obj"),
    ],
    ids=["package-root", "package-subfolder", "file-url-relative"],
)
def test_package_and_file_urls_resolve_inside_the_asset(tmp_path: Path, filename: str, where: str) -> None:
    urdf = two_link_urdf(joint("hinge", "revolute", "base", "part", limit=(0.0, 1.0)), child_visual=mesh(filename))
    asset = load_asset(write_asset(tmp_path / "thing", urdf, {where: TRIANGLE_OBJ}))
    assert asset.links["part"].parts[0].source == where


def test_prismatic_axis_is_normalised(tmp_path: Path) -> None:
    urdf = two_link_urdf(joint("slide", "prismatic", "base", "part", axis=(2.0, 0.0, 0.0), limit=(0.0, 1.0)))
    asset = load_asset(write_asset(tmp_path / "slider", urdf))
    assert np.array_equal(asset.joints["slide"].axis, [1.0, 0.0, 0.0])
    pose = link_poses(asset, {"slide": np.array([0.5])})["part"][0]
    assert np.allclose(pose[:3, 3], [0.5, 0.0, 0.0])  # 0.5 m, not 1 m


def test_oblique_axis_is_normalised(tmp_path: Path) -> None:
    urdf = two_link_urdf(joint("hinge", "revolute", "base", "part", axis=(0.0, 3.0, 4.0), limit=(0.0, 1.0)))
    asset = load_asset(write_asset(tmp_path / "hinge", urdf))
    assert np.allclose(asset.joints["hinge"].axis, [0.0, 0.6, 0.8])


@pytest.mark.parametrize(
    ("kind", "limit", "rest"),
    [
        ("revolute", (0.2, 1.0), 0.2),
        ("revolute", (-1.0, -0.3), -0.3),
        ("prismatic", (-0.5, 0.5), 0.0),
        ("prismatic", (0.1, 0.4), 0.1),
        ("continuous", None, 0.0),
    ],
)
def test_rest_pose_is_zero_clamped_into_the_limits(
    tmp_path: Path, kind: str, limit: tuple[float, float] | None, rest: float
) -> None:
    asset = load_asset(write_asset(tmp_path / "a", two_link_urdf(joint("j", kind, "base", "part", limit=limit))))
    assert asset.joints["j"].rest == rest
    assert asset.rest_vector().tolist() == [rest]
    assert resolve_joint_values(asset, {}, 1)["j"].tolist() == [rest]


def test_continuous_joint_ignores_a_limit_tag(tmp_path: Path) -> None:
    asset = load_asset(
        write_asset(tmp_path / "a", two_link_urdf(joint("j", "continuous", "base", "part", limit=(0.3, 0.5))))
    )
    spec = asset.joints["j"]
    assert not spec.bounded and spec.rest == 0.0 and spec.clamp(10.0) == 10.0


def test_mimic_follows_multiplier_and_offset(tmp_path: Path) -> None:
    asset = load_asset(write_cabinet(tmp_path / "cab", flap_offset=0.1))
    assert asset.controllable_joints == ("lid_hinge", "drawer_slide", "knob_spin")
    assert asset.movable_joints == ("lid_hinge", "drawer_slide", "knob_spin", "flap_mimic")
    lid = np.array([0.0, 0.4, 1.2])
    values = resolve_joint_values(asset, {"lid_hinge": lid}, 3)
    assert np.allclose(values["flap_mimic"], 0.5 * lid + 0.1)
    poses = link_poses(asset, {"lid_hinge": lid})
    relative = np.linalg.inv(poses["lid"]) @ poses["flap"]
    angles = np.arctan2(relative[:, 2, 1], relative[:, 1, 1])  # rotation about +x
    assert np.allclose(angles, 0.5 * lid + 0.1)


def test_rest_vector_puts_a_mimic_where_its_leader_puts_it(tmp_path: Path) -> None:
    asset = load_asset(write_cabinet(tmp_path / "cab", flap_offset=0.1))
    at_rest = resolve_joint_values(asset, {}, 1)
    assert asset.rest_vector().tolist() == [at_rest[j][0] for j in asset.movable_joints] == [0.0, 0.0, 0.0, 0.1]


def test_primitive_geometry_is_exact(cabinet: ArticulatedAsset) -> None:
    lid = cabinet.links["lid"].vertices()
    assert np.allclose(lid.min(axis=0), [-1.0, 0.0, 0.0]) and np.allclose(lid.max(axis=0), [1.0, 1.0, 0.1])
    knob = cabinet.links["knob"].vertices()  # cylinder r 0.1, length 0.1, turned onto +x
    assert np.allclose(knob.min(axis=0), [0.0, -0.1, -0.1]) and np.allclose(knob.max(axis=0), [0.1, 0.1, 0.1])
    radial = np.linalg.norm(knob[:, 1:], axis=1)
    assert np.allclose(radial[radial > 1e-9], 0.1)
    assert cabinet.links["world"].parts == ()
    assert len(cabinet.links["drawer"].parts) == 2
    assert cabinet.links["drawer"].semantics.label == "drawer_front"


def test_sphere_primitive(tmp_path: Path) -> None:
    visual = '<visual><geometry><sphere radius="0.25"/></geometry></visual>'
    asset = load_asset(write_asset(tmp_path / "ball", robot(link("ball", visual))))
    assert np.allclose(np.linalg.norm(asset.links["ball"].vertices(), axis=1), 0.25)
    assert asset.joint_order == () and asset.movable_joints == ()


def test_loading_is_deterministic(cabinet_dir: Path) -> None:
    assert_same_asset(load_asset(cabinet_dir), load_asset(cabinet_dir))


def test_cylinder_visual_origin(tmp_path: Path) -> None:
    urdf = robot(link("base", cylinder(0.5, 2.0, xyz=(0.0, 0.0, 1.0))))
    vertices = load_asset(write_asset(tmp_path / "can", urdf)).links["base"].vertices()
    assert np.allclose(vertices.min(axis=0), [-0.5, -0.5, 0.0]) and np.allclose(vertices.max(axis=0), [0.5, 0.5, 2.0])
    assert math.isclose(float(np.linalg.norm(vertices[:, :2], axis=1).max()), 0.5)
