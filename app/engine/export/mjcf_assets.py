"""Per-link pieces of ``scene.xml``: inline meshes, colour materials and inertials.

Meshes are written inline (``<mesh vertex=... face=...>``, link-frame metres rounded to
1e-8 m) so ``scene.xml`` is one self-contained file; ``inertia="shell"`` lets MuJoCo
accept open and flat meshes. Parts MuJoCo cannot take (no area) are left out and
listed. Geoms are visual only (``contype``/``conaffinity`` 0): PartNet meshes are not
watertight, so no collision model is claimed. Inertials are *approximations* from each
link's bounding box at :data:`DENSITY_KG_M3` (the engine keeps no URDF inertials), enough
for MuJoCo to compile and simulate, not measured masses.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from xml.etree import ElementTree

import numpy as np

from app.engine.asset.model import LinkSpec, MeshPart

DENSITY_KG_M3 = 300.0
MIN_EXTENT_M = 1e-3
MIN_MASS_KG = 1e-3
MIN_AREA_M2 = 1e-12
MIN_MESH_VERTICES = 4
"""MuJoCo needs at least 4 vertices per mesh; a single triangle gets its first vertex repeated."""
VERTEX_DECIMALS = 8


def numbers(values: np.ndarray | list[float]) -> str:
    """Space-separated shortest round-trip reprs."""
    return " ".join(map(repr, np.asarray(values, dtype=np.float64).reshape(-1).tolist()))


def inertial(link: LinkSpec) -> dict[str, str]:
    """``<inertial>`` attributes: a solid box over the link's geometry (link frame)."""
    vertices = link.vertices()
    if vertices.shape[0] == 0:
        return {"pos": "0 0 0", "mass": repr(MIN_MASS_KG), "diaginertia": numbers([MIN_MASS_KG * MIN_EXTENT_M**2] * 3)}
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    extent = np.maximum(high - low, MIN_EXTENT_M)
    mass = max(DENSITY_KG_M3 * float(np.prod(extent)), MIN_MASS_KG)
    squares = extent**2
    diagonal = mass / 12.0 * np.array([squares[1] + squares[2], squares[0] + squares[2], squares[0] + squares[1]])
    return {"pos": numbers((low + high) / 2.0), "mass": repr(mass), "diaginertia": numbers(diagonal)}


def _area(part: MeshPart) -> float:
    triangles = part.vertices[part.faces]
    return float(np.linalg.norm(np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]), axis=1).sum() / 2.0)


@dataclass
class MeshLibrary:
    """Collects ``<mesh>`` and ``<material>`` elements for the ``<asset>`` section."""

    meshes: list[ElementTree.Element] = field(default_factory=list)
    materials: dict[tuple[float, float, float, float], str] = field(default_factory=dict)
    skipped: list[str] = field(default_factory=list)
    names: set[str] = field(default_factory=set)

    def geoms(self, link: LinkSpec) -> list[dict[str, str]]:
        """``<geom>`` attributes for the link's usable parts (adds their meshes/materials)."""
        result = []
        for index, part in enumerate(link.parts):
            if len(part.faces) == 0 or _area(part) < MIN_AREA_M2:
                self.skipped.append(f"{link.name} part {index} ({part.visual or part.source}): no area")
                continue
            name = self._unique(f"{link.name}_{index}")
            vertices = np.round(np.asarray(part.vertices, dtype=np.float64), VERTEX_DECIMALS)
            if vertices.shape[0] < MIN_MESH_VERTICES:
                vertices = np.concatenate([vertices, np.repeat(vertices[:1], MIN_MESH_VERTICES - vertices.shape[0], axis=0)])
            self.meshes.append(ElementTree.Element("mesh", {
                "name": name, "vertex": numbers(vertices), "face": " ".join(map(str, part.faces.reshape(-1).tolist())), "inertia": "shell",
            }))
            result.append({"type": "mesh", "mesh": name, "material": self._material(part), "contype": "0", "conaffinity": "0", "group": "1"})
        return result

    def _material(self, part: MeshPart) -> str:
        rgba = tuple(float(v) for v in part.material.base_color)
        key = (rgba[0], rgba[1], rgba[2], rgba[3])
        if key not in self.materials:
            self.materials[key] = f"material_{len(self.materials)}"
        return self.materials[key]

    def _unique(self, name: str) -> str:
        candidate, suffix = name, 1
        while candidate in self.names:
            candidate = f"{name}_{suffix}"
            suffix += 1
        self.names.add(candidate)
        return candidate

    def asset_element(self) -> ElementTree.Element:
        element = ElementTree.Element("asset")
        for rgba, name in self.materials.items():
            ElementTree.SubElement(element, "material", {"name": name, "rgba": numbers(list(rgba))})
        element.extend(self.meshes)
        return element
