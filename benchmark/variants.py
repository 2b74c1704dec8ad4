"""Variants of an asset folder for the metamorphic probe (:mod:`benchmark.metamorphic`): the same object written
down differently (``flip``, ``rename``, ``reorder``, ``shift``, ``move``), turned (``yaw``), resting ajar (``ajar``) or
seen in a mirror (``mirror``: its left and right swapped), with the :class:`Mapping` from the original's joint values to
the variant's."""

from __future__ import annotations

import math
import os
import re
import shutil
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

TRANSFORMS = ("flip", "rename", "reorder", "shift", "mirror", "move", "yaw", "ajar")
PURE = ("flip", "rename", "reorder", "shift", "move")
MOVABLE = ("revolute", "prismatic", "continuous")
NUMBERED = re.compile(r"^(link|joint)_(\d+)$")


@dataclass
class Mapping:
    """How a variant's joints relate to the original's: new name and sign per joint, the base turn."""

    names: dict[str, str] = field(default_factory=dict)
    signs: dict[str, float] = field(default_factory=dict)
    yaw_deg: float = 0.0
    offsets: dict[str, float] = field(default_factory=dict)
    """Joint -> what ``ajar`` adds to its values (after the sign): the variant's zero is the original's offset."""
    limits: dict[str, tuple[float, float]] = field(default_factory=dict)
    """Joint -> the original's limits, for each joint ``ajar`` set resting part-way."""
    mirrored: bool = False
    """``mirror``: the object is its own mirror image across the URDF's XZ plane (world +Y and -Y swapped)."""

    def name(self, joint: str) -> str:
        return self.names.get(joint, joint)

    def sign(self, joint: str) -> float:
        return self.signs.get(joint, 1.0)

    def value(self, joint: str, value: float) -> float:
        """The variant's value for the original's ``value`` of ``joint`` (the same pose)."""
        return self.sign(joint) * value + self.offsets.get(joint, 0.0)


def _xyz(text: str | None) -> np.ndarray:
    return np.array([float(v) for v in (text or "0 0 0").split()], dtype=float)


def _fmt(values: np.ndarray) -> str:
    return " ".join(repr(float(v)) for v in values)


def rpy_matrix(rpy: np.ndarray) -> np.ndarray:
    r, p, y = rpy
    rx = np.array([[1, 0, 0], [0, math.cos(r), -math.sin(r)], [0, math.sin(r), math.cos(r)]])
    ry = np.array([[math.cos(p), 0, math.sin(p)], [0, 1, 0], [-math.sin(p), 0, math.cos(p)]])
    rz = np.array([[math.cos(y), -math.sin(y), 0], [math.sin(y), math.cos(y), 0], [0, 0, 1]])
    return rz @ ry @ rx


def _matrix_rpy(m: np.ndarray) -> np.ndarray:
    pitch = math.asin(max(-1.0, min(1.0, -float(m[2, 0]))))
    if abs(math.cos(pitch)) > 1e-9:
        return np.array([math.atan2(m[2, 1], m[2, 2]), pitch, math.atan2(m[1, 0], m[0, 0])])
    return np.array([math.atan2(-m[1, 2], m[1, 1]), pitch, 0.0])  # gimbal lock: roll carries the rest


def _flip(robot: ET.Element, mapping: Mapping) -> None:
    joints = {j.get("name", ""): j for j in robot.iter("joint")}
    flipped = {name for name, j in joints.items() if j.get("type") in MOVABLE}
    for name in flipped:
        joint = joints[name]
        axis = joint.find("axis")
        if axis is None:
            axis = ET.SubElement(joint, "axis", {"xyz": "1 0 0"})  # URDF's default axis, now written down
        axis.set("xyz", _fmt(-_xyz(axis.get("xyz"))))
        limit = joint.find("limit")
        if limit is not None and joint.get("type") != "continuous":
            lower, upper = float(limit.get("lower", "0")), float(limit.get("upper", "0"))
            limit.set("lower", repr(-upper))
            limit.set("upper", repr(-lower))
        mapping.signs[name] = -1.0
    for joint in joints.values():
        mimic = joint.find("mimic")
        if mimic is not None and joint.get("name") in flipped:
            leader_sign = -1.0 if mimic.get("joint") in flipped else 1.0
            # q_f = m q_l + o, both written with flipped signs: -q_f' = m (s q_l') + o
            mimic.set("multiplier", repr(-leader_sign * float(mimic.get("multiplier", "1"))))
            mimic.set("offset", repr(-float(mimic.get("offset", "0"))))


