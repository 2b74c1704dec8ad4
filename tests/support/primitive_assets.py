"""Tiny URDF assets built in a temporary folder (box/cylinder primitives, tiny OBJ files).

Used by the engine tests; nothing here touches the shared PartNet folder.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from pathlib import Path

Vec = tuple[float, float, float]

TRIANGLE_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
"""A one-triangle OBJ (unit right triangle in the xy plane)."""


def _v(values: Iterable[float]) -> str:
    return " ".join(repr(float(v)) for v in values)


def origin(xyz: Vec = (0.0, 0.0, 0.0), rpy: Vec = (0.0, 0.0, 0.0)) -> str:
    return f'<origin xyz="{_v(xyz)}" rpy="{_v(rpy)}"/>'


def box(size: Vec, xyz: Vec = (0.0, 0.0, 0.0), rpy: Vec = (0.0, 0.0, 0.0), name: str | None = None) -> str:
    label = f' name="{name}"' if name else ""
    return f'<visual{label}>{origin(xyz, rpy)}<geometry><box size="{_v(size)}"/></geometry></visual>'


def cylinder(radius: float, length: float, xyz: Vec = (0.0, 0.0, 0.0), rpy: Vec = (0.0, 0.0, 0.0)) -> str:
    return (
        f'<visual>{origin(xyz, rpy)}<geometry><cylinder radius="{radius!r}" length="{length!r}"/></geometry></visual>'
    )


def mesh(filename: str, xyz: Vec = (0.0, 0.0, 0.0), scale: Vec | None = None) -> str:
    scaled = f' scale="{_v(scale)}"' if scale else ""
    return f'<visual>{origin(xyz)}<geometry><mesh filename="{filename}"{scaled}/></geometry></visual>'


def link(name: str, *visuals: str) -> str:
    return f'<link name="{name}">{"".join(visuals)}</link>'


def joint(
    name: str,
    kind: str,
    parent: str,
    child: str,
    *,
    xyz: Vec = (0.0, 0.0, 0.0),
    rpy: Vec = (0.0, 0.0, 0.0),
    axis: Vec | None = (0.0, 0.0, 1.0),
    limit: tuple[float, float] | None = None,
    mimic: tuple[str, float, float] | None = None,
) -> str:
    """A ``<joint>``; ``limit`` = (lower, upper), ``mimic`` = (leader, multiplier, offset)."""
    parts = [
        f'<joint name="{name}" type="{kind}">',
        origin(xyz, rpy),
        f'<parent link="{parent}"/>',
        f'<child link="{child}"/>',
    ]
    if axis is not None:
        parts.append(f'<axis xyz="{_v(axis)}"/>')
    if limit is not None:
        parts.append(f'<limit lower="{limit[0]!r}" upper="{limit[1]!r}" effort="10.0" velocity="2.0"/>')
    if mimic is not None:
        parts.append(f'<mimic joint="{mimic[0]}" multiplier="{mimic[1]!r}" offset="{mimic[2]!r}"/>')
    parts.append("</joint>")
    return "".join(parts)


def robot(*elements: str, name: str = "fixture") -> str:
    return f'<?xml version="1.0"?>\n<robot name="{name}">\n' + "\n".join(elements) + "\n</robot>\n"


def write_asset(
    root: Path, urdf: str | None, files: Mapping[str, str | bytes] | None = None, urdf_name: str = "mobility.urdf"
) -> Path:
    """Write ``urdf`` (if given) and extra ``files`` (relative path -> content) under ``root``."""
    root.mkdir(parents=True, exist_ok=True)
    if urdf is not None:
        (root / urdf_name).write_text(urdf, encoding="utf-8")
    for relative, content in (files or {}).items():
        target = root / relative
        target.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, bytes):
            target.write_bytes(content)
        else:
            target.write_text(content, encoding="utf-8")
    return root


def two_link_urdf(joint_xml: str, *, child_visual: str | None = None) -> str:
    """``base`` (unit box) + ``part`` (small box) connected by ``joint_xml`` (parent base, child part)."""
    return robot(
        link("base", box((1.0, 1.0, 1.0))),
        link("part", child_visual or box((0.2, 0.2, 0.2))),
        joint_xml,
    )


# --- the "cabinet": a hand-computable primitive asset ------------------------------------

CABINET_LIMITS = {"lid_hinge": (0.0, math.pi / 2), "drawer_slide": (0.0, 0.6), "flap_mimic": (-1.0, 1.0)}


def cabinet_urdf(*, flap_offset: float = 0.0) -> str:
    """A cabinet with every joint kind.

    ``world`` (no geometry) -fixed-> ``base`` box 2 x 1 x 0.5 standing on z = 0;
    ``lid_hinge`` revolute about +x at (0, -0.5, 0.5), lid box 2 x 1 x 0.1 on top;
    ``drawer_slide`` prismatic, axis written ``0 2 0``, drawer box 1.6 x 0.8 x 0.2 inside the base;
    ``knob_spin`` continuous about +x at (1, 0, 0.25), knob cylinder r 0.1, length 0.1 along +x;
    ``flap_mimic`` revolute on the lid's far edge, mimics ``lid_hinge`` (x 0.5 + ``flap_offset``),
    flap box 2 x 0.3 x 0.02.
    """
    return robot(
        link("world"),
        link("base", box((2.0, 1.0, 0.5), xyz=(0.0, 0.0, 0.25), name="body")),
        link("lid", box((2.0, 1.0, 0.1), xyz=(0.0, 0.5, 0.05), name="lid_panel")),
        link("drawer", box((1.6, 0.8, 0.2), name="drawer_front-1"), box((1.6, 0.8, 0.2), name="drawer_front-2")),
        link("knob", cylinder(0.1, 0.1, xyz=(0.05, 0.0, 0.0), rpy=(0.0, math.pi / 2, 0.0))),
        link("flap", box((2.0, 0.3, 0.02), xyz=(0.0, 0.15, 0.01))),
        joint("root_fixed", "fixed", "world", "base", axis=None),
        joint(
            "lid_hinge",
            "revolute",
            "base",
            "lid",
            xyz=(0.0, -0.5, 0.5),
            axis=(1.0, 0.0, 0.0),
            limit=CABINET_LIMITS["lid_hinge"],
        ),
        joint(
            "drawer_slide",
            "prismatic",
            "base",
            "drawer",
            xyz=(0.0, 0.0, 0.2),
            axis=(0.0, 2.0, 0.0),
            limit=CABINET_LIMITS["drawer_slide"],
        ),
        joint("knob_spin", "continuous", "base", "knob", xyz=(1.0, 0.0, 0.25), axis=(1.0, 0.0, 0.0)),
        joint(
            "flap_mimic",
            "revolute",
            "lid",
            "flap",
            xyz=(0.0, 1.0, 0.1),
            axis=(1.0, 0.0, 0.0),
            limit=CABINET_LIMITS["flap_mimic"],
            mimic=("lid_hinge", 0.5, flap_offset),
        ),
        name="cabinet",
    )


def write_cabinet(root: Path, *, flap_offset: float = 0.0) -> Path:
    return write_asset(root, cabinet_urdf(flap_offset=flap_offset))
