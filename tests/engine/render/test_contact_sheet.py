"""Contact sheets: layout, captions, argument checks (pure PIL)."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from app.engine.errors import RenderError
from app.engine.render.contact_sheet import CELL_PADDING_PX, contact_sheet


def test_grid_layout_and_captions() -> None:
    colors = [(255, 0, 0), (0, 255, 0), (0, 0, 255)]
    images = [Image.new("RGB", (60, 40), c) for c in colors]
    images.append(Image.new("RGB", (30, 20), (0, 0, 0)))  # smaller: centred in its cell
    sheet = contact_sheet(images, ["GT t=0", "pred t=0", "GT t=1", "pred t=1"], columns=2)
    pixels = np.asarray(sheet)
    step_x = 60 + 2 * CELL_PADDING_PX
    step_y = (sheet.size[1]) // 2
    assert sheet.size[0] == 2 * step_x
    assert tuple(pixels[CELL_PADDING_PX + 20, CELL_PADDING_PX + 30]) == colors[0]
    assert tuple(pixels[CELL_PADDING_PX + 20, step_x + CELL_PADDING_PX + 30]) == colors[1]
    assert tuple(pixels[step_y + CELL_PADDING_PX + 20, CELL_PADDING_PX + 30]) == colors[2]
    assert tuple(pixels[step_y + CELL_PADDING_PX + 20, step_x + CELL_PADDING_PX + 30]) == (0, 0, 0)
    assert tuple(pixels[step_y + CELL_PADDING_PX + 2, step_x + CELL_PADDING_PX + 2]) == (255, 255, 255)
    caption_band = pixels[CELL_PADDING_PX + 40 : step_y, :step_x]
    assert (caption_band < 128).any()  # caption text drawn under the first image


def test_long_captions_are_shortened_and_arguments_checked() -> None:
    image = Image.new("RGB", (50, 30), (200, 200, 200))
    sheet = contact_sheet([image], ["a caption far too long for a fifty pixel cell"], columns=3)
    assert sheet.size[0] == 50 + 2 * CELL_PADDING_PX  # columns clamp to the image count
    with pytest.raises(RenderError):
        contact_sheet([], [], columns=1)
    with pytest.raises(RenderError):
        contact_sheet([image], ["a", "b"], columns=1)
    with pytest.raises(RenderError):
        contact_sheet([image], ["a"], columns=0)
