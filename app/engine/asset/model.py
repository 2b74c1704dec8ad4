"""The frozen in-memory model of an articulated asset.

Frames: every link has its own frame (the URDF link frame). A joint's ``origin``
maps points from the joint frame to the parent link frame; the child link frame
is the joint frame moved by the joint motion. World = root link frame, +Z up.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from itertools import pairwise
from typing import Literal

import numpy as np

from app.engine.types import FloatArray, IntArray, Transform, Vector3

JointType = Literal["revolute", "continuous", "prismatic", "fixed"]
MOVABLE_TYPES: frozenset[str] = frozenset({"revolute", "continuous", "prismatic"})


def _frozen(array: FloatArray | IntArray) -> FloatArray | IntArray:
    array.setflags(write=False)
    return array


@dataclass(frozen=True)
class Mimic:
    """``q = multiplier * q[joint] + offset``."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True, eq=False)
class JointSpec:
    """One URDF joint.

    Attributes
    ----------
    origin : (4, 4) float
        Joint frame -> parent link frame.
    axis : (3,) float
        Unit axis in the joint frame (zero vector for fixed joints).
    lower, upper : float or None
        Limits (radians or metres); ``None`` for continuous and fixed joints.
    rest : float
        Rest value: 0 clamped into the limits.
    """

    name: str
    type: JointType
    parent: str
    child: str
    origin: Transform
    axis: Vector3
    lower: float | None = None
    upper: float | None = None
    effort: float | None = None
    velocity: float | None = None
    mimic: Mimic | None = None

    @property
    def movable(self) -> bool:
        return self.type in MOVABLE_TYPES

    @property
    def bounded(self) -> bool:
        return self.type in ("revolute", "prismatic")

    @property
    def rest(self) -> float:
        return self.clamp(0.0)

    def clamp(self, q: float) -> float:
        """Clamp a value into the joint limits (continuous and fixed joints unchanged)."""
        if not self.bounded or self.lower is None or self.upper is None:
            return float(q)
        return float(min(max(q, self.lower), self.upper))

    def clamp_array(self, q: FloatArray) -> FloatArray:
        if not self.bounded or self.lower is None or self.upper is None:
            return q
        return np.clip(q, self.lower, self.upper)


@dataclass(frozen=True)
class Material:
    """A PBR-ish material kept from the source mesh (glTF metallic-roughness)."""

    name: str
    base_color: tuple[float, float, float, float] = (0.8, 0.8, 0.8, 1.0)
    image_png: bytes | None = None
    metallic: float = 0.0
    roughness: float = 1.0
    double_sided: bool = True


@dataclass(frozen=True, eq=False)
class MeshPart:
    """A material-homogeneous triangle mesh of a link, in the link frame.

    Attributes
    ----------
    vertices : (n, 3) float, metres, link frame
    faces : (m, 3) int
    normals : (n, 3) float or None, unit length
    uv : (n, 2) float or None, glTF convention (v down)
    source : the mesh file (relative to the asset) or ``primitive:<kind>``
    visual : the URDF ``<visual name=...>`` it came from ("" when unnamed), e.g. ``handle-27``
    """

    vertices: FloatArray
    faces: IntArray
    normals: FloatArray | None
    uv: FloatArray | None
    material: Material
    source: str
    visual: str = ""

    def __post_init__(self) -> None:
        _frozen(self.vertices)
        _frozen(self.faces)
        if self.normals is not None:
            _frozen(self.normals)
        if self.uv is not None:
            _frozen(self.uv)


@dataclass(frozen=True)
class LinkSemantics:
    """What a link is, from ``semantics.txt`` and/or URDF visual names."""

    label: str | None = None
    joint_kind: str | None = None
    visual_names: tuple[str, ...] = ()
    source: Literal["semantics.txt", "urdf", "none"] = "none"


@dataclass(frozen=True, eq=False)
class LinkSpec:
    """One URDF link with its visual geometry (possibly empty)."""

    name: str
    parts: tuple[MeshPart, ...] = ()
    semantics: LinkSemantics = field(default_factory=LinkSemantics)

    @property
    def has_geometry(self) -> bool:
        return bool(self.parts)

    def vertices(self) -> FloatArray:
        """(n, 3) all part vertices in the link frame (empty (0, 3) if none)."""
        if not self.parts:
            return np.zeros((0, 3))
        return np.concatenate([p.vertices for p in self.parts], axis=0)


class LinkNames(tuple[str, ...]):
    """Link names in ``link_order`` whose ``in`` is a set lookup: callers test every link of an asset
    against the links a joint moves, which over a tuple made the per-joint work grow with the square
    of the asset's size."""

    def __contains__(self, name: object) -> bool:
        members: frozenset[str] | None = self.__dict__.get("members")
        if members is None:
            members = self.__dict__["members"] = frozenset(self)
        try:
            return name in members
        except TypeError:  # an unhashable value is no link name
            return False


