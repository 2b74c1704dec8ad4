"""Phrases that tell similar parts apart: "the top drawer (link_2)", "the lower-left door (link_0)".

Used wherever a user must choose between parts: ambiguity refusals, ``artimo inspect``
and the per-clause explanation. Positions are as seen facing the object's front.
"""

from __future__ import annotations

from app.engine.asset.model import ArticulatedAsset
from app.engine.offline.geometry import ObjectGeometry
from app.engine.offline.grounding import Part, _lines, position
from app.engine.offline.naming import describe_link

_ORDINAL_WORDS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth")


def _line_labels(count: int, near: str, far: str) -> list[str]:
    if count == 1:
        return [""]
    if count == 2:
        return [near, far]
    if count == 3:
        return [near, "middle", far]
    return [f"{_ORDINAL_WORDS[i] if i < len(_ORDINAL_WORDS) else str(i + 1)} from the {near}" for i in range(count)]


def _labels(parts: list[Part], obj: ObjectGeometry) -> dict[str, tuple[str, str]]:
    """joint -> (row label, column label) among ``parts``."""
    rows = _lines(parts, obj, axis=2)
    columns = _lines(parts, obj, axis=1)
    row_names = _line_labels(len(rows), "top", "bottom")
    column_names = _line_labels(len(columns), "left", "right")
    out: dict[str, tuple[str, str]] = {}
    for part in parts:
        row = next(i for i, line in enumerate(rows) if part in line)
        column = next(i for i, line in enumerate(columns) if part in line)
        out[part.joint] = (row_names[row], column_names[column])
    return out


def _combine(row: str, column: str) -> str:
    if not row or not column:
        return row or column
    if " from the " in row or " from the " in column:
        return f"{row}, {column}"
    return f"{'upper' if row == 'top' else 'lower' if row == 'bottom' else row}-{column}"


def distinguishing(parts: list[Part], obj: ObjectGeometry) -> dict[str, str]:
    """joint -> the shortest position words that single it out among ``parts`` ("" if none do)."""
    if len(parts) < 2:
        return {p.joint: "" for p in parts}
    labels = _labels(parts, obj)
    out: dict[str, str] = {}
    for part in parts:
        row, column = labels[part.joint]
        for choice in (row, column, _combine(row, column)):
            if choice and sum(1 for q in parts if _matches(labels[q.joint], choice)) == 1:
                out[part.joint] = choice
                break
        else:
            out[part.joint] = ""
    return out


def _matches(label: tuple[str, str], choice: str) -> bool:
    row, column = label
    return choice in (row, column, _combine(row, column)) and (choice != row or True) and (
        choice == _combine(row, column) or choice == row or choice == column)


def name_each(parts: list[Part], asset: ArticulatedAsset, obj: ObjectGeometry, noun: str | None = None) -> list[str]:
    """How to say each part: "the upper door (link_1)"."""
    words = distinguishing(parts, obj)
    out = []
    for part in parts:
        label = noun or (part.kind.value if part.kind is not None else describe_link(asset, part.link).split(" (")[0])
        where = words.get(part.joint, "")
        out.append(f"the {where + ' ' if where else ''}{label} ({part.link})")
    return out


def where_is(part: Part, obj: ObjectGeometry) -> dict[str, str]:
    """Where a part sits on the object as seen from its front: top/bottom, left/right, front/back
    (an empty string on an axis where it sits in the middle third)."""
    local = position(part, obj)
    half = [max(float(e) / 2.0, 1e-9) for e in (obj.extents @ abs(obj.front), obj.extents @ abs(obj.right), obj.extents @ abs(obj.up))]

    def side(value: float, extent: float, low: str, high: str) -> str:
        if value > extent / 3.0:
            return high
        if value < -extent / 3.0:
            return low
        return ""

    return {"vertical": side(float(local[2]), half[2], "bottom", "top"), "horizontal": side(float(local[1]), half[1], "left", "right"),
            "depth": side(float(local[0]), half[0], "back", "front")}
