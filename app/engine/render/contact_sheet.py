"""A captioned grid of images (e.g. GT vs predicted key states in benchmark reports)."""

from __future__ import annotations

from collections.abc import Sequence

from PIL import Image, ImageDraw

from app.engine.errors import RenderError
from app.engine.render.annotate import font

CELL_PADDING_PX = 6
CAPTION_FONT_PX = 16
ELLIPSIS = "..."
Color = tuple[int, int, int]


def _fit_text(draw: ImageDraw.ImageDraw, text: str, width: int, size_px: int) -> str:
    """``text`` shortened with an ellipsis until it fits ``width`` pixels."""
    face = font(size_px)
    if draw.textlength(text, font=face) <= width:
        return text
    while text and draw.textlength(text + ELLIPSIS, font=face) > width:
        text = text[:-1]
    return text + ELLIPSIS


def contact_sheet(
    images: Sequence[Image.Image],
    captions: Sequence[str],
    columns: int,
    *,
    background: Color = (255, 255, 255),
    caption_px: int = CAPTION_FONT_PX,
) -> Image.Image:
    """Lay ``images`` out row by row in ``columns`` columns, each with its caption underneath.

    Every cell is as large as the largest image; smaller images are centred. Captions
    that do not fit the cell width are shortened with an ellipsis.

    Raises
    ------
    RenderError
        No images, ``columns`` < 1, or a caption count different from the image count.
    """
    if not images:
        raise RenderError("contact_sheet needs at least one image")
    if columns < 1:
        raise RenderError(f"columns must be >= 1, got {columns}")
    if len(captions) != len(images):
        raise RenderError(f"{len(images)} images but {len(captions)} captions")
    cell_w = max(im.size[0] for im in images)
    cell_h = max(im.size[1] for im in images)
    caption_h = round(caption_px * 1.5)
    columns = min(columns, len(images))
    rows = -(-len(images) // columns)
    step_x = cell_w + 2 * CELL_PADDING_PX
    step_y = cell_h + caption_h + 2 * CELL_PADDING_PX
    sheet = Image.new("RGB", (columns * step_x, rows * step_y), background)
    draw = ImageDraw.Draw(sheet)
    for index, (image, caption) in enumerate(zip(images, captions, strict=True)):
        column, row = index % columns, index // columns
        x = column * step_x + CELL_PADDING_PX
        y = row * step_y + CELL_PADDING_PX
        sheet.paste(image.convert("RGB"), (x + (cell_w - image.size[0]) // 2, y + (cell_h - image.size[1]) // 2))
        text = _fit_text(draw, caption, cell_w, caption_px)
        draw.text(
            (x + cell_w / 2, y + cell_h + caption_h / 2), text, fill=(0, 0, 0), font=font(caption_px), anchor="mm"
        )
    return sheet