@dataclass(frozen=True, eq=False)
class ArticulatedAsset:
    """An asset ready for planning, execution and export.

    ``joint_order`` lists every joint parents-first (topological), ties broken by
    URDF declaration order; all per-joint arrays in the engine use this order.
    """

    name: str
    urdf_file: str
    root_link: str
    links: Mapping[str, LinkSpec]
    joints: Mapping[str, JointSpec]
    joint_order: tuple[str, ...]
    link_order: tuple[str, ...]
    warnings: tuple[str, ...] = ()
    content_hash: str = ""

    @cached_property
    def movable_joints(self) -> tuple[str, ...]:
        """Non-fixed joints in ``joint_order`` (mimic joints included)."""
        return tuple(j for j in self.joint_order if self.joints[j].movable)

    @cached_property
    def controllable_joints(self) -> tuple[str, ...]:
        """Movable joints that are not mimics (the ones a plan may drive)."""
        return tuple(j for j in self.movable_joints if self.joints[j].mimic is None)

    @cached_property
    def visual_links(self) -> tuple[str, ...]:
        return tuple(n for n in self.link_order if self.links[n].has_geometry)

    def parent_joint(self, link: str) -> JointSpec | None:
        """The joint whose child is ``link`` (None for the root)."""
        return self._parent_joint_map.get(link)

    def child_joints(self, link: str) -> tuple[JointSpec, ...]:
        """The joints whose parent is ``link``, in ``joint_order``."""
        return self._child_joint_map.get(link, ())

    def descendants(self, link: str) -> LinkNames:
        """``link`` and every link below it, in ``link_order``: a slice of the depth-first order (work in the size of
        the subtree, and no sort when that slice is already in ``link_order``, as in a chain)."""
        order, span, falls = self.depth_first
        if link not in span:  # not reachable from the root: walk it
            return self._walked_descendants(link)
        first, end = span[link]
        below = order[first:end]
        if falls[end - 1] == falls[first]:  # already in link_order
            return LinkNames(below)
        index = self._link_index
        return LinkNames(sorted((n for n in below if n in index), key=index.__getitem__))

    def _walked_descendants(self, link: str) -> LinkNames:
        found = {link}
        below = [link]
        while below:
            for joint in self._child_joint_map.get(below.pop(), ()):
                found.add(joint.child)
                below.append(joint.child)
        index = self._link_index
        return LinkNames(sorted((n for n in found if n in index), key=index.__getitem__))

    @cached_property
    def depth_first(self) -> tuple[tuple[str, ...], dict[str, tuple[int, int]], tuple[int, ...]]:
        """(every link reachable from the root, parents first with each subtree contiguous and children in joint
        order; link -> (first, end) of its subtree in it; per position k, how many neighbours before k are out of
        ``link_order``: a slice [a, b) is in ``link_order`` when entries a and b - 1 are equal)."""
        order: list[str] = []
        stack = [self.root_link]
        while stack:
            link = stack.pop()
            order.append(link)
            stack.extend(joint.child for joint in reversed(self.child_joints(link)))
        size = dict.fromkeys(order, 1)
        for link in reversed(order):  # children come after their parent: sum bottom-up
            parent = self.parent_joint(link)
            if parent is not None and parent.parent in size:
                size[parent.parent] += size[link]
        index = {n: k for k, n in enumerate(order)}
        rank = [self._link_index.get(n, -1) for n in order]
        falls = [0]
        for before, after in pairwise(rank):
            falls.append(falls[-1] + (before > after or min(before, after) < 0))
        return tuple(order), {n: (index[n], index[n] + size[n]) for n in order}, tuple(falls)

    def moving_links(self, joint: str) -> LinkNames:
        """Links moved by ``joint``: its child and all descendants."""
        return self.descendants(self.joints[joint].child)

    @cached_property
    def _parent_joint_map(self) -> dict[str, JointSpec]:
        return {j.child: j for j in self.joints.values()}

    @cached_property
    def _child_joint_map(self) -> dict[str, tuple[JointSpec, ...]]:
        children: dict[str, list[JointSpec]] = {}
        for name in self.joint_order:
            joint = self.joints[name]
            children.setdefault(joint.parent, []).append(joint)
        return {parent: tuple(joints) for parent, joints in children.items()}

    @cached_property
    def _link_index(self) -> dict[str, int]:
        return {name: i for i, name in enumerate(self.link_order)}

    def rest_vector(self) -> FloatArray:
        """(j,) rest values of ``movable_joints``; a mimic joint follows its leader's rest.

        Matches :func:`app.engine.asset.kinematics.resolve_joint_values` with no values
        given (a mimic of a fixed joint sits at its own rest).
        """
        values: dict[str, float] = {}

        def rest_of(name: str) -> float:
            if name not in values:
                joint = self.joints[name]
                leader = None if joint.mimic is None else self.joints.get(joint.mimic.joint)
                if joint.mimic is not None and leader is not None and leader.movable:
                    values[name] = joint.clamp(joint.mimic.multiplier * rest_of(leader.name) + joint.mimic.offset)
                else:
                    values[name] = joint.rest
            return values[name]

        return np.array([rest_of(j) for j in self.movable_joints], dtype=np.float64)
