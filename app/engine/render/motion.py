"""What a link does between two keyframes, in camera terms (pure numpy).

Rotation convention (the only one used anywhere in the renderer)
-----------------------------------------------------------------
Let ``a`` be the unit axis of the link's driving joint in world coordinates at the
head frame and ``dq = q(tail) - q(head)``. The **signed axis** is
``s = a * sign(dq)``; the motion is then always a right-handed rotation by ``|dq|``
about ``s``, i.e. counter-clockwise when seen from the tip of ``s`` looking back at
the pivot. Nothing else is flipped: for ``dq < 0`` only the axis changes sign (the
authors flipped both the axis and the cw/ccw word, which cancelled out, §6.1.1).

- DOT-OUT: ``s . (eye - pivot) > 0`` — ``s`` points out of the screen, toward the
  viewer, so the rotation **appears counter-clockwise** on screen.
- CROSS-IN: otherwise — ``s`` points into the screen and the rotation **appears
  clockwise**.

Translation: ``s = a * sign(dq)`` is the direction of travel; its screen arrow is
the projected displacement. When that projection is shorter than
:data:`MIN_PROJECTED_PX` the travel is along the line of sight and the same badge
is used: DOT-OUT = toward the viewer, CROSS-IN = away.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

import numpy as np

from app.engine.asset.model import ArticulatedAsset, JointSpec
from app.engine.errors import RenderError
from app.engine.render.camera import Camera
from app.engine.render.sampling import sample_link_points
from app.engine.types import FloatArray, Transforms, Vector3

STATIC_EPS = 1e-6
"""|dq| below this (rad or m) counts as no motion."""
MIN_PROJECTED_PX = 2.0
TRACK_CANDIDATES = 512
VISIBLE_DEPTH_FRACTION = 0.02
"""A candidate is visible when its depth is within this fraction of the eye-target distance of the depth buffer."""


@dataclass(frozen=True)
class MotionCue:
    """The motion of ``link`` over a keyframe window, seen from one camera.

    Attributes
    ----------
    joint : the driving joint (nearest movable joint above the link), None if none
    kind : "rotation", "translation" or "static"
    delta : float, ``q(tail) - q(head)`` of ``joint`` (radians or metres)
    signed_axis : (3,) unit world vector ``axis * sign(delta)`` at the head frame (zeros if static)
    axis_label : dominant signed world component of ``signed_axis`` ("+X", "-Z", ...; "" if static)
    pivot : (3,) world point on the joint axis at the head frame
    toward_viewer : DOT-OUT (True) / CROSS-IN (False); None if static
    screen_direction : (2,) unit screen vector (x right, y down) of a translation; zeros otherwise
    """

    link: str
    joint: str | None
    kind: Literal["rotation", "translation", "static"]
    delta: float
    signed_axis: Vector3
    axis_label: str
    pivot: Vector3
    toward_viewer: bool | None
    screen_direction: FloatArray

    @property
    def badge(self) -> str | None:
        """ "DOT-OUT" or "CROSS-IN" (None if static)."""
        if self.toward_viewer is None:
            return None
        return "DOT-OUT" if self.toward_viewer else "CROSS-IN"

    @property
    def screen_rotation(self) -> Literal["ccw", "cw"] | None:
        """Apparent on-screen sense of a rotation: ccw for DOT-OUT, cw for CROSS-IN."""
        if self.kind != "rotation":
            return None
        return "ccw" if self.toward_viewer else "cw"


def driving_joint(asset: ArticulatedAsset, link: str) -> JointSpec | None:
    """The nearest movable joint on the path from ``link`` up to the root."""
    if link not in asset.links:
        raise RenderError(f"unknown link '{link}'")
    joint = asset.parent_joint(link)
    while joint is not None and not joint.movable:
        joint = asset.parent_joint(joint.parent)
    return joint


def axis_label(vector: Vector3) -> str:
    """ "+X"/"-X"/... for the component of largest magnitude."""
    index = int(np.argmax(np.abs(vector)))
    return ("+" if vector[index] >= 0 else "-") + "XYZ"[index]


def motion_cue(
    asset: ArticulatedAsset,
    link: str,
    q_head: Mapping[str, float],
    q_tail: Mapping[str, float],
    poses_head: Mapping[str, FloatArray],
    camera: Camera,
) -> MotionCue:
    """Describe ``link``'s motion from the head to the tail frame (see the module docstring).

    ``q_head``/``q_tail`` hold the joint values of both frames; ``poses_head`` the
    (4, 4) world link poses of the head frame.
    """
    joint = driving_joint(asset, link)
    zero = np.zeros(3)
    if joint is None:
        return MotionCue(link, None, "static", 0.0, zero, "", zero, None, np.zeros(2))
    delta = float(q_tail[joint.name] - q_head[joint.name])
    frame = np.asarray(poses_head[joint.parent], dtype=np.float64).reshape(4, 4) @ joint.origin
    axis = frame[:3, :3] @ joint.axis
    pivot = frame[:3, 3]
    if abs(delta) < STATIC_EPS or not np.any(axis):
        return MotionCue(link, joint.name, "static", delta, zero, "", pivot, None, np.zeros(2))
    signed = axis / np.linalg.norm(axis) * np.sign(delta)
    toward = bool(signed @ (camera.eye - pivot) > 0.0)
    kind: Literal["rotation", "translation"] = "translation" if joint.type == "prismatic" else "rotation"
    direction = np.zeros(2)
    if kind == "translation":
        (start, end), _ = camera.project(np.stack([pivot, pivot + signed * abs(delta)]))
        length = float(np.linalg.norm(end - start))
        if length >= MIN_PROJECTED_PX:
            direction = (end - start) / length
    return MotionCue(link, joint.name, kind, delta, signed, axis_label(signed), pivot, toward, direction)


def _preferred_candidates(
    head: FloatArray,
    head_depth: FloatArray,
    camera: Camera,
    ids: np.ndarray | None,
    depth: np.ndarray | None,
    link_index: int | None,
) -> np.ndarray:
    """(n,) bool: candidates visible at the head frame, else those inside the image, else all."""
    inside = (
        (head[:, 0] >= 0)
        & (head[:, 0] < camera.width)
        & (head[:, 1] >= 0)
        & (head[:, 1] < camera.height)
        & (head_depth > 0)
    )
    preferred = inside
    if ids is not None and depth is not None and link_index is not None and inside.any():
        cols = np.clip(head[:, 0].astype(int), 0, camera.width - 1)
        rows = np.clip(head[:, 1].astype(int), 0, camera.height - 1)
        tolerance = VISIBLE_DEPTH_FRACTION * float(np.linalg.norm(camera.eye - camera.target))
        visible = inside & (ids[rows, cols] == link_index) & (np.abs(depth[rows, cols] - head_depth) <= tolerance)
        if visible.any():
            preferred = visible
    if not preferred.any():
        preferred = np.ones(len(head), dtype=bool)
    return preferred


def tracked_point(
    asset: ArticulatedAsset,
    link: str,
    link_track: Transforms,
    camera: Camera,
    ids: np.ndarray | None = None,
    depth: np.ndarray | None = None,
    link_index: int | None = None,
) -> tuple[Vector3, FloatArray]:
    """Choose the surface point of ``link`` whose projected path is longest, preferring visible ones.

    Parameters
    ----------
    link_track : (k, 4, 4) world poses of ``link`` over the window (head first)
    ids, depth : (H, W) ID and depth buffers of the head frame (optional visibility test)
    link_index : index of ``link`` in the ID buffer

    Returns
    -------
    point : (3,) link frame
    pixels : (k, 2) its projected track
    """
    if asset.links[link].has_geometry:
        candidates = sample_link_points(asset, link, TRACK_CANDIDATES)
    else:
        candidates = np.zeros((1, 3))
    world = np.einsum("kij,nj->kni", link_track[:, :3, :3], candidates) + link_track[:, None, :3, 3]
    frames, count = world.shape[:2]
    pixels, point_depth = camera.project(world.reshape(-1, 3))
    pixels = pixels.reshape(frames, count, 2)
    point_depth = point_depth.reshape(frames, count)
    path = np.linalg.norm(np.diff(pixels, axis=0), axis=2).sum(axis=0) if frames > 1 else np.zeros(count)
    preferred = _preferred_candidates(pixels[0], point_depth[0], camera, ids, depth, link_index)
    best = int(np.argmax(np.where(preferred, path, -1.0)))
    return candidates[best], pixels[:, best]
