"""Offscreen OpenGL rendering through EGL (Mesa llvmpipe on CPU-only machines).

One moderngl context per process, created lazily on first use. Every render call
holds one process-wide lock and makes the context current, so threads may share it.
Fork: a process that has rendered must not fork children that render — llvmpipe's
rasteriser threads are not inherited and the child would hang in its first read-back,
so such a child gets a :class:`RenderError` instead. Processes forked before the first
render (Celery prefork workers whose master never renders) are unaffected.

Outputs
-------
- :func:`render_rgba` — lit, textured colour image.
- :func:`render_points` — per-link point sprites in flat colours (overlays).
- :func:`render_id_depth` / :func:`render_link_ids` — the ID buffer: per pixel, the
  index of the nearest link (-1 for background) and its view depth.
- :func:`render_link_masks` — per-link **full silhouettes**: each link is drawn
  alone (no depth test against the others), so a link hidden behind another still
  has its whole projected shape. This makes a link's mask depend only on its own pose
  and the camera, which is what GT-vs-prediction 2D metrics compare. Visible-only
  masks are ``ids == index`` from :func:`render_link_ids`.

Poses are ``{link: (4, 4)}`` world transforms (link frame -> world, as returned by
:func:`app.engine.asset.kinematics.link_poses` for one frame; ``(1, 4, 4)`` is accepted).
Images are row 0 = top, matching :meth:`Camera.project` pixel coordinates.
"""

from __future__ import annotations

import logging
import os
import threading
from collections import OrderedDict
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.render import shaders
from app.engine.render.camera import Camera
from app.engine.render.gpu_assets import AssetCache, AssetResources, point_array
from app.engine.types import Transform

logger = logging.getLogger(__name__)

APT_PACKAGES = "libegl1 libegl-mesa0 libgl1-mesa-dri"
EXTRA_HINT = "pip install 'artimo[render]' (moderngl)"
AMBIENT = 0.35
DIFFUSE = 0.65
DEFAULT_SAMPLES = 4
HEADLIGHT_RAISE = 0.5
"""The light rides with the camera, raised by this fraction of the eye-target distance along the camera's up."""
BACK_FACE_OFFSET = (1.0, 8.0)
"""glPolygonOffset (factor, units) applied to back faces in the shaded pass."""
FRAMEBUFFER_CACHE_SIZE = 8
MAX_MASK_TILES_SIDE = 16384
Color = tuple[int, int, int]


@dataclass
class _GLState:
    ctx: Any
    programs: dict[str, Any]
    pid: int
    framebuffers: OrderedDict[tuple[Any, ...], Any]


_LOCK = threading.RLock()
_STATE: _GLState | None = None
_ASSETS = AssetCache()


def _after_fork_in_child() -> None:
    """A child must not wait on a lock some parent thread held at fork time; ``_STATE`` stays to be refused."""
    global _LOCK
    _LOCK = threading.RLock()


os.register_at_fork(after_in_child=_after_fork_in_child)


def _import_moderngl() -> Any:
    try:
        import moderngl
    except ImportError as exc:
        raise RenderError(f"offscreen rendering needs moderngl: {EXTRA_HINT}") from exc
    return moderngl


def _create_context() -> Any:
    """A standalone EGL context (GL 3.3 core or newer)."""
    moderngl = _import_moderngl()
    try:
        ctx = moderngl.create_context(standalone=True, backend="egl", require=330)
    except Exception as exc:  # glcontext raises bare Exception/ImportError/OSError types
        raise RenderError(
            f"cannot create an EGL OpenGL context ({type(exc).__name__}: {exc}); "
            f"install the Mesa EGL packages: apt-get install {APT_PACKAGES}"
        ) from exc
    logger.info("EGL context: %s / %s", ctx.info.get("GL_RENDERER"), ctx.info.get("GL_VERSION"))
    return ctx


