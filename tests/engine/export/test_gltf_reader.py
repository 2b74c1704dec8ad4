"""The glTF reader on hand-made documents (every interpolation, accessor layout and
primitive mode it claims to support), on a third-party GLB, and on malformed input."""

from __future__ import annotations

import base64
import json
import math
import struct
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import trimesh

from app.engine.errors import MetricError
from app.engine.export.gltf_reader import parse_gltf, read_glb
from app.engine.export.rotations import compose_trs, quaternion_to_matrix

COMPONENTS = {
    np.dtype(np.float32): 5126,
    np.dtype(np.uint16): 5123,
    np.dtype(np.uint32): 5125,
    np.dtype(np.int16): 5122,
}
TYPES = {1: "SCALAR", 2: "VEC2", 3: "VEC3", 4: "VEC4"}


class Doc:
    """Builds a glTF JSON document whose single buffer is a base64 data URI."""

    def __init__(self) -> None:
        self.data = bytearray()
        self.doc: dict[str, Any] = {"asset": {"version": "2.0"}, "bufferViews": [], "accessors": [], "nodes": []}

    def view(self, raw: bytes, stride: int | None = None) -> int:
        self.data += b"\x00" * (-len(self.data) % 4)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw)}
        if stride:
            view["byteStride"] = stride
        self.data += raw
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, values: Any, dtype: Any = np.float32, **extra: Any) -> int:
        array = np.asarray(values, dtype=dtype)
        table = array.reshape(array.shape[0], -1)
        entry = {
            "bufferView": self.view(table.tobytes()),
            "componentType": COMPONENTS[array.dtype],
            "count": table.shape[0],
            "type": TYPES[table.shape[1]],
        }
        entry.update(extra)
        self.doc["accessors"].append(entry)
        return len(self.doc["accessors"]) - 1

    def node(self, **fields: Any) -> int:
        self.doc["nodes"].append(fields)
        return len(self.doc["nodes"]) - 1

    def animate(
        self, node: int, path: str, times: Any, values: Any, interpolation: str = "LINEAR", name: str = "action"
    ) -> None:
        animations = self.doc.setdefault("animations", [])
        animation = next((a for a in animations if a["name"] == name), None)
        if animation is None:
            animation = {"name": name, "channels": [], "samplers": []}
            animations.append(animation)
        sampler = {
            "input": self.accessor(np.asarray(times).reshape(-1, 1)),
            "output": self.accessor(values),
            "interpolation": interpolation,
        }
        animation["samplers"].append(sampler)
        animation["channels"].append(
            {"sampler": len(animation["samplers"]) - 1, "target": {"node": node, "path": path}}
        )

    def text(self) -> bytes:
        payload = base64.b64encode(bytes(self.data)).decode()
        self.doc["buffers"] = [{"byteLength": len(self.data), "uri": "data:application/octet-stream;base64," + payload}]
        return json.dumps(self.doc).encode()


def z_rotation(angle: float) -> list[float]:
    return [0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2)]


def glb_from(document: dict[str, Any], binary: bytes) -> bytes:
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\x00" * (-len(binary) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def test_hierarchy_composes_matrix_and_trs_nodes() -> None:
    doc = Doc()
    parent_matrix = compose_trs(np.array([[1.0, 2.0, 3.0]]), np.array([z_rotation(0.7)]), np.array([[2.0, 2.0, 2.0]]))[
        0
    ]
    child = doc.node(name="child", translation=[0.5, 0.0, 0.0], rotation=[math.sin(0.2), 0.0, 0.0, math.cos(0.2)])
    doc.node(name="parent", matrix=parent_matrix.T.reshape(-1).tolist(), children=[child])
    scene = parse_gltf(doc.text())
    world = scene.world_transforms(0.0)
    child_local = compose_trs(
        np.array([[0.5, 0.0, 0.0]]), np.array([[math.sin(0.2), 0.0, 0.0, math.cos(0.2)]]), np.ones((1, 3))
    )[0]
    np.testing.assert_allclose(world["parent"], parent_matrix, atol=1e-12)
    np.testing.assert_allclose(world["child"], parent_matrix @ child_local, atol=1e-12)
    assert scene.parent("child") == "parent" and scene.children("parent") == ("child",)
    np.testing.assert_array_equal(scene.animation_times(), [0.0])


