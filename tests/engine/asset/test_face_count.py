"""Triangle counts read before parsing (so an oversized mesh is refused before the expensive work)."""

from __future__ import annotations

import struct
from pathlib import Path

import pytest

from app.engine.asset import face_count
from app.engine.asset.face_count import least_faces


def test_obj_face_lines_are_counted_across_block_boundaries(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(face_count, "CHUNK_BYTES", 7)  # lines split across many blocks
    path = tmp_path / "m.obj"
    path.write_text("f 1 2 3\nv 0 0 0\n# f not a face\nf 1 2 3 4\r\nvt 0 0\nf\t1 2 3\nf 3 2 1")
    assert least_faces(path) == 4


def test_binary_stl_header_count_and_ascii_facets(tmp_path: Path) -> None:
    binary = tmp_path / "b.stl"
    binary.write_bytes(b"\0" * 80 + struct.pack("<I", 3) + b"\0" * 150)
    assert least_faces(binary) == 3
    ascii_stl = tmp_path / "a.stl"
    ascii_stl.write_text("solid x\n facet normal 0 0 1\n outer loop\n endloop\n endfacet\n facet normal 0 0 1\nendsolid\n")
    assert least_faces(ascii_stl) == 2


def test_ply_and_off_headers(tmp_path: Path) -> None:
    ply = tmp_path / "m.ply"
    ply.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nelement face 5000000\nend_header\n")
    assert least_faces(ply) == 5_000_000
    off = tmp_path / "m.off"
    off.write_text("OFF\n# comment\n4 7 0\n")
    assert least_faces(off) == 7
    assert least_faces(tmp_path / "unknown.dae") == 0
