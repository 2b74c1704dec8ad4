"""2D annotations drawn on rendered images (pure numpy + PIL).

- :func:`draw_axis_legend`: world-axis legend in the top-right corner, +X red, +Y
  green, +Z blue. Each axis is drawn as its projection on the camera's right/up
  axes (so foreshortening shows); an axis pointing almost straight at or away from
  the viewer is drawn as a circled dot (toward the viewer) or cross (away).
- :func:`link_box`: a link's projected bounding box from its mesh vertices.
- :func:`place_label`: a filled tag with the label text next to a box, avoiding
  already occupied rectangles.

Boxes are ``(x0, y0, x1, y1)`` pixel rectangles, y down.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping, Sequence

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from app.engine.asset.model import ArticulatedAsset
from app.engine.render.camera import Camera
from app.engine.render.palette import RGB, text_color
from app.engine.types import Transform

Box = tuple[float, float, float, float]

AXIS_COLORS: dict[str, RGB] = {"X": (220, 40, 40), "Y": (40, 170, 40), "Z": (40, 80, 220)}
LEGEND_MIN_PROJECTED = 0.2
"""An axis whose projected length is below this is shown as a dot/cross marker."""
LEGEND_MARGIN_PX = 8
REFERENCE_SIDE_PX = 600.0
MIN_UI_SCALE = 0.5
MAX_UI_SCALE = 2.0
LABEL_PADDING_PX = 3
LABEL_RINGS = 6
LABEL_RING_DIRECTIONS = 12
LABEL_HARD_WEIGHT = 100.0
LABEL_RING_PENALTY = 0.05


def ui_scale(size: tuple[int, int]) -> float:
    """Scale of annotation sizes for an image of ``size`` (1.0 at 600 px on the short side)."""
    return min(max(min(size) / REFERENCE_SIDE_PX, MIN_UI_SCALE), MAX_UI_SCALE)


@functools.lru_cache(maxsize=16)
def font(size_px: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    """Pillow's bundled font at ``size_px`` (deterministic, no system fonts)."""
    return ImageFont.load_default(size=max(6, size_px))


def draw_arrow(
    draw: ImageDraw.ImageDraw,
    start: Sequence[float],
    end: Sequence[float],
    color: RGB,
    width: int,
    *,
    outline: bool = True,
) -> None:
    """A straight arrow from ``start`` to ``end`` with a triangular head (black outline optional)."""
    sx, sy = float(start[0]), float(start[1])
    ex, ey = float(end[0]), float(end[1])
    length = math.hypot(ex - sx, ey - sy)
    if length < 1e-6:
        return
    ux, uy = (ex - sx) / length, (ey - sy) / length
    head = min(max(3.0 * width, 8.0), 0.6 * length)
    bx, by = ex - ux * head, ey - uy * head
    wing = 0.55 * head
    tip = [(ex, ey), (bx - uy * wing, by + ux * wing), (bx + uy * wing, by - ux * wing)]
    if outline:
        draw.line([(sx, sy), (bx, by)], fill=(0, 0, 0), width=width + 2)
        draw.polygon(tip, fill=(0, 0, 0), outline=(0, 0, 0), width=2)
    draw.line([(sx, sy), (bx, by)], fill=color, width=width)
    draw.polygon(tip, fill=color)


def draw_axis_marker(
    draw: ImageDraw.ImageDraw, center: Sequence[float], radius: float, toward: bool, color: RGB, width: int
) -> None:
    """A circled dot (``toward`` the viewer, "out of the screen") or cross (away, "into the screen")."""
    cx, cy = float(center[0]), float(center[1])
    draw.ellipse((cx - radius, cy - radius, cx + radius, cy + radius), outline=color, width=width, fill=(255, 255, 255))
    if toward:
        dot = max(2.0, 0.35 * radius)
        draw.ellipse((cx - dot, cy - dot, cx + dot, cy + dot), fill=color)
    else:
        arm = 0.55 * radius
        draw.line([(cx - arm, cy - arm), (cx + arm, cy + arm)], fill=color, width=width)
        draw.line([(cx - arm, cy + arm), (cx + arm, cy - arm)], fill=color, width=width)


