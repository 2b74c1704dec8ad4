"""Posed link sequences: what the metrics compare, from a trajectory or an animated GLB.

A :class:`PoseSequence` holds, for T frames, the world pose (URDF world, +Z up) of every
visual link the source provides; visual links it does not provide are ``missing`` and
score worst.

Trajectories (ours or ``trajectory.jsonl`` from another tool) are posed by the asset's
forward kinematics after clamping every bounded, non-mimic joint into its URDF limits
(as our executor would); mimic joints are always derived from their leaders.

GLBs are read geometrically: a link's pose is the world transform of the node that
carries it (a node named exactly as the link, or one mapped to it by ``node_map``),
sampled at every distinct key time of the first animation. glTF is +Y up, so node world
transforms are brought back to +Z up with the inverse of
:data:`~app.engine.export.rotations.Z_UP_TO_Y_UP` (``up_axis="Y"``, the default and what
our ``artimo_root`` node produces); ``up_axis="Z"`` takes them as they are. The node's
frame must be the URDF link frame (meshes in link coordinates), as in our exporter.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from app.engine.asset.kinematics import base_transforms, link_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import MetricError
from app.engine.execute.trajectory import Trajectory
from app.engine.export.gltf_reader import GltfScene
from app.engine.export.rotations import Z_UP_TO_Y_UP
from app.engine.types import FloatArray, Transforms

UpAxis = Literal["Y", "Z"]


@dataclass(frozen=True, eq=False)
class PoseSequence:
    """World poses of visual links over T frames.

    Attributes
    ----------
    times : (T,) float, seconds
    poses : {link: (T, 4, 4) float} link frame -> world (+Z up)
    missing : visual links the source does not provide
    """

    times: FloatArray
    poses: Mapping[str, Transforms]
    missing: tuple[str, ...]
    source: str
    notes: tuple[str, ...] = field(default_factory=tuple)

    @property
    def frame_count(self) -> int:
        return int(self.times.shape[0])

    def take(self, frames: list[int]) -> PoseSequence:
        """The sub-sequence at ``frames`` (indices may repeat)."""
        index = np.asarray(frames, dtype=np.int64)
        return PoseSequence(
            times=self.times[index],
            poses={name: pose[index] for name, pose in self.poses.items()},
            missing=self.missing,
            source=self.source,
            notes=self.notes,
        )


def empty_sequence(asset: ArticulatedAsset, source: str, note: str) -> PoseSequence:
    """A one-frame sequence with every visual link missing (a prediction that does not exist)."""
    return PoseSequence(times=np.zeros(1), poses={}, missing=asset.visual_links, source=source, notes=(note,))


def clamped_joint_values(asset: ArticulatedAsset, trajectory: Trajectory) -> tuple[dict[str, FloatArray], list[str]]:
    """{controllable joint: (T,) values clamped to its limits}, and notes on clamped joints."""
    values: dict[str, FloatArray] = {}
    notes = []
    for name in asset.controllable_joints:
        if name not in trajectory.joint_names:
            continue
        raw = np.asarray(trajectory.joint(name), dtype=np.float64)
        clamped = asset.joints[name].clamp_array(raw)
        if not np.array_equal(clamped, raw):
            worst = float(np.abs(clamped - raw).max())
            notes.append(f"joint {name}: values outside its limits clamped (by up to {worst:.6g})")
        values[name] = clamped
    return values, notes


def trajectory_sequence(
    asset: ArticulatedAsset, trajectory: Trajectory, source: str, notes: tuple[str, ...] = ()
) -> PoseSequence:
    """Pose every visual link of ``asset`` along ``trajectory`` (clamped, mimics derived)."""
    values, clamp_notes = clamped_joint_values(asset, trajectory)
    count = trajectory.frame_count
    base = base_transforms(np.asarray(trajectory.base_translation), np.asarray(trajectory.base_rotation_xyzw))
    poses = link_poses(asset, values, base=base, frames=count)
    return PoseSequence(
        times=np.asarray(trajectory.times, dtype=np.float64).copy(),
        poses={name: poses[name] for name in asset.visual_links},
        missing=(),
        source=source,
        notes=tuple(notes) + tuple(clamp_notes),
    )


def _node_for_links(
    asset: ArticulatedAsset, scene: GltfScene, node_map: Mapping[str, str] | None
) -> tuple[dict[str, str], list[str]]:
    """{visual link: node name} from exact names, overridden by ``node_map`` {node: link}."""
    notes = []
    chosen: dict[str, str] = {}
    names = set(scene.node_names)
    for node, link in sorted((node_map or {}).items()):
        if link not in asset.links:
            raise MetricError(f"node map: '{node}' maps to '{link}', which is not a link of {asset.name}")
        if node not in names:
            notes.append(f"node map: the GLB has no node '{node}'")
            continue
        if link in chosen:
            raise MetricError(f"node map: link '{link}' is mapped from both '{chosen[link]}' and '{node}'")
        chosen[link] = node
    for link in asset.visual_links:
        if link not in chosen and link in names:
            chosen[link] = link
    return chosen, notes


def glb_sequence(
    asset: ArticulatedAsset,
    scene: GltfScene,
    *,
    node_map: Mapping[str, str] | None = None,
    up_axis: UpAxis = "Y",
    animation: int | str = 0,
) -> PoseSequence:
    """Link poses from an animated GLB's node world transforms (see the module docstring).

    Raises
    ------
    MetricError
        A bad node map or animation.
    """
    chosen, notes = _node_for_links(asset, scene, node_map)
    times = np.asarray(scene.animation_times(animation), dtype=np.float64)
    tracks = scene.world_transform_tracks(times, animation) if chosen else {}
    back = Z_UP_TO_Y_UP.T if up_axis == "Y" else np.eye(4)
    poses = {link: back[None] @ tracks[chosen[link]] for link in asset.visual_links if link in chosen}
    missing = tuple(link for link in asset.visual_links if link not in chosen)
    if missing:
        notes.append(f"links with no node in the GLB (scored worst): {', '.join(missing)}")
    return PoseSequence(
        times=times, poses=poses, missing=missing, source=scene.source, notes=tuple(notes + scene.warnings)
    )