def test_linear_translation_and_slerp_rotation_clamp_outside_the_keys() -> None:
    doc = Doc()
    node = doc.node(name="n")
    doc.animate(node, "translation", [0.0, 2.0], [[0.0, 0.0, 0.0], [2.0, 4.0, -2.0]])
    doc.animate(node, "rotation", [0.0, 2.0], [z_rotation(0.0), z_rotation(math.pi / 2)])
    scene = parse_gltf(doc.text())
    tracks = scene.world_transform_tracks([-1.0, 0.0, 0.5, 1.0, 2.0, 9.0])["n"]
    np.testing.assert_allclose(
        tracks[:, :3, 3], [[0, 0, 0], [0, 0, 0], [0.5, 1, -0.5], [1, 2, -1], [2, 4, -2], [2, 4, -2]], atol=1e-7
    )
    for transform, angle in zip(tracks, [0, 0, math.pi / 8, math.pi / 4, math.pi / 2, math.pi / 2], strict=True):
        np.testing.assert_allclose(transform[:3, :3], quaternion_to_matrix(np.array(z_rotation(angle))), atol=1e-7)


def test_slerp_takes_the_short_way_when_signs_flip() -> None:
    doc = Doc()
    node = doc.node(name="n")
    doc.animate(node, "rotation", [0.0, 1.0], [z_rotation(0.2), [-v for v in z_rotation(0.4)]])
    rotation = parse_gltf(doc.text()).world_transforms(0.5)["n"][:3, :3]
    np.testing.assert_allclose(rotation, quaternion_to_matrix(np.array(z_rotation(0.3))), atol=1e-7)


def test_step_holds_the_last_key() -> None:
    doc = Doc()
    node = doc.node(name="n")
    doc.animate(node, "translation", [0.0, 1.0, 2.0], [[0, 0, 0], [1, 0, 0], [5, 0, 0]], interpolation="STEP")
    tracks = parse_gltf(doc.text()).world_transform_tracks([0.5, 1.0, 1.99, 2.0, 3.0])["n"]
    np.testing.assert_allclose(tracks[:, 0, 3], [0, 1, 1, 5, 5])


def test_cubic_spline_uses_values_and_tangents() -> None:
    doc = Doc()
    node = doc.node(name="n")
    # keys at t=0 and t=2: (in-tangent, value, out-tangent) per key; out-tangent of key 0 is 2 units/s.
    values = [[0, 0, 0], [0, 0, 0], [2, 0, 0], [0, 0, 0], [1, 0, 0], [0, 0, 0]]
    doc.animate(node, "translation", [0.0, 2.0], values, interpolation="CUBICSPLINE")
    track = parse_gltf(doc.text()).world_transform_tracks([0.0, 0.5, 1.0, 2.0, 4.0])["n"][:, 0, 3]

    def hermite(s: float) -> float:
        return (s**3 - 2 * s**2 + s) * 2.0 * 2.0 + (-2 * s**3 + 3 * s**2) * 1.0

    np.testing.assert_allclose(track, [0.0, hermite(0.25), hermite(0.5), 1.0, 1.0], atol=1e-7)


def test_normalized_short_rotations_and_scale_channels() -> None:
    doc = Doc()
    node = doc.node(name="n")
    shorts = np.round(np.array([z_rotation(0.0), z_rotation(1.0)]) * 32767).astype(np.int16)
    doc.animate(node, "rotation", [0.0, 1.0], shorts)
    doc.doc["accessors"][-1]["normalized"] = True
    doc.animate(node, "scale", [0.0, 1.0], [[1, 1, 1], [3, 3, 3]])
    transform = parse_gltf(doc.text()).world_transforms(1.0)["n"]
    np.testing.assert_allclose(transform[:3, :3], 3.0 * quaternion_to_matrix(np.array(z_rotation(1.0))), atol=1e-4)