def _state() -> _GLState:
    """The process's GL state, created on first use (callers hold ``_LOCK``)."""
    global _STATE
    if _STATE is not None and _STATE.pid != os.getpid():
        raise RenderError(
            f"the EGL renderer was initialised in process {_STATE.pid} before it forked; Mesa llvmpipe's "
            "rasteriser threads do not survive fork() and rendering here would hang. Render only in "
            "processes that have not inherited a renderer (e.g. Celery worker children, not the master) "
            "or start workers with the 'spawn' method"
        )
    if _STATE is None:
        ctx = _create_context()
        with ctx:
            programs = {
                "shaded": ctx.program(vertex_shader=shaders.SHADED_VERTEX, fragment_shader=shaders.SHADED_FRAGMENT),
                "flat": ctx.program(vertex_shader=shaders.FLAT_VERTEX, fragment_shader=shaders.FLAT_FRAGMENT),
                "points": ctx.program(vertex_shader=shaders.POINTS_VERTEX, fragment_shader=shaders.POINTS_FRAGMENT),
            }
        _STATE = _GLState(ctx=ctx, programs=programs, pid=os.getpid(), framebuffers=OrderedDict())
    return _STATE


def get_context() -> Any:
    """The process's moderngl context (created on first call).

    Raises
    ------
    RenderError
        moderngl is not installed, or EGL/Mesa is missing.
    """
    with _LOCK:
        return _state().ctx


def release_asset(asset: ArticulatedAsset) -> None:
    """Free the GPU buffers of ``asset`` now (they are otherwise freed after it is collected)."""
    with _LOCK:
        found = _ASSETS.pop(asset)
        if found is not None and _STATE is not None:
            with _STATE.ctx:
                found.release()


def _framebuffer(state: _GLState, kind: str, size: tuple[int, int], samples: int) -> Any:
    """A cached framebuffer: ``rgba`` (RGBA8 + depth), ``id`` (RG32F + depth) or ``mask`` (R8)."""
    key = (kind, size, samples)
    if key in state.framebuffers:
        state.framebuffers.move_to_end(key)
        return state.framebuffers[key]
    ctx = state.ctx
    if kind == "rgba":
        fbo = ctx.framebuffer(ctx.renderbuffer(size, 4, samples=samples), ctx.depth_renderbuffer(size, samples=samples))
    elif kind == "id":
        fbo = ctx.framebuffer(ctx.renderbuffer(size, 2, dtype="f4"), ctx.depth_renderbuffer(size))
    else:
        fbo = ctx.framebuffer(ctx.renderbuffer(size, 1))
    state.framebuffers[key] = fbo
    while len(state.framebuffers) > FRAMEBUFFER_CACHE_SIZE:
        _, old = state.framebuffers.popitem(last=False)
        for attachment in (*old.color_attachments, old.depth_attachment):
            if attachment is not None:
                attachment.release()
        old.release()
    return fbo


def _matrix_bytes(matrix: NDArray[np.float64]) -> bytes:
    """Column-major float32 bytes of a (4, 4) matrix, as GLSL ``mat4`` expects."""
    return np.asarray(matrix, dtype=np.float64).T.astype(np.float32).tobytes()


def _pose(poses: Mapping[str, Transform], link: str) -> NDArray[np.float64]:
    if link not in poses:
        raise RenderError(f"no pose given for link '{link}'")
    pose = np.asarray(poses[link], dtype=np.float64)
    if pose.shape == (1, 4, 4):
        pose = pose[0]
    if pose.shape != (4, 4) or not np.all(np.isfinite(pose)):
        raise RenderError(f"pose of link '{link}' must be a finite (4, 4) matrix, got shape {pose.shape}")
    return pose


def _read(fbo: Any, size: tuple[int, int], components: int, dtype: str) -> NDArray[Any]:
    """Read an attachment as (H, W, components), row 0 = top."""
    raw = fbo.read(components=components, dtype=dtype, alignment=1)
    numpy_dtype = np.uint8 if dtype == "f1" else np.float32
    return np.frombuffer(raw, dtype=numpy_dtype).reshape(size[1], size[0], components)[::-1].copy()


@contextmanager
def _session(asset: ArticulatedAsset) -> Iterator[tuple[_GLState, AssetResources]]:
    """Hold the lock, make the context current, free dead objects, yield the asset's buffers."""
    with _LOCK:
        state = _state()
        with state.ctx:
            _ASSETS.collect()
            yield state, _ASSETS.get(state.ctx, state.programs, asset)


