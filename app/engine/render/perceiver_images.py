"""The perceiver's images (4 reference + 4 overlay views at rest), cached on disk per asset.

They depend only on the asset's content, the image size and this renderer, so a second
job on the same asset reads them back instead of rendering (~1.4 s on two CPU cores). The
cache lives under the asset cache folder (``views/<key>/``, written atomically); without a
cache folder every job renders.
"""

from __future__ import annotations

import hashlib
import io
import logging
from pathlib import Path

from app.engine.asset.model import ArticulatedAsset
from app.engine.files import atomic_write_bytes

logger = logging.getLogger(__name__)

RENDER_VERSION = "views-1"
"""Bump when the look of the reference/overlay images changes (old cache entries are then ignored)."""
VIEW_COUNT = 4
PNG_COMPRESS_LEVEL = 3


def image_names() -> list[str]:
    return [f"{prefix}_view_{index:02d}.png" for prefix in ("reference", "overlay") for index in range(1, VIEW_COUNT + 1)]


def _png(image: object) -> bytes:
    buffer = io.BytesIO()
    image.save(buffer, format="PNG", compress_level=PNG_COMPRESS_LEVEL)  # type: ignore[attr-defined]
    return buffer.getvalue()


def _render(asset: ArticulatedAsset, size: tuple[int, int]) -> dict[str, bytes]:
    from app.engine.render.views import render_overlay_views, render_reference_views

    names = image_names()
    pictures = render_reference_views(asset, size=size) + render_overlay_views(asset, size=size)
    return {name: _png(picture) for name, picture in zip(names, pictures, strict=True)}


def perceiver_images(asset: ArticulatedAsset, size: tuple[int, int], cache_dir: Path | None = None) -> dict[str, bytes]:
    """{name: PNG bytes} of the reference and overlay views (needs EGL unless cached).

    Raises
    ------
    RenderError
        Rendering was needed and is unavailable.
    """
    folder = None
    if cache_dir is not None:
        key = hashlib.sha256(f"{asset.content_hash}:{size[0]}x{size[1]}:{RENDER_VERSION}".encode()).hexdigest()[:32]
        folder = cache_dir / "views" / key
        if all((folder / name).is_file() for name in image_names()):
            try:
                return {name: (folder / name).read_bytes() for name in image_names()}
            except OSError as exc:  # a cache that cannot be read is rebuilt
                logger.warning("view cache %s unreadable (%s); rendering again", folder, exc)
    images = _render(asset, size)
    if folder is not None:
        try:
            for name, data in images.items():
                atomic_write_bytes(folder / name, data)
        except OSError as exc:
            logger.warning("cannot write the view cache %s: %s", folder, exc)
    return images
