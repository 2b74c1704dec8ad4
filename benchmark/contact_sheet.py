"""Render the ground-truth key states of benchmark cases into contact-sheet PNGs (annotation review).

Usage::

    python -m benchmark.contact_sheet --cases benchmark/cases/dev.jsonl \
        [--assets ROOT] --out out/sheets [--case ID ...]     (ROOT: $ARTIMO_PARTNET_ROOT, else ../shared/assets/partnet)

Per case, one PNG ``<out>/<case_id>.png``: a title strip (case id, motion type, prompt),
then one row per view and one column per state — the rest pose followed by the K GT key
states (each phase's end, ordered by end time, exactly as the evaluator compiles them).
Every caption names the phase, its end time and the values of the joints constrained in
it (``base`` shows the base translation).

Rows: the two orbits (of eight azimuths, 25 degrees elevation) in which consecutive
states differ the most, framing the union of every state's box (so whole-object motion
shows as displacement); then, when only some links move and they are small or hidden, a
close-up framed on them — drawn with the rest of the object when some outside view shows
them, else drawn alone. Images are for human review only.
"""

from __future__ import annotations

import argparse
import itertools
import logging
import sys
from collections.abc import Sequence
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import EngineError, MetricError
from app.engine.metrics.annotation import Case
from app.engine.metrics.compiler import GroundTruth, compile_case
from app.engine.metrics.sequence import PoseSequence, trajectory_sequence
from app.engine.render.annotate import font
from app.engine.render.camera import Camera, orbit_camera
from app.engine.render.contact_sheet import contact_sheet
from app.engine.render.gl_backend import render_link_ids, render_rgba
from app.engine.types import Transform
from benchmark.cases import read_cases
from benchmark.paths import assets_or_partnet

logger = logging.getLogger(__name__)

CELL_PX = (320, 260)
CANDIDATE_AZIMUTHS_DEG = (0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0)
ELEVATION_DEG = 25.0
VIEWS_PER_SHEET = 2
PICK_PX = 96
"""Side of the small ID renders used to pick the views."""
FRAMING_SLACK = 1.1
"""The union box diagonal is enlarged by this much so moving parts stay inside the frame."""
CLOSE_UP_SLACK = 3.0
"""The close-up frames the moving links' box enlarged this much, so some context shows."""
CLOSE_UP_MAX_FRACTION = 0.35
"""A close-up row is added when the moving links' box is below this fraction of the object's (or hidden)."""
CAPTION_PX = 12
TITLE_FONT_PX = 16
TITLE_LINE_PX = 22
_COLLAPSED = np.zeros((4, 4))
"""Pose that collapses a link to the origin, so it is not drawn."""
_COLLAPSED[3, 3] = 1.0

Box = tuple[np.ndarray, np.ndarray]


def state_sequence(asset: ArticulatedAsset, truth: GroundTruth) -> PoseSequence:
    """Rest (frame 0) followed by the K key-state frames of the GT trajectory."""
    full = trajectory_sequence(asset, truth.trajectory, source="ground truth")
    return full.take([0] + [state.frame for state in truth.key_states])


def _poses(sequence: PoseSequence, index: int) -> dict[str, Transform]:
    return {link: pose[index] for link, pose in sequence.poses.items()}


def union_box(asset: ArticulatedAsset, sequence: PoseSequence, links: Sequence[str] | None = None) -> Box:
    """(low (3,), high (3,)) world box holding ``links`` (default: all visual links) in every state."""
    lows, highs = [], []
    for link in sequence.poses if links is None else links:
        poses = sequence.poses[link]
        vertices = np.concatenate([part.vertices for part in asset.links[link].parts], axis=0)
        posed = (np.einsum("tij,nj->tni", poses[:, :3, :3], vertices) + poses[:, None, :3, 3]).reshape(-1, 3)
        lows.append(posed.min(axis=0))
        highs.append(posed.max(axis=0))
    return np.min(lows, axis=0), np.max(highs, axis=0)


def _camera(box: Box, slack: float, azimuth: float, size: tuple[int, int]) -> Camera:
    low, high = box
    return orbit_camera(
        0.5 * (low + high),
        float(np.linalg.norm(high - low)) * slack,
        azimuth,
        ELEVATION_DEG,
        width=size[0],
        height=size[1],
    )


def moving_links(asset: ArticulatedAsset, truth: GroundTruth) -> tuple[str, ...]:
    """Links that move in some key state, when they are not the whole object (else empty)."""
    if any(state.base_constrained for state in truth.key_states):
        return ()
    moving = {link for state in truth.key_states for link in state.dynamic_links}
    return tuple(link for link in asset.visual_links if link in moving) if len(moving) < len(asset.visual_links) else ()


