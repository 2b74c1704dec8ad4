"""The lxml URDF reader reads what yourdfpy read: the same records for every shared URDF and for
the corners of the format, the same assets through the loader, and the same refusals.
"""

from __future__ import annotations

from pathlib import Path
from unittest import mock

import numpy as np
import pytest
from support.obj_compare import image_fingerprint
from support.primitive_assets import box, joint, link, robot
from support.urdf_reference import assert_same_robot, robot_via_yourdfpy

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.urdf import parse_urdf
from app.engine.asset.urdf_reader import origin_matrix, read_urdf
from app.engine.errors import AssetError
from tests.conftest import partnet_root


def _urdfs() -> list[Path]:
    try:
        partnet = partnet_root()
    except RuntimeError:
        return []
    roots = [root for root in (partnet, partnet.parent / "partnet-extra") if root.is_dir()]
    return [folder / "mobility.urdf" for root in roots for folder in sorted(root.iterdir()) if (folder / "mobility.urdf").is_file()]


URDFS = _urdfs()
IDS = [f"{path.parent.parent.name}/{path.parent.name}" for path in URDFS]
needs_assets = pytest.mark.skipif(not URDFS, reason="the shared PartNet-Mobility assets are not here (set ARTIMO_PARTNET_ROOT)")


@needs_assets
def test_every_shared_urdf_reads_as_yourdfpy_reads_it() -> None:
    assert len(URDFS) > 100
    for path in URDFS:
        data = path.read_bytes()
        assert_same_robot(read_urdf(data, path.name), robot_via_yourdfpy(data, path.name))


@needs_assets
def test_every_shared_urdf_gives_the_same_joints_and_tree() -> None:
    for path in URDFS:
        data = path.read_bytes()
        ours = parse_urdf(data, path.name)
        with mock.patch("app.engine.asset.urdf.read_urdf", robot_via_yourdfpy):
            reference = parse_urdf(data, path.name)
        assert (ours.root_link, ours.joint_order, ours.link_order) == (reference.root_link, reference.joint_order, reference.link_order)
        for name, spec in ours.joints.items():
            _same_joint(spec, reference.joints[name])


def _same_joint(a: object, b: object) -> None:
    for field in ("name", "type", "parent", "child", "lower", "upper", "effort", "velocity", "mimic"):
        assert getattr(a, field) == getattr(b, field), field
    for field in ("origin", "axis"):
        assert getattr(a, field).tobytes() == getattr(b, field).tobytes(), field


def _assert_same_asset(ours: ArticulatedAsset, reference: ArticulatedAsset) -> None:
    assert (ours.name, ours.urdf_file, ours.root_link, ours.joint_order, ours.link_order, ours.warnings, ours.content_hash) == (
        reference.name, reference.urdf_file, reference.root_link, reference.joint_order, reference.link_order, reference.warnings,
        reference.content_hash)
    for name, spec in ours.joints.items():
        _same_joint(spec, reference.joints[name])
    for name, spec in ours.links.items():
        other = reference.links[name]
        assert spec.semantics == other.semantics and len(spec.parts) == len(other.parts)
        for part, expected in zip(spec.parts, other.parts, strict=True):
            for field in ("vertices", "faces", "normals", "uv"):
                a, b = getattr(part, field), getattr(expected, field)
                assert (a is None and b is None) or a.tobytes() == b.tobytes(), (name, field)
            assert (part.material, part.source, part.visual) == (expected.material, expected.source, expected.visual)


@needs_assets
@pytest.mark.slow
@pytest.mark.parametrize("path", URDFS, ids=IDS)
def test_a_shared_asset_is_the_same_through_either_urdf_reader(path: Path) -> None:
    with mock.patch("app.engine.asset.obj_reader.png", image_fingerprint):  # the URDF, not texture encoding, is under test
        ours = load_asset(path.parent)
        with mock.patch("app.engine.asset.urdf.read_urdf", robot_via_yourdfpy):
            reference = load_asset(path.parent)
    _assert_same_asset(ours, reference)