def test_interleaved_sparse_and_strip_fan_primitives() -> None:
    doc = Doc()
    positions = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=np.float32)
    normals = np.tile(np.array([[0, 0, 1]], dtype=np.float32), (4, 1))
    view = doc.view(np.hstack([positions, normals]).tobytes(), stride=24)
    doc.doc["accessors"].append({"bufferView": view, "componentType": 5126, "count": 4, "type": "VEC3"})
    sparse_rows = doc.view(np.array([2], dtype=np.uint16).tobytes())
    sparse_values = doc.view(np.array([[0, 7, 0]], dtype=np.float32).tobytes())
    doc.doc["accessors"].append(
        {
            "bufferView": view,
            "componentType": 5126,
            "count": 4,
            "type": "VEC3",
            "sparse": {
                "count": 1,
                "indices": {"bufferView": sparse_rows, "componentType": 5123},
                "values": {"bufferView": sparse_values},
            },
        }
    )
    strip = doc.accessor([0, 1, 2, 3], dtype=np.uint16)
    primitives = [
        {"attributes": {"POSITION": 0}, "indices": strip, "mode": 5},
        {"attributes": {"POSITION": 1}, "indices": strip, "mode": 6},
        {"attributes": {"POSITION": 0}},
        {"attributes": {"POSITION": 0}, "mode": 0},
    ]
    doc.doc["meshes"] = [{"primitives": primitives}]
    doc.node(name="m", mesh=0)
    geometry = parse_gltf(doc.text()).node_geometry("m")
    assert len(geometry) == 3
    np.testing.assert_array_equal(geometry[0][0], positions)
    np.testing.assert_array_equal(geometry[0][1], [[0, 1, 2], [2, 1, 3]])
    np.testing.assert_array_equal(geometry[1][0][2], [0, 7, 0])
    np.testing.assert_array_equal(geometry[1][1], [[0, 1, 2], [0, 2, 3]])
    np.testing.assert_array_equal(geometry[2][1], [[0, 1, 2]])


