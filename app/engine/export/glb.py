"""``animation.glb`` (SPEC §4): the asset's link tree animated by a trajectory.

Layout of the written glTF:

- node 0 ``artimo_root``: rotation ``-90 deg about X`` (URDF +Z up -> glTF +Y up)
  composed with the base pose, i.e. translation ``R p(t)`` and rotation ``R Rb(t)``;
  its only child is the root link's node.
- one node per URDF link, named exactly as the link, nested as the kinematic tree;
  a child link's local transform is ``joint.origin @ motion(q)``; static TRS = frame 0.
  ``extras.joint`` = ``{name, type, axis, lower, upper}`` of the link's parent joint
  (``null`` for the root link).
- one mesh per link with geometry (vertices in the link frame), one primitive per part.
- one animation ``action`` with LINEAR channels at the trajectory's frame times for the
  paths that move.

The JSON and binary chunk are written directly; output is byte-identical for identical
input.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.asset.model import ArticulatedAsset, JointSpec
from app.engine.errors import ExportError
from app.engine.execute.trajectory import Trajectory
from app.engine.export.animation import NodeTrack, add_animation, check_trajectory, link_tracks, normalised, root_track
from app.engine.export.glb_meshes import geometry_block
from app.engine.files import atomic_write_bytes

logger = logging.getLogger(__name__)

ROOT_NODE_NAME = "artimo_root"
GENERATOR = "ArtiMo animated GLB exporter"


def joint_extras(joint: JointSpec | None) -> dict[str, Any]:
    """``extras`` of a link node: its parent joint (``{"joint": None}`` for the root link)."""
    if joint is None:
        return {"joint": None}
    return {
        "joint": {
            "name": joint.name,
            "type": joint.type,
            "axis": [float(v) for v in joint.axis],
            "lower": None if joint.lower is None else float(joint.lower),
            "upper": None if joint.upper is None else float(joint.upper),
        }
    }


def _static_trs(node: dict[str, Any], track: NodeTrack) -> None:
    """Frame-0 TRS, rounded to float32 like the animation keys (so both agree exactly)."""
    translation = [float(v) for v in track.translation[0].astype(np.float32)]
    rotation = [float(v) for v in normalised(track.rotation[:1])[0].astype(np.float32)]
    if any(v != 0.0 for v in translation):
        node["translation"] = translation
    if rotation != [0.0, 0.0, 0.0, 1.0]:
        node["rotation"] = rotation


def _nodes(
    asset: ArticulatedAsset, tracks: dict[str, NodeTrack], root: NodeTrack, meshes: dict[str, int]
) -> list[dict[str, Any]]:
    index = {name: i + 1 for i, name in enumerate(asset.link_order)}
    top: dict[str, Any] = {"name": ROOT_NODE_NAME, "children": [index[asset.root_link]]}
    _static_trs(top, root)
    top["extras"] = {"asset": asset.name, "up_axis": "Y", "source_up_axis": "Z"}
    nodes = [top]
    for name in asset.link_order:
        node: dict[str, Any] = {"name": name}
        children = [index[j.child] for j in asset.child_joints(name)]
        if children:
            node["children"] = children
        if name in meshes:
            node["mesh"] = meshes[name]
        _static_trs(node, tracks[name])
        node["extras"] = joint_extras(asset.parent_joint(name))
        nodes.append(node)
    return nodes


def glb_bytes(asset: ArticulatedAsset, trajectory: Trajectory) -> bytes:
    """The animated GLB of ``asset`` moved by ``trajectory``, as bytes.

    Parameters
    ----------
    asset
        The articulated asset (meshes in link frames, URDF world +Z up).
    trajectory
        Joint values (f, j) and base pose per frame; keys are written at ``trajectory.times``.

    Raises
    ------
    ExportError
        Trajectory not representable (see :func:`check_trajectory`) or malformed geometry.
    """
    check_trajectory(asset, trajectory)
    block = geometry_block(asset)
    builder = block.builder.copy()
    tracks = link_tracks(asset, trajectory)
    root = root_track(trajectory)
    nodes = _nodes(asset, tracks, root, dict(block.mesh_of_link))
    targets = [(0, root)] + [(i + 1, tracks[name]) for i, name in enumerate(asset.link_order)]
    animation = add_animation(builder, trajectory.times, targets)
    document = builder.document(
        asset={"generator": GENERATOR, "version": "2.0"},
        scene=0,
        scenes=[{"name": asset.name, "nodes": [0]}],
        nodes=nodes,
        animations=[animation],
    )
    return builder.glb(document)


def export_glb(asset: ArticulatedAsset, trajectory: Trajectory, path: str | Path) -> Path:
    """Write :func:`glb_bytes` atomically to ``path``; returns the path.

    Raises
    ------
    ExportError
        As :func:`glb_bytes`, or when the file cannot be written.
    """
    data = glb_bytes(asset, trajectory)
    try:
        target = atomic_write_bytes(path, data)
    except OSError as exc:
        raise ExportError(f"cannot write {path}: {exc}") from exc
    logger.debug("wrote %s (%d bytes, %d frames)", target, len(data), trajectory.frame_count)
    return target
