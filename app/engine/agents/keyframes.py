"""HEAD/TAIL keyframes with motion cues for one critic case, from the view that shows it best.

The view is chosen among the four canonical ones (azimuth 0/90/180/270, elevation 20): the
one where the moving link is visible at the tail and its tracked motion projects longest.
"""

from __future__ import annotations

import io
from typing import Any

import numpy as np

from app.engine.asset.kinematics import base_transforms, link_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.providers.base import Image

KEYFRAME_SIZE = (640, 480)


def _poses_at(asset: ArticulatedAsset, trajectory: Trajectory, frame: int) -> dict[str, np.ndarray]:
    values = {name: trajectory.joint(name)[frame : frame + 1] for name in trajectory.joint_names}
    poses = link_poses(asset, values, base_transforms(trajectory.base_translation[frame : frame + 1]))
    return {name: pose[0] for name, pose in poses.items()}


def _best_camera(asset: ArticulatedAsset, trajectory: Trajectory, link: str, head: int, tail: int) -> Any:
    from app.engine.render import gl_backend
    from app.engine.render.camera import canonical_views, view_camera

    head_poses, tail_poses = _poses_at(asset, trajectory, head), _poses_at(asset, trajectory, tail)
    vertices = asset.links[link].vertices()
    best, best_score = None, -1.0
    for view in canonical_views():
        camera = view_camera(asset, view, *KEYFRAME_SIZE)
        ids, names = gl_backend.render_link_ids(asset, tail_poses, camera)
        visible = float(np.count_nonzero(ids == names.index(link))) if link in names else 0.0
        start = vertices @ head_poses[link][:3, :3].T + head_poses[link][:3, 3]
        end = vertices @ tail_poses[link][:3, :3].T + tail_poses[link][:3, 3]
        moved = float(np.linalg.norm(camera.project(end)[0] - camera.project(start)[0], axis=1).mean()) if vertices.shape[0] else 0.0
        score = np.sqrt(visible) + moved
        if score > best_score:
            best, best_score = camera, score
    return best


def critic_keyframes(asset: ArticulatedAsset, trajectory: Trajectory, case: dict[str, Any]) -> list[Image]:
    """[HEAD, TAIL] PNGs for ``case`` (needs EGL; raises RenderError without it)."""
    from app.engine.render.cues import render_keyframes

    link, head, tail = case["link"], int(case["head_frame"]), int(case["tail_frame"])
    camera = _best_camera(asset, trajectory, link, head, tail)
    images = []
    for tag, picture in zip(("HEAD", "TAIL"), render_keyframes(asset, trajectory, link, head, tail, camera), strict=True):
        buffer = io.BytesIO()
        picture.save(buffer, format="PNG")
        images.append(Image(name=f"TIMELINE_SAMPLE_{tag}_seg{case['segment_index']}_{case['joint']}.png", png=buffer.getvalue()))
    return images
