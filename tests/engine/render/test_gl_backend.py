"""EGL renders: ID buffer, per-link masks, textures, determinism and error reporting."""

from __future__ import annotations

import hashlib
import io
import multiprocessing
import multiprocessing.queues
import os
import subprocess
import sys
import textwrap
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from support.primitive_assets import box, link, robot, write_asset

from app.engine.asset.kinematics import link_poses, rest_poses
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.render import gl_backend
from app.engine.render.camera import Camera, canonical_views, view_camera

REPO = Path(__file__).resolve().parents[3]


def _front_camera(distance: float, size: int = 256, fov: float = 35.0) -> Camera:
    return Camera(
        eye=np.array([distance, 0.0, 0.0]), target=np.zeros(3), fov_deg=fov, width=size, height=size, near=0.1, far=10.0
    )


def test_box_mask_area_matches_projection(unit_box: ArticulatedAsset) -> None:
    camera = _front_camera(4.0)
    masks = gl_backend.render_link_masks(unit_box, rest_poses(unit_box), camera)
    # seen head-on, the cube's silhouette is its front face (x = 0.5), 1 m wide at depth 3.5 m
    side_px = camera.focal_px * 1.0 / 3.5
    assert masks["cube"].sum() == pytest.approx(side_px**2, rel=0.03)
    ids, names = gl_backend.render_link_ids(unit_box, rest_poses(unit_box), camera)
    assert names == ("cube",)
    assert np.array_equal(ids >= 0, masks["cube"])
    assert set(np.unique(ids)) == {-1, 0}


def test_rendered_pixels_land_where_camera_projects(tmp_path: Path) -> None:
    urdf = robot(link("marker", box((0.1, 0.1, 0.1), xyz=(0.0, 0.6, 0.4))), name="marker")
    asset = load_asset(write_asset(tmp_path / "marker", urdf))
    camera = Camera(
        eye=np.array([4.0, 0.0, 0.0]), target=np.zeros(3), fov_deg=35.0, width=320, height=240, near=0.1, far=10.0
    )
    mask = gl_backend.render_link_masks(asset, rest_poses(asset), camera)["marker"]
    rows, cols = np.nonzero(mask)
    centroid = np.array([cols.mean() + 0.5, rows.mean() + 0.5])  # pixel centres
    expected, _ = camera.project(np.array([[0.05, 0.6, 0.4]]))  # centre of the front face
    np.testing.assert_allclose(centroid, expected[0], atol=0.5)
    assert expected[0][0] > 160 and expected[0][1] < 120  # +Y is right, +Z is up


def test_door_mask_changes_when_opened_and_others_do_not(door_scene: ArticulatedAsset) -> None:
    camera = view_camera(door_scene, canonical_views()[0], 256, 256)
    closed = gl_backend.render_link_masks(door_scene, rest_poses(door_scene), camera)
    opened_poses = {k: v[0] for k, v in link_poses(door_scene, {"hinge": np.array([1.2])}).items()}
    opened = gl_backend.render_link_masks(door_scene, opened_poses, camera)
    iou = (closed["door"] & opened["door"]).sum() / (closed["door"] | opened["door"]).sum()
    assert iou < 0.6
    assert np.array_equal(closed["body"], opened["body"])
    assert np.array_equal(closed["core"], opened["core"])


def test_masks_are_full_silhouettes_while_ids_are_visible_surfaces(door_scene: ArticulatedAsset) -> None:
    poses = rest_poses(door_scene)
    camera = view_camera(door_scene, canonical_views()[0], 200, 200)
    masks = gl_backend.render_link_masks(door_scene, poses, camera)
    ids, names = gl_backend.render_link_ids(door_scene, poses, camera)
    core = names.index("core")
    assert masks["core"].sum() > 100  # hidden inside the body, but its silhouette is there
    assert not np.any(ids == core)
    assert np.all(masks["body"][ids == names.index("body")])
    subset = gl_backend.render_link_masks(door_scene, poses, camera, links=["door"])
    assert list(subset) == ["door"] and np.array_equal(subset["door"], masks["door"])
    with pytest.raises(RenderError):
        gl_backend.render_link_masks(door_scene, poses, camera, links=["nope"])


