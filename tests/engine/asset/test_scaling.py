"""Work that grows with the asset's size, not with its square: counted calls, never timed (benchmark/speed_scaling.py times it)."""

from __future__ import annotations

import gc
import itertools
import weakref
from pathlib import Path

import numpy as np
import pytest
from support.primitive_assets import box, cabinet_urdf, joint, link, robot, write_asset

from app.engine.asset import kinematics
from app.engine.asset.kinematics import link_poses, resolve_joint_values
from app.engine.asset.layout import asset_layout
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset


def chain(tmp_path: Path, count: int) -> ArticulatedAsset:
    """``count`` revolute joints in a row, every third one a mimic of the joint before it, and a side branch."""
    links = [link(f"l{i}", box((0.02, 0.02, 0.1), xyz=(0.0, 0.0, 0.05))) for i in range(count + 2)]
    joints = [joint(f"j{i}", "revolute", f"l{i}", f"l{i + 1}", xyz=(0.0, 0.0, 0.1), axis=(1.0, 0.0, 0.0), limit=(-0.5, 0.5),
                    mimic=(f"j{i - 1}", -0.5, 0.1) if i % 3 == 2 else None) for i in range(count)]
    joints.append(joint("side", "prismatic", "l1", f"l{count + 1}", xyz=(0.1, 0.0, 0.0), axis=(0.0, 1.0, 0.0), limit=(0.0, 0.2)))
    return load_asset(write_asset(tmp_path / f"chain{count}", robot(*links, *joints, name=f"chain{count}")))


