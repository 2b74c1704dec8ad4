"""URDF text -> checked joint and link records.

:mod:`app.engine.asset.urdf_reader` reads the elements as written; this module judges them: it
rejects floating/planar joints, normalises axes, rejects revolute/prismatic joints without limits,
and checks the tree (a single root, unknown links, duplicate names and cycles).
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass

import numpy as np

from app.engine.asset.model import JointSpec, JointType, Mimic
from app.engine.asset.urdf_reader import UrdfJoint, UrdfRobot, read_urdf
from app.engine.errors import AssetError
from app.engine.types import FloatArray

AXIS_EPS = 1e-9
DEFAULT_AXIS = (1.0, 0.0, 0.0)  # URDF default when <axis> is absent
MAX_COORDINATE_M = 1e4
"""Largest position, size or joint limit accepted (metres or radians): 10 km. Larger values
are typos or attacks, and overflow the geometry computed from them."""
MAX_MULTIPLIER = 1e3
"""Largest |mimic multiplier|."""
JOINT_TYPES: dict[str, JointType] = {"revolute": "revolute", "continuous": "continuous", "prismatic": "prismatic", "fixed": "fixed"}


def finite_numbers(values: object, count: int, what: str, *, file: str, element: str, bound: float = MAX_COORDINATE_M) -> FloatArray:
    """``values`` as ``count`` finite floats no larger than ``bound`` in magnitude.

    Raises
    ------
    AssetError
        Another count, NaN, infinity or a value past ``bound``, naming ``what``.
    """
    try:
        array = np.asarray(values, dtype=np.float64).reshape(-1)
    except (TypeError, ValueError) as exc:
        raise AssetError(f"{what} is not a list of numbers", file=file, element=element) from exc
    if array.shape != (count,):
        raise AssetError(f"{what} needs {count} numbers, got {array.size}", file=file, element=element)
    if not np.all(np.isfinite(array)):
        raise AssetError(f"{what} holds a NaN or infinite value {array.tolist()}", file=file, element=element)
    if np.any(np.abs(array) > bound):
        raise AssetError(f"{what} {array.tolist()} is larger than {bound:g} in magnitude", file=file, element=element)
    return array


def check_transform(matrix: object, what: str, *, file: str, element: str) -> FloatArray:
    """A (4, 4) rigid transform with a finite rotation and a bounded translation."""
    transform = np.asarray(matrix, dtype=np.float64)
    if transform.shape != (4, 4) or not np.all(np.isfinite(transform)):
        raise AssetError(f"{what} is not a finite transform (NaN or infinite xyz/rpy)", file=file, element=element)
    finite_numbers(transform[:3, 3], 3, f"{what} xyz", file=file, element=element)
    return transform


@dataclass(frozen=True)
class ParsedUrdf:
    robot: UrdfRobot
    joints: dict[str, JointSpec]
    root_link: str
    joint_order: tuple[str, ...]
    link_order: tuple[str, ...]


def parse_urdf(data: bytes, file_name: str) -> ParsedUrdf:
    """Parse and check URDF text (already vetted by :func:`check_urdf_xml`).

    Raises
    ------
    AssetError
        Any structural problem, naming the file and the joint or link.
    """
    robot = read_urdf(data, file_name)
    _check_names(robot, file_name)
    link_names = frozenset(link.name for link in robot.links)  # once, not per joint (linear in the asset's size)
    joints = {j.name: _joint_spec(j, link_names, file_name) for j in robot.joints}
    _check_mimics(joints, file_name)
    root, joint_order, link_order = _tree_order(robot, joints, file_name)
    return ParsedUrdf(robot=robot, joints=joints, root_link=root, joint_order=joint_order, link_order=link_order)


def _check_names(robot: UrdfRobot, file_name: str) -> None:
    if not robot.links:
        raise AssetError("URDF has no <link>", file=file_name)
    for kind, items in (("link", robot.links), ("joint", robot.joints)):
        seen: set[str] = set()
        for item in items:
            if not item.name:
                raise AssetError(f"a <{kind}> has no name", file=file_name, element=kind)
            if item.name in seen:
                raise AssetError(f"duplicate {kind} name '{item.name}'", file=file_name, element=f"{kind} {item.name}")
            seen.add(item.name)


def _joint_spec(joint: UrdfJoint, link_names: frozenset[str], file_name: str) -> JointSpec:
    element = f"joint {joint.name}"
    if joint.type in ("floating", "planar"):
        raise AssetError(f"{joint.type} joints are not supported", file=file_name, element=element)
    kind = JOINT_TYPES.get(joint.type or "")
    if kind is None:
        raise AssetError(f"unknown joint type '{joint.type}'", file=file_name, element=element)
    ends: list[str] = []
    for role, link in (("parent", joint.parent), ("child", joint.child)):
        if link is None or link not in link_names:
            raise AssetError(f"{role} link '{link}' is not defined", file=file_name, element=element)
        ends.append(link)
    parent, child = ends
    origin = check_transform(np.eye(4) if joint.origin is None else joint.origin, "origin", file=file_name, element=element)
    axis = np.zeros(3)
    if kind != "fixed":
        raw = finite_numbers(DEFAULT_AXIS if joint.axis is None else joint.axis, 3, "axis", file=file_name, element=element)
        norm = float(np.linalg.norm(raw))
        if norm < AXIS_EPS:
            raise AssetError("axis is zero", file=file_name, element=element)
        axis = raw / norm
    lower: float | None = None
    upper: float | None = None
    limit = joint.limit
    if joint.type in ("revolute", "prismatic"):
        if limit is None:
            raise AssetError(f"{joint.type} joint has no <limit>", file=file_name, element=element)
        if limit.lower is None or limit.upper is None:
            raise AssetError(f"{joint.type} joint <limit> lacks lower or upper", file=file_name, element=element)
        bounds = finite_numbers([limit.lower, limit.upper], 2, "limit lower/upper", file=file_name, element=element)
        lower, upper = float(bounds[0]), float(bounds[1])
        if lower > upper:
            raise AssetError(f"limit lower={lower} upper={upper} is not a valid range", file=file_name, element=element)
    effort = velocity = None
    if limit is not None:
        for name, value in (("effort", limit.effort), ("velocity", limit.velocity)):
            if value is not None:
                (number,) = finite_numbers([value], 1, f"limit {name}", file=file_name, element=element, bound=float("inf"))
                if number < 0:
                    raise AssetError(f"limit {name} {number} is negative", file=file_name, element=element)
        effort = None if limit.effort is None else float(limit.effort)
        velocity = None if limit.velocity is None else float(limit.velocity)
    mimic = None
    if joint.mimic is not None:
        multiplier, offset = finite_numbers(
            [1.0 if joint.mimic.multiplier is None else joint.mimic.multiplier, 0.0 if joint.mimic.offset is None else joint.mimic.offset],
            2, "mimic multiplier/offset", file=file_name, element=element)
        if abs(multiplier) > MAX_MULTIPLIER:
            raise AssetError(f"mimic multiplier {multiplier} is larger than {MAX_MULTIPLIER:g}", file=file_name, element=element)
        mimic = Mimic(joint=str(joint.mimic.joint), multiplier=float(multiplier), offset=float(offset))
    origin.setflags(write=False)
    axis.setflags(write=False)
    return JointSpec(
        name=joint.name,
        type=kind,
        parent=parent,
        child=child,
        origin=origin,
        axis=axis,
        lower=lower,
        upper=upper,
        effort=effort,
        velocity=velocity,
        mimic=mimic,
    )


def _check_mimics(joints: dict[str, JointSpec], file_name: str) -> None:
    for joint in joints.values():
        if joint.mimic is None:
            continue
        element = f"joint {joint.name}"
        if not joint.movable:
            raise AssetError("a fixed joint cannot mimic", file=file_name, element=element)
        target = joints.get(joint.mimic.joint)
        if target is None:
            raise AssetError(f"mimics unknown joint '{joint.mimic.joint}'", file=file_name, element=element)
        seen = {joint.name}
        while target.mimic is not None:
            if target.name in seen:
                raise AssetError("mimic joints form a cycle", file=file_name, element=element)
            seen.add(target.name)
            nxt = joints.get(target.mimic.joint)
            if nxt is None:
                raise AssetError(f"mimics unknown joint '{target.mimic.joint}'", file=file_name, element=f"joint {target.name}")
            target = nxt


def _cycle_from(link: str, parent_of: dict[str, JointSpec]) -> list[str]:
    """Names of the joints of the cycle reached by walking up from ``link`` (every link on the way has a parent)."""
    seen: list[str] = []
    while link not in seen:
        seen.append(link)
        link = parent_of[link].parent
    cycle = seen[seen.index(link) :]
    return [parent_of[name].name for name in reversed(cycle)]


def _tree_order(robot: UrdfRobot, joints: dict[str, JointSpec], file_name: str) -> tuple[str, tuple[str, ...], tuple[str, ...]]:
    """The root link, and joints and links parents-first (breadth first, ties in document order)."""
    parent_of: dict[str, JointSpec] = {}
    for joint in joints.values():
        if joint.child in parent_of:
            raise AssetError(
                f"link '{joint.child}' is the child of two joints ('{parent_of[joint.child].name}' and '{joint.name}')",
                file=file_name,
                element=f"joint {joint.name}",
            )
        parent_of[joint.child] = joint
    roots = [link.name for link in robot.links if link.name not in parent_of]
    children: dict[str, list[JointSpec]] = {}
    for joint in joints.values():
        children.setdefault(joint.parent, []).append(joint)
    reached = set(roots)
    queue = deque(roots)
    while queue:
        for joint in children.get(queue.popleft(), []):
            reached.add(joint.child)
            queue.append(joint.child)
    unreached = [link.name for link in robot.links if link.name not in reached]
    if unreached:  # every unreached link has a parent, so walking up must loop
        cycle = _cycle_from(unreached[0], parent_of)
        raise AssetError(f"the joints form a cycle ({' -> '.join(cycle)})", file=file_name, element=f"joint {cycle[0]}")
    if len(roots) > 1:
        raise AssetError(
            f"the URDF has {len(roots)} root links ({', '.join(roots)}); links must form one tree",
            file=file_name,
            element=f"link {roots[1]}",
        )
    joint_order: list[str] = []
    link_order: list[str] = [roots[0]]
    queue = deque([roots[0]])
    while queue:
        for joint in children.get(queue.popleft(), []):
            joint_order.append(joint.name)
            link_order.append(joint.child)
            queue.append(joint.child)
    return roots[0], tuple(joint_order), tuple(link_order)
