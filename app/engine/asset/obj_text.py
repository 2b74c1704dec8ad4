"""The text of a Wavefront OBJ file in the common subset -> vertex arrays and faces grouped by material.

The subset is what exporters such as the PartNet-Mobility one (SSTK) write: UTF-8 lines (no tabs)
``v x y z``, ``vt u v [w]``, ``vn x y z``, triangles ``f`` in one of the forms ``a b c``,
``a/t b/t c/t``, ``a//n b//n c//n`` or ``a/t/n b/t/n c/t/n`` (1-based indices, the same form for
every face of a material), ``usemtl``, ``o``, ``g``, ``s``, one ``mtllib``, and ``#`` comments.
Anything else raises :class:`NotInSubset` and the file goes to trimesh.

The grouping follows what trimesh does with ``group_material=True`` (its default): one mesh per
``usemtl`` name, faces in file order, and the meshes listed last-material-first.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from app.engine.asset.mtl_reader import NotInSubset
from app.engine.types import FloatArray, IntArray

_CONTROL = re.compile(r"[\x00-\x09\x0b-\x1f\x7f]")
"""ASCII control characters but the newline (tabs included: trimesh does not split on them)."""
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_NAME = re.compile(r"\S+")
SCENE_ROOT = "world"
"""The root frame of a trimesh scene: a mesh named so would not be listed like the others."""


def _rows_pattern(row: str) -> re.Pattern[str]:
    """Rows of ``row`` (spaces around and between the values), one per line."""
    return re.compile(rf"(?: *{row} *\n)* *{row} *", re.ASCII)


def _numbers_row(count: int) -> str:
    return " +".join([_NUMBER] * count)


_NUMBER_ROWS = {count: _rows_pattern(_numbers_row(count)) for count in (2, 3)}
FACE_FORMS = {"v": r"\d+", "v/vt": r"\d+/\d+", "v//vn": r"\d+//\d+", "v/vt/vn": r"\d+/\d+/\d+"}
_FACE_ROWS = {form: _rows_pattern(" +".join([ref] * 3)) for form, ref in FACE_FORMS.items()}
_UNIQUE_KEY_LIMIT = {2: 2**31 - 1, 3: 2**20 - 1}
"""Indices above these would make trimesh order unmerged vertices another way (its row hash no longer fits
64 bits): such meshes go to trimesh."""


@dataclass(frozen=True)
class FaceGroup:
    """The triangles of one material: 0-based indices into the file's ``v``, ``vt`` and ``vn`` lists."""

    material: str | None
    vertex: IntArray
    texture: IntArray | None
    normal: IntArray | None


@dataclass(frozen=True)
class ObjText:
    """A parsed OBJ file.

    Attributes
    ----------
    vertices, uv, normals : (n, 3), (t, 2) and (k, 3) float
        Every ``v``, ``vt`` (first two values) and ``vn`` line in file order (None when there are none).
    groups
        One per material, in the order trimesh's scene lists them (last first used, first).
    """

    vertices: FloatArray
    uv: FloatArray | None
    normals: FloatArray | None
    mtllib: str | None
    groups: tuple[FaceGroup, ...]


def _floats(rows: list[str], width: int, what: str) -> FloatArray | None:
    if not rows:
        return None
    joined = "\n".join(rows)
    if "+e" in joined or "-e" in joined or not _NUMBER_ROWS[width].fullmatch(joined):
        raise NotInSubset(f"a {what} line is not {width} plain numbers")
    values = np.fromstring(joined, dtype=np.float64, sep=" ")
    if values.size != width * len(rows):
        raise NotInSubset(f"{what} lines hold {values.size} numbers, expected {width * len(rows)}")
    return values.reshape((len(rows), width))


def _face_form(row: str) -> str:
    first = (row.split() or [""])[0]
    slashes = first.count("/")
    form = {0: "v", 1: "v/vt", 2: "v//vn" if "//" in first else "v/vt/vn"}.get(slashes, "")
    if not form:
        raise NotInSubset(f"face reference {first!r} is not v, v/vt, v//vn or v/vt/vn")
    return form