def legend_box(size: tuple[int, int]) -> Box:
    """Where :func:`draw_axis_legend` puts the legend on an image of ``size`` (top-right corner)."""
    scale = ui_scale(size)
    width, height = round(130 * scale), round(110 * scale)
    x1 = size[0] - LEGEND_MARGIN_PX
    return (float(x1 - width), float(LEGEND_MARGIN_PX), float(x1), float(LEGEND_MARGIN_PX + height))


def draw_axis_legend(image: Image.Image, camera: Camera) -> Box:
    """Draw the world-axis legend in the top-right corner; returns its box."""
    scale = ui_scale(image.size)
    box = legend_box(image.size)
    x0, y0 = round(box[0]), round(box[1])
    width, height = round(box[2] - box[0]), round(box[3] - box[1])
    draw = ImageDraw.Draw(image)
    draw.rounded_rectangle(box, radius=round(8 * scale), fill=(255, 255, 255), outline=(90, 90, 90), width=1)
    origin = (x0 + 0.42 * width, y0 + 0.55 * height)
    length = 0.36 * min(width, height)
    letters = font(round(16 * scale))
    markers = 0
    view = camera.eye - camera.target
    for index, axis in enumerate("XYZ"):
        unit = np.eye(3)[index]
        direction = camera.screen_direction(unit)
        projected = float(np.linalg.norm(direction))
        color = AXIS_COLORS[axis]
        if projected < LEGEND_MIN_PROJECTED:
            center = (x0 + 14 * scale + markers * 34 * scale, y0 + height - 14 * scale)
            draw_axis_marker(draw, center, 7 * scale, bool(unit @ view > 0), color, max(1, round(2 * scale)))
            draw.text((center[0] + 9 * scale, center[1]), axis, fill=color, font=letters, anchor="lm")
            markers += 1
            continue
        end = (origin[0] + direction[0] * length, origin[1] + direction[1] * length)
        draw_arrow(draw, origin, end, color, max(2, round(3 * scale)))
        tip = direction / projected
        label_at = (end[0] + tip[0] * 10 * scale, end[1] + tip[1] * 10 * scale)
        draw.text(label_at, axis, fill=color, font=letters, anchor="mm", stroke_width=1, stroke_fill=(255, 255, 255))
    return box


def link_box(asset: ArticulatedAsset, link: str, pose: Transform, camera: Camera) -> Box | None:
    """The projected bounding box of ``link``'s vertices, clipped to the image (None if off-screen)."""
    vertices = asset.links[link].vertices()
    if not len(vertices):
        return None
    pose = np.asarray(pose, dtype=np.float64).reshape(4, 4)
    pixels, depth = camera.project(vertices @ pose[:3, :3].T + pose[:3, 3])
    pixels = pixels[depth > camera.near]
    if not len(pixels):
        return None
    x0, y0 = np.maximum(pixels.min(axis=0), 0.0)
    x1 = min(float(pixels[:, 0].max()), camera.width - 1.0)
    y1 = min(float(pixels[:, 1].max()), camera.height - 1.0)
    if x1 < x0 or y1 < y0:
        return None
    return (float(x0), float(y0), x1, y1)


def _area(box: Box) -> float:
    return (box[2] - box[0]) * (box[3] - box[1])


def overlap_area(a: Box, b: Box) -> float:
    return max(0.0, min(a[2], b[2]) - max(a[0], b[0])) * max(0.0, min(a[3], b[3]) - max(a[1], b[1]))


def _label_spots(box: Box, w: float, h: float) -> list[tuple[float, float, int]]:
    """Candidate top-left corners of a ``w`` x ``h`` tag for ``box``, with their ring index (0 = adjacent)."""
    x0, y0, x1, y1 = box
    spots = [(x0, y0 - h, 0), (x1 - w, y0 - h, 0), (x0, y1, 0), (x1 - w, y1, 0), (x1, y0, 0), (x0 - w, y0, 0)]
    cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
    reach = 0.5 * math.hypot(x1 - x0, y1 - y0)
    for ring in range(1, LABEL_RINGS + 1):
        for step in range(LABEL_RING_DIRECTIONS):
            angle = 2.0 * math.pi * step / LABEL_RING_DIRECTIONS
            distance = reach + ring * 1.3 * h
            spots.append((cx + math.cos(angle) * distance - 0.5 * w, cy - math.sin(angle) * distance - 0.5 * h, ring))
    return spots


