"""Objects of several like parts, made from dev assets: the whole object repeated, stacked or set side by side.

The dev pool holds few objects with many parts of one kind (two drawers at most), so a rule that picks "the third
drawer from the top" or "the middle door" among many was never tried on it. A *stack* step writes one object made of
``copies`` copies of an asset, each the next one's neighbour along a world axis (``z`` up, or ``x`` / ``y``), fixed
to the first copy's root, with a gap of :data:`GAP_M` between their boxes at rest. Every copy keeps its moving parts,
so the result has ``copies`` parts of each kind, in a row or a column::

    "d/storage_19179": {"source": "partnet/storage_19179", "steps": [["stack3z"], ["rename"]]}

Copy ``c`` (from 0) of ``link_n`` / ``joint_n`` is ``link_{n + c*K}`` / ``joint_{n + c*K}`` with ``K`` one more than
the asset's highest number; other names get ``_c``. semantics.txt gains each copy's lines.
"""

from __future__ import annotations

import copy
import re
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from app.engine.asset.loader import load_asset
from app.engine.asset.summary import world_bounds
from benchmark.variants import materialize, relink

STEP = re.compile(r"^stack([2-4])([xyz])$")
"""A stack step's name: ``stack<copies><axis>``, e.g. ``stack3z`` (three copies, one above the other)."""
GAP_M = 0.02
NUMBERED = re.compile(r"^(link|joint)_(\d+)$")
AXES = {"x": 0, "y": 1, "z": 2}


def is_stack(step: tuple[str, ...]) -> bool:
    return len(step) == 1 and STEP.match(step[0]) is not None


def _renamer(names: list[str], copy_index: int, stride: int) -> dict[str, str]:
    renamed = {}
    for name in names:
        match = NUMBERED.match(name)
        renamed[name] = f"{match.group(1)}_{int(match.group(2)) + copy_index * stride}" if match else f"{name}_{copy_index}"
    return renamed


def _stride(robot: ET.Element) -> int:
    numbers = [int(m.group(2)) for e in robot if e.tag in ("link", "joint") and (m := NUMBERED.match(e.get("name", "")))]
    return max(numbers, default=-1) + 1


def _root(robot: ET.Element) -> str:
    children = {c.get("link", "") for j in robot.iter("joint") if (c := j.find("child")) is not None}
    roots = [lk.get("name", "") for lk in robot.iter("link") if lk.get("name") not in children]
    if len(roots) != 1:
        raise ValueError(f"expected one root link, found {len(roots)}")
    return roots[0]


def _copied(elements: list[ET.Element], copy_index: int, stride: int) -> tuple[list[ET.Element], dict[str, str]]:
    links = _renamer([e.get("name", "") for e in elements if e.tag == "link"], copy_index, stride)
    joints = _renamer([e.get("name", "") for e in elements if e.tag == "joint"], copy_index, stride)
    out = []
    for element in elements:
        twin = copy.deepcopy(element)
        twin.set("name", (links if element.tag == "link" else joints)[element.get("name", "")])
        relink(twin, links, joints)
        out.append(twin)
    return out, links


def write_stack(source: Path, target: Path, step: str) -> None:
    """Write the stack named ``step`` (see :data:`STEP`) of the asset folder ``source`` into ``target``."""
    match = STEP.match(step)
    if match is None:
        raise ValueError(f"not a stack step: {step}")
    copies, axis = int(match.group(1)), AXES[match.group(2)]
    bounds = np.concatenate(list(world_bounds(load_asset(source)).values()), axis=0)
    pitch = float(bounds[:, axis].max() - bounds[:, axis].min()) + GAP_M
    urdf = source / "mobility.urdf"
    tree = ET.parse(urdf)
    robot = tree.getroot()
    root, stride = _root(robot), _stride(robot)
    semantics_file = source / "semantics.txt"
    semantics = semantics_file.read_text().splitlines() if semantics_file.is_file() else []
    lines = list(semantics)
    original = [e for e in robot if e.tag in ("link", "joint")]
    for index in range(1, copies):
        elements, links = _copied(original, index, stride)
        robot.extend(elements)
        offset = ["0", "0", "0"]
        offset[axis] = repr(index * pitch)
        joint = ET.SubElement(robot, "joint", {"name": f"stack_{index}", "type": "fixed"})
        ET.SubElement(joint, "origin", {"xyz": " ".join(offset), "rpy": "0 0 0"})
        ET.SubElement(joint, "parent", {"link": root})
        ET.SubElement(joint, "child", {"link": links[root]})
        lines += [" ".join([links.get(p[0], p[0]), *p[1:]]) for line in semantics if (p := line.split())]
    if target.exists():
        shutil.rmtree(target)
    target.mkdir(parents=True)
    tree.write(target / urdf.name, encoding="utf-8", xml_declaration=True)
    if semantics:
        (target / "semantics.txt").write_text("\n".join(lines) + "\n")
    materialize(source, target)
