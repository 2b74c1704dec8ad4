"""Pack every distinct texture of an asset into one RGBA atlas (pure numpy + PIL).

PartNet assets can carry hundreds of tiny textures (``kitchen_pot_100038``: 906
distinct images, most 3 x 6 px, on 1100+ two-triangle parts). One atlas lets a whole
link be drawn in one call; the shader wraps uv inside each texture's rectangle, so
glTF ``REPEAT`` addressing keeps working.

Packing is a deterministic shelf packer: textures sorted by (height, width, digest)
descending, rows filled left to right. Textures larger than ``max_side`` are
downscaled (LANCZOS) first; if the atlas would still exceed ``max_atlas``, the cap
is halved and packing restarts.
"""

from __future__ import annotations

import hashlib
import io
import logging
import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from PIL import Image

from app.engine.errors import RenderError

logger = logging.getLogger(__name__)

MAX_TEXTURE_SIDE = 512
"""Largest texture side kept in the atlas (a whole-object render rarely shows one texture larger)."""
MAX_ATLAS_SIDE = 8192
MIN_TEXTURE_SIDE = 8
ATLAS_WIDTH_SLACK = 1.15
"""The atlas width starts at sqrt(total area) x this, so rows come out roughly square."""

Rect = tuple[int, int, int, int]
"""(x, y, width, height) in atlas texels; row 0 is the top row of every image."""


@dataclass(frozen=True, eq=False)
class TextureAtlas:
    """Packed textures.

    Attributes
    ----------
    pixels : (H, W, 4) uint8, row 0 = top
    rects : {sha256 hex of the PNG bytes: (x, y, w, h)}
    """

    pixels: NDArray[np.uint8]
    rects: dict[str, Rect]


def texture_key(png: bytes) -> str:
    """The atlas key of a texture: sha256 of its PNG bytes."""
    return hashlib.sha256(png).hexdigest()


def _decode(png: bytes, key: str) -> Image.Image:
    try:
        with Image.open(io.BytesIO(png)) as image:
            return image.convert("RGBA")
    except (OSError, ValueError) as exc:
        raise RenderError(f"cannot decode texture {key[:12]}: {exc}") from exc


def _fit(image: Image.Image, cap: int) -> Image.Image:
    width, height = image.size
    side = max(width, height)
    if side <= cap:
        return image
    scale = cap / side
    return image.resize((max(1, round(width * scale)), max(1, round(height * scale))), Image.Resampling.LANCZOS)


def _shelf_pack(sizes: list[tuple[str, int, int]], width: int) -> tuple[dict[str, Rect], int]:
    rects: dict[str, Rect] = {}
    x = y = row_height = 0
    for key, w, h in sizes:
        if x + w > width:
            x, y, row_height = 0, y + row_height, 0
        rects[key] = (x, y, w, h)
        x += w
        row_height = max(row_height, h)
    return rects, y + row_height


def build_atlas(
    pngs: Iterable[bytes], *, max_side: int = MAX_TEXTURE_SIDE, max_atlas: int = MAX_ATLAS_SIDE
) -> TextureAtlas:
    """Pack the distinct images among ``pngs`` (duplicates share one rectangle).

    Raises
    ------
    RenderError
        Undecodable image, or the textures cannot fit even at the smallest cap.
    """
    decoded = {texture_key(png): png for png in pngs}
    sources = {key: _decode(png, key) for key, png in sorted(decoded.items())}
    if not sources:
        return TextureAtlas(pixels=np.full((1, 1, 4), 255, dtype=np.uint8), rects={})
    cap = max_side
    while cap >= MIN_TEXTURE_SIDE:
        images = {key: _fit(image, cap) for key, image in sources.items()}
        sizes = sorted(((k, *im.size) for k, im in images.items()), key=lambda s: (-s[2], -s[1], s[0]))
        area = sum(w * h for _, w, h in sizes)
        width = min(max_atlas, max(max(w for _, w, _ in sizes), math.ceil(math.sqrt(area) * ATLAS_WIDTH_SLACK)))
        rects, height = _shelf_pack(sizes, width)
        if height <= max_atlas:
            pixels = np.zeros((height, width, 4), dtype=np.uint8)
            for key, (x, y, w, h) in rects.items():
                pixels[y : y + h, x : x + w] = np.asarray(images[key], dtype=np.uint8)
            logger.debug("texture atlas %dx%d for %d textures (cap %d)", width, height, len(rects), cap)
            return TextureAtlas(pixels=pixels, rects=rects)
        cap //= 2
    raise RenderError(f"{len(sources)} textures do not fit a {max_atlas}x{max_atlas} atlas")
