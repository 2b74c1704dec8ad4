"""Reference and overlay images for the perceiver (paper §3.2.1 "Data preprocessing").

- Reference views: the textured object, shaded, with the world-axis legend.
- Overlay views: every visual link in its own flat colour (:func:`link_colors`),
  drawn as seeded surface **points** so interior parts show through the gaps, plus
  one box and one compact label per link (:func:`link_labels`; the legend
  :func:`label_legend` maps labels back to link names) and the axis legend.

Both use the same cameras: the orbit views of :mod:`camera` framing the object at
the rendered pose.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping, Sequence

import numpy as np
from numpy.typing import NDArray
from PIL import Image

from app.engine.asset.kinematics import rest_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.render import gl_backend
from app.engine.render.annotate import Box, annotate_links, draw_axis_legend
from app.engine.render.camera import Camera, ViewSpec, canonical_views, view_camera
from app.engine.render.palette import label_legend, link_colors, link_labels
from app.engine.types import Transform

logger = logging.getLogger(__name__)

DEFAULT_SIZE = (800, 600)
OVERLAY_POINTS_PER_LINK = 6000
OVERLAY_POINT_SIZE_PX = 2.0

__all__ = ["label_legend", "render_overlay_views", "render_reference_views", "view_cameras"]


def _frame_poses(asset: ArticulatedAsset, poses: Mapping[str, Transform] | None) -> dict[str, Transform]:
    """{link: (4, 4)} of one frame (rest when None; (1, 4, 4) entries are squeezed)."""
    if poses is None:
        return rest_poses(asset)
    out = {
        name: np.asarray(pose)[0] if np.shape(pose) == (1, 4, 4) else np.asarray(pose) for name, pose in poses.items()
    }
    missing = [n for n in asset.visual_links if n not in out]
    if missing:
        raise RenderError(f"poses are missing for links {missing}")
    return out


def view_cameras(
    asset: ArticulatedAsset,
    poses: Mapping[str, Transform] | None = None,
    views: Sequence[ViewSpec] | None = None,
    size: tuple[int, int] = DEFAULT_SIZE,
) -> list[Camera]:
    """The cameras of ``views`` (canonical by default) framing ``asset`` at ``poses``."""
    frame = _frame_poses(asset, poses)
    chosen = canonical_views() if views is None else tuple(views)
    return [view_camera(asset, view, size[0], size[1], frame) for view in chosen]


def _to_image(rgba: NDArray[np.uint8]) -> Image.Image:
    """RGB image of an (H, W, 4) render (alpha dropped; the background is already opaque white)."""
    return Image.fromarray(np.ascontiguousarray(rgba[..., :3]))


def render_reference_views(
    asset: ArticulatedAsset,
    poses: Mapping[str, Transform] | None = None,
    views: Sequence[ViewSpec] | None = None,
    size: tuple[int, int] = DEFAULT_SIZE,
    *,
    samples: int = gl_backend.DEFAULT_SAMPLES,
) -> list[Image.Image]:
    """Textured, shaded RGB renders of ``asset`` with the world-axis legend, one per view.

    Parameters
    ----------
    poses : {link: (4, 4)} world poses of one frame; rest pose when None
    views : orbit views; :func:`canonical_views` when None
    size : (width, height) in pixels

    Raises
    ------
    RenderError
        No EGL/moderngl, or poses missing for a visual link.
    """
    frame = _frame_poses(asset, poses)
    images = []
    for camera in view_cameras(asset, frame, views, size):
        image = _to_image(gl_backend.render_rgba(asset, frame, camera, samples=samples))
        draw_axis_legend(image, camera)
        images.append(image)
    return images


def render_overlay_views(
    asset: ArticulatedAsset,
    poses: Mapping[str, Transform] | None = None,
    views: Sequence[ViewSpec] | None = None,
    size: tuple[int, int] = DEFAULT_SIZE,
    *,
    points_per_link: int = OVERLAY_POINTS_PER_LINK,
    point_size: float = OVERLAY_POINT_SIZE_PX,
) -> list[Image.Image]:
    """Colour-coded point renders with per-link boxes, labels and the axis legend, one per view.

    Colours come from :func:`link_colors` (distinct, from the sorted link names);
    labels from :func:`link_labels` (see :mod:`palette` for the scheme). Each link is
    ``points_per_link`` surface points sampled with a generator seeded from
    ``sha256(asset name, link name)``, so the images are reproducible.
    """
    frame = _frame_poses(asset, poses)
    colors = link_colors(asset)
    labels = link_labels(asset)
    images = []
    for camera in view_cameras(asset, frame, views, size):
        rgba = gl_backend.render_points(asset, frame, camera, colors, count=points_per_link, point_size=point_size)
        image = _to_image(rgba)
        occupied: list[Box] = [draw_axis_legend(image, camera)]
        annotate_links(image, asset, frame, camera, colors, labels, occupied)
        images.append(image)
    return images
