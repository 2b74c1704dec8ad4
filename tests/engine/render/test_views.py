"""Reference and overlay views: framing, colours, labels, legend, determinism."""

from __future__ import annotations

import gc
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from support.primitive_assets import box, joint, link, robot, write_asset

from app.engine.asset.kinematics import rest_poses
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.render import gl_backend
from app.engine.render.camera import ViewSpec, canonical_views, view_camera
from app.engine.render.palette import MAX_NAME_LABEL_CHARS, label_legend, link_colors, link_labels
from app.engine.render.views import render_overlay_views, render_reference_views

FRAMED_ASSETS = [
    "safe_101593",
    "microwave_7119",
    "door_8877",
    "kitchen_pot_100038",
    "washing_machine_103508",
    "toilet_102622",
    "laptop_10101",
]


@pytest.mark.parametrize("name", FRAMED_ASSETS)
def test_object_is_fully_inside_all_canonical_views(load_partnet: Callable[[str], ArticulatedAsset], name: str) -> None:
    asset = load_partnet(name)
    poses = rest_poses(asset)
    for view in canonical_views():
        camera = view_camera(asset, view, 240, 180, poses)
        ids, _ = gl_backend.render_link_ids(asset, poses, camera)
        border = np.concatenate([ids[0], ids[-1], ids[:, 0], ids[:, -1]])
        assert np.all(border == -1), (name, view)
        assert (ids >= 0).mean() > 0.03, (name, view)  # and not a speck either


def test_reference_views_show_the_object(load_partnet: Callable[[str], ArticulatedAsset]) -> None:
    safe = load_partnet("safe_101593")
    images = render_reference_views(safe, size=(320, 240))
    assert len(images) == 4 and all(im.size == (320, 240) and im.mode == "RGB" for im in images)
    for image, view in zip(images, canonical_views(), strict=True):
        pixels = np.asarray(image).astype(int)
        camera = view_camera(safe, view, 320, 240)
        ids, _ = gl_backend.render_link_ids(safe, rest_poses(safe), camera)
        object_px = pixels[ids >= 0]
        assert np.abs(object_px - 255).max(axis=1).mean() > 30  # the object is not the white background
        legend = pixels[10:80, 200:310]  # top-right corner holds the axis legend
        assert (np.abs(legend[..., 0] - 220) < 30).sum() + (np.abs(legend[..., 2] - 220) < 30).sum() > 20


def test_reference_views_are_deterministic_and_follow_the_view(load_partnet: Callable[[str], ArticulatedAsset]) -> None:
    pot = load_partnet("kitchen_pot_100038")
    first = render_reference_views(pot, views=[ViewSpec(30.0, 40.0, 50.0, 1.2)], size=(200, 160))
    second = render_reference_views(pot, views=[ViewSpec(30.0, 40.0, 50.0, 1.2)], size=(200, 160))
    assert first[0].tobytes() == second[0].tobytes()
    other = render_reference_views(pot, views=[ViewSpec(30.0, 40.0, 20.0, 1.2)], size=(200, 160))
    assert other[0].tobytes() != first[0].tobytes()  # the fov is really used


def test_overlay_colours_are_unique_and_drawn_per_link(load_partnet: Callable[[str], ArticulatedAsset]) -> None:
    safe = load_partnet("safe_101564")  # 14 links
    colors = link_colors(safe)
    assert sorted(colors) == sorted(safe.visual_links)
    assert len(set(colors.values())) == len(colors)
    assert all(max(c) - min(c) > 40 for c in colors.values())  # saturated, never background white/grey
    assert link_colors(safe) == colors  # deterministic
    points = gl_backend.render_points(
        safe, rest_poses(safe), view_camera(safe, canonical_views()[2], 400, 300), colors, count=3000
    )
    flat = points[..., :3].reshape(-1, 3)
    for name, color in colors.items():
        assert np.all(flat == color, axis=1).sum() > 0, name


def test_points_reveal_parts_hidden_in_the_mesh_render(load_partnet: Callable[[str], ArticulatedAsset]) -> None:
    safe = load_partnet("safe_101593")
    poses = rest_poses(safe)
    camera = view_camera(safe, canonical_views()[0], 400, 300)  # behind the safe: the door is hidden
    ids, names = gl_backend.render_link_ids(safe, poses, camera)
    door = names.index("link_0")
    assert not np.any(ids == door)
    colors = link_colors(safe)
    points = gl_backend.render_points(safe, poses, camera, colors, count=6000)
    assert np.all(points[..., :3] == colors["link_0"], axis=2).sum() > 100


def test_overlay_views_have_labels_boxes_and_are_deterministic(door_scene: ArticulatedAsset) -> None:
    first = render_overlay_views(door_scene, size=(400, 300))
    second = render_overlay_views(door_scene, size=(400, 300))
    assert [im.tobytes() for im in first] == [im.tobytes() for im in second]
    colors = link_colors(door_scene)
    pixels = np.asarray(first[0])
    for name, color in colors.items():
        assert np.all(pixels == color, axis=2).sum() > 50, name
    assert label_legend(door_scene) == {"body": "body", "core": "core", "door": "door"}


def test_long_link_names_get_index_labels(tmp_path: Path) -> None:
    long_name = "a_really_long_link_name"
    assert len(long_name) > MAX_NAME_LABEL_CHARS
    urdf = robot(
        link("base", box((1.0, 1.0, 1.0))),
        link(long_name, box((0.2, 0.2, 0.2))),
        joint("j", "fixed", "base", long_name, xyz=(0.0, 0.0, 0.7), axis=None),
    )
    asset = load_asset(write_asset(tmp_path / "long", urdf))
    assert link_labels(asset) == {long_name: "L0", "base": "L1"}
    assert label_legend(asset) == {"L0": long_name, "L1": "base"}
    assert len(render_overlay_views(asset, size=(200, 150))) == 4


def test_collected_assets_release_their_gpu_buffers(tmp_path: Path) -> None:
    asset = load_asset(write_asset(tmp_path / "tmp_box", robot(link("cube", box((1.0, 1.0, 1.0))))))
    camera = view_camera(asset, canonical_views()[0], 64, 64)
    gl_backend.render_link_ids(asset, rest_poses(asset), camera)
    resources = gl_backend._ASSETS.get(gl_backend.get_context(), {}, asset)
    del asset
    gc.collect()
    assert (
        resources.links and resources in gl_backend._ASSETS._dead
    )  # queued: freed at the next render, context current
    other = load_asset(write_asset(tmp_path / "tmp_box2", robot(link("cube", box((1.0, 1.0, 1.0))))))
    gl_backend.render_link_ids(other, rest_poses(other), camera)
    assert not resources.links and not gl_backend._ASSETS._dead
