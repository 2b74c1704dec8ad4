"""The coverage-view selection role (paper supplementary §2.3): one view per moving link for the critic.

Geometric (no model): :func:`app.engine.render.coverage.choose_view`. Model-backed
(:func:`select_views`): the VLM sees the four canonical renders with boxes and labels on
the required links and picks, per link, a current view where the link has a visible box
and a readable label, or proposes cameras from the discrete bank. Its reply is checked
(known links, values on the bank, selections among the current views) and sent back on
error; each choice is then confirmed geometrically (the link must show in it), proposals
are scored by visible pixels, and any link left without a usable view gets the geometric
choice. A failed coverage call falls back to the geometric choice with a note.
"""

from __future__ import annotations

import io
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from app.engine.agents.ask import ask
from app.engine.agents.expectations import Expectations
from app.engine.agents.keyframes import render_off_loop
from app.engine.agents.prompts import PromptStore
from app.engine.agents.roles import Context
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import PlanValidationError, ProviderError, RoleOutputError
from app.engine.providers.base import ChatModel, Image
from app.engine.render.camera import ViewSpec, canonical_views
from app.engine.render.coverage import (
    AZIMUTH_SET,
    DISTANCE_SCALE_SET,
    ELEVATION_SET,
    FOV_SET,
    ViewChoice,
    choose_view,
    on_bank,
    visible_pixels,
)
from app.engine.report import CoverageChoice, RoleCall
from app.engine.types import Transforms

VIEW_SIZE = (800, 600)
MAX_PROPOSALS = 4
PNG_COMPRESS_LEVEL = 3


class CameraView(BaseModel):
    model_config = ConfigDict(extra="forbid")
    azimuth_deg: float
    elevation_deg: float
    distance_scale: float = 1.0
    fov_deg: float = 35.0

    def spec(self) -> ViewSpec:
        return ViewSpec(self.azimuth_deg % 360.0, self.elevation_deg, self.fov_deg, self.distance_scale)


class LinkCheck(BaseModel):
    link: str
    bbox_visible: bool | None = None
    label_readable: bool | None = None
    trajectory_observability: Literal["high", "medium", "low", "unknown"] = "unknown"
    evidence: str = ""


class CoverageReply(BaseModel):
    """The coverage selector's output (supplementary §2.3 schema)."""

    selected_views_by_link: dict[str, CameraView] = Field(default_factory=dict)
    selected_views: list[CameraView] = Field(default_factory=list)
    need_more_views: bool = False
    proposed_views: list[CameraView] = Field(default_factory=list)
    reason: str = ""
    selection_explanation: dict[str, Any] | None = None


def check_reply(reply: CoverageReply, required: list[str], current: list[ViewSpec]) -> None:
    """Raise PlanValidationError listing every link/view problem (sent back to the model)."""
    problems = []
    for link, view in reply.selected_views_by_link.items():
        if link not in required:
            problems.append(f"selected_views_by_link.{link}: not a required link (required: {', '.join(required)})")
        elif view.spec() not in current:
            problems.append(f"selected_views_by_link.{link}: {view.model_dump()} is not one of the current views; propose it instead")
    for index, view in enumerate(reply.proposed_views):
        if not on_bank(view.spec()):
            problems.append(f"proposed_views[{index}]: values must come from the allowed sets (azimuth {list(AZIMUTH_SET)}, elevation "
                            f"{list(ELEVATION_SET)}, distance_scale {list(DISTANCE_SCALE_SET)}, fov {list(FOV_SET)})")
    if len(reply.proposed_views) > MAX_PROPOSALS:
        problems.append(f"proposed_views: at most {MAX_PROPOSALS} cameras")
    missing = [link for link in required if link not in reply.selected_views_by_link]
    if missing and not reply.proposed_views:
        problems.append(f"no view for {', '.join(missing)}: select a current view or set need_more_views and propose cameras")
    if problems:
        raise PlanValidationError("coverage reply does not fit the scene", issues=problems)


