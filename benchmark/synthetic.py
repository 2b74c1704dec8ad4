"""Synthetic predictions of a case: the ground truth and controlled degradations of it.

Used to check an evaluator (every degradation must score strictly below the perfect
prediction) and to time it. Degradations of a GT trajectory:

- ``perfect``: the GT trajectory itself;
- ``half_way``: every joint and the base go only half-way from rest;
- ``wrong_joint``: each constrained joint's motion is played on another, unconstrained
  movable joint instead (skipped when the asset has none);
- ``reversed``: the frames in reverse order;
- ``static``: the rest pose throughout;
- ``missing_part``: the first constrained joint never moves (absent from the file).

``deleted_link_glb`` writes the GT as a GLB whose node of one link is renamed, so that
link is missing from the prediction.
"""

from __future__ import annotations

import json
import struct
from pathlib import Path

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.export.glb import glb_bytes
from app.engine.export.gltf_container import split_glb
from app.engine.export.jsonl import write_trajectory_jsonl
from app.engine.files import atomic_write_bytes
from app.engine.metrics.compiler import GroundTruth

GLB_MAGIC = 0x46546C67
JSON_CHUNK = 0x4E4F534A
BIN_CHUNK = 0x004E4942


def with_values(trajectory: Trajectory, q: np.ndarray, translation: np.ndarray | None = None) -> Trajectory:
    """``trajectory`` with joint values ``q`` (f, j) and, if given, base translations (f, 3)."""
    return Trajectory(
        fps=trajectory.fps,
        times=trajectory.times.copy(),
        joint_names=trajectory.joint_names,
        q=q,
        base_translation=trajectory.base_translation.copy() if translation is None else translation,
        base_rotation_xyzw=trajectory.base_rotation_xyzw.copy(),
    )


def _constrained(truth: GroundTruth) -> list[str]:
    seen: list[str] = []
    for state in sorted(truth.key_states, key=lambda s: s.phase_index):
        seen.extend(j for j in state.constrained_joints if j not in seen)
    return seen


def degraded_trajectories(asset: ArticulatedAsset, truth: GroundTruth) -> dict[str, Trajectory]:
    """{name: trajectory} of the perfect prediction and every applicable degradation."""
    gt = truth.trajectory
    rest = np.array([asset.joints[n].rest for n in gt.joint_names])
    out = {"perfect": gt}
    out["half_way"] = with_values(gt, rest + 0.5 * (gt.q - rest), 0.5 * gt.base_translation)
    constrained = [j for j in _constrained(truth) if j in gt.joint_names]
    spare = [j for j in asset.controllable_joints if j not in constrained and j in gt.joint_names]
    if constrained and spare:
        q = np.tile(rest, (gt.frame_count, 1))
        for source, target in zip(constrained, spare, strict=False):
            joint = asset.joints[target]
            moved = gt.q[:, gt.joint_names.index(source)] - asset.joints[source].rest
            q[:, gt.joint_names.index(target)] = joint.clamp_array(joint.rest + moved)
        out["wrong_joint"] = with_values(gt, q, gt.base_translation.copy())
    out["reversed"] = with_values(gt, gt.q[::-1].copy(), gt.base_translation[::-1].copy())
    out["static"] = with_values(gt, np.tile(rest, (gt.frame_count, 1)), np.zeros_like(gt.base_translation))
    if constrained:
        q = gt.q.copy()
        column = gt.joint_names.index(constrained[0])
        q[:, column] = rest[column]
        out["missing_part"] = with_values(gt, q)
    return out


def write_predictions(asset: ArticulatedAsset, truth: GroundTruth, folder: Path) -> dict[str, Path]:
    """Write every degraded trajectory to ``folder/<name>/trajectory.jsonl``."""
    return {
        name: write_trajectory_jsonl(t, folder / name / "trajectory.jsonl")
        for name, t in degraded_trajectories(asset, truth).items()
    }


def pack_glb(document: dict[str, object], binary: bytes | None) -> bytes:
    """A GLB container of a glTF JSON document and its binary chunk."""
    text = json.dumps(document, separators=(",", ":")).encode("utf-8")
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), JSON_CHUNK) + text
    if binary:
        padded = binary + b"\0" * (-len(binary) % 4)
        body += struct.pack("<II", len(padded), BIN_CHUNK) + padded
    return struct.pack("<III", GLB_MAGIC, 2, 12 + len(body)) + body


def deleted_link_glb(asset: ArticulatedAsset, trajectory: Trajectory, link: str, path: Path) -> Path:
    """The animated GLB of ``trajectory`` with ``link``'s node renamed (so the link is missing)."""
    document, binary = split_glb(glb_bytes(asset, trajectory), "synthetic")
    for node in document["nodes"]:
        if node.get("name") == link:
            node["name"] = f"renamed_{link}"
    return atomic_write_bytes(path, pack_glb(document, binary))
