"""Load a prediction (``trajectory.jsonl`` or an animated GLB) as a :class:`PoseSequence`.

Node maps (for GLBs whose nodes are not named after links) are JSON objects, either
flat ``{"node name": "link name", ...}`` or ``{"nodes": {...}, "up_axis": "Y" | "Z"}``;
``up_axis`` says which axis is up in the GLB's world (glTF's ``Y`` by default).
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import MetricError
from app.engine.export.gltf_reader import read_glb
from app.engine.export.jsonl import read_trajectory_jsonl
from app.engine.metrics.sequence import PoseSequence, UpAxis, glb_sequence, trajectory_sequence

PREDICTION_FILES: tuple[str, ...] = ("trajectory.jsonl", "animation.glb")
"""File names looked for in a prediction folder, in this order."""
GLB_SUFFIXES = (".glb", ".gltf")


@dataclass(frozen=True)
class NodeMap:
    """GLB node name -> link name, and the GLB's up axis."""

    nodes: Mapping[str, str] = field(default_factory=dict)
    up_axis: UpAxis = "Y"


def parse_node_map(raw: Any, source: str = "node map") -> NodeMap:
    """Validate a node-map JSON value.

    Raises
    ------
    MetricError
        Not an object of strings, or a bad ``up_axis``.
    """
    if not isinstance(raw, dict):
        raise MetricError(f"{source}: expected a JSON object")
    structured = "nodes" in raw and isinstance(raw["nodes"], dict)
    nodes = raw["nodes"] if structured else raw
    up_axis = raw.get("up_axis", "Y") if structured else "Y"
    extra = sorted(set(raw) - {"nodes", "up_axis"}) if structured else []
    if extra:
        raise MetricError(f"{source}: unknown keys {', '.join(extra)}")
    if up_axis not in ("Y", "Z"):
        raise MetricError(f"{source}: up_axis must be 'Y' or 'Z', got {up_axis!r}")
    if not all(isinstance(k, str) and isinstance(v, str) for k, v in nodes.items()):
        raise MetricError(f"{source}: node names and link names must be strings")
    axis: UpAxis = "Y" if up_axis == "Y" else "Z"
    return NodeMap(nodes=dict(sorted(nodes.items())), up_axis=axis)


def read_node_map(path: str | Path) -> NodeMap:
    """Read a node-map JSON file (see the module docstring).

    Raises
    ------
    MetricError
        Unreadable file or invalid content.
    """
    source = Path(path)
    try:
        raw = json.loads(source.read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise MetricError(f"cannot read node map {source}: {exc}") from exc
    return parse_node_map(raw, source.name)


def find_prediction(folder: Path) -> Path | None:
    """The first of :data:`PREDICTION_FILES` present in ``folder`` (None when there is none)."""
    for name in PREDICTION_FILES:
        if (folder / name).is_file():
            return folder / name
    return None


def load_prediction(path: str | Path, asset: ArticulatedAsset, *, node_map: NodeMap | None = None) -> PoseSequence:
    """Read ``path`` (``.jsonl`` trajectory or ``.glb``/``.gltf``) as posed links of ``asset``.

    Raises
    ------
    MetricError
        Unreadable or malformed prediction, unknown file type, or a bad node map.
    """
    source = Path(path)
    if source.suffix.lower() == ".jsonl":
        trajectory, notes = read_trajectory_jsonl(source, asset)
        return trajectory_sequence(asset, trajectory, source=source.name, notes=tuple(notes))
    if source.suffix.lower() in GLB_SUFFIXES:
        mapping = node_map or NodeMap()
        return glb_sequence(asset, read_glb(source), node_map=mapping.nodes, up_axis=mapping.up_axis)
    raise MetricError(f"{source.name}: a prediction must be a .jsonl trajectory or a .glb/.gltf file")