def _annotated_views(asset: ArticulatedAsset, links: list[str], views: list[ViewSpec], rendered: list[bytes] | None = None) -> list[Image]:
    """Textured renders at rest with boxes and labels on ``links`` only; ``rendered`` reuses the perceiver's reference PNGs."""
    from PIL import Image as PILImage

    from app.engine.asset.kinematics import rest_poses
    from app.engine.render.annotate import annotate_links, legend_box
    from app.engine.render.palette import link_colors, link_labels
    from app.engine.render.views import render_reference_views, view_cameras

    colors = {link: color for link, color in link_colors(asset).items() if link in links}
    cameras = view_cameras(asset, views=views, size=VIEW_SIZE)
    pictures = [PILImage.open(io.BytesIO(data)).convert("RGB") for data in rendered] if rendered else render_reference_views(asset, views=views, size=VIEW_SIZE)
    poses, labels = rest_poses(asset), link_labels(asset)
    images = []
    for index, (picture, camera, view) in enumerate(zip(pictures, cameras, views, strict=True), start=1):
        annotate_links(picture, asset, poses, camera, colors, labels, [legend_box(VIEW_SIZE)])
        buffer = io.BytesIO()
        picture.save(buffer, format="PNG", compress_level=PNG_COMPRESS_LEVEL)
        images.append(Image(name=f"COVERAGE_VIEW_{index}_AZ{view.azimuth_deg:g}_EL{view.elevation_deg:g}.png", png=buffer.getvalue()))
    return images


def _reference_pngs(context: Context) -> list[bytes] | None:
    """The perceiver's reference views (canonical cameras, rest pose) when they were rendered at the coverage size."""
    names = [f"reference_view_{index:02d}.png" for index in range(1, 5)]
    if tuple(context.config.image_size) != VIEW_SIZE or not all(name in context.images for name in names):
        return None
    return [context.images[name] for name in names]


def _confirm(asset: ArticulatedAsset, poses: dict[str, Transforms], link: str, reply: CoverageReply) -> ViewChoice | None:
    """The model's view for ``link`` if the link shows in it; else the best of its proposals that shows it."""
    candidates = ([reply.selected_views_by_link[link].spec()] if link in reply.selected_views_by_link else [])
    candidates += [v.spec() for v in reply.proposed_views]
    for view in candidates:
        pixels = visible_pixels(asset, poses, link, view)
        if pixels > 0:
            return ViewChoice(link=link, view=view, visible_px=pixels, covered=True)
    return None


def _record(choice: ViewChoice, source: str) -> CoverageChoice:
    view = choice.view
    return CoverageChoice(link=choice.link, azimuth_deg=view.azimuth_deg, elevation_deg=view.elevation_deg, distance_scale=view.distance_scale,
                          fov_deg=view.fov_deg, visible_px=choice.visible_px, source=source)


def geometric_views(asset: ArticulatedAsset, windows: dict[str, dict[str, Transforms]]) -> dict[str, CoverageChoice]:
    """The geometric choice for every link of ``windows`` ({link: its motion window's poses})."""
    return {link: _record(choose_view(asset, poses, link), "geometric") for link, poses in windows.items()}


async def select_views(
    chat: ChatModel, prompts: PromptStore, context: Context, expected: Expectations, windows: dict[str, dict[str, Transforms]],
) -> tuple[dict[str, CoverageChoice], list[RoleCall], list[str]]:
    """Per-link views chosen by the model (confirmed geometrically), the calls made and notes."""
    from app.engine.render.palette import link_labels

    required = list(windows)
    current = list(canonical_views())
    labels = link_labels(context.asset)
    images = await render_off_loop(_annotated_views, context.asset, required, current, _reference_pngs(context))
    prompt = prompts.render("coverage", prompt=context.prompt, views=", ".join(i.name for i in images),
                            links=[{"name": link, "label": labels.get(link, link), "motion": expected.describe(_joint(context, link))} for link in required],
                            azimuths=list(AZIMUTH_SET), elevations=list(ELEVATION_SET), distances=list(DISTANCE_SCALE_SET), fovs=list(FOV_SET))
    try:
        reply, calls = await ask(chat, prompt, CoverageReply, attempts=context.config.role_attempts, images=images,
                                 check=lambda r: check_reply(r, required, current))
    except (RoleOutputError, ProviderError) as exc:
        fallen = geometric_views(context.asset, windows)
        return fallen, list(getattr(exc, "calls", ())), [f"coverage selection failed ({type(exc).__name__}: {exc}); geometric views used"]
    chosen: dict[str, CoverageChoice] = {}
    notes = []
    for link, poses in windows.items():
        confirmed = await render_off_loop(_confirm, context.asset, poses, link, reply)
        if confirmed is None:
            notes.append(f"coverage: the model's views do not show {link}; geometric view used")
            chosen[link] = _record(await render_off_loop(choose_view, context.asset, poses, link), "geometric")
        else:
            chosen[link] = _record(confirmed, "model")
    return chosen, calls, notes


def _joint(context: Context, link: str) -> str:
    joint = context.asset.parent_joint(link)
    return joint.name if joint is not None else ""