def render_rgba(
    asset: ArticulatedAsset,
    poses: Mapping[str, Transform],
    camera: Camera,
    *,
    background: Color = (255, 255, 255),
    samples: int = DEFAULT_SAMPLES,
) -> NDArray[np.uint8]:
    """(H, W, 4) uint8 shaded render; alpha is coverage (0 on the background).

    Lighting: ambient :data:`AMBIENT` plus a headlight at the eye (:data:`DIFFUSE`);
    textures from ``MeshPart.material.image_png`` and ``uv``, base colour otherwise.
    ``samples`` > 0 enables MSAA with that many samples (clamped to the GL maximum).
    """
    size = (camera.width, camera.height)
    with _session(asset) as (state, resources):
        ctx = state.ctx
        samples = int(min(max(samples, 0), ctx.max_samples))
        fbo = _framebuffer(state, "rgba", size, samples)
        fbo.use()
        fbo.clear(*(c / 255.0 for c in background), 0.0, depth=1.0)
        ctx.enable_only(ctx.DEPTH_TEST)
        program = state.programs["shaded"]
        program["u_view_projection"].write(_matrix_bytes(camera.view_projection()))
        _, camera_up, _ = camera.basis()
        light = camera.eye + camera_up * HEADLIGHT_RAISE * float(np.linalg.norm(camera.eye - camera.target))
        program["u_light"].value = tuple(float(v) for v in light)
        program["u_ambient"].value = AMBIENT
        program["u_diffuse"].value = DIFFUSE
        program["u_atlas"].value = 0
        resources.atlas.use(location=0)
        # pass 1: front faces; pass 2: back faces pushed slightly back, so where a
        # mesh holds both sides of a panel (coincident faces, opposite winding, often
        # different materials, as in PartNet) the front face wins instead of z-fighting,
        # while a surface that only exists seen from behind is still drawn.
        for cull, offset in (("back", (0.0, 0.0)), ("front", BACK_FACE_OFFSET)):
            ctx.enable(ctx.CULL_FACE)
            ctx.cull_face = cull
            ctx.polygon_offset = offset
            for link, mesh in resources.links.items():
                program["u_model"].write(_matrix_bytes(_pose(poses, link)))
                mesh.vao_shaded.render(ctx.TRIANGLES)
        ctx.polygon_offset = (0.0, 0.0)
        ctx.disable(ctx.CULL_FACE)
        if samples > 0:
            resolved = _framebuffer(state, "rgba", size, 0)
            ctx.copy_framebuffer(resolved, fbo)
            fbo = resolved
        return _read(fbo, size, 4, "f1")


def render_points(
    asset: ArticulatedAsset,
    poses: Mapping[str, Transform],
    camera: Camera,
    colors: Mapping[str, Color],
    *,
    count: int,
    point_size: float = 2.0,
    background: Color = (255, 255, 255),
) -> NDArray[np.uint8]:
    """(H, W, 4) uint8: ``count`` seeded surface points per link in ``colors`` (links not in it are skipped).

    Points are depth-tested square sprites of ``point_size`` pixels, unlit, no MSAA.
    """
    size = (camera.width, camera.height)
    with _session(asset) as (state, resources):
        ctx = state.ctx
        fbo = _framebuffer(state, "rgba", size, 0)
        fbo.use()
        fbo.clear(*(c / 255.0 for c in background), 0.0, depth=1.0)
        ctx.enable_only(ctx.DEPTH_TEST | ctx.PROGRAM_POINT_SIZE)
        program = state.programs["points"]
        program["u_view_projection"].write(_matrix_bytes(camera.view_projection()))
        program["u_point_size"].value = float(point_size)
        for link in sorted(colors):
            vao = point_array(ctx, state.programs, resources, asset, link, count)
            program["u_model"].write(_matrix_bytes(_pose(poses, link)))
            program["u_color"].value = tuple(c / 255.0 for c in colors[link])
            vao.render(ctx.POINTS)
        return _read(fbo, size, 4, "f1")


