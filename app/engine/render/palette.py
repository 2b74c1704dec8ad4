"""Per-link colours and compact labels for overlay and keyframe images.

Colours
-------
Visual links are sorted by name; link ``i`` gets hue ``frac(HUE_START + i * golden
ratio)`` with saturation and value cycling through small tables, so neighbours in
the sort order differ strongly and the result depends only on the link names (no
hashing of paths). Any 8-bit collision is resolved by nudging the hue.

Labels
------
A label must be short enough to read in an image and must name the same link in
every image of a run (the authors mixed link and joint integers, §6.1.8). Scheme:

- if every visual link name is at most :data:`MAX_NAME_LABEL_CHARS` characters and
  printable ASCII (e.g. PartNet's ``link_3``), the label **is the link name**;
- otherwise every link gets ``L<i>``, with ``i`` its index among the sorted visual
  link names, and :func:`label_legend` maps labels back to links.
"""

from __future__ import annotations

import colorsys

from app.engine.asset.model import ArticulatedAsset

RGB = tuple[int, int, int]

GOLDEN_RATIO_CONJUGATE = 0.6180339887498949
HUE_START = 0.02
SATURATIONS = (0.85, 0.65, 0.95)
VALUES = (0.88, 0.70)
COLLISION_HUE_STEP = 0.013
MAX_NAME_LABEL_CHARS = 12


def _rgb(hue: float, saturation: float, value: float) -> RGB:
    r, g, b = colorsys.hsv_to_rgb(hue % 1.0, saturation, value)
    return (round(r * 255), round(g * 255), round(b * 255))


def link_colors(asset: ArticulatedAsset) -> dict[str, RGB]:
    """{visual link: distinct (r, g, b) 0..255}, keyed in sorted link-name order."""
    colors: dict[str, RGB] = {}
    used: set[RGB] = set()
    for index, name in enumerate(sorted(asset.visual_links)):
        hue = HUE_START + index * GOLDEN_RATIO_CONJUGATE
        saturation = SATURATIONS[index % len(SATURATIONS)]
        value = VALUES[(index // len(SATURATIONS)) % len(VALUES)]
        color = _rgb(hue, saturation, value)
        while color in used:
            hue += COLLISION_HUE_STEP
            color = _rgb(hue, saturation, value)
        used.add(color)
        colors[name] = color
    return colors


def link_labels(asset: ArticulatedAsset) -> dict[str, str]:
    """{visual link: compact label} (see the module docstring for the scheme)."""
    names = sorted(asset.visual_links)
    readable = all(len(n) <= MAX_NAME_LABEL_CHARS and n.isascii() and n.isprintable() for n in names)
    if readable:
        return {n: n for n in names}
    return {n: f"L{i}" for i, n in enumerate(names)}


def label_legend(asset: ArticulatedAsset) -> dict[str, str]:
    """{label: visual link}, the inverse of :func:`link_labels`."""
    return {label: link for link, label in link_labels(asset).items()}


def text_color(background: RGB) -> RGB:
    """Black or white, whichever reads better on ``background`` (Rec. 601 luma)."""
    luma = 0.299 * background[0] + 0.587 * background[1] + 0.114 * background[2]
    return (0, 0, 0) if luma > 140 else (255, 255, 255)
