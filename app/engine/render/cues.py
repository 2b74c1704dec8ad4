"""Motion cues on critic keyframes (paper supp. §2.4 "Motion-cue construction").

For one link and one window ``[frame_head, frame_tail]`` of a trajectory:

- HEAD image (identity grounding): the render at ``frame_head`` with the link's box
  and label, the world-axis legend and a caption.
- TAIL image (diagnosis): the render at ``frame_tail`` with the same box/label/legend
  plus
  - the **point track**: one surface point of the link (the visible one whose
    projected path is longest, see :func:`motion.tracked_point`) followed through
    forward kinematics over the window; a hollow circle marks its start, a filled
    circle its end;
  - a **straight arrow** along the projected translation (prismatic joints), or
  - a **circular arrow** (revolute/continuous joints) drawn in the apparent screen
    sense, with a **DOT-OUT / CROSS-IN badge** in its centre.

Convention (one, used by arrow, badge and text alike): the signed axis is the world
joint axis times ``sign(q_tail - q_head)``; the motion is a right-handed rotation
about it. DOT-OUT means the signed axis points out of the screen (toward the viewer)
and the rotation appears counter-clockwise; CROSS-IN means it points into the screen
and the rotation appears clockwise. The text next to the badge is
``"<signed axis> DOT-OUT"`` (e.g. ``"-Z CROSS-IN"``). See :mod:`motion`.

Drawing is pure numpy + PIL; only :func:`render_keyframes` renders (through EGL).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
from PIL import Image, ImageDraw

from app.engine.asset.kinematics import base_transforms, link_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.execute.trajectory import Trajectory
from app.engine.render.annotate import (
    Box,
    draw_arrow,
    draw_axis_legend,
    draw_axis_marker,
    font,
    link_box,
    overlap_area,
    place_label,
    ui_scale,
)
from app.engine.render.camera import Camera
from app.engine.render.motion import MotionCue, motion_cue, tracked_point
from app.engine.render.palette import RGB, link_colors, link_labels
from app.engine.types import FloatArray, Transform, Transforms

MAX_TRACK_SAMPLES = 48
GLYPH_SIDE_PX = 120
ARC_SWEEP_DEG = 300.0
ARC_START_DEG = 120.0
ARC_SEGMENTS = 60
TRACK_WIDTH_PX = 3
FALLBACK_COLOR: RGB = (230, 60, 30)
BOX_WIDTH_PX = 3


def darker(color: RGB, factor: float = 0.7) -> RGB:
    return (round(color[0] * factor), round(color[1] * factor), round(color[2] * factor))


def draw_track(image: Image.Image, pixels: FloatArray, color: RGB) -> None:
    """Polyline through ``pixels`` (k, 2); hollow (white) circle at the start, filled circle at the end."""
    draw = ImageDraw.Draw(image)
    scale = ui_scale(image.size)
    points = [(float(x), float(y)) for x, y in pixels]
    width = max(2, round(TRACK_WIDTH_PX * scale))
    if len(points) > 1:
        draw.line(points, fill=(0, 0, 0), width=width + 2, joint="curve")
        draw.line(points, fill=color, width=width, joint="curve")
    radius = 7.0 * scale
    sx, sy = points[0]
    # hollow start: white inside (the track line does not show through), ring in the link colour
    draw.ellipse((sx - radius - 1, sy - radius - 1, sx + radius + 1, sy + radius + 1), fill=(0, 0, 0))
    draw.ellipse(
        (sx - radius, sy - radius, sx + radius, sy + radius),
        fill=(255, 255, 255),
        outline=color,
        width=max(2, round(3 * scale)),
    )
    ex, ey = points[-1]
    draw.ellipse(
        (ex - radius, ey - radius, ex + radius, ey + radius),
        fill=color,
        outline=(0, 0, 0),
        width=max(1, round(2 * scale)),
    )


def _arrow_head(
    draw: ImageDraw.ImageDraw, tip: tuple[float, float], direction: FloatArray, size: float, color: RGB
) -> None:
    ux, uy = direction / max(float(np.linalg.norm(direction)), 1e-9)
    bx, by = tip[0] - ux * size, tip[1] - uy * size
    wing = 0.6 * size
    polygon = [tip, (bx - uy * wing, by + ux * wing), (bx + uy * wing, by - ux * wing)]
    draw.polygon(polygon, fill=color, outline=(0, 0, 0), width=2)


def draw_rotation_glyph(image: Image.Image, center: Sequence[float], radius: float, cue: MotionCue, color: RGB) -> None:
    """Circular arrow in the cue's apparent screen sense with the DOT-OUT/CROSS-IN badge and text."""
    draw = ImageDraw.Draw(image)
    ccw = cue.screen_rotation == "ccw"
    sign = 1.0 if ccw else -1.0
    angles = np.radians(ARC_START_DEG + sign * np.linspace(0.0, ARC_SWEEP_DEG, ARC_SEGMENTS))
    cx, cy = float(center[0]), float(center[1])
    # math angles with y up; the image's y points down, hence the minus sign
    arc = [(cx + radius * math.cos(a), cy - radius * math.sin(a)) for a in angles]
    width = max(3, round(radius / 7))
    draw.line(arc, fill=(0, 0, 0), width=width + 2, joint="curve")
    draw.line(arc, fill=color, width=width, joint="curve")
    last = angles[-1]
    tangent = sign * np.array([-math.sin(last), -math.cos(last)])
    _arrow_head(draw, arc[-1], tangent, 2.6 * width + 4, color)
    draw_axis_marker(draw, (cx, cy), 0.42 * radius, bool(cue.toward_viewer), darker(color), max(2, width - 1))
    _glyph_text(image, (cx, cy + radius + 0.5 * width + 2), f"{cue.axis_label} {cue.badge}", color)