def _label_cost(tag: Box, ring: int, occupied: Sequence[Box], obstacles: Sequence[Box]) -> float:
    """Hard overlap with other tags/legend, soft cover of link boxes (fraction hidden), distance."""
    area = (tag[2] - tag[0]) * (tag[3] - tag[1])
    hard = sum(overlap_area(tag, other) for other in occupied) / area
    soft = sum(
        overlap_area(tag, other) / max((other[2] - other[0]) * (other[3] - other[1]), 1.0) for other in obstacles
    )
    return LABEL_HARD_WEIGHT * hard + soft + LABEL_RING_PENALTY * ring


def place_label(
    image: Image.Image,
    text: str,
    box: Box,
    color: RGB,
    occupied: list[Box],
    obstacles: Sequence[Box] = (),
    *,
    size_px: int | None = None,
) -> Box:
    """Draw ``text`` on a tag of ``color`` next to ``box``; appends and returns the tag's box.

    Candidates: the six spots touching the box (above left/right, below left/right,
    beside the top corners), then rings of spots farther out. The cost strongly
    penalises covering anything in ``occupied`` (other tags, the legend), then the
    fraction of each ``obstacles`` box hidden (link boxes, including the own one),
    then the distance; ties go to the earlier candidate. A tag away from its box gets
    a thin leader line in the link colour.
    """
    draw = ImageDraw.Draw(image)
    face = font(size_px or round(15 * ui_scale(image.size)))
    left, top, right, bottom = draw.textbbox((0, 0), text, font=face)
    w, h = right - left + 2 * LABEL_PADDING_PX, bottom - top + 2 * LABEL_PADDING_PX
    best, best_cost, best_ring = box, math.inf, 0
    for sx, sy, ring in _label_spots(box, w, h):
        sx = min(max(sx, 0.0), image.size[0] - w)
        sy = min(max(sy, 0.0), image.size[1] - h)
        tag = (sx, sy, sx + w, sy + h)
        cost = _label_cost(tag, ring, occupied, obstacles)
        if cost < best_cost:
            best, best_cost, best_ring = tag, cost, ring
    if best_ring > 0:
        anchor = (
            min(max(0.5 * (best[0] + best[2]), box[0]), box[2]),
            min(max(0.5 * (best[1] + best[3]), box[1]), box[3]),
        )
        draw.line([(0.5 * (best[0] + best[2]), 0.5 * (best[1] + best[3])), anchor], fill=color, width=1)
    draw.rectangle(best, fill=color, outline=(0, 0, 0), width=1)
    draw.text(
        (best[0] + LABEL_PADDING_PX - left, best[1] + LABEL_PADDING_PX - top), text, fill=text_color(color), font=face
    )
    occupied.append(best)
    return best


def annotate_links(
    image: Image.Image,
    asset: ArticulatedAsset,
    poses: Mapping[str, Transform],
    camera: Camera,
    colors: Mapping[str, RGB],
    labels: Mapping[str, str],
    occupied: list[Box],
    *,
    line_width: int = 2,
) -> dict[str, Box]:
    """Draw a box and a label for every link of ``colors`` (sorted by name); returns the boxes."""
    draw = ImageDraw.Draw(image)
    boxes: dict[str, Box] = {}
    for link in sorted(colors):
        box = link_box(asset, link, poses[link], camera)
        if box is None:
            continue
        draw.rectangle(box, outline=colors[link], width=line_width)
        boxes[link] = box
    obstacles = list(boxes.values())
    for link, box in sorted(boxes.items(), key=lambda item: _area(item[1])):  # small links pick first
        place_label(image, labels[link], box, colors[link], occupied, obstacles)
    return boxes