def render_id_depth(
    asset: ArticulatedAsset, poses: Mapping[str, Transform], camera: Camera
) -> tuple[NDArray[np.int32], NDArray[np.float32], tuple[str, ...]]:
    """The ID buffer and depth buffer.

    Returns
    -------
    ids : (H, W) int32, index into ``link_names`` of the nearest surface, -1 for background
    depth : (H, W) float32, metres along the viewing direction, ``inf`` on the background
    link_names : the asset's visual links in ``asset.visual_links`` order
    """
    size = (camera.width, camera.height)
    names = tuple(asset.visual_links)
    with _session(asset) as (state, resources):
        ctx = state.ctx
        fbo = _framebuffer(state, "id", size, 0)
        fbo.use()
        fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        ctx.enable_only(ctx.DEPTH_TEST)
        program = state.programs["flat"]
        program["u_view_projection"].write(_matrix_bytes(camera.view_projection()))
        for index, link in enumerate(names):
            program["u_model"].write(_matrix_bytes(_pose(poses, link)))
            program["u_value"].value = float(index + 1)
            resources.links[link].vao_flat.render(ctx.TRIANGLES)
        raw = _read(fbo, size, 2, "f4")
    ids = np.rint(raw[..., 0]).astype(np.int32) - 1
    depth = np.where(ids >= 0, raw[..., 1], np.inf).astype(np.float32)
    return ids, depth, names


def render_link_ids(
    asset: ArticulatedAsset, poses: Mapping[str, Transform], camera: Camera
) -> tuple[NDArray[np.int32], tuple[str, ...]]:
    """(ids (H, W) int32 with -1 for background, link_names): see :func:`render_id_depth`."""
    ids, _, names = render_id_depth(asset, poses, camera)
    return ids, names


def _mask_grid(count: int, size: tuple[int, int]) -> tuple[int, int]:
    columns = max(1, min(count, MAX_MASK_TILES_SIDE // size[0]))
    rows = -(-count // columns)
    if rows * size[1] > MAX_MASK_TILES_SIDE:
        raise RenderError(f"{count} masks of {size[0]}x{size[1]} do not fit one {MAX_MASK_TILES_SIDE}-pixel target")
    return columns, rows


def render_link_masks(
    asset: ArticulatedAsset, poses: Mapping[str, Transform], camera: Camera, links: Iterable[str] | None = None
) -> dict[str, NDArray[np.bool_]]:
    """{link: (H, W) bool full silhouette} for ``links`` (default: every visual link).

    Each link is rasterised alone into its own tile of one target (one draw per link,
    one read-back), without MSAA: a pixel belongs to the mask when its centre is
    covered. Links without geometry get an all-false mask.

    Raises
    ------
    RenderError
        Unknown link name, missing pose, or no EGL/moderngl.
    """
    wanted = tuple(asset.visual_links if links is None else links)
    for link in wanted:
        if link not in asset.links:
            raise RenderError(f"unknown link '{link}'")
    drawn = [link for link in wanted if asset.links[link].has_geometry]
    width, height = camera.width, camera.height
    masks = {link: np.zeros((height, width), dtype=bool) for link in wanted}
    if not drawn:
        return masks
    columns, rows = _mask_grid(len(drawn), (width, height))
    target = (columns * width, rows * height)
    with _session(asset) as (state, resources):
        ctx = state.ctx
        fbo = _framebuffer(state, "mask", target, 0)
        fbo.use()
        fbo.clear(0.0, 0.0, 0.0, 0.0)
        ctx.enable_only(ctx.NOTHING)
        program = state.programs["flat"]
        program["u_view_projection"].write(_matrix_bytes(camera.view_projection()))
        program["u_value"].value = 1.0
        for index, link in enumerate(drawn):
            column, row = index % columns, index // columns
            ctx.viewport = (column * width, (rows - 1 - row) * height, width, height)
            program["u_model"].write(_matrix_bytes(_pose(poses, link)))
            resources.links[link].vao_flat.render(ctx.TRIANGLES)
        fbo.viewport = (0, 0, *target)
        pixels = _read(fbo, target, 1, "f1")[..., 0]
    for index, link in enumerate(drawn):
        column, row = index % columns, index // columns
        masks[link] = pixels[row * height : (row + 1) * height, column * width : (column + 1) * width] > 127
    return masks