def test_depth_buffer_is_view_depth(unit_box: ArticulatedAsset) -> None:
    camera = _front_camera(4.0, size=64)
    ids, depth, _ = gl_backend.render_id_depth(unit_box, rest_poses(unit_box), camera)
    assert depth[32, 32] == pytest.approx(3.5, abs=1e-3)
    assert np.all(np.isinf(depth[ids < 0]))


def test_missing_pose_raises(door_scene: ArticulatedAsset) -> None:
    poses = rest_poses(door_scene)
    del poses["door"]
    with pytest.raises(RenderError, match="door"):
        gl_backend.render_rgba(door_scene, poses, view_camera(door_scene, canonical_views()[0], 64, 64))


def _checker_png() -> bytes:
    image = Image.new("RGB", (2, 2))
    image.putdata([(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)])  # top: red green; bottom: blue white
    buffer = io.BytesIO()
    image.save(buffer, format="PNG")
    return buffer.getvalue()


QUAD_OBJ = """mtllib quad.mtl
v 0 -0.5 -0.5
v 0 0.5 -0.5
v 0 0.5 0.5
v 0 -0.5 0.5
vt 0 0
vt 2 0
vt 2 2
vt 0 2
usemtl checker
f 1/1 2/2 3/3
f 1/1 3/3 4/4
"""


def test_texture_repeat_through_the_atlas(tmp_path: Path) -> None:
    files = {
        "quad.obj": QUAD_OBJ,
        "quad.mtl": "newmtl checker\nKd 1 1 1\nmap_Kd checker.png\n",
        "checker.png": _checker_png(),
    }
    urdf = robot(link("panel", '<visual><geometry><mesh filename="quad.obj"/></geometry></visual>'), name="quad")
    asset = load_asset(write_asset(tmp_path / "quad", urdf, files))
    camera = _front_camera(3.0)
    rgb = gl_backend.render_rgba(asset, rest_poses(asset), camera, samples=0)[..., :3].astype(int)
    side = camera.focal_px / 3.0
    expected_rows = {0: ("blue", "white"), 1: ("red", "green")}  # uv (0..2) repeats the 2x2 image twice
    for row in range(4):
        for col in range(4):
            x = round(128 + (-0.5 + (col + 0.5) / 4) * side)
            y = round(128 - (-0.5 + (row + 0.5) / 4) * side)
            r, g, b = rgb[y, x]
            name = expected_rows[row % 2][col % 2]
            colour = {"red": r > 150 > g and b < 60, "green": g > 150 > r and b < 60, "blue": b > 150 > r and g < 60}
            colour["white"] = min(r, g, b) > 180
            assert colour[name], (row, col, name, (r, g, b))


def test_textured_partnet_asset_uses_its_texture(load_partnet: Callable[[str], ArticulatedAsset]) -> None:
    door = load_partnet("door_8877")  # wood texture
    camera = view_camera(door, canonical_views()[0], 200, 150)
    rgba = gl_backend.render_rgba(door, rest_poses(door), camera)
    object_pixels = rgba[rgba[..., 3] == 255][:, :3].astype(float)
    r, _, b = object_pixels.mean(axis=0)
    assert r > b + 40  # brown wood, not the grey base colour
    assert object_pixels.std(axis=0).max() > 10  # textured, not flat


def test_renders_are_deterministic(load_partnet: Callable[[str], ArticulatedAsset]) -> None:
    pot = load_partnet("kitchen_pot_100038")
    camera = view_camera(pot, canonical_views()[1], 320, 240)
    first = gl_backend.render_rgba(pot, rest_poses(pot), camera)
    second = gl_backend.render_rgba(pot, rest_poses(pot), camera)
    assert first.tobytes() == second.tobytes()
    ids_a, depth_a, _ = gl_backend.render_id_depth(pot, rest_poses(pot), camera)
    ids_b, depth_b, _ = gl_backend.render_id_depth(pot, rest_poses(pot), camera)
    assert ids_a.tobytes() == ids_b.tobytes() and depth_a.tobytes() == depth_b.tobytes()


