"""yourdfpy as a reference for :mod:`app.engine.asset.urdf_reader`.

``robot_via_yourdfpy`` reads URDF text with yourdfpy (as the loader did before it had its own
reader) into the reader's records, so the two can be compared field by field, or swapped under
the loader to compare whole assets.
"""

from __future__ import annotations

import io
from typing import Any

import numpy as np
import yourdfpy

from app.engine.asset.urdf_reader import (
    UrdfGeometry,
    UrdfJoint,
    UrdfLimit,
    UrdfLink,
    UrdfMaterial,
    UrdfMimic,
    UrdfRobot,
    UrdfVisual,
)


def _material(material: Any) -> UrdfMaterial | None:
    if material is None:
        return None
    return UrdfMaterial(name=material.name, rgba=None if material.color is None else material.color.rgba)


def _geometry(geometry: Any) -> UrdfGeometry:
    if geometry.mesh is not None:
        return UrdfGeometry(kind="mesh", filename=geometry.mesh.filename, scale=geometry.mesh.scale)
    if geometry.box is not None:
        return UrdfGeometry(kind="box", size=geometry.box.size)
    if geometry.cylinder is not None:
        return UrdfGeometry(kind="cylinder", radius=geometry.cylinder.radius, length=geometry.cylinder.length)
    return UrdfGeometry(kind="sphere", radius=geometry.sphere.radius)


def _joint(joint: Any) -> UrdfJoint:
    limit = None if joint.limit is None else UrdfLimit(lower=joint.limit.lower, upper=joint.limit.upper, effort=joint.limit.effort,
                                                        velocity=joint.limit.velocity)
    mimic = None if joint.mimic is None else UrdfMimic(joint=joint.mimic.joint, multiplier=joint.mimic.multiplier, offset=joint.mimic.offset)
    return UrdfJoint(name=joint.name, type=joint.type, parent=joint.parent, child=joint.child, origin=joint.origin, axis=joint.axis,
                     limit=limit, mimic=mimic)


def robot_via_yourdfpy(data: bytes, file_name: str) -> UrdfRobot:
    """``data`` read by yourdfpy, as :class:`UrdfRobot` (yourdfpy's exceptions pass through)."""
    with np.errstate(invalid="ignore", over="ignore"):
        robot = yourdfpy.URDF.load(io.BytesIO(data), build_scene_graph=False, load_meshes=False, build_collision_scene_graph=False).robot
    links = tuple(
        UrdfLink(name=link.name, visuals=tuple(
            UrdfVisual(name=v.name, origin=v.origin, geometry=_geometry(v.geometry), material=_material(v.material)) for v in link.visuals))
        for link in robot.links
    )
    materials = tuple(m for m in (_material(m) for m in robot.materials) if m is not None)
    return UrdfRobot(name=robot.name, links=links, joints=tuple(_joint(j) for j in robot.joints), materials=materials)


def _same_value(where: str, a: object, b: object) -> None:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        assert isinstance(a, np.ndarray) and isinstance(b, np.ndarray), f"{where}: {a!r} != {b!r}"
        assert a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes(), f"{where}: {a!r} != {b!r}"
    elif isinstance(a, float) and isinstance(b, float) and np.isnan(a):
        assert np.isnan(b), f"{where}: {a!r} != {b!r}"
    else:
        assert type(a) is type(b) and a == b, f"{where}: {a!r} != {b!r}"


def _same_fields(where: str, a: object, b: object, fields: tuple[str, ...]) -> None:
    assert (a is None) == (b is None), f"{where}: {a!r} != {b!r}"
    if a is not None:
        for name in fields:
            _same_value(f"{where}.{name}", getattr(a, name), getattr(b, name))


def assert_same_robot(ours: UrdfRobot, reference: UrdfRobot) -> None:
    """Every field equal; arrays (origins included) bit for bit."""
    assert ours.name == reference.name
    assert [link.name for link in ours.links] == [link.name for link in reference.links]
    for link, other in zip(ours.links, reference.links, strict=True):
        assert len(link.visuals) == len(other.visuals), link.name
        for index, (visual, expected) in enumerate(zip(link.visuals, other.visuals, strict=True)):
            where = f"link {link.name} visual {index}"
            _same_fields(where, visual, expected, ("name", "origin"))
            _same_fields(f"{where} geometry", visual.geometry, expected.geometry, ("kind", "filename", "scale", "size", "radius", "length"))
            _same_fields(f"{where} material", visual.material, expected.material, ("name", "rgba"))
    assert len(ours.joints) == len(reference.joints)
    for joint, expected in zip(ours.joints, reference.joints, strict=True):
        where = f"joint {joint.name}"
        _same_fields(where, joint, expected, ("name", "type", "parent", "child", "origin", "axis"))
        _same_fields(f"{where} limit", joint.limit, expected.limit, ("lower", "upper", "effort", "velocity"))
        _same_fields(f"{where} mimic", joint.mimic, expected.mimic, ("joint", "multiplier", "offset"))
    assert len(ours.materials) == len(reference.materials)
    for material, expected in zip(ours.materials, reference.materials, strict=True):
        _same_fields("material", material, expected, ("name", "rgba"))