VISUAL_CORNERS = {
    "rpy and xyz": '<visual name="a"><origin xyz="0.1 -2e-3 3" rpy="0.3 -1.2 2.9"/><geometry><box size="1 2 3"/></geometry></visual>',
    "rpy only": '<visual><origin rpy="3.14159 0 -0.5"/><geometry><sphere radius="0.2"/></geometry></visual>',
    "xyz with four numbers": '<visual><origin xyz="1 2 3 4"/><geometry><box size="1 1 1"/></geometry></visual>',
    "box size with commas": '<visual><geometry><box size="1,2, 3"/></geometry></visual>',
    "one scale": '<visual><geometry><mesh filename="m.obj" scale="2"/></geometry></visual>',
    "scale with commas": '<visual><geometry><mesh filename="m.obj" scale="1,2,3"/></geometry></visual>',
    "empty scale": '<visual><geometry><mesh filename="m.obj" scale=""/></geometry></visual>',
    "no filename": '<visual><geometry><mesh/></geometry></visual>',
    "cylinder": '<visual><geometry><cylinder radius="0.1" length="2"/></geometry></visual>',
    "colour without rgba": '<visual><geometry><sphere radius="1"/></geometry><material name="m"><color/></material></visual>',
    "named material": '<visual><geometry><sphere radius="1"/></geometry><material name="steel"/></visual>',
    "rgba with three numbers": '<visual><geometry><sphere radius="1"/></geometry><material><color rgba="1 0 0"/></material></visual>',
    "nan origin": '<visual><origin xyz="nan 0 0" rpy="0 inf 0"/><geometry><sphere radius="1"/></geometry></visual>',
    "comment before the shape": '<visual><geometry><!-- c --><sphere radius="1"/></geometry></visual>',
}
JOINT_CORNERS = {
    "no axis": '<joint name="j" type="revolute"><parent link="base"/><child link="part"/><limit lower="0" upper="1"/></joint>',
    "axis without xyz": '<joint name="j" type="continuous"><parent link="base"/><child link="part"/><axis/></joint>',
    "axis with two numbers": '<joint name="j" type="continuous"><parent link="base"/><child link="part"/><axis xyz="0 1"/></joint>',
    "partial limit": '<joint name="j" type="prismatic"><parent link="base"/><child link="part"/><limit upper="0.5" effort="3"/></joint>',
    "mimic defaults": '<joint name="j" type="fixed"><parent link="base"/><child link="part"/><mimic joint="k"/></joint>',
    "mimic values": '<joint name="j" type="revolute"><parent link="base"/><child link="part"/><origin xyz="1 0 0" rpy="0 0 1.5"/>'
                    '<limit lower="-1" upper="1" velocity="2"/><mimic joint="k" multiplier="-2" offset="0.25"/></joint>',
    "no type, no parent link": '<joint name="j"><parent/><child link="part"/></joint>',
    "extra elements": '<joint name="j" type="fixed"><parent link="base"/><child link="part"/><dynamics damping="x"/>'
                      '<calibration rising="1"/><safety_controller k_velocity="2"/></joint>',
}


def _document(visual: str = "", joint_xml: str = "") -> bytes:
    return (f'<robot name="r"><material name="steel"><color rgba="0.5 0.5 0.6 1"/></material><link name="base">'
            f'<inertial><origin xyz="0 0 1"/><mass value="2"/><inertia ixx="1" iyy="2" izz="3"/></inertial></link>'
            f'<link name="part">{visual}<collision><geometry><box size="1 1 1"/></geometry></collision></link>{joint_xml}</robot>').encode()


@pytest.mark.parametrize("visual", sorted(VISUAL_CORNERS))
def test_a_visual_reads_as_yourdfpy_reads_it(visual: str) -> None:
    data = _document(visual=VISUAL_CORNERS[visual])
    assert_same_robot(read_urdf(data, "r.urdf"), robot_via_yourdfpy(data, "r.urdf"))


@pytest.mark.parametrize("joint_xml", sorted(JOINT_CORNERS))
def test_a_joint_reads_as_yourdfpy_reads_it(joint_xml: str) -> None:
    data = _document(joint_xml=JOINT_CORNERS[joint_xml])
    assert_same_robot(read_urdf(data, "r.urdf"), robot_via_yourdfpy(data, "r.urdf"))


