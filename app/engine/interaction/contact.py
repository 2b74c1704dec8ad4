"""Choose the contact point of one actuated phase from the link's mesh (deterministic).

Rules (all in the phase link's frame, at the frame the phase starts from):

* whole-object push: the centre of the object's rear face (facing away from the motion);
* rotation about an axis through the part: when the most free space is along the axis
  (knob, dial, turntable) the centre of that face, action ``turn``; when it is across the
  axis (rocker switch) the end of that face that goes into it, pushed;
* prismatic part or a part swinging about an off-centre axis (drawer, button, door, lid,
  pedal): the face it is touched on is the push side (opposite its motion) for a control,
  and the side with the most free space in front for a part moved by hand. On that face:
  a handle's grip when the part has one (a visual named ``*handle*``/``*grip*``/``*knob*``),
  else the tread centre for a swinging control (pedal, lever), the face centre for a
  sliding part (button, drawer front), the free edge for a swinging part (door, lid).
  Action: ``pull`` when the contact starts moving out of its face, else ``push``.

A caller-given action (``push``/``pull``) picks the side: push = opposite the motion.
The point is the mesh surface point nearest the rule's target, on triangles facing that
side, so it lies on the surface; its normal is the triangle's, pointing out of the face.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.interaction.features import basis, end_target, face_target, free_edge_target, more_exposed, snap, unit
from app.engine.interaction.model import Action, ActuatedPhase, ContactFeature
from app.engine.types import FloatArray, Transform

GRIP = re.compile(r"handle|grip|knob", re.IGNORECASE)
CENTRED_RATIO = 0.25
"""A rotating part turns about its own centre when its box centre is closer to the axis
than this fraction of its farthest point (knob, dial, wheel; not a door or a pedal)."""


class NoContact(Exception):
    """The phase's link has nothing to touch (no geometry in its rigid group)."""


@dataclass(frozen=True)
class Contact:
    """Chosen contact: ``point``/``normal`` in the link frame, ``direction_world`` at t0."""

    point: FloatArray
    normal: FloatArray
    feature: ContactFeature
    action: Action
    direction_world: FloatArray


def rigid_group(asset: ArticulatedAsset, link: str) -> tuple[str, ...]:
    """``link`` and every link joined to it through fixed joints only (up and down), in link order."""
    group = {link}
    changed = True
    while changed:
        changed = False
        for joint in asset.joints.values():
            if joint.type == "fixed" and (joint.parent in group) != (joint.child in group):
                group |= {joint.parent, joint.child}
                changed = True
    return tuple(n for n in asset.link_order if n in group)


def _triangles(asset: ArticulatedAsset, links: tuple[str, ...], poses: dict[str, Transform], frame: Transform) -> tuple[FloatArray, FloatArray]:
    """(t, 3, 3) triangles of ``links`` in the frame ``frame`` (world pose), and (t,) grip flags."""
    inverse = np.linalg.inv(frame)
    chunks, grips = [], []
    for name in links:
        relative = inverse @ poses[name]
        for part in asset.links[name].parts:
            vertices = part.vertices @ relative[:3, :3].T + relative[:3, 3]
            chunks.append(vertices[part.faces])
            grips.append(np.full(len(part.faces), bool(GRIP.search(part.visual))))
    if not chunks:
        return np.zeros((0, 3, 3)), np.zeros(0, dtype=bool)
    return np.concatenate(chunks), np.concatenate(grips)


def _limit(asset: ArticulatedAsset, poses: dict[str, Transform]) -> float:
    everything, _ = _triangles(asset, asset.link_order, poses, np.eye(4))
    points = everything.reshape(-1, 3)
    return float(np.linalg.norm(points.max(axis=0) - points.min(axis=0))) if points.size else 1.0


@dataclass(frozen=True)
class _Scene:
    """The link's world placement and the geometry that stays put while it moves."""

    rotation: FloatArray
    translation: FloatArray
    others: FloatArray
    limit: float

    def most_exposed(self, directions: list[FloatArray], vertices: FloatArray) -> int:
        """Index of the link's side (directions in the link frame) with the most free space in front (first on ties)."""
        world = vertices @ self.rotation.T + self.translation
        return more_exposed([self.rotation @ d for d in directions], world, self.others, self.limit)


def _others(asset: ArticulatedAsset, joint: str, poses: dict[str, Transform]) -> FloatArray:
    """World triangles of every link the joint does not move."""
    moved = set(asset.moving_links(joint))
    still = tuple(n for n in asset.link_order if n not in moved)
    triangles, _ = _triangles(asset, still, poses, np.eye(4))
    return triangles