def draw_translation_glyph(
    image: Image.Image, center: Sequence[float], half_length: float, cue: MotionCue, color: RGB
) -> None:
    """Straight arrow along the projected travel (or a badge when travelling along the line of sight)."""
    draw = ImageDraw.Draw(image)
    cx, cy = float(center[0]), float(center[1])
    direction = cue.screen_direction
    if np.any(direction):
        start = (cx - direction[0] * half_length, cy - direction[1] * half_length)
        end = (cx + direction[0] * half_length, cy + direction[1] * half_length)
        draw_arrow(draw, start, end, color, max(4, round(half_length / 6)))
        _glyph_text(image, (cx, cy + half_length * 0.55 + 6), cue.axis_label, color)
    else:
        draw_axis_marker(draw, (cx, cy), 0.45 * half_length, bool(cue.toward_viewer), darker(color), 3)
        _glyph_text(image, (cx, cy + half_length * 0.5 + 6), f"{cue.axis_label} {cue.badge}", color)


def _glyph_text(image: Image.Image, top_center: tuple[float, float], text: str, color: RGB) -> None:
    draw = ImageDraw.Draw(image)
    draw.text(
        top_center,
        text,
        fill=darker(color, 0.8),
        font=font(round(16 * ui_scale(image.size))),
        anchor="ma",
        stroke_width=2,
        stroke_fill=(255, 255, 255),
    )


def glyph_box(link_box: Box | None, side: float, size: tuple[int, int], occupied: Sequence[Box]) -> Box:
    """Where to put a ``side`` x ``side`` glyph: right of, left of, above or below the link box, first free spot."""
    width, height = size
    x0, y0, x1, y1 = link_box if link_box is not None else (0.5 * width, 0.5 * height, 0.5 * width, 0.5 * height)
    cy, cx = 0.5 * (y0 + y1), 0.5 * (x0 + x1)
    gap = 10.0
    corners = [
        (x1 + gap, cy - side / 2),
        (x0 - gap - side, cy - side / 2),
        (cx - side / 2, y0 - gap - side),
        (cx - side / 2, y1 + gap),
    ]
    candidates = []
    for gx, gy in corners:
        gx, gy = min(max(gx, 0.0), width - side), min(max(gy, 0.0), height - side)
        box = (gx, gy, gx + side, gy + side)
        inside_cost = overlap_area(box, link_box) if link_box is not None else 0.0
        candidates.append((sum(overlap_area(box, o) for o in occupied) + inside_cost, box))
    return min(candidates, key=lambda c: c[0])[1]


def window_poses(asset: ArticulatedAsset, trajectory: Trajectory, frames: np.ndarray) -> dict[str, Transforms]:
    """{link: (k, 4, 4)} world poses at ``frames`` of ``trajectory`` (base motion included)."""
    unknown = [j for j in trajectory.joint_names if j not in asset.joints]
    if unknown:
        raise RenderError(f"trajectory joints {unknown} are not in asset '{asset.name}'")
    values = {name: trajectory.q[frames, i] for i, name in enumerate(trajectory.joint_names)}
    base = base_transforms(trajectory.base_translation[frames], trajectory.base_rotation_xyzw[frames])
    return link_poses(asset, values, base=base, frames=len(frames))


def _window_frames(trajectory: Trajectory, head: int, tail: int) -> np.ndarray:
    if not 0 <= head <= tail < trajectory.frame_count:
        raise RenderError(f"keyframes must satisfy 0 <= head <= tail < {trajectory.frame_count}, got {head}, {tail}")
    count = min(tail - head + 1, MAX_TRACK_SAMPLES)
    return np.unique(np.rint(np.linspace(head, tail, count)).astype(int))


