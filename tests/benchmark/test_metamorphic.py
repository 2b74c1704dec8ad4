"""The metamorphic probe's variants: the same shape and motion, written down differently; expectations follow."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from app.engine.asset.kinematics import link_poses
from app.engine.asset.loader import load_asset
from benchmark import metamorphic, variants
from benchmark.metamorphic import Mapping, comparable, make_variant, transform_expect
from tests.conftest import partnet_root

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

MIMIC_URDF = """<?xml version="1.0"?>
<robot name="pair">
  <link name="base"><visual><geometry><box size="1 1 0.2"/></geometry></visual></link>
  <link name="link_0"><visual><origin xyz="0.2 0 0"/><geometry><box size="0.4 0.1 0.05"/></geometry></visual></link>
  <link name="link_1"><visual><origin xyz="0.2 0 0"/><geometry><box size="0.4 0.1 0.05"/></geometry></visual></link>
  <joint name="joint_0" type="revolute"><parent link="base"/><child link="link_0"/><origin xyz="0 0.3 0.2" rpy="0.1 0.2 0.3"/>
    <axis xyz="0 0 1"/><limit lower="-0.5" upper="1.2" effort="1" velocity="1"/></joint>
  <joint name="joint_1" type="revolute"><parent link="base"/><child link="link_1"/><origin xyz="0 -0.3 0.2"/>
    <axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="joint_0" multiplier="-0.5" offset="0.1"/></joint>
  <joint name="joint_2" type="prismatic"><parent link="link_0"/><child link="link_2"/><origin xyz="0.4 0 0"/>
    <axis xyz="1 0 0"/><limit lower="0" upper="0.3" effort="1" velocity="1"/></joint>
  <link name="link_2"><visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual></link>
</robot>
"""


def _poses(asset_dir: Path, values: dict[str, float]) -> dict[str, np.ndarray]:
    model = load_asset(asset_dir)
    return {name: pose[0] for name, pose in link_poses(model, {k: np.array([v]) for k, v in values.items()}, frames=1).items()}


def _placed(asset_dir: Path, values: dict[str, float]) -> dict[str, np.ndarray]:
    """Every link's vertices where the joint values put them in the world."""
    model = load_asset(asset_dir)
    poses = link_poses(model, {k: np.array([v]) for k, v in values.items()}, frames=1)
    return {name: model.links[name].vertices() @ pose[0][:3, :3].T + pose[0][:3, 3] for name, pose in poses.items()}


@pytest.mark.parametrize("transforms", [("flip",), ("rename",), ("reorder",), ("shift",), ("move",), metamorphic.PURE])
def test_pure_variants_place_every_link_alike(tmp_path: Path, transforms: tuple[str, ...]) -> None:
    source = tmp_path / "pair"
    source.mkdir()
    (source / "mobility.urdf").write_text(MIMIC_URDF)
    (source / "semantics.txt").write_text("link_0 hinge arm\nlink_1 hinge arm\nlink_2 slider block\n")
    mapping = make_variant(source, tmp_path / "variant", transforms)
    values = {"joint_0": 0.7, "joint_2": 0.2}
    before = _placed(source, values)
    after = _placed(tmp_path / "variant", {mapping.name(k): mapping.sign(k) * v for k, v in values.items()})
    links = {"link_0": "link_2", "link_2": "link_0"} if "rename" in transforms else {}
    offset = variants.MOVE if "move" in transforms else np.zeros(3)
    for link, points in before.items():
        assert np.allclose(after[links.get(link, link)], points + offset, atol=1e-9), link
    if "rename" in transforms:
        assert (tmp_path / "variant" / "semantics.txt").read_text().splitlines()[0] == "link_2 hinge arm"
    changed = (tmp_path / "variant" / "mobility.urdf").read_text() != MIMIC_URDF
    assert changed


def _sorted(points: np.ndarray) -> np.ndarray:
    return points[np.lexsort(np.round(points, 9).T[::-1])]