def choose_contact(asset: ArticulatedAsset, phase: ActuatedPhase, poses: dict[str, Transform], *, sign: float = 1.0,
                   push_direction: FloatArray | None = None) -> Contact:
    """The contact of ``phase`` with the object posed at ``poses`` (world, at the phase's first frame).

    ``sign`` says which way the joint starts to move (+1 or -1); ``push_direction`` is the
    unit world direction the base starts to move in (whole-object push only).

    Raises
    ------
    NoContact
        The link's rigid group has no geometry.
    """
    frame = poses[phase.link]
    group = rigid_group(asset, phase.link)
    triangles, grips = _triangles(asset, group, poses, frame)
    if triangles.shape[0] == 0:
        raise NoContact(f"link {phase.link} (and the links fixed to it) has no geometry to touch")
    rotation = frame[:3, :3]
    vertices = triangles.reshape(-1, 3)
    if phase.joint is None:
        if push_direction is None:
            raise ValueError("a whole-object push needs push_direction")
        e = -(rotation.T @ push_direction)
        found = snap(triangles, face_target(vertices, e), e)
        return Contact(found.point, found.normal, "rear_face", phase.action or "push", push_direction)
    joint = asset.joints[phase.joint]
    child = np.linalg.inv(frame) @ poses[joint.child]
    axis, anchor = unit(child[:3, :3] @ joint.axis), child[:3, 3]
    scene = _Scene(rotation, frame[:3, 3], _others(asset, phase.joint, poses), _limit(asset, poses))
    if joint.type == "prismatic":
        return _slide(phase, triangles, grips, sign * axis, scene)
    centre = (vertices.min(axis=0) + vertices.max(axis=0)) / 2.0
    offset = centre - anchor - ((centre - anchor) @ axis) * axis
    reach = np.linalg.norm(vertices - anchor - np.outer((vertices - anchor) @ axis, axis), axis=1).max()
    if np.linalg.norm(offset) < CENTRED_RATIO * reach:
        return _centred(phase, triangles, sign * axis, anchor, scene)
    return _swing(phase, triangles, grips, axis * sign, anchor, unit(np.cross(sign * axis, offset)), scene)


def _side(phase: ActuatedPhase, motion: FloatArray, vertices: FloatArray, scene: _Scene) -> FloatArray:
    """The face normal (link frame) the actor touches for a part moving along ``motion`` here."""
    if phase.action == "pull":
        return motion
    if phase.action == "push" or phase.kind == "control_actuation":
        return -motion
    return [motion, -motion][scene.most_exposed([motion, -motion], vertices)]


def _centred(phase: ActuatedPhase, triangles: FloatArray, omega: FloatArray, anchor: FloatArray, scene: _Scene) -> Contact:
    """A part rotating about its own middle: a knob/dial/turntable (free along the axis) is turned at
    its face centre; a rocker (free across the axis) is pushed on the end that goes into its face."""
    vertices = triangles.reshape(-1, 3)
    axis = unit(omega)
    first, second = basis(axis)
    sides = [axis, -axis, first, -first, second, -second]
    best = scene.most_exposed(sides, vertices)
    side = sides[best]
    if best < 2:
        found = snap(triangles, face_target(vertices, side), side)
        return Contact(found.point, found.normal, "face_centre", "turn", scene.rotation @ omega)
    found = snap(triangles, end_target(vertices, side, -unit(np.cross(side, omega))), side)
    velocity = unit(np.cross(omega, found.point - anchor))
    action: Action = phase.action or ("pull" if float(velocity @ side) > 0 else "push")
    return Contact(found.point, found.normal, "tread", action, scene.rotation @ velocity)


def _slide(phase: ActuatedPhase, triangles: FloatArray, grips: FloatArray, motion: FloatArray, scene: _Scene) -> Contact:
    vertices = triangles.reshape(-1, 3)
    e = _side(phase, motion, vertices, scene)
    use_grip = phase.kind != "control_actuation" and bool(grips.any())
    pool = triangles[grips] if use_grip else triangles
    found = snap(pool, face_target(pool.reshape(-1, 3), e), e)
    action: Action = phase.action or ("pull" if float(motion @ e) > 0 else "push")
    return Contact(found.point, found.normal, "handle" if use_grip else "face_centre", action, scene.rotation @ motion)


def _swing(phase: ActuatedPhase, triangles: FloatArray, grips: FloatArray, omega: FloatArray, anchor: FloatArray, motion: FloatArray,
           scene: _Scene) -> Contact:
    """A part swinging about an off-centre axis; ``motion`` is how its centre starts to move."""
    vertices = triangles.reshape(-1, 3)
    e = _side(phase, motion, vertices, scene)
    feature: ContactFeature
    if phase.kind != "control_actuation" and grips.any():
        pool, feature = triangles[grips], "handle"
        target = face_target(pool.reshape(-1, 3), e)
    elif phase.kind == "control_actuation":
        pool, feature = triangles, "tread"
        target = face_target(vertices, e)
    else:
        pool, feature = triangles, "free_edge"
        target = free_edge_target(vertices, unit(omega), anchor, e)
    found = snap(pool, target, e)
    velocity = unit(np.cross(omega, found.point - anchor))
    action: Action = phase.action or ("pull" if float(velocity @ e) > 0 else "push")
    return Contact(found.point, found.normal, feature, action, scene.rotation @ velocity)