def _numbered_backwards(names: list[str], prefix: str) -> dict[str, str]:
    numbers = sorted(int(m.group(2)) for n in names if (m := NUMBERED.match(n)) and m.group(1) == prefix)
    return {f"{prefix}_{a}": f"{prefix}_{b}" for a, b in zip(numbers, reversed(numbers), strict=True)}


def relink(joint: ET.Element, links: dict[str, str], joints: dict[str, str]) -> None:
    """The joint's parent, child and mimicked joint renamed by ``links`` / ``joints`` (names not in them kept)."""
    for tag in ("parent", "child"):
        element = joint.find(tag)
        if element is not None:
            element.set("link", links.get(element.get("link", ""), element.get("link", "")))
    mimic = joint.find("mimic")
    if mimic is not None:
        mimic.set("joint", joints.get(mimic.get("joint", ""), mimic.get("joint", "")))


def _rename(robot: ET.Element, mapping: Mapping) -> dict[str, str]:
    links = _numbered_backwards([lk.get("name", "") for lk in robot.iter("link")], "link")
    joints = _numbered_backwards([j.get("name", "") for j in robot.iter("joint")], "joint")
    for link in robot.iter("link"):
        link.set("name", links.get(link.get("name", ""), link.get("name", "")))
    for joint in robot.iter("joint"):
        joint.set("name", joints.get(joint.get("name", ""), joint.get("name", "")))
        relink(joint, links, joints)
    mapping.names = {old: joints.get(old, old) for old in set(mapping.signs) | set(joints)}
    return links


def _reorder(robot: ET.Element) -> None:
    elements = [e for e in robot if e.tag in ("link", "joint")]
    for element in elements:
        robot.remove(element)
    for element in reversed(elements):
        robot.append(element)


def _origin(element: ET.Element) -> np.ndarray:
    """The 4x4 pose an element's ``<origin>`` writes (identity when it has none)."""
    origin = element.find("origin")
    pose = np.eye(4)
    if origin is not None:
        pose[:3, :3] = rpy_matrix(_xyz(origin.get("rpy")))
        pose[:3, 3] = _xyz(origin.get("xyz"))
    return pose


def _set_origin(element: ET.Element, pose: np.ndarray) -> None:
    origin = element.find("origin")
    if origin is None:
        origin = ET.SubElement(element, "origin")
    origin.set("xyz", _fmt(pose[:3, 3]))
    origin.set("rpy", _fmt(_matrix_rpy(pose[:3, :3])))


SHIFT_M = 0.05
"""How far ``shift`` slides each joint's frame along its axis."""
MOVE = np.array([1.3, -0.7, 0.25])
"""Where ``move`` puts the whole object."""


def _attr(element: ET.Element, tag: str, name: str) -> str:
    """``<tag name=...>`` of ``element`` ("" when absent)."""
    found = element.find(tag)
    return found.get(name, "") if found is not None else ""


def _axis(joint: ET.Element) -> np.ndarray:
    """The joint's unit axis (URDF's default ``1 0 0`` when it writes none)."""
    axis = _xyz(_attr(joint, "axis", "xyz") or "1 0 0")
    return axis / np.linalg.norm(axis)


