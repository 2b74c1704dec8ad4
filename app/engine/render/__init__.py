"""Offscreen rendering: cameras, EGL renders, reference/overlay views, ID masks, motion cues.

Optional extra ``render`` (moderngl) plus Mesa EGL (``libegl1 libegl-mesa0
libgl1-mesa-dri``). Importing this package never imports moderngl; the first render
call creates the EGL context and raises :class:`~app.engine.errors.RenderError`
naming what to install when it cannot.

Modules: :mod:`camera` (pinhole + orbit framing), :mod:`gl_backend` (EGL context,
shaded/point/ID/mask passes), :mod:`views` (reference and overlay images),
:mod:`cues` + :mod:`motion` (critic keyframes), :mod:`contact_sheet`; helpers
:mod:`atlas`, :mod:`gpu_assets`, :mod:`shaders`, :mod:`sampling`, :mod:`palette`,
:mod:`annotate`.
"""

from __future__ import annotations

from app.engine.render.camera import Camera, ViewSpec, asset_bounds, canonical_views, orbit_camera, view_camera
from app.engine.render.contact_sheet import contact_sheet
from app.engine.render.palette import label_legend, link_colors, link_labels

__all__ = [
    "Camera",
    "ViewSpec",
    "asset_bounds",
    "canonical_views",
    "contact_sheet",
    "label_legend",
    "link_colors",
    "link_labels",
    "orbit_camera",
    "view_camera",
]