def test_renders_are_identical_across_processes(load_partnet: Callable[[str], ArticulatedAsset], partnet: Path) -> None:
    code = textwrap.dedent(
        f"""
        import hashlib, sys
        from app.engine.asset.kinematics import rest_poses
        from app.engine.asset.loader import load_asset
        from app.engine.render import gl_backend
        from app.engine.render.camera import canonical_views, view_camera
        asset = load_asset({str(partnet / "safe_101593")!r})
        camera = view_camera(asset, canonical_views()[2], 320, 240)
        sys.stdout.write(hashlib.sha256(gl_backend.render_rgba(asset, rest_poses(asset), camera).tobytes()).hexdigest())
        """
    )
    env = {**os.environ, "LP_NUM_THREADS": "1"}  # another rasteriser thread count must not change pixels
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=REPO, env=env, timeout=120
    )
    safe = load_partnet("safe_101593")
    camera = view_camera(safe, canonical_views()[2], 320, 240)
    local = hashlib.sha256(gl_backend.render_rgba(safe, rest_poses(safe), camera).tobytes()).hexdigest()
    assert out.stdout.strip() == local


def test_missing_moderngl_names_the_extra() -> None:
    code = textwrap.dedent(
        """
        import sys
        sys.modules["moderngl"] = None
        from app.engine.errors import RenderError
        from app.engine.render import gl_backend
        try:
            gl_backend.get_context()
        except RenderError as exc:
            sys.stdout.write(str(exc))
        """
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=REPO, timeout=60)
    assert "artimo[render]" in out.stdout and "moderngl" in out.stdout


def test_missing_egl_names_the_apt_packages(monkeypatch: pytest.MonkeyPatch) -> None:
    import moderngl

    def broken(**_: object) -> None:
        raise ImportError("libEGL.so.1: cannot open shared object file")

    monkeypatch.setattr(moderngl, "create_context", broken)
    with pytest.raises(RenderError) as caught:
        gl_backend._create_context()
    assert "libegl1 libegl-mesa0 libgl1-mesa-dri" in str(caught.value)


def test_importing_the_render_package_does_not_import_moderngl() -> None:
    code = "import sys, app.engine.render.views, app.engine.render.cues, app.engine.render; sys.stdout.write(str('moderngl' in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=REPO, timeout=60)
    assert out.stdout == "False"


def test_threads_share_the_context_safely(door_scene: ArticulatedAsset) -> None:
    camera = view_camera(door_scene, canonical_views()[0], 128, 128)
    angles = [0.0, 0.4, 0.8, 1.2]
    poses = [{k: v[0] for k, v in link_poses(door_scene, {"hinge": np.array([a])}).items()} for a in angles]
    serial = [gl_backend.render_link_masks(door_scene, p, camera)["door"] for p in poses]
    with ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(lambda p: gl_backend.render_link_masks(door_scene, p, camera)["door"], poses * 3))
    for index, mask in enumerate(parallel):
        assert np.array_equal(mask, serial[index % len(angles)])


def _render_in_child(asset: ArticulatedAsset, camera: Camera, queue: multiprocessing.queues.Queue) -> None:  # type: ignore[type-arg]
    try:
        gl_backend.render_link_ids(asset, rest_poses(asset), camera)
        queue.put("rendered")
    except RenderError as exc:
        queue.put(str(exc))


def test_a_forked_child_of_a_rendering_process_refuses_instead_of_hanging(unit_box: ArticulatedAsset) -> None:
    camera = _front_camera(4.0, size=32)
    gl_backend.render_link_ids(unit_box, rest_poses(unit_box), camera)  # the parent has rendered
    context = multiprocessing.get_context("fork")
    queue = context.Queue()
    child = context.Process(target=_render_in_child, args=(unit_box, camera, queue))
    child.start()
    child.join(60)
    assert child.exitcode == 0
    assert "fork" in queue.get(timeout=5)
