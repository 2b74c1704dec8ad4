"""``scene.xml``: the asset as an MJCF model with keyframes (read with the ``mujoco`` package).

One ``<body>`` per URDF link, **named as the link**, nested as the kinematic tree; its
``pos``/``quat`` are the joint origin. Joints keep their URDF names: revolute ->
``hinge`` with ``range``, continuous -> unlimited ``hinge``, prismatic -> ``slide`` with
``range``, fixed -> none (the body is welded). Mimic joints are real joints tied to their
leader by an ``<equality><joint polycoef=...>``. When the base moves the root body gets a
free joint (``base``), placed at the first frame's base pose. Keyframes:
``<key name time qpos>`` at the first frame, at the end of every plan phase and at the
last frame (one key per distinct frame; ``time`` is the frame's time). Applying a key
(``mj_resetDataKeyframe`` + ``mj_kinematics``) reproduces the link poses of that frame.
Opens in MuJoCo's ``simulate`` viewer (``python -m mujoco.viewer --mjcf scene.xml``).
A link named ``world`` can only be the root of an object whose base does not move (it is
MuJoCo's world body then).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from xml.etree import ElementTree

import numpy as np

from app.engine.asset.model import JointSpec
from app.engine.errors import ExportError
from app.engine.export.mjcf_assets import MeshLibrary, inertial, numbers
from app.engine.export.rotations import matrix_to_quaternion
from app.engine.export.track import ExportTrack
from app.engine.files import atomic_write_text
from app.engine.types import FloatArray

MJCF_FILE = "scene.xml"
WORLD_BODY = "world"
FREE_JOINT = "base"
JOINT_TYPES = {"revolute": "hinge", "continuous": "hinge", "prismatic": "slide"}


def _wxyz(rotation: FloatArray) -> FloatArray:
    x, y, z, w = matrix_to_quaternion(rotation)
    return np.array([w, x, y, z])


def key_frames(track: ExportTrack, phase_ends: Sequence[tuple[str, float]]) -> list[tuple[str, int]]:
    """(key name, frame index): the first frame, each phase end (nearest frame), the last frame.

    One key per distinct frame, in frame order; the first name given for a frame wins.
    """
    last = max(track.frame_count - 1, 0)
    marks = [("start", 0), *((f"{name}_end", min(max(round(t1 * track.fps), 0), last)) for name, t1 in phase_ends), ("end", last)]
    chosen: dict[int, str] = {}
    for name, frame in marks:
        chosen.setdefault(frame, name)
    used: set[str] = set()
    keys = []
    for frame in sorted(chosen):
        name, suffix = chosen[frame], 1
        while name in used:
            name, suffix = f"{chosen[frame]}_{suffix}", suffix + 1
        used.add(name)
        keys.append((name, frame))
    return keys


class _Builder:
    def __init__(self, track: ExportTrack, geometry: bool) -> None:
        self.track, self.asset, self.geometry = track, track.asset, geometry
        self.library = MeshLibrary()
        self.qpos_layout: list[str] = []
        """Names in qpos order: FREE marker for the free joint, else movable joint names."""
        self.free_name = FREE_JOINT if FREE_JOINT not in self.asset.joints else f"artimo_{FREE_JOINT}"

    def worldbody(self) -> ElementTree.Element:
        asset, track = self.asset, self.track
        for link in asset.link_order:
            if link == WORLD_BODY and (link != asset.root_link or track.base_moves):
                raise ExportError("a link named 'world' is MuJoCo's world body: it must be the root of an object whose base does not move")
        world = ElementTree.Element("worldbody")
        if asset.root_link == WORLD_BODY:
            self._fill(world, WORLD_BODY, with_inertial=False)
            return world
        base = track.local[asset.root_link][0]
        body = ElementTree.SubElement(world, "body", {"name": asset.root_link, "pos": numbers(base[:3, 3]), "quat": numbers(_wxyz(base[:3, :3]))})
        if track.base_moves:
            ElementTree.SubElement(body, "freejoint", {"name": self.free_name})
            self.qpos_layout.append(self.free_name)
        self._fill(body, asset.root_link, with_inertial=True)
        return world

    def _fill(self, body: ElementTree.Element, link: str, *, with_inertial: bool) -> None:
        spec = self.asset.links[link]
        if with_inertial:
            ElementTree.SubElement(body, "inertial", inertial(spec))
        if self.geometry:
            for attributes in self.library.geoms(spec):
                ElementTree.SubElement(body, "geom", attributes)
        for joint in self.asset.child_joints(link):
            self._child(body, joint)

    def _child(self, parent: ElementTree.Element, joint: JointSpec) -> None:
        body = ElementTree.SubElement(parent, "body", {
            "name": joint.child, "pos": numbers(joint.origin[:3, 3]), "quat": numbers(_wxyz(joint.origin[:3, :3])),
        })
        if joint.movable:
            attributes = {"name": joint.name, "type": JOINT_TYPES[joint.type], "pos": "0 0 0", "axis": numbers(joint.axis)}
            if joint.bounded and joint.lower is not None and joint.upper is not None:
                attributes.update(limited="true", range=numbers([joint.lower, joint.upper]))
            else:
                attributes["limited"] = "false"
            ElementTree.SubElement(body, "joint", attributes)
            self.qpos_layout.append(joint.name)
        self._fill(body, joint.child, with_inertial=True)

    def equality(self) -> ElementTree.Element | None:
        ties = [j for j in self.asset.joints.values() if j.movable and j.mimic is not None
                and j.mimic.joint in self.asset.joints and self.asset.joints[j.mimic.joint].movable]
        if not ties:
            return None
        element = ElementTree.Element("equality")
        for joint in ties:
            assert joint.mimic is not None
            ElementTree.SubElement(element, "joint", {
                "joint1": joint.name, "joint2": joint.mimic.joint, "polycoef": numbers([joint.mimic.offset, joint.mimic.multiplier, 0.0, 0.0, 0.0]),
            })
        return element

    def qpos(self, frame: int) -> FloatArray:
        values: list[float] = []
        trajectory = self.track.trajectory
        for name in self.qpos_layout:
            if name == self.free_name and name not in self.asset.joints:
                x, y, z, w = np.asarray(trajectory.base_rotation_xyzw[frame], dtype=np.float64)
                values.extend([*np.asarray(trajectory.base_translation[frame], dtype=np.float64).tolist(), w, x, y, z])
            else:
                values.append(float(self.track.values[name][frame]))
        return np.array(values, dtype=np.float64)


def mjcf_text(track: ExportTrack, phase_ends: Sequence[tuple[str, float]] = (), *, geometry: bool = True) -> str:
    """The ``scene.xml`` text (needs no optional package; reading it back needs ``mujoco``).

    Raises
    ------
    ExportError
        A link named ``world`` that is not a static root.
    """
    builder = _Builder(track, geometry)
    root = ElementTree.Element("mujoco", {"model": track.asset.name})
    ElementTree.SubElement(root, "compiler", {"angle": "radian", "autolimits": "true"})
    worldbody = builder.worldbody()
    if builder.library.skipped:
        root.append(ElementTree.Comment(" parts left out (MuJoCo needs an area): " + "; ".join(builder.library.skipped) + " "))
    root.append(builder.library.asset_element())
    root.append(worldbody)
    equality = builder.equality()
    if equality is not None:
        root.append(equality)
    keyframe = ElementTree.SubElement(root, "keyframe")
    for name, frame in key_frames(track, phase_ends):
        attributes = {"name": name, "time": repr(float(track.trajectory.times[frame]))}
        if builder.qpos_layout:
            attributes["qpos"] = numbers(builder.qpos(frame))
        ElementTree.SubElement(keyframe, "key", attributes)
    ElementTree.indent(root)
    return ElementTree.tostring(root, encoding="unicode") + "\n"


def write_mjcf(track: ExportTrack, out_dir: Path, phase_ends: Sequence[tuple[str, float]] = (), *, geometry: bool = True) -> str:
    """Write ``scene.xml`` into ``out_dir``; returns its file name."""
    atomic_write_text(out_dir / MJCF_FILE, mjcf_text(track, phase_ends, geometry=geometry))
    return MJCF_FILE
