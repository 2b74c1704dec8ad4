"""URDF text -> :class:`UrdfRobot`, the elements the loader uses, read with lxml.

This reads what the engine takes from a URDF (links and their visuals, joints, named materials)
and nothing more, with yourdfpy's reading rules: the same defaults (``xyz``/``rpy`` 0, axis
``1 0 0``, mimic multiplier 1 and offset 0, colour ``1 1 1 1``), the same number syntax (Python
``float``; commas separate the values of ``size`` and ``scale``), the same origin matrices bit for
bit, and the same refusals: a file yourdfpy could not read (a missing ``<geometry>``, a missing
``size`` or ``radius``, a number that is not one, a ``<collision>``, ``<inertial>``,
``<calibration>`` or ``<safety_controller>`` with such a fault) is refused here too, naming the
element. What the values mean is checked later, by :mod:`app.engine.asset.urdf` and the loader.

The text has passed :func:`app.engine.asset.safety.check_urdf_xml` (size, DTD, entities, depth).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
from lxml import etree

from app.engine.errors import AssetError
from app.engine.types import FloatArray, Transform

GeometryKind = Literal["mesh", "box", "cylinder", "sphere"]
_CHECKED_ONLY = {"calibration": ("rising", "falling"), "safety_controller": ("soft_lower_limit", "soft_upper_limit", "k_position", "k_velocity")}
"""Joint elements whose numbers must read (yourdfpy reads them) though the engine does not use them."""


@dataclass(frozen=True, eq=False)
class UrdfMaterial:
    """A ``<material>``: its name and ``<color rgba>`` values as written (None without ``<color>``)."""

    name: str | None
    rgba: FloatArray | None = None


@dataclass(frozen=True, eq=False)
class UrdfGeometry:
    """The first child of a ``<geometry>``.

    Attributes
    ----------
    scale : float, (k,) float or None
        A mesh's ``scale``: one number, several, or None when absent or empty.
    size : (k,) float or None
        A box's ``size`` values as written (any count).
    """

    kind: GeometryKind
    filename: str | None = None
    scale: float | FloatArray | None = None
    size: FloatArray | None = None
    radius: float | None = None
    length: float | None = None


@dataclass(frozen=True, eq=False)
class UrdfVisual:
    """A ``<visual>``; ``origin`` is None without an ``<origin>`` element."""

    name: str | None
    origin: Transform | None
    geometry: UrdfGeometry
    material: UrdfMaterial | None


@dataclass(frozen=True, eq=False)
class UrdfLink:
    name: str
    visuals: tuple[UrdfVisual, ...] = ()


@dataclass(frozen=True)
class UrdfLimit:
    lower: float | None = None
    upper: float | None = None
    effort: float | None = None
    velocity: float | None = None


@dataclass(frozen=True)
class UrdfMimic:
    joint: str | None
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True, eq=False)
class UrdfJoint:
    """A ``<joint>``; ``axis`` holds the ``<axis xyz>`` values as written (``1 0 0`` when absent)."""

    name: str
    type: str | None
    parent: str | None
    child: str | None
    origin: Transform | None
    axis: FloatArray
    limit: UrdfLimit | None = None
    mimic: UrdfMimic | None = None


@dataclass(frozen=True, eq=False)
class UrdfRobot:
    """The ``<robot>``: its links, joints and top-level named materials, in document order."""

    name: str
    links: tuple[UrdfLink, ...]
    joints: tuple[UrdfJoint, ...]
    materials: tuple[UrdfMaterial, ...]


class _Reader:
    """Reads one document; every refusal names the URDF file and the element."""

    def __init__(self, file_name: str) -> None:
        self.file_name = file_name

    def fail(self, problem: str, element: str) -> AssetError:
        return AssetError(f"cannot parse URDF: {problem}", file=self.file_name, element=element)

    def number(self, text: str | float, what: str, element: str) -> float:
        try:
            return float(text)
        except ValueError as exc:
            raise self.fail(f"{what} {text!r} is not a number", element) from exc

    def numbers(self, text: str, what: str, element: str, *, commas: bool = False) -> list[float]:
        fields = (text.replace(",", " ") if commas else text).split()
        return [self.number(field, what, element) for field in fields]

    def optional(self, node: etree._Element, attribute: str, element: str) -> float | None:
        text = node.get(attribute)
        return None if text is None else self.number(text, f"{node.tag} {attribute}", element)

    def required(self, node: etree._Element, attribute: str, element: str) -> float:
        text = node.get(attribute)
        if text is None:
            raise self.fail(f"<{node.tag}> has no {attribute} attribute", element)
        return self.number(text, f"{node.tag} {attribute}", element)

    def origin(self, node: etree._Element | None, element: str) -> Transform | None:
        """The ``<origin>`` as a (4, 4) matrix: translation times the static-xyz rotation of ``rpy``."""
        if node is None:
            return None
        xyz = self.numbers(node.get("xyz", "0 0 0"), "origin xyz", element)
        rpy = self.numbers(node.get("rpy", "0 0 0"), "origin rpy", element)
        if len(xyz) < 3 or len(rpy) < 3:  # more than 3: the first 3 count, as yourdfpy reads them
            raise self.fail(f"origin needs 3 xyz and 3 rpy numbers, got {len(xyz)} and {len(rpy)}", element)
        with np.errstate(invalid="ignore", over="ignore"):  # NaN/inf: the caller refuses the matrix
            return origin_matrix(np.array(xyz[:3]), np.array(rpy[:3]))

    def geometry(self, node: etree._Element | None, element: str) -> UrdfGeometry:
        if node is None:
            raise self.fail("no <geometry>", element)
        if len(node) == 0:
            raise self.fail("<geometry> is empty", element)
        shape = node[0]
        if shape.tag == "mesh":
            scale: float | FloatArray | None = None
            if "scale" in shape.attrib:
                values = self.numbers(shape.get("scale", ""), "mesh scale", element, commas=True)
                scale = None if not values else values[0] if len(values) == 1 else np.array(values)
            return UrdfGeometry(kind="mesh", filename=shape.get("filename"), scale=scale)
        if shape.tag == "box":
            if shape.get("size") is None:
                raise self.fail("<box> has no size attribute", element)
            return UrdfGeometry(kind="box", size=np.array(self.numbers(shape.get("size", ""), "box size", element, commas=True)))
        if shape.tag == "cylinder":
            return UrdfGeometry(kind="cylinder", radius=self.required(shape, "radius", element), length=self.required(shape, "length", element))
        if shape.tag == "sphere":
            return UrdfGeometry(kind="sphere", radius=self.required(shape, "radius", element))
        tag = shape.tag if isinstance(shape.tag, str) else type(shape).__name__.strip("_")
        raise self.fail(f"unknown geometry <{tag}>", element)

    def material(self, node: etree._Element | None, element: str) -> UrdfMaterial | None:
        if node is None:
            return None
        color = node.find("color")
        rgba = None if color is None else np.array(self.numbers(color.get("rgba", "1 1 1 1"), "color rgba", element))
        return UrdfMaterial(name=node.get("name"), rgba=rgba)

    def visual(self, node: etree._Element, element: str) -> UrdfVisual:
        geometry = self.geometry(node.find("geometry"), element)
        origin = self.origin(node.find("origin"), element)
        return UrdfVisual(name=node.get("name"), origin=origin, geometry=geometry, material=self.material(node.find("material"), element))

    def inertial(self, node: etree._Element | None, element: str) -> None:
        """Check an ``<inertial>`` reads (its values are not used)."""
        if node is None:
            return
        self.origin(node.find("origin"), element)
        inertia = node.find("inertia")
        if inertia is not None:
            for attribute in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
                self.optional(inertia, attribute, element)
        mass = node.find("mass")
        if mass is not None:
            self.optional(mass, "value", element)

    def link(self, node: etree._Element, index: int) -> UrdfLink:
        name = node.get("name", "")
        element = f"link {name or index}"
        self.inertial(node.find("inertial"), element)
        visuals = tuple(self.visual(v, f"{element} visual {v.get('name') or i}") for i, v in enumerate(node.findall("visual")))
        for i, collision in enumerate(node.findall("collision")):  # read and dropped, as long as they read
            where = f"{element} collision {collision.get('name') or i}"
            self.geometry(collision.find("geometry"), where)
            self.origin(collision.find("origin"), where)
        return UrdfLink(name=name, visuals=visuals)

    def joint(self, node: etree._Element, index: int) -> UrdfJoint:
        name = node.get("name", "")
        element = f"joint {name or index}"
        parent, child = node.find("parent"), node.find("child")
        origin = self.origin(node.find("origin"), element)
        axis_node = node.find("axis")
        axis = np.array(self.numbers("1 0 0" if axis_node is None else axis_node.get("xyz", "1 0 0"), "axis xyz", element))
        limit = node.find("limit")
        limits = None
        if limit is not None:
            limits = UrdfLimit(lower=self.optional(limit, "lower", element), upper=self.optional(limit, "upper", element),
                               effort=self.optional(limit, "effort", element), velocity=self.optional(limit, "velocity", element))
        mimic_node = node.find("mimic")
        mimic = None
        if mimic_node is not None:
            mimic = UrdfMimic(joint=mimic_node.get("joint"), multiplier=self.number(mimic_node.get("multiplier", 1.0), "mimic multiplier", element),
                              offset=self.number(mimic_node.get("offset", 0.0), "mimic offset", element))
        for tag, attributes in _CHECKED_ONLY.items():  # read and dropped, as long as they read
            extra = node.find(tag)
            if extra is not None:
                for attribute in attributes:
                    self.optional(extra, attribute, element)
        return UrdfJoint(name=name, type=node.get("type"), parent=None if parent is None else parent.get("link"),
                         child=None if child is None else child.get("link"), origin=origin, axis=axis, limit=limits, mimic=mimic)


def origin_matrix(xyz: FloatArray, rpy: FloatArray) -> Transform:
    """(4, 4) ``translate(xyz) @ Rz(yaw) @ Ry(pitch) @ Rx(roll)``, composed as yourdfpy composes it.

    The products run through identity and translation matrices in the same order (so a NaN or
    infinite input spreads the same way) and the rotation entries are the same products of sines
    and cosines: the matrices equal yourdfpy's bit for bit.
    """
    roll, pitch, yaw = rpy
    sr, sp, sy = np.sin(roll), np.sin(pitch), np.sin(yaw)
    cr, cp, cy = np.cos(roll), np.cos(pitch), np.cos(yaw)
    cr_cy, cr_sy, sr_cy, sr_sy = cr * cy, cr * sy, sr * cy, sr * sy
    rotation = np.eye(4)
    rotation[0, :3] = (cp * cy, sp * sr_cy - cr_sy, sp * cr_cy + sr_sy)
    rotation[1, :3] = (cp * sy, sp * sr_sy + cr_cy, sp * cr_sy - sr_cy)
    rotation[2, :3] = (-sp, cp * sr, cp * cr)
    translation = np.identity(4)
    translation[:3, 3] = xyz
    matrix = np.dot(np.dot(np.identity(4), translation), rotation)
    matrix /= matrix[3, 3]
    return matrix


def read_urdf(data: bytes, file_name: str) -> UrdfRobot:
    """Read URDF text.

    Raises
    ------
    AssetError
        The text is not XML lxml reads, or an element cannot be read (``cannot parse URDF: ...``,
        naming the element).
    """
    parser = etree.XMLParser(remove_comments=True, remove_blank_text=True, resolve_entities=False, no_network=True)
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError as exc:
        raise AssetError(f"cannot parse URDF: XMLSyntaxError: {exc}", file=file_name) from exc
    reader = _Reader(file_name)
    name = root.get("name")
    if name is None:
        raise reader.fail("<robot> has no name attribute", "robot")
    links = tuple(reader.link(node, i) for i, node in enumerate(root.findall("link")))
    joints = tuple(reader.joint(node, i) for i, node in enumerate(root.findall("joint")))
    materials = tuple(reader.material(node, f"material {node.get('name') or i}") for i, node in enumerate(root.findall("material")))
    return UrdfRobot(name=name, links=links, joints=joints, materials=tuple(m for m in materials if m is not None))