@pytest.mark.parametrize("transforms", [("mirror",), ("mirror", "flip", "rename", "shift")])
def test_mirror_places_every_point_at_its_reflection_and_moves_alike(tmp_path: Path, transforms: tuple[str, ...]) -> None:
    source = tmp_path / "pair"
    source.mkdir()
    (source / "mobility.urdf").write_text(MIMIC_URDF)
    mapping = make_variant(source, tmp_path / "variant", transforms)
    assert mapping.mirrored
    links = {"link_0": "link_2", "link_2": "link_0"} if "rename" in transforms else {}
    for values in ({}, {"joint_0": 0.7, "joint_2": 0.2}, {"joint_0": -0.4, "joint_2": 0.05}):
        before = _placed(source, values)
        after = _placed(tmp_path / "variant", {mapping.name(k): mapping.value(k, v) for k, v in values.items()})
        for link, points in before.items():  # boxes: the same corners, in another order
            assert np.allclose(_sorted(after[links.get(link, link)]), _sorted(points * [1.0, -1.0, 1.0]), atol=1e-9), (link, values)


def test_mirror_swaps_the_prompt_sides_and_the_base_translation() -> None:
    assert metamorphic.mirror_words("Open the Left door, then turn the knob clockwise") == "Open the Right door, then turn the knob counterclockwise"
    assert not comparable({"prompt": "Do it right away", "expect": {}}, ("mirror",))
    assert comparable({"prompt": "open the right door", "expect": {}}, ("mirror",))
    for handed in ("turn the tap on", "tighten the cap", "swing the lever toward hot"):  # conventions a mirror does not keep
        assert not comparable({"prompt": handed, "expect": {}}, ("mirror",)), handed
    out = transform_expect({"base": {"translation": [0.1, 0.2, 0.3], "tol": 0.05}}, Mapping(mirrored=True))
    assert out["base"]["translation"] == [0.1, -0.2, 0.3]


def test_mirror_of_a_mesh_asset_reflects_its_vertices(tmp_path: Path) -> None:
    source = partnet_root() / "faucet_148"
    make_variant(source, tmp_path / "faucet_148", ("mirror",))
    for values in ({}, {"joint_0": 0.9}):
        before, after = _placed(source, values), _placed(tmp_path / "faucet_148", values)
        for link, points in before.items():  # meshes: each vertex at its reflection, in the same order
            assert np.allclose(after[link], points * [1.0, -1.0, 1.0], atol=1e-9), link


def test_yaw_turns_the_whole_object(tmp_path: Path) -> None:
    make_variant(EXAMPLES / "oven", tmp_path / "oven", ("yaw",))
    before, after = _poses(EXAMPLES / "oven", {}), _poses(tmp_path / "oven", {})
    turn = np.eye(4)
    turn[:2, :2] = [[0.0, -1.0], [1.0, 0.0]]
    root = load_asset(EXAMPLES / "oven").root_link
    assert np.allclose(after[root], before[root])
    for link in before:
        assert np.allclose(after[link], turn @ before[link] if link != root else before[link], atol=1e-9), link


def test_expectations_follow_the_variant() -> None:
    mapping = Mapping(names={"joint_0": "joint_2", "joint_2": "joint_0"}, signs={"joint_0": -1.0}, yaw_deg=90.0)
    expect = {"refuse": False, "joints": {"joint_0": {"final_range": [0.2, 1.0]}, "joint_2": {"final": 0.3, "tol": 0.1}},
              "any_of": [{"joint_0": {"peak": 0.5, "tol": 0.1}}], "optional": ["joint_2"], "order": ["joint_0", "joint_2@ret"],
              "hold": {"joint": "joint_0", "min_s": 1.0}, "base": {"translation": [1.0, 0.0, 0.0], "tol": 0.05}}
    out = transform_expect(expect, mapping)
    assert out["joints"] == {"joint_2": {"final_range": [-1.0, -0.2]}, "joint_0": {"final": 0.3, "tol": 0.1}}
    assert out["any_of"] == [{"joint_2": {"peak": -0.5, "tol": 0.1}}]
    assert out["optional"] == ["joint_0"] and out["order"] == ["joint_2", "joint_0@ret"] and out["hold"]["joint"] == "joint_2"
    assert out["base"]["translation"] == pytest.approx([0.0, 1.0, 0.0], abs=1e-9)
    assert expect["joints"]["joint_0"] == {"final_range": [0.2, 1.0]}  # the original is left as it was


def test_rows_naming_joints_are_not_carried_over_a_rename() -> None:
    row = {"prompt": "set joint_1 to 0.5", "expect": {"refuse": False}}
    assert not comparable(row, ("rename",)) and comparable(row, ("flip",))
    assert not comparable({"prompt": "x", "expect": {"order": ["FULL", "joint_0"]}}, ("flip",))


