"""How many triangles a mesh file has at least, read cheaply before it is parsed.

A 5M-triangle OBJ costs tens of seconds and gigabytes to parse; its face lines can be
counted in a fraction of a second, so an asset over its triangle budget is refused before
the expensive work. Each reader returns a lower bound (a polygon line counts as one
triangle), or 0 for formats whose count is not cheap to read (DAE, GLB/GLTF), which are
then checked while they are read.
"""

from __future__ import annotations

import re
import struct
from pathlib import Path

CHUNK_BYTES = 1 << 22
BINARY_STL_HEADER = 80
_PLY_FACES = re.compile(rb"^element\s+face\s+(\d+)\s*$", re.MULTILINE)


def _count_line_starts(path: Path, prefixes: tuple[bytes, ...]) -> int:
    """Lines of ``path`` starting with one of ``prefixes`` (streamed in blocks; no line is split)."""
    needles = tuple(b"\n" + prefix for prefix in prefixes)
    count = 0
    carry = b"\n"
    with open(path, "rb") as handle:
        while block := handle.read(CHUNK_BYTES):
            text = carry + block
            cut = text.rfind(b"\n")
            if cut <= 0:
                carry = text
                continue
            complete, carry = text[:cut], text[cut:]
            count += sum(complete.count(needle) for needle in needles)
    return count + sum(carry.count(needle) for needle in needles)


def _obj(path: Path) -> int:
    return _count_line_starts(path, (b"f ", b"f\t"))


def _stl(path: Path) -> int:
    with open(path, "rb") as handle:
        head = handle.read(BINARY_STL_HEADER + 4)
    size = path.stat().st_size
    if len(head) == BINARY_STL_HEADER + 4:
        (declared,) = struct.unpack("<I", head[BINARY_STL_HEADER:])
        if BINARY_STL_HEADER + 4 + 50 * declared == size:  # binary: the header's count is exact
            return int(declared)
    return _count_line_starts(path, (b"facet", b" facet", b"\tfacet", b"  facet"))


def _ply(path: Path) -> int:
    with open(path, "rb") as handle:
        head = handle.read(64 * 1024)
    header = head.split(b"end_header", 1)[0]
    found = _PLY_FACES.search(header)
    return int(found.group(1)) if found else 0


def _off(path: Path) -> int:
    with open(path, "rb") as handle:
        head = handle.read(64 * 1024)
    lines = [line.split(b"#", 1)[0].strip() for line in head.splitlines()]
    lines = [line for line in lines if line]
    if not lines or not lines[0].upper().endswith(b"OFF"):
        return 0
    counts = lines[0][3:].split() or (lines[1].split() if len(lines) > 1 else [])
    try:
        return int(counts[1])
    except (IndexError, ValueError):
        return 0


_READERS = {".obj": _obj, ".stl": _stl, ".ply": _ply, ".off": _off}


def least_faces(path: Path) -> int:
    """A lower bound of the triangles in mesh file ``path`` (0 when not cheap to know)."""
    reader = _READERS.get(path.suffix.lower())
    return 0 if reader is None else reader(path)