def only(sequence: PoseSequence, links: Sequence[str]) -> PoseSequence:
    """``sequence`` with every other link collapsed to a point (not drawn)."""
    poses = {
        name: pose if name in links else np.broadcast_to(_COLLAPSED, pose.shape).copy()
        for name, pose in sequence.poses.items()
    }
    return PoseSequence(times=sequence.times, poses=poses, missing=sequence.missing, source=sequence.source)


def _ids(asset: ArticulatedAsset, sequence: PoseSequence, camera: Camera) -> list[np.ndarray]:
    return [render_link_ids(asset, _poses(sequence, k), camera)[0] for k in range(sequence.frame_count)]


def overview_azimuths(asset: ArticulatedAsset, sequence: PoseSequence, box: Box) -> tuple[list[float], bool]:
    """The ``VIEWS_PER_SHEET`` azimuths (sorted) where consecutive states differ most, and whether any differ.

    Score of a view: pixels whose link id (or background) changes between consecutive
    states, plus a tenth of the pixels the object covers (prefers larger views on ties).
    """
    scores = []
    for order, azimuth in enumerate(CANDIDATE_AZIMUTHS_DEG):
        ids = _ids(asset, sequence, _camera(box, FRAMING_SLACK, azimuth, (PICK_PX, PICK_PX)))
        changed = sum(int((a != b).sum()) for a, b in itertools.pairwise(ids))
        scores.append((changed + 0.1 * sum(int((i >= 0).sum()) for i in ids), changed, order, azimuth))
    ranked = sorted(scores, key=lambda s: (-s[0], s[2]))
    return sorted(s[3] for s in ranked[:VIEWS_PER_SHEET]), max(s[1] for s in scores) > 0


def close_up(
    asset: ArticulatedAsset, sequence: PoseSequence, moving: Sequence[str], whole: Box
) -> tuple[PoseSequence, float, str]:
    """(sequence to draw, azimuth, label) of the close-up on ``moving``.

    The azimuth is the one, among cameras outside the object's box, that shows the most
    pixels of the moving links over all states; when none shows any, the moving links are
    drawn alone from the azimuth where they cover the most pixels.
    """
    box = union_box(asset, sequence, moving)
    names = asset.visual_links
    wanted = [names.index(link) for link in moving]
    best: tuple[int, float] = (0, CANDIDATE_AZIMUTHS_DEG[0])
    for azimuth in CANDIDATE_AZIMUTHS_DEG:
        camera = _camera(box, CLOSE_UP_SLACK, azimuth, (PICK_PX, PICK_PX))
        if np.all(camera.eye >= whole[0]) and np.all(camera.eye <= whole[1]):
            continue  # an eye inside the object sees it from within
        shown = sum(int(np.isin(ids, wanted).sum()) for ids in _ids(asset, sequence, camera))
        best = max(best, (shown, azimuth), key=lambda s: s[0])
    if best[0] > 0:
        return sequence, best[1], "close-up"
    alone = only(sequence, moving)
    covered = [
        sum(int((ids >= 0).sum()) for ids in _ids(asset, alone, _camera(box, CLOSE_UP_SLACK, az, (PICK_PX, PICK_PX))))
        for az in CANDIDATE_AZIMUTHS_DEG
    ]
    return alone, CANDIDATE_AZIMUTHS_DEG[int(np.argmax(covered))], "moving parts only"


def state_caption(truth: GroundTruth, index: int) -> str:
    """Caption of column ``index`` (0 = rest): phase, end time and the constrained values."""
    if index == 0:
        return "rest"
    state = truth.key_states[index - 1]
    values = truth.trajectory.joint_values()
    parts = [f"{joint}={float(values[joint][state.frame]):+.3f}" for joint in state.constrained_joints]
    if state.base_constrained:
        shift = np.asarray(truth.trajectory.base_translation)[state.frame]
        parts.append("base=[" + ",".join(f"{v:+.2f}" for v in shift) + "]")
    return f"k{index} {state.phase} t={state.time_s:.2f}s " + " ".join(parts)


def _wrap(text: str, width_px: int) -> list[str]:
    """``text`` broken at spaces into lines at most ``width_px`` wide in the title font."""
    face = font(TITLE_FONT_PX)
    measure = ImageDraw.Draw(Image.new("RGB", (1, 1)))
    lines: list[str] = []
    for word in text.split(" "):
        if lines and measure.textlength(f"{lines[-1]} {word}", font=face) <= width_px:
            lines[-1] = f"{lines[-1]} {word}"
        else:
            lines.append(word)
    return lines