def test_main_reports_changed_outcomes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    source = tmp_path / "assets" / "pair"
    source.mkdir(parents=True)
    (source / "mobility.urdf").write_text(MIMIC_URDF)
    expect = tmp_path / "expect.jsonl"
    expect.write_text(json.dumps({"id": "p1", "asset": "pair", "asset_dir": "pair", "prompt": "open it", "type": "single",
                                  "expect": {"refuse": False, "joints": {"joint_0": {"final_range": [1.1, 1.3]}}}}) + "\n")
    outcomes = {"original": "right", "variant": "wrong_silent"}

    def judge(out: Path, rows: Path, assets: Path) -> dict[str, dict[str, object]]:
        assert (assets / "pair" / "mobility.urdf").is_file()
        return {"p1": {"prompt": "open it", "outcome": outcomes[out.name], "errors": [f"{out.name} error"]}}

    ran: list[Path] = []
    monkeypatch.setattr(metamorphic, "_judge", judge)
    assert metamorphic.main(["--expect", str(expect), "--assets", str(tmp_path / "assets"), "--out", str(tmp_path / "out")],
                            runner=lambda rows, out, assets: ran.append(rows)) == 0
    assert [p.name for p in ran] == ["original.jsonl", "expect.jsonl"]
    variant = json.loads((tmp_path / "out" / "expect.jsonl").read_text())
    assert variant["expect"]["joints"] == {"joint_2": {"final_range": [-1.3, -1.1]}}
    diff = json.loads((tmp_path / "out" / "diff.json").read_text())
    assert diff["changed"][0]["variant"] == "wrong_silent"
    assert "1 changed outcome (1 right -> wrong" in capsys.readouterr().out


def test_unknown_transform_is_an_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert metamorphic.main(["--expect", "x", "--assets", str(tmp_path), "--out", str(tmp_path / "o"), "--transforms", "mirrored"]) == 2
    assert "unknown transform" in capsys.readouterr().err


@pytest.mark.parametrize("transforms", [("ajar",), ("ajar", "flip", "rename")])
def test_ajar_rests_the_door_part_way_and_keeps_its_motion(tmp_path: Path, transforms: tuple[str, ...]) -> None:
    source = tmp_path / "pair"
    source.mkdir()
    (source / "mobility.urdf").write_text(MIMIC_URDF.replace('lower="0" upper="0.3"', 'lower="-0.3" upper="0"'))
    (source / "semantics.txt").write_text("link_0 hinge arm\nlink_1 hinge arm\nlink_2 slider drawer\n")
    mapping = make_variant(source, tmp_path / "variant", transforms)
    assert list(mapping.limits) == ["joint_2"] and mapping.limits["joint_2"] == (-0.3, 0.0)  # the drawer only; the arms are no door
    for value in (-0.3, -0.1, 0.0):
        before = _placed(source, {"joint_2": value})
        after = _placed(tmp_path / "variant", {mapping.name("joint_2"): mapping.value("joint_2", value)})
        for link, points in before.items():
            renamed = {"link_0": "link_2", "link_2": "link_0"}.get(link, link) if "rename" in transforms else link
            assert np.allclose(after[renamed], points, atol=1e-9), (value, link)
    at_rest = _placed(tmp_path / "variant", {})
    renamed = "link_0" if "rename" in transforms else "link_2"
    assert np.allclose(at_rest[renamed], _placed(source, {"joint_2": -0.09})["link_2"], atol=1e-9)  # rests 30% of the way
    row = {"expect": {"refuse": False, "joints": {"joint_2": {"final_range": [-0.31, -0.28]}}}}
    assert metamorphic.rests_elsewhere_alike(row, mapping)
    assert not metamorphic.rests_elsewhere_alike({"expect": {"refuse": False, "joints": {"joint_2": {"final": -0.15, "tol": 0.02}}}}, mapping)
    assert not metamorphic.rests_elsewhere_alike({"expect": {"refuse": False, "joints": {"joint_0": {"final": 1.2, "tol": 0.02}}}}, mapping)


def test_turns_of_the_whole_object_are_not_carried_over_a_move() -> None:
    row = {"prompt": "Rotate the bucket a quarter turn in place.", "expect": {"refuse": False, "base": {"translation": [0, 0, 0], "tol": 0.1}}}
    assert not comparable(row, ("move",)) and comparable(row, ("flip",))
    assert comparable({"prompt": "lift the toaster 10 cm", "expect": {"refuse": False, "base": {"translation": [0, 0, 0.1], "tol": 0.1}}}, ("move",))
