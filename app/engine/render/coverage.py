"""Coverage-view selection, geometric (paper supplementary §2.3, made without a model).

For each moving link the critic needs one view where the link is visible over its
motion. Candidates are the four canonical views (azimuth 0/90/180/270, elevation 20);
each is scored by the link's **visible pixels** in the ID buffer, summed over a few
frames of the motion (head, middle, tail). When no canonical view shows the link well
enough (an interior tray behind a door), views from the discrete bank (azimuth every 30
degrees, elevations 30/45/60) are scored too. Cameras frame the object's box over the
whole motion window, so the start and end of the motion stay inside the image.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.render.camera import Camera, ViewSpec, asset_bounds, canonical_views, orbit_camera
from app.engine.types import Transforms

AZIMUTH_SET = tuple(float(a) for a in range(0, 360, 30))
ELEVATION_SET = (10.0, 20.0, 30.0, 45.0, 60.0)
DISTANCE_SCALE_SET = (0.8, 1.0, 1.2, 1.5, 1.8, 2.2)
FOV_SET = (25.0, 35.0, 45.0)
BANK_ELEVATIONS = (30.0, 45.0, 60.0)
SCORE_SIZE = (200, 150)
"""ID-buffer size used for scoring (small: only pixel counts matter)."""
MIN_VISIBLE_FRACTION = 0.004
"""A view covers a link when at least this fraction of the score image shows it (summed over frames / frames)."""
SAMPLE_FRAMES = 3


@dataclass(frozen=True)
class ViewChoice:
    link: str
    view: ViewSpec
    visible_px: int
    """Visible pixels of the link at the keyframe size, averaged over the sampled frames."""
    covered: bool


def on_bank(view: ViewSpec) -> bool:
    """Whether every value of ``view`` comes from the discrete camera bank."""
    return (view.azimuth_deg % 360.0 in AZIMUTH_SET and view.elevation_deg in ELEVATION_SET
            and view.distance_scale in DISTANCE_SCALE_SET and view.fov_deg in FOV_SET)


def window_frames(head: int, tail: int) -> list[int]:
    return sorted({head, (head + tail) // 2, tail})[:SAMPLE_FRAMES]


def framing_camera(asset: ArticulatedAsset, poses: Mapping[str, Transforms], view: ViewSpec, size: tuple[int, int]) -> Camera:
    """The orbit camera of ``view`` that frames the object over every pose in ``poses`` ({link: (k, 4, 4)})."""
    center, diag = asset_bounds(asset, poses)
    return orbit_camera(center, diag, view.azimuth_deg, view.elevation_deg, view.fov_deg, view.distance_scale, size[0], size[1])


def visible_pixels(asset: ArticulatedAsset, poses: Mapping[str, Transforms], link: str, view: ViewSpec, size: tuple[int, int] = SCORE_SIZE) -> int:
    """Pixels of ``link`` visible from ``view``, summed over the frames of ``poses`` (needs EGL)."""
    from app.engine.render import gl_backend

    camera = framing_camera(asset, poses, view, size)
    total = 0
    frames = next(iter(poses.values())).shape[0]
    for index in range(frames):
        frame = {name: pose[index] for name, pose in poses.items()}
        ids, names = gl_backend.render_link_ids(asset, frame, camera)
        if link in names:
            total += int(np.count_nonzero(ids == names.index(link)))
    return total


def choose_view(
    asset: ArticulatedAsset, poses: Mapping[str, Transforms], link: str, *, candidates: Sequence[ViewSpec] | None = None,
    keyframe_size: tuple[int, int] = (640, 480),
) -> ViewChoice:
    """The candidate view (canonical first, then the bank) showing the most of ``link`` over ``poses``."""
    frames = next(iter(poses.values())).shape[0]
    area = SCORE_SIZE[0] * SCORE_SIZE[1] * frames
    scale = keyframe_size[0] * keyframe_size[1] / (SCORE_SIZE[0] * SCORE_SIZE[1]) / frames
    pool = list(candidates) if candidates is not None else list(canonical_views())
    scored = [(visible_pixels(asset, poses, link, view), -index, view) for index, view in enumerate(pool)]
    best = max(scored, key=lambda item: (item[0], item[1]))
    if best[0] < MIN_VISIBLE_FRACTION * area and candidates is None:
        bank = [ViewSpec(az, el) for el in BANK_ELEVATIONS for az in AZIMUTH_SET]
        more = [(visible_pixels(asset, poses, link, view), -index - len(pool), view) for index, view in enumerate(bank)]
        best = max([best, *more], key=lambda item: (item[0], item[1]))
    return ViewChoice(link=link, view=best[2], visible_px=round(best[0] * scale), covered=best[0] >= MIN_VISIBLE_FRACTION * area)