def _title(case: Case, width: int) -> Image.Image:
    lines = _wrap(f"{case.case_id}  [{case.motion_type}]  {case.prompt}", width - 12)
    strip = Image.new("RGB", (width, TITLE_LINE_PX * len(lines) + 6), (235, 235, 235))
    draw = ImageDraw.Draw(strip)
    for row, line in enumerate(lines):
        draw.text((6, 3 + row * TITLE_LINE_PX), line, fill=(0, 0, 0), font=font(TITLE_FONT_PX))
    return strip


def _row(
    asset: ArticulatedAsset, truth: GroundTruth, sequence: PoseSequence, camera: Camera, label: str
) -> tuple[list[Image.Image], list[str]]:
    images, captions = [], []
    for index in range(sequence.frame_count):
        images.append(Image.fromarray(render_rgba(asset, _poses(sequence, index), camera)[..., :3].copy()))
        caption = state_caption(truth, index)
        captions.append(f"{label} {caption}" if index == 0 else caption)
    return images, captions


def case_sheet(case: Case, asset: ArticulatedAsset) -> Image.Image:
    """The contact sheet of one case (raises ``MetricError`` when it does not compile)."""
    truth = compile_case(case, asset)
    sequence = state_sequence(asset, truth)
    whole = union_box(asset, sequence)
    azimuths, visible = overview_azimuths(asset, sequence, whole)
    images: list[Image.Image] = []
    captions: list[str] = []
    for azimuth in azimuths:
        row = _row(asset, truth, sequence, _camera(whole, FRAMING_SLACK, azimuth, CELL_PX), f"az{azimuth:.0f}")
        images += row[0]
        captions += row[1]
    moving = moving_links(asset, truth)
    if moving:
        low, high = union_box(asset, sequence, moving)
        if not visible or np.linalg.norm(high - low) < CLOSE_UP_MAX_FRACTION * np.linalg.norm(whole[1] - whole[0]):
            drawn, azimuth, label = close_up(asset, sequence, moving, whole)
            row = _row(
                asset, truth, drawn, _camera((low, high), CLOSE_UP_SLACK, azimuth, CELL_PX), f"{label} az{azimuth:.0f}"
            )
            images += row[0]
            captions += row[1]
    grid = contact_sheet(images, captions, columns=sequence.frame_count, caption_px=CAPTION_PX)
    title = _title(case, grid.size[0])
    sheet = Image.new("RGB", (grid.size[0], grid.size[1] + title.size[1]), (255, 255, 255))
    sheet.paste(title, (0, 0))
    sheet.paste(grid, (0, title.size[1]))
    return sheet


def render_sheets(cases: Sequence[Case], assets_root: Path, out_dir: Path) -> list[Path]:
    """Write one PNG per case; a case that fails is logged and skipped. Returns the written paths."""
    out_dir.mkdir(parents=True, exist_ok=True)
    loaded: dict[str, ArticulatedAsset] = {}
    written = []
    for case in cases:
        try:
            if case.asset not in loaded:
                loaded[case.asset] = load_asset(assets_root / case.asset)
            sheet = case_sheet(case, loaded[case.asset])
        except EngineError as exc:
            logger.error("case %s: %s", case.case_id, exc)
            continue
        path = out_dir / f"{case.case_id}.png"
        sheet.save(path)
        written.append(path)
        logger.info("wrote %s", path)
    return written


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Render GT key states of benchmark cases into contact-sheet PNGs.")
    parser.add_argument("--cases", required=True, type=Path, help="cases .jsonl file")
    parser.add_argument("--assets", type=Path, default=None,
                        help="folder holding the cases' asset folders (default: $ARTIMO_PARTNET_ROOT, else ../shared/assets/partnet)")
    parser.add_argument("--out", required=True, type=Path, help="output folder for the PNGs")
    parser.add_argument("--case", action="append", default=None, help="only this case id (repeatable)")
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(levelname)s %(message)s")
    cases = read_cases(args.cases)
    if args.case:
        unknown = sorted(set(args.case) - {c.case_id for c in cases})
        if unknown:
            parser.error(f"unknown case ids: {', '.join(unknown)}")
        cases = [c for c in cases if c.case_id in set(args.case)]
    try:
        root = assets_or_partnet(args.assets)
    except MetricError as exc:
        parser.error(str(exc))
    written = render_sheets(cases, root, args.out)
    return 0 if len(written) == len(cases) else 1


if __name__ == "__main__":
    sys.exit(main())
