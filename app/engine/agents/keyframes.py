"""HEAD/TAIL keyframes with motion cues for one critic case, from the view chosen for its link.

The view comes from coverage-view selection (:mod:`app.engine.render.coverage`, or the
model's choice); the camera frames the object over the whole motion window, so the
tracked point's start (hollow circle) and end (filled circle) are both inside the image.
Rendering runs in a worker thread (:func:`render_off_loop`) so model calls in flight are
not held up by it.
"""

from __future__ import annotations

import asyncio
import io
from collections.abc import Callable
from typing import TypeVar

import numpy as np

from app.engine.agents.summaries import CriticCase
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.providers.base import Image
from app.engine.render.camera import ViewSpec
from app.engine.types import Transforms

KEYFRAME_SIZE = (640, 480)
PNG_COMPRESS_LEVEL = 3
T = TypeVar("T")


async def render_off_loop(function: Callable[..., T], *args: object) -> T:
    """Run a render function in a thread (the GL backend serialises GL work with its own lock)."""
    return await asyncio.to_thread(function, *args)


def window_poses(asset: ArticulatedAsset, trajectory: Trajectory, head: int, tail: int) -> dict[str, Transforms]:
    """{link: (k, 4, 4)} world poses at the sampled frames of ``[head, tail]`` (head, middle, tail)."""
    from app.engine.render.coverage import window_frames
    from app.engine.render.cues import window_poses as poses_at

    return poses_at(asset, trajectory, np.asarray(window_frames(head, tail)))


def critic_keyframes(asset: ArticulatedAsset, trajectory: Trajectory, case: CriticCase, view: ViewSpec) -> list[Image]:
    """[HEAD, TAIL] PNGs for ``case`` seen from ``view`` (needs EGL; raises RenderError without it)."""
    from app.engine.render.coverage import framing_camera
    from app.engine.render.cues import render_keyframes

    head, tail = case.head_frame, case.tail_frame
    camera = framing_camera(asset, window_poses(asset, trajectory, head, tail), view, KEYFRAME_SIZE)
    images = []
    for tag, picture in zip(("HEAD", "TAIL"), render_keyframes(asset, trajectory, case.link, head, tail, camera), strict=True):
        buffer = io.BytesIO()
        picture.save(buffer, format="PNG", compress_level=PNG_COMPRESS_LEVEL)
        images.append(Image(name=f"TIMELINE_SAMPLE_{tag}_seg{case.segment_index}_{case.joint}.png", png=buffer.getvalue()))
    return images