def _shift(robot: ET.Element) -> None:
    """Each movable joint's frame slid along its own axis, its child's contents slid back: the same hinge line."""
    links = {lk.get("name", ""): lk for lk in robot.iter("link")}
    for joint in list(robot.iter("joint")):
        if joint.get("type") not in MOVABLE:
            continue
        axis = _axis(joint)
        slide, back = np.eye(4), np.eye(4)
        slide[:3, 3], back[:3, 3] = SHIFT_M * axis, -SHIFT_M * axis
        _set_origin(joint, _origin(joint) @ slide)
        child = _attr(joint, "child", "link")
        held = [e for tag in ("visual", "collision", "inertial") for e in links[child].findall(tag)] if child in links else []
        held += [j for j in robot.iter("joint") if (p := j.find("parent")) is not None and p.get("link") == child]
        for element in held:
            _set_origin(element, back @ _origin(element))


MIRROR = np.diag([1.0, -1.0, 1.0, 1.0])
"""``mirror``: the reflection across the URDF's XZ plane."""


def _mirror(robot: ET.Element, mapping: Mapping) -> None:
    """The object's mirror image: every pose ``T`` conjugated by the reflection ``M`` (``M T M``, a proper pose), every
    mesh scaled by ``M``, so every point lands at ``M p``. A joint moves alike at the same values: a slide along ``M a``,
    a hinge about ``-M a`` (a reflection reverses the sense of every turn)."""
    for joint in robot.iter("joint"):
        _set_origin(joint, MIRROR @ _origin(joint) @ MIRROR)
        if joint.get("type") in MOVABLE:
            axis = MIRROR[:3, :3] @ _axis(joint)
            axis_element = joint.find("axis")
            if axis_element is None:
                axis_element = ET.SubElement(joint, "axis")
            axis_element.set("xyz", _fmt(-axis if joint.get("type") in ("revolute", "continuous") else axis))
    for link in robot.iter("link"):
        for element in (e for tag in ("visual", "collision", "inertial") for e in link.findall(tag)):
            if element.find("origin") is not None:
                _set_origin(element, MIRROR @ _origin(element) @ MIRROR)
            for mesh in element.iter("mesh"):
                scale = _xyz(mesh.get("scale") or "1 1 1")
                scale = np.repeat(scale, 3) if scale.size == 1 else scale
                mesh.set("scale", _fmt(MIRROR[:3, :3] @ scale))
    mapping.mirrored = True


def _root_held(robot: ET.Element) -> list[ET.Element]:
    """What places the object in the world: the root link's own shapes and the joints hanging from it."""
    children = {c.get("link", "") for j in robot.iter("joint") if (c := j.find("child")) is not None}
    roots = {lk.get("name") for lk in robot.iter("link") if lk.get("name") not in children}
    held = [e for lk in robot.iter("link") if lk.get("name") in roots for tag in ("visual", "collision", "inertial") for e in lk.findall(tag)]
    return held + [j for j in robot.iter("joint") if (p := j.find("parent")) is not None and p.get("link") in roots]


def _place(robot: ET.Element, pose: np.ndarray) -> None:
    for element in _root_held(robot):
        _set_origin(element, pose @ _origin(element))


def _move(robot: ET.Element) -> None:
    """The whole object placed elsewhere (everything the root carries, offset by :data:`MOVE`)."""
    offset = np.eye(4)
    offset[:3, 3] = MOVE
    _place(robot, offset)


def _yaw(robot: ET.Element, mapping: Mapping, degrees: float = 90.0) -> None:
    """The whole object turned ``degrees`` about up (the URDF's +Z)."""
    turn = np.eye(4)
    turn[:3, :3] = rpy_matrix(np.array([0.0, 0.0, math.radians(degrees)]))
    _place(robot, turn)
    mapping.yaw_deg = degrees


AJAR = 0.3
"""``ajar``: the fraction of its travel a door, lid, drawer or window rests away from its resting limit."""
OPENABLE_LABELS = ("door", "lid", "drawer", "window", "screen", "cover", "flap", "board")


