"""An animated GIF preview of a trajectory: one fixed camera that frames every state.

The camera is a three-quarter orbit view (elevation :data:`PREVIEW_ELEVATION_DEG`) on the side
where the moving parts are (their mean offset from the object's centre), so the drawer, door
or lid that moves faces the viewer whichever way the asset is authored. Frames are evenly
spaced over the whole trajectory (at most ``max_frames``), each shown for the time it stands
for; the last frame is held a little longer before the loop restarts.
"""

from __future__ import annotations

import io
import itertools
import math

import numpy as np
from PIL import Image

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.execute.trajectory import Trajectory
from app.engine.render import gl_backend
from app.engine.render.camera import DEFAULT_FOV_DEG, ViewSpec, asset_bounds, view_camera
from app.engine.render.cues import window_poses
from app.engine.types import Transforms

PREVIEW_SIZE = (480, 360)
MAX_PREVIEW_FRAMES = 60
PREVIEW_ELEVATION_DEG = 25.0
THREE_QUARTER_AZIMUTHS_DEG = (45.0, 135.0, 225.0, 315.0)
FINAL_HOLD_MS = 800
MIN_FRAME_MS = 20
"""GIF viewers treat shorter frame delays as 'as fast as possible'; never go below."""
MOVED_M = 1e-6


def preview_frames(frame_count: int, max_frames: int) -> np.ndarray:
    """Indices of the frames shown: evenly spaced, first and last always included."""
    if frame_count < 1:
        raise RenderError("the trajectory has no frames")
    count = max(1, min(frame_count, max_frames))
    return np.unique(np.rint(np.linspace(0, frame_count - 1, count)).astype(int))


def _centroids(asset: ArticulatedAsset, poses: dict[str, Transforms]) -> dict[str, np.ndarray]:
    """{link: (k, 3)} world centroid of each visual link's vertices at every shown frame."""
    out = {}
    for name in asset.visual_links:
        local = asset.links[name].vertices().mean(axis=0)
        stack = np.asarray(poses[name], dtype=np.float64)
        out[name] = np.einsum("tij,j->ti", stack[:, :3, :3], local) + stack[:, :3, 3]
    return out


def preview_view(asset: ArticulatedAsset, poses: dict[str, Transforms]) -> ViewSpec:
    """The three-quarter view facing the moving parts (the first candidate when nothing moves)."""
    centroids = _centroids(asset, poses)
    center, _ = asset_bounds(asset, {name: np.asarray(p)[0] for name, p in poses.items()})
    moving = [c for c in centroids.values() if float(np.ptp(c, axis=0).max()) > MOVED_M]
    offset = np.zeros(2)
    for track in moving:
        offset += (track[0] - center)[:2]
    best = THREE_QUARTER_AZIMUTHS_DEG[0]
    if float(np.linalg.norm(offset)) > MOVED_M:
        def facing(azimuth: float) -> float:
            rad = math.radians(azimuth)
            return float(np.dot([math.cos(rad), math.sin(rad)], offset))

        best = max(THREE_QUARTER_AZIMUTHS_DEG, key=facing)
    return ViewSpec(best, PREVIEW_ELEVATION_DEG, DEFAULT_FOV_DEG, 1.0)


def render_preview_gif(
    asset: ArticulatedAsset,
    trajectory: Trajectory,
    *,
    size: tuple[int, int] = PREVIEW_SIZE,
    max_frames: int = MAX_PREVIEW_FRAMES,
) -> bytes:
    """GIF bytes of ``trajectory`` played on ``asset`` (base motion included), looping.

    Raises
    ------
    RenderError
        No EGL/moderngl, no frames, or a trajectory joint that ``asset`` lacks.
    """
    frames = preview_frames(trajectory.frame_count, max_frames)
    poses = window_poses(asset, trajectory, frames)
    camera = view_camera(asset, preview_view(asset, poses), size[0], size[1], poses)  # framed on the union of all states
    images = []
    for index in range(len(frames)):
        frame = {name: np.asarray(stack)[index] for name, stack in poses.items()}
        rgba = gl_backend.render_rgba(asset, frame, camera)
        images.append(Image.fromarray(np.ascontiguousarray(rgba[..., :3])).quantize(colors=255, dither=Image.Dither.NONE))
    step_ms = [max(MIN_FRAME_MS, round(1000.0 * (b - a) / trajectory.fps)) for a, b in itertools.pairwise(frames.tolist())]
    durations = [*step_ms, FINAL_HOLD_MS]
    buffer = io.BytesIO()
    images[0].save(buffer, format="GIF", save_all=True, append_images=images[1:], duration=durations, loop=0, optimize=False)
    return buffer.getvalue()