def test_gltf_with_an_external_buffer_and_names(tmp_path: Path) -> None:
    doc = Doc()
    doc.accessor([[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    doc.doc["meshes"] = [{"primitives": [{"attributes": {"POSITION": 0}}]}]
    doc.node(name="twin", mesh=0)
    doc.node(name="twin")
    doc.node()
    (tmp_path / "data.bin").write_bytes(bytes(doc.data))
    document = dict(doc.doc, buffers=[{"byteLength": len(doc.data), "uri": "data.bin"}])
    (tmp_path / "scene.gltf").write_text(json.dumps(document))
    scene = read_glb(tmp_path / "scene.gltf")
    assert scene.node_names == ("twin", "twin#1", "node_2")
    assert scene.warnings and "repeated" in scene.warnings[0]
    assert scene.node_geometry("twin")[0][1].tolist() == [[0, 1, 2]]
    assert scene.node_geometry("node_2") == []
    document["buffers"][0]["uri"] = "../outside.bin"
    (tmp_path / "escape.gltf").write_text(json.dumps(document))
    with pytest.raises(MetricError, match="outside"):
        read_glb(tmp_path / "escape.gltf")


def test_animation_selection_by_name_and_index() -> None:
    doc = Doc()
    node = doc.node(name="n")
    doc.animate(node, "translation", [0.0, 1.0], [[0, 0, 0], [1, 0, 0]], name="first")
    doc.animate(node, "translation", [0.0, 3.0], [[0, 0, 0], [0, 3, 0]], name="second")
    scene = parse_gltf(doc.text())
    assert scene.animation_names == ("first", "second")
    np.testing.assert_array_equal(scene.animation_times("second"), [0.0, 3.0])
    np.testing.assert_allclose(scene.world_transforms(1.0, animation=1)["n"][:3, 3], [0, 1, 0])
    with pytest.raises(MetricError, match="no animation named"):
        scene.animation_times("third")
    with pytest.raises(MetricError, match="no animation 2"):
        scene.channels(2)


def test_a_third_party_glb_from_trimesh(tmp_path: Path) -> None:
    scene = trimesh.Scene()
    box = trimesh.creation.box(extents=(0.2, 0.3, 0.4))
    turn = trimesh.transformations.rotation_matrix(0.6, [0, 1, 1], [0.1, 0.0, 0.0])
    scene.add_geometry(box, node_name="lid", geom_name="lid_mesh", transform=turn)
    scene.add_geometry(
        trimesh.creation.icosphere(subdivisions=1, radius=0.1),
        node_name="knob",
        geom_name="knob_mesh",
        parent_node_name="lid",
        transform=trimesh.transformations.translation_matrix([0, 0, 0.3]),
    )
    path = tmp_path / "third_party.glb"
    path.write_bytes(scene.export(file_type="glb"))
    ours = read_glb(path)
    world = ours.world_transforms(0.0)
    for name in ("lid", "knob"):
        ((vertices, faces),) = ours.node_geometry(name)
        placed = vertices @ world[name][:3, :3].T + world[name][:3, 3]
        expected_transform, geometry = scene.graph[name]
        reference = trimesh.transform_points(scene.geometry[geometry].vertices, expected_transform)
        np.testing.assert_allclose(placed, reference, atol=1e-6)
        assert faces.shape == scene.geometry[geometry].faces.shape


def _valid_glb() -> bytes:
    doc = Doc()
    node = doc.node(name="n")
    doc.animate(node, "translation", [0.0, 1.0], [[0, 0, 0], [1, 0, 0]])
    document = dict(doc.doc, buffers=[{"byteLength": len(doc.data)}])
    return glb_from(document, bytes(doc.data))


def _edit_json(data: bytes, change: Any) -> bytes:
    (length,) = struct.unpack("<I", data[12:16])
    document = json.loads(data[20 : 20 + length])
    change(document)
    (bin_length,) = struct.unpack("<I", data[20 + length : 24 + length])
    return glb_from(document, data[28 + length : 28 + length + bin_length])


@pytest.mark.parametrize(
    ("mutate", "message"),
    [
        (lambda d: b"glTX" + d[4:], "bad magic"),
        (lambda d: d[:4] + struct.pack("<I", 1) + d[8:], "version 1"),
        (lambda d: d[:-8], "truncated"),
        (lambda d: d[:12] + struct.pack("<I", 10**6) + d[16:], "past the end"),
        (lambda d: d[:16] + struct.pack("<I", 0x004E4942) + d[20:], "not JSON"),
        (lambda d: b"not json at all", "neither a GLB"),
        (lambda d: b'{"asset": ', "cannot be parsed"),
        (lambda d: _edit_json(d, lambda j: j["asset"].update(version="1.0")), "version '1.0'"),
        (lambda d: _edit_json(d, lambda j: j.update(extensionsRequired=["KHR_draco_mesh_compression"])), "compressed"),
        (lambda d: _edit_json(d, lambda j: j["animations"][0]["samplers"][0].update(output=99)), "missing accessor 99"),
        (
            lambda d: _edit_json(d, lambda j: j["animations"][0]["samplers"][0].update(interpolation="SPLINE")),
            "interpolation",
        ),
        (lambda d: _edit_json(d, lambda j: j["accessors"][1].update(count=3)), "runs past"),
        (lambda d: _edit_json(d, lambda j: j["nodes"].extend([{"children": [0]}, {"children": [0]}])), "two parents"),
        (lambda d: _edit_json(d, lambda j: j["nodes"].extend([{"children": [2]}, {"children": [1]}])), "cycle"),
        (
            lambda d: _edit_json(d, lambda j: j["animations"][0]["channels"][0]["target"].update(node=5)),
            "missing node 5",
        ),
        (lambda d: _edit_json(d, lambda j: j["nodes"][0].update(translation=[1, 2])), "bad matrix"),
    ],
)
def test_malformed_files_raise_metric_errors(mutate: Any, message: str) -> None:
    with pytest.raises(MetricError, match=message):
        scene = parse_gltf(mutate(_valid_glb()), source="case.glb")
        scene.world_transforms(0.5)


def test_reader_rejects_decreasing_times_and_bad_indices() -> None:
    doc = Doc()
    node = doc.node(name="n")
    doc.animate(node, "translation", [1.0, 0.0], [[0, 0, 0], [1, 0, 0]])
    with pytest.raises(MetricError, match="non-decreasing"):
        parse_gltf(doc.text()).animation_times()
    doc = Doc()
    doc.accessor([[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    doc.accessor([0, 1, 3], dtype=np.uint16)
    doc.doc["meshes"] = [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}]
    doc.node(name="m", mesh=0)
    with pytest.raises(MetricError, match=r"outside 0\.\.2"):
        parse_gltf(doc.text()).node_geometry("m")
    with pytest.raises(MetricError, match="no node named"):
        parse_gltf(doc.text()).node_geometry("x")
    with pytest.raises(MetricError, match="cannot read"):
        read_glb(Path("/nonexistent/file.glb"))