def test_origins_equal_yourdfpys_bit_for_bit() -> None:
    generator = np.random.default_rng(7)
    for xyz, rpy in zip(generator.uniform(-3, 3, (500, 3)).tolist(), generator.uniform(-7, 7, (500, 3)).tolist(), strict=True):
        numbers = " ".join(map(repr, xyz)), " ".join(map(repr, rpy))
        visual = f'<visual><origin xyz="{numbers[0]}" rpy="{numbers[1]}"/><geometry><sphere radius="1"/></geometry></visual>'
        data = _document(visual=visual)
        ours = read_urdf(data, "r.urdf").links[1].visuals[0].origin
        reference = robot_via_yourdfpy(data, "r.urdf").links[1].visuals[0].origin
        assert ours is not None and reference is not None and ours.tobytes() == reference.tobytes()
    assert np.allclose(origin_matrix(np.zeros(3), np.array([0.0, 0.0, np.pi / 2]))[:3, :3], [[0, -1, 0], [1, 0, 0], [0, 0, 1]])


REFUSED = {
    "no geometry": _document(visual="<visual/>"),
    "empty geometry": _document(visual="<visual><geometry/></visual>"),
    "unknown shape": _document(visual="<visual><geometry><capsule/></geometry></visual>"),
    "box without size": _document(visual="<visual><geometry><box/></geometry></visual>"),
    "cylinder without length": _document(visual='<visual><geometry><cylinder radius="1"/></geometry></visual>'),
    "sphere radius not a number": _document(visual='<visual><geometry><sphere radius="big"/></geometry></visual>'),
    "two xyz numbers": _document(visual='<visual><origin xyz="1 2"/><geometry><sphere radius="1"/></geometry></visual>'),
    "rpy not a number": _document(visual='<visual><origin rpy="0 0 x"/><geometry><sphere radius="1"/></geometry></visual>'),
    "colour not a number": _document(visual='<visual><geometry><sphere radius="1"/></geometry><material><color rgba="red"/></material></visual>'),
    "collision without geometry": b'<robot name="r"><link name="a"><collision/></link></robot>',
    "inertia not a number": b'<robot name="r"><link name="a"><inertial><inertia ixx="heavy"/></inertial></link></robot>',
    "mass not a number": b'<robot name="r"><link name="a"><inertial><mass value="?"/></inertial></link></robot>',
    "limit not a number": _document(joint_xml='<joint name="j" type="revolute"><parent link="base"/><child link="part"/>'
                                              '<limit lower="low" upper="1"/></joint>'),
    "calibration not a number": _document(joint_xml='<joint name="j" type="fixed"><parent link="base"/><child link="part"/>'
                                                    '<calibration rising="soon"/></joint>'),
    "mimic multiplier not a number": _document(joint_xml='<joint name="j" type="fixed"><parent link="base"/><child link="part"/>'
                                                         '<mimic joint="k" multiplier="twice"/></joint>'),
    "robot without a name": b'<robot><link name="a"/></robot>',
}


@pytest.mark.parametrize("case", sorted(REFUSED))
def test_what_yourdfpy_could_not_read_is_refused(case: str) -> None:
    data = REFUSED[case]
    with pytest.raises((ValueError, TypeError, AttributeError, KeyError, IndexError)):
        robot_via_yourdfpy(data, "r.urdf")
    with pytest.raises(AssetError, match="cannot parse URDF") as caught:
        read_urdf(data, "r.urdf")
    assert caught.value.file == "r.urdf" and caught.value.element


def test_unnamed_links_and_joints_are_refused_by_the_name_check() -> None:
    for urdf, says in ((robot("<link/>", link("b", box((1.0, 1.0, 1.0)))), "a <link> has no name"),
                       (robot(link("a", box((1.0, 1.0, 1.0))), link("b", box((1.0, 1.0, 1.0))),
                              joint("", "fixed", "a", "b").replace(' name=""', "")), "a <joint> has no name")):
        with pytest.raises(AssetError, match=says):
            parse_urdf(urdf.encode(), "r.urdf")