def _caption(image: Image.Image, text: str) -> Box:
    draw = ImageDraw.Draw(image)
    face = font(round(15 * ui_scale(image.size)))
    left, top, right, bottom = draw.textbbox((10, 10), text, font=face)
    box = (left - 5.0, top - 4.0, right + 5.0, bottom + 4.0)
    draw.rounded_rectangle(box, radius=5, fill=(255, 255, 255), outline=(90, 90, 90))
    draw.text((10, 10), text, fill=(0, 0, 0), font=face)
    return box


def keyframe_motion(
    asset: ArticulatedAsset, trajectory: Trajectory, link: str, frame_head: int, frame_tail: int, camera: Camera
) -> MotionCue:
    """The :class:`MotionCue` that :func:`render_keyframes` draws (for the critic's text, same convention)."""
    frames = _window_frames(trajectory, frame_head, frame_tail)
    head_poses = {name: pose[0] for name, pose in window_poses(asset, trajectory, frames[:1]).items()}
    q = trajectory.joint_values()
    head = {j: float(v[frame_head]) for j, v in q.items()}
    tail = {j: float(v[frame_tail]) for j, v in q.items()}
    return motion_cue(asset, link, head, tail, head_poses, camera)


def _annotated_render(
    asset: ArticulatedAsset, poses: Mapping[str, Transform], camera: Camera, link: str, caption: str
) -> tuple[Image.Image, Box | None, list[Box]]:
    """Render one frame, then draw the legend, the caption and the link's box and label."""
    from app.engine.render import gl_backend  # the only GL dependency of this module

    image = Image.fromarray(gl_backend.render_rgba(asset, poses, camera)[..., :3].copy())
    occupied = [draw_axis_legend(image, camera), _caption(image, caption)]
    color = link_colors(asset).get(link, FALLBACK_COLOR)
    box = link_box(asset, link, poses[link], camera) if asset.links[link].has_geometry else None
    if box is not None:
        ImageDraw.Draw(image).rectangle(box, outline=color, width=max(2, round(BOX_WIDTH_PX * ui_scale(image.size))))
        place_label(image, link_labels(asset).get(link, link), box, color, occupied)
    return image, box, occupied


def render_keyframes(
    asset: ArticulatedAsset,
    trajectory: Trajectory,
    link: str,
    frame_head: int,
    frame_tail: int,
    camera: Camera,
) -> tuple[Image.Image, Image.Image]:
    """HEAD and TAIL keyframe images of ``link`` over ``[frame_head, frame_tail]`` (see module docstring).

    Raises
    ------
    RenderError
        Unknown link, frames out of range, trajectory/asset mismatch, or no EGL.
    """
    from app.engine.render import gl_backend

    if link not in asset.links:
        raise RenderError(f"unknown link '{link}'")
    frames = _window_frames(trajectory, frame_head, frame_tail)
    track_poses = window_poses(asset, trajectory, frames)
    head_poses = {name: pose[0] for name, pose in track_poses.items()}
    tail_poses = {name: pose[-1] for name, pose in track_poses.items()}
    ids, depth, names = gl_backend.render_id_depth(asset, head_poses, camera)
    index = names.index(link) if link in names else None
    _, track = tracked_point(asset, link, track_poses[link], camera, ids, depth, index)
    label = link_labels(asset).get(link, link)
    times = trajectory.times
    head, _, _ = _annotated_render(
        asset, head_poses, camera, link, f"HEAD  frame {frame_head}  t={times[frame_head]:.2f}s  link {label}"
    )
    tail, box, occupied = _annotated_render(
        asset, tail_poses, camera, link, f"TAIL  frame {frame_tail}  t={times[frame_tail]:.2f}s  link {label}"
    )
    color = link_colors(asset).get(link, FALLBACK_COLOR)
    draw_track(tail, track, color)
    _draw_cue(tail, keyframe_motion(asset, trajectory, link, frame_head, frame_tail, camera), box, color, occupied)
    return head, tail


def _draw_cue(image: Image.Image, cue: MotionCue, box: Box | None, color: RGB, occupied: list[Box]) -> None:
    if cue.kind == "static":
        return
    side = GLYPH_SIDE_PX * ui_scale(image.size)
    spot = glyph_box(box, side, image.size, occupied)
    center = (0.5 * (spot[0] + spot[2]), 0.5 * (spot[1] + spot[3]) - 0.1 * side)
    if cue.kind == "rotation":
        draw_rotation_glyph(image, center, 0.32 * side, cue, color)
    else:
        draw_translation_glyph(image, center, 0.4 * side, cue, color)
    occupied.append(spot)
