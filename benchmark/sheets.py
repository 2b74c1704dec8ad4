"""Contact sheets of an evaluation: per case, GT key states above the matched predicted frames.

Row 1: the ground truth at each key state; row 2: the prediction at the frame matched to
it (links missing from the prediction are not drawn; a case without a usable prediction
gets blank cells); row 3, when the run folder ``<pred_root>/<case_id>/images/`` holds
``reference*.png`` renders, up to K of them. Renders use one camera per case: of the
four canonical orbits (azimuth 0/90/180/270, elevation 20, fov 35) the one that shows
the most pixels of the key states' dynamic links (the 2D metrics always use azimuth 0;
the sheet only illustrates).
"""

from __future__ import annotations

import io
import logging
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image

from app.engine.errors import MetricError
from app.engine.files import atomic_write_bytes
from app.engine.metrics.compiler import compile_case
from app.engine.metrics.prediction import NodeMap, find_prediction, load_prediction
from app.engine.metrics.scores2d import framing
from app.engine.metrics.scoring import ground_truth_sequence
from app.engine.types import Transform
from benchmark.cases import read_cases
from benchmark.runner import cached_asset

logger = logging.getLogger(__name__)

SHEET_CELL_PX = 240
REFERENCE_PATTERN = "reference*.png"
_COLLAPSED = np.zeros((4, 4))
"""Pose of a link the prediction lacks: every vertex collapses to the origin, nothing is drawn."""
_COLLAPSED[3, 3] = 1.0


def _render(asset: Any, poses: dict[str, Transform], camera: Any) -> Image.Image:
    from app.engine.render.gl_backend import render_rgba

    return Image.fromarray(render_rgba(asset, poses, camera)[..., :3].copy())


def _sheet_camera(asset: Any, geometry: Any, gt: Any, states: list[dict[str, Any]]) -> Any:
    from app.engine.render.camera import CANONICAL_AZIMUTHS_DEG, CANONICAL_ELEVATION_DEG, DEFAULT_FOV_DEG, orbit_camera
    from app.engine.render.gl_backend import render_link_ids

    center, diagonal = framing(asset, geometry, gt)
    best, chosen = -1, None
    for azimuth in CANONICAL_AZIMUTHS_DEG:
        camera = orbit_camera(
            center, diagonal, azimuth, CANONICAL_ELEVATION_DEG, DEFAULT_FOV_DEG, 1.0, SHEET_CELL_PX, SHEET_CELL_PX
        )
        shown = 0
        for k, state in enumerate(states):
            ids, names = render_link_ids(asset, {link: gt.poses[link][k] for link in geometry.links}, camera)
            wanted = [names.index(link) for link in state["dynamic_links"]]
            shown += int(np.isin(ids, wanted).sum())
        if shown > best:
            best, chosen = shown, camera
    return chosen


def _references(folder: Path, count: int) -> list[Path]:
    images = folder / "images"
    return sorted(images.glob(REFERENCE_PATTERN))[:count] if images.is_dir() else []


def case_sheet(
    record: dict[str, Any], case: Any, assets_root: Path, pred_root: Path, node_map: NodeMap | None
) -> Image.Image:
    """The contact sheet of one evaluated case.

    Raises
    ------
    RenderError
        The renderer is unavailable.
    """
    from app.engine.render.contact_sheet import contact_sheet

    asset, geometry = cached_asset(str(assets_root / case.asset))
    truth = compile_case(case, asset)
    gt = ground_truth_sequence(asset, truth)
    camera = _sheet_camera(asset, geometry, gt, record["states"])
    images, captions = [], []
    for k, state in enumerate(record["states"]):
        images.append(_render(asset, {link: gt.poses[link][k] for link in geometry.links}, camera))
        captions.append(f"GT {k}: {state['phase']} @{state['gt_frame']}")
    prediction = None
    found = find_prediction(pred_root / case.case_id)
    if record["matched_frames"] is not None and found is not None:
        prediction = load_prediction(found, asset, node_map=node_map)
    for state in record["states"]:
        if prediction is None:
            images.append(Image.new("RGB", (SHEET_CELL_PX, SHEET_CELL_PX), (235, 235, 235)))
            captions.append(f"pred: {record['status']}")
            continue
        frame = state["pred_frame"]
        poses = {
            link: prediction.poses[link][frame] if link in prediction.poses else _COLLAPSED for link in geometry.links
        }
        images.append(_render(asset, poses, camera))
        captions.append(f"pred frame {frame} (gIoU {state['values']['P_gIoU']:.2f})")
    for path in _references(pred_root / case.case_id, len(record["states"])):
        with Image.open(path) as image:
            images.append(
                image.convert("RGB").resize((SHEET_CELL_PX, round(SHEET_CELL_PX * image.size[1] / image.size[0])))
            )
        captions.append(path.name)
    return contact_sheet(images, captions, columns=len(record["states"]))


def write_contact_sheets(
    document: dict[str, Any],
    cases_file: Path,
    assets_root: Path,
    pred_root: Path,
    folder: Path,
    node_map: NodeMap | None = None,
) -> dict[str, str]:
    """Write ``folder/<case_id>.png`` for every case with key states; {case_id: path relative to the report}."""
    cases = {case.case_id: case for case in read_cases(cases_file)}
    written: dict[str, str] = {}
    for record in document["cases"]:
        if not record["states"]:
            continue
        if record["case_id"] not in cases:
            raise MetricError(f"case {record['case_id']} is not in {cases_file.name}")
        sheet = case_sheet(record, cases[record["case_id"]], assets_root, pred_root, node_map)
        buffer = io.BytesIO()
        sheet.save(buffer, format="PNG")
        path = atomic_write_bytes(folder / f"{record['case_id']}.png", buffer.getvalue())
        written[record["case_id"]] = f"{folder.name}/{path.name}"
    return written