def _index_columns(rows: list[str], form: str, counts: dict[str, int]) -> dict[str, IntArray]:
    """The 0-based index arrays of one group's faces, by kind (``v``, ``vt``, ``vn``)."""
    joined = "\n".join(rows)
    if not _FACE_ROWS[form].fullmatch(joined):
        raise NotInSubset(f"the faces of one material are not all triangles of positive indices in the form {form}")
    kinds = form.replace("//", "/").split("/")
    flat = np.fromstring(joined.replace("/", " "), dtype=np.int64, sep=" ")
    if flat.size != 3 * len(kinds) * len(rows):
        raise NotInSubset("face lines hold an unexpected count of indices")
    table = flat.reshape((len(rows), 3, len(kinds)))
    columns: dict[str, IntArray] = {}
    limit = _UNIQUE_KEY_LIMIT.get(len(kinds), 2**62)
    for position, kind in enumerate(kinds):
        column = table[:, :, position]
        if column.size and (column.min() < 1 or column.max() > counts[kind]):
            raise NotInSubset(f"a face refers to {kind} {int(column.min())}..{int(column.max())} of {counts[kind]}")
        if counts[kind] >= limit:
            raise NotInSubset(f"{counts[kind]} {kind} entries: more than the built-in reader orders like trimesh")
        columns[kind] = column - 1
    return columns


def _material_name(rest: str) -> str:
    names = _NAME.findall(rest)
    if len(names) != 1 or names[0] == SCENE_ROOT:
        raise NotInSubset(f"usemtl {rest.strip()!r} is not one name (or is {SCENE_ROOT!r})")
    return names[0]


def parse_obj(data: bytes) -> ObjText:
    """Parse OBJ bytes in the subset.

    Raises
    ------
    NotInSubset
        The file uses something outside the subset.
    """
    try:
        text = data.decode("utf-8").strip().replace("\r\n", "\n")
    except UnicodeDecodeError as exc:
        raise NotInSubset("the OBJ file is not UTF-8") from exc
    if _CONTROL.search(text) or "\\" in text:
        raise NotInSubset("the OBJ file holds tabs, control characters or backslashes")
    rows: dict[str, list[str]] = {"v": [], "vt": [], "vn": []}
    faces: dict[str | None, list[str]] = {}
    material: str | None = None
    mtllib: str | None = None
    directives = {"usemtl": 0, "mtllib": 0}
    for line in text.split("\n"):
        key, _, rest = line.partition(" ")
        if key in rows:
            rows[key].append(rest)
        elif key == "f":
            faces.setdefault(material, []).append(rest)
        elif key == "usemtl":
            material = _material_name(rest)
            directives[key] += 1
        elif key == "mtllib":
            mtllib = rest.strip()
            directives[key] += 1
        elif key == "o" and rest.strip() == SCENE_ROOT:
            raise NotInSubset(f"an object is called {SCENE_ROOT!r}")
        elif not (key in ("o", "g", "s") or line.startswith("#") or not line):
            raise NotInSubset(f"statement {key[:20]!r} is outside the subset")
    for word, count in directives.items():  # trimesh finds these words anywhere, comments and names included
        if text.count(word) != count:
            raise NotInSubset(f"'{word}' appears outside its own statements")
    if directives["mtllib"] > 1:
        raise NotInSubset("more than one mtllib")
    if not faces:
        raise NotInSubset("the file has no faces")
    vertices = _floats(rows["v"], 3, "v")
    if vertices is None:
        raise NotInSubset("the file has no vertices")
    uv_width = len(rows["vt"][0].split()) if rows["vt"] else 2
    if uv_width not in (2, 3):
        raise NotInSubset("vt lines are not 2 or 3 numbers")
    uv = _floats(rows["vt"], uv_width, "vt")
    normals = _floats(rows["vn"], 3, "vn")
    counts = {"v": len(vertices), "vt": 0 if uv is None else len(uv), "vn": 0 if normals is None else len(normals)}
    groups = []
    for name, lines in faces.items():
        columns = _index_columns(lines, _face_form(lines[0]), counts)
        groups.append(FaceGroup(material=name, vertex=columns["v"], texture=columns.get("vt"), normal=columns.get("vn")))
    return ObjText(vertices=vertices, uv=None if uv is None else uv[:, :2], normals=normals, mtllib=mtllib,
                   groups=tuple(reversed(groups)))