@pytest.fixture
def motions(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The joints whose motion was computed (every call of ``joint_motion`` by ``link_poses``)."""
    called: list[str] = []
    original = kinematics.joint_motion

    def counted(spec, q):  # type: ignore[no-untyped-def]
        called.append(spec.name)
        return original(spec, q)

    monkeypatch.setattr(kinematics, "joint_motion", counted)
    return called


def branches(tmp_path: Path) -> ArticulatedAsset:
    """Two branches whose joints are declared interleaved: ``link_order`` is not the depth-first order."""
    links = [link(n, box((0.05, 0.05, 0.05))) for n in ("base", "a", "b", "a2", "b2")]
    joints = [joint(f"j_{child}", "revolute", parent, child, xyz=(0.1, 0.0, 0.0), axis=(0.0, 0.0, 1.0), limit=(0.0, 1.0))
              for parent, child in (("base", "a"), ("base", "b"), ("a", "a2"), ("b", "b2"))]
    return load_asset(write_asset(tmp_path / "branches", robot(*links, *joints, name="branches")))


def _assets(tmp_path: Path) -> list[ArticulatedAsset]:
    return [chain(tmp_path, 9), load_asset(write_asset(tmp_path / "cabinet", cabinet_urdf(flap_offset=0.2))), branches(tmp_path)]


def test_poses_with_some_joints_given_equal_poses_with_every_joint_given(tmp_path: Path) -> None:
    """Joints not given sit at rest and mimics follow their leaders, bit for bit as when every value is spelt out."""
    rng = np.random.default_rng(3)
    for asset in _assets(tmp_path):
        movable = asset.movable_joints
        for size in (0, 1, 2):
            for given in itertools.combinations(movable, size):
                values = {name: rng.uniform(-0.4, 0.4, 3) for name in given}
                everything = resolve_joint_values(asset, values, 3)
                partial, full = link_poses(asset, values, frames=3), link_poses(asset, everything, frames=3)
                assert partial.keys() == full.keys()
                for name in full:
                    assert partial[name].shape == (3, 4, 4) and np.array_equal(partial[name], full[name]), (asset.name, given, name)


def test_one_joint_driven_computes_the_motion_of_that_joint_and_its_mimics(tmp_path: Path, motions: list[str]) -> None:
    """Before: the motion of every movable joint of the asset, on every call."""
    asset = chain(tmp_path, 30)
    link_poses(asset, {}, frames=1)
    motions.clear()
    link_poses(asset, {"j10": np.array([0.1, 0.2])})
    assert motions == ["j10", "j11"]  # j11 mimics j10
    link_poses(asset, {"side": np.array([0.1])})
    assert motions[2:] == ["side"]


def test_the_rest_transforms_kept_per_asset_do_not_keep_it_alive(tmp_path: Path) -> None:
    """A collected asset frees its GPU buffers (tests/engine/render): nothing kept for the kinematics holds it."""
    asset = chain(tmp_path, 3)
    link_poses(asset, {"j0": np.array([0.2])})
    alive = weakref.ref(asset)
    del asset
    gc.collect()
    assert alive() is None


def test_the_layout_computes_a_bounded_number_of_motions_per_joint(tmp_path: Path, motions: list[str]) -> None:
    """``artimo inspect`` / the asset summary route: before, every joint's reading posed the whole chain
    (joint motions grew with the square of the joint count: 420 for 20 joints, 1640 for 40)."""
    counts = {}
    for size in (20, 40):
        motions.clear()
        asset_layout(chain(tmp_path, size))
        counts[size] = len(motions)
    assert counts[40] <= 2 * counts[20] + 4, counts
    assert counts[40] <= 3 * 41, counts


def _descendants_by_scan(asset: ArticulatedAsset, start: str) -> tuple[str, ...]:
    found = {start}
    for name in asset.joint_order:
        if asset.joints[name].parent in found:
            found.add(asset.joints[name].child)
    return tuple(n for n in asset.link_order if n in found)


def test_tree_lookups_agree_with_a_scan_of_the_joints(tmp_path: Path) -> None:
    """Both ways ``descendants`` answers: a bare slice of the depth-first order where that slice is in ``link_order``,
    a sorted slice where it is not (the interleaved branches' root)."""
    assets = _assets(tmp_path)
    bare = {asset.depth_first[2][span[1] - 1] == asset.depth_first[2][span[0]] for asset in assets for span in asset.depth_first[1].values()}
    assert bare == {True, False}
    for asset in assets:
        for name in asset.link_order:
            below = asset.descendants(name)
            assert below == _descendants_by_scan(asset, name)
            assert all(n in below for n in below) and "no such link" not in below and [] not in below  # type: ignore[comparison-overlap]
            assert asset.child_joints(name) == tuple(asset.joints[j] for j in asset.joint_order if asset.joints[j].parent == name)
            parent = asset.parent_joint(name)
            assert parent is None if name == asset.root_link else parent is not None and parent.child == name
        for name in asset.joint_order:
            assert asset.moving_links(name) == _descendants_by_scan(asset, asset.joints[name].child)


def test_rest_points_slices_are_the_subtrees_and_their_complements(tmp_path: Path) -> None:
    """The depth-first layout the per-joint geometry reads: a joint's moved points are its subtree's, and its static
    box is the box of every other link (checked against a direct walk, on a chain with mimics and a side branch, and a
    cabinet)."""
    from app.engine.offline.geometry import _local_points, _posed
    from app.engine.offline.rest_points import RestPoints

    for asset in _assets(tmp_path):
        points = _local_points(asset)
        rest = link_poses(asset, {}, frames=1)
        world = {n: _posed(points, rest, [n]) for n in asset.visual_links if n in points}
        laid_out = RestPoints.of(asset, world)
        for name in asset.joint_order:
            child = asset.joints[name].child
            below = asset.descendants(child)
            expected = np.concatenate([world[n] for n in below if n in world] or [np.zeros((0, 3))])
            got = laid_out.below(child)
            assert sorted(map(tuple, got)) == sorted(map(tuple, expected))
            others = [world[n] for n in world if n not in below]
            box = laid_out.box_without(child)
            if not others:
                assert box is None
                continue
            assert box is not None
            stacked = np.concatenate(others)
            np.testing.assert_array_equal(box[0], stacked.min(axis=0))
            np.testing.assert_array_equal(box[1], stacked.max(axis=0))


def test_a_joint_moving_more_points_than_the_cap_is_judged_on_a_stride_of_them(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each joint's geometry reads at most ``MAX_MOVED_POINTS`` points (a chain's first joints move all the others, which
    made the layout grow with the square of the chain); below the cap every point is read."""
    from app.engine.offline import geometry

    seen: list[int] = []
    original = geometry._closedness

    def counted(moving, low, high):  # type: ignore[no-untyped-def]
        seen.append(moving.shape[0])
        return original(moving, low, high)

    monkeypatch.setattr(geometry, "_closedness", counted)
    asset = chain(tmp_path, 12)
    geometry.analyse(asset)
    assert max(seen) > 20
    monkeypatch.setattr(geometry, "MAX_MOVED_POINTS", 20)
    seen.clear()
    capped = geometry.analyse(chain(tmp_path / "again", 12))
    assert seen and max(seen) <= 20
    assert set(capped.joints) == set(geometry.analyse(asset).joints)