def _ajar(robot: ET.Element, mapping: Mapping, labels: dict[str, str]) -> None:
    """Every door, lid, drawer, window or screen (by its PartNet label) that rests at one of its limits now rests
    :data:`AJAR` of the way to the other: its joint's zero moved there, its limits moved back (same motion)."""
    mimicked = {m.get("joint") for j in robot.iter("joint") if (m := j.find("mimic")) is not None}
    for joint in robot.iter("joint"):
        name, limit = joint.get("name", ""), joint.find("limit")
        label = labels.get(_attr(joint, "child", "link"), "")
        if joint.get("type") not in ("revolute", "prismatic") or limit is None or name in mimicked or joint.find("mimic") is not None:
            continue
        if not any(word in label for word in OPENABLE_LABELS):
            continue
        lower, upper = float(limit.get("lower", "0")), float(limit.get("upper", "0"))
        if upper - lower <= 1e-6 or min(abs(lower), abs(upper)) > 1e-6:
            continue  # no travel, or it rests part-way already
        offset = AJAR * ((upper - lower) if abs(lower) <= 1e-6 else (lower - upper))
        axis = _axis(joint)
        move = np.eye(4)
        if joint.get("type") == "revolute":
            move[:3, :3] = _axis_rotation(axis, offset)
        else:
            move[:3, 3] = offset * axis
        _set_origin(joint, _origin(joint) @ move)
        limit.set("lower", repr(lower - offset))
        limit.set("upper", repr(upper - offset))
        mapping.limits[name] = (lower, upper)
        mapping.offsets[name] = -offset


def _axis_rotation(axis: np.ndarray, angle: float) -> np.ndarray:
    x, y, z = axis
    k = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * (k @ k)


def materialize(source: Path, target: Path) -> None:
    """The asset's other files, hard-linked where the file system allows (meshes are large)."""
    def link(src: str, dst: str) -> object:
        try:
            os.link(src, dst)
        except OSError:
            shutil.copy2(src, dst)
        return dst
    for entry in source.iterdir():
        if entry.name == "semantics.txt" or entry.suffix == ".urdf":
            continue
        if entry.is_dir():
            shutil.copytree(entry, target / entry.name, copy_function=link, dirs_exist_ok=True)
        else:
            link(str(entry), str(target / entry.name))


def _semantics(source: Path) -> list[str]:
    semantics = source / "semantics.txt"
    return semantics.read_text().splitlines() if semantics.is_file() else []


def make_variant(source: Path, target: Path, transforms: tuple[str, ...]) -> Mapping:
    """Write the variant of the asset folder ``source`` into ``target``; return how its joints map."""
    urdf = source / "mobility.urdf"
    if not urdf.is_file():
        found = sorted(source.glob("*.urdf"))
        if len(found) != 1:
            raise ValueError(f"{source}: expected mobility.urdf or exactly one .urdf file, found {len(found)}")
        urdf = found[0]
    tree = ET.parse(urdf)
    robot = tree.getroot()
    mapping = Mapping()
    links: dict[str, str] = {}
    if "ajar" in transforms:  # first, while links and joints have the original's names
        _ajar(robot, mapping, {p[0]: p[-1] for line in _semantics(source) if len(p := line.split()) >= 3})
    if "flip" in transforms:
        _flip(robot, mapping)
        mapping.offsets = {j: mapping.sign(j) * v for j, v in mapping.offsets.items()}
    if "rename" in transforms:
        links = _rename(robot, mapping)
    if "reorder" in transforms:
        _reorder(robot)
    if "shift" in transforms:
        _shift(robot)
    if "mirror" in transforms:
        _mirror(robot, mapping)
    if "move" in transforms:
        _move(robot)
    if "yaw" in transforms:
        _yaw(robot, mapping)

    if target.exists():
        shutil.rmtree(target)
    target.mkdir(parents=True)
    tree.write(target / urdf.name, encoding="utf-8", xml_declaration=True)
    if (source / "semantics.txt").is_file():
        lines = [" ".join([links.get(parts[0], parts[0]), *parts[1:]]) if (parts := line.split()) else line for line in _semantics(source)]
        (target / "semantics.txt").write_text("\n".join(lines) + "\n")
    materialize(source, target)
    return mapping
