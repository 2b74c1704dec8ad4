"""Actuated phases + trajectory -> ``interaction.json`` (contact point, normal, path per phase)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.execute.trajectory import Trajectory
from app.engine.export.rotations import matrix_to_quaternion
from app.engine.export.track import MOTION_EPS, ExportTrack, build_track
from app.engine.files import atomic_write_text
from app.engine.interaction.contact import Contact, NoContact, choose_contact
from app.engine.interaction.model import ActuatedPhase, Interaction, InteractionDocument, PathSample
from app.engine.types import FloatArray

INTERACTION_FILE = "interaction.json"
TIME_EPS = 1e-9
MIN_DISPLACEMENT_M = 1e-6
"""A pushed base's direction is read from its first displacement at least this long."""


def phase_frames(trajectory: Trajectory, t0: float, t1: float) -> tuple[int, int]:
    """First and last frame covering ``[t0, t1]``: the one at or just before t0, the one at or just after t1."""
    last = max(trajectory.frame_count - 1, 0)
    first = min(max(math.floor(t0 * trajectory.fps + TIME_EPS), 0), last)
    final = min(max(math.ceil(t1 * trajectory.fps - TIME_EPS), first), last)
    return first, final


def _continuous(quaternions: FloatArray) -> FloatArray:
    """Flip signs so consecutive quaternions agree (and the first has w >= 0)."""
    out = np.array(quaternions, dtype=np.float64)
    if out.shape[0] and out[0, 3] < 0:
        out[0] = -out[0]
    for index in range(1, out.shape[0]):
        if float(out[index] @ out[index - 1]) < 0:
            out[index] = -out[index]
    return out


def _vector(values: FloatArray) -> tuple[float, float, float]:
    x, y, z = (float(v) for v in values)
    return (x, y, z)


def _contact(asset: ArticulatedAsset, track: ExportTrack, phase: ActuatedPhase, first: int, final: int) -> Contact | str:
    """The phase's contact, or why it has none."""
    poses = {name: stack[first] for name, stack in track.world.items()}
    if phase.joint is None:
        translation = np.asarray(track.trajectory.base_translation[first : final + 1], dtype=np.float64)
        lengths = np.linalg.norm(translation - translation[0], axis=1)
        moved = np.flatnonzero(lengths >= MIN_DISPLACEMENT_M)
        if moved.size == 0:
            return f"{phase.link}: the base does not move in [{phase.t0}, {phase.t1}] s"
        direction = (translation[moved[0]] - translation[0]) / lengths[moved[0]]
        return choose_contact(asset, phase, poses, push_direction=direction)
    values = track.values[phase.joint][first : final + 1]
    changes = np.flatnonzero(np.abs(values - values[0]) > MOTION_EPS)
    if changes.size == 0:
        return f"{phase.link}: joint {phase.joint} does not move in [{phase.t0}, {phase.t1}] s"
    sign = 1.0 if values[changes[0]] > values[0] else -1.0
    return choose_contact(asset, phase, poses, sign=sign)


def _record(track: ExportTrack, phase: ActuatedPhase, contact: Contact, first: int, final: int) -> Interaction:
    stack = track.world[phase.link][first : final + 1]
    positions = stack[:, :3, :3] @ contact.point + stack[:, :3, 3]
    orientations = _continuous(matrix_to_quaternion(stack[:, :3, :3]))
    times = track.trajectory.times[first : final + 1]
    path = [
        PathSample(time_s=float(t), position=_vector(p), orientation_xyzw=(float(q[0]), float(q[1]), float(q[2]), float(q[3])))
        for t, p, q in zip(times.tolist(), positions, orientations, strict=True)
    ]
    return Interaction(
        link=phase.link, joint=phase.joint, t0=phase.t0, t1=phase.t1, contact_point=path[0].position,
        contact_normal=_vector(stack[0, :3, :3] @ contact.normal), path=path, action=contact.action,
        direction=_vector(contact.direction_world), kind=phase.kind, feature=contact.feature,
    )


def _mismatch(asset: ArticulatedAsset, phase: ActuatedPhase) -> str:
    """Why the phase names no usable link/joint pair ("" when it does)."""
    if phase.link not in asset.links:
        return f"{phase.link}: unknown link"
    if phase.joint is None:
        return ""
    joint = asset.joints.get(phase.joint)
    if joint is None or not joint.movable:
        return f"{phase.link}: unknown or fixed joint {phase.joint!r}"
    if phase.link not in asset.moving_links(phase.joint):
        return f"{phase.link}: joint {phase.joint} does not move it"
    return ""


def interaction_targets(asset: ArticulatedAsset, trajectory: Trajectory, phases: Sequence[ActuatedPhase],
                        track: ExportTrack | None = None) -> InteractionDocument:
    """One :class:`Interaction` per actuated phase (phases that cannot have one are listed in ``notes``)."""
    track = track or build_track(asset, trajectory)
    interactions, notes = [], []
    for phase in phases:
        problem = _mismatch(asset, phase)
        if problem:
            notes.append(problem)
            continue
        first, final = phase_frames(trajectory, phase.t0, phase.t1)
        try:
            contact = _contact(asset, track, phase, first, final)
        except NoContact as exc:
            notes.append(str(exc))
            continue
        if isinstance(contact, str):
            notes.append(contact)
            continue
        interactions.append(_record(track, phase, contact, first, final))
    return InteractionDocument(interactions=interactions, notes=notes)


def write_interactions(out_dir: Path, document: InteractionDocument) -> str:
    """Write ``interaction.json`` into ``out_dir``; returns its file name."""
    atomic_write_text(out_dir / INTERACTION_FILE, document.dumps() + "\n")
    return INTERACTION_FILE
