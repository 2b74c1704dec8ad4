"""Codes entered on a keypad: "type 1-2-3-4", "enter the code top-left, bottom-middle".

Keys are found by their place in the keypad's grid of rows and columns (as seen facing it).
Digits follow the telephone layout (1 2 3 / 4 5 6 / 7 8 9 / * 0 #) on a 3-column keypad of
three or four rows; on any other layout digits are refused with a hint to name keys by place.
"""

from __future__ import annotations

from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.words import Side
from app.engine.offline.grounding import Part, _lines
from app.engine.offline.referents import Referents

_PHONE: dict[str, tuple[int, int]] = {str(d): ((d - 1) // 3, (d - 1) % 3) for d in range(1, 10)}
_PHONE["0"] = (3, 1)


def _phone(rows: list[list[Part]], columns: list[list[Part]]) -> bool:
    return len(columns) == 3 and len(rows) in (3, 4)


def _grid(keys: list[Part], refs: Referents) -> tuple[list[list[Part]], list[list[Part]]]:
    """Rows and columns of the keypad. A key outside the grid (an "open" or "enter" button of its own size, or alone in
    its row or column) is left out when the rest make a phone layout."""
    rows, columns = _lines(keys, refs.obj, axis=2), _lines(keys, refs.obj, axis=1)
    if _phone(rows, columns):
        return rows, columns
    sizes = sorted(k.geometry.size for k in keys)
    middle = sizes[len(sizes) // 2]
    odd = {k.joint for k in keys if not middle / 1.5 <= k.geometry.size <= middle * 1.5}
    lone = {p.joint for line in (*rows, *columns) if len(line) == 1 for p in line}
    for outside in (odd, lone, odd | lone):
        kept = [k for k in keys if k.joint not in outside]
        if outside and len(kept) >= 9:
            grid = _lines(kept, refs.obj, axis=2), _lines(kept, refs.obj, axis=1)
            if _phone(*grid):
                return grid
    return rows, columns


def _at(rows: list[list[Part]], columns: list[list[Part]], row: int, column: int) -> Part | None:
    if row >= len(rows) or column >= len(columns):
        return None
    found = [p for p in rows[row] if p in columns[column]]
    return found[0] if len(found) == 1 else None


def _place(sides: tuple[str, ...], rows: list[list[Part]], columns: list[list[Part]]) -> Part | None:
    row = column = None
    for side in sides:
        if "=" in side:
            line, _, number = side.partition("=")
            index = int(number) - 1 if int(number) > 0 else -1
            if line == "row":
                row = index if index >= 0 else len(rows) - 1
            else:
                column = index if index >= 0 else len(columns) - 1
            continue
        if side == Side.TOP.value:
            row = 0
        elif side == Side.BOTTOM.value:
            row = len(rows) - 1
        elif side == Side.LEFT.value:
            column = 0
        elif side == Side.RIGHT.value:
            column = len(columns) - 1
        elif side == Side.MIDDLE.value:
            if row is None and len(rows) % 2 == 1 and any(s in (Side.LEFT.value, Side.RIGHT.value) for s in sides):
                row = len(rows) // 2
            elif column is None and len(columns) % 2 == 1:
                column = len(columns) // 2
            elif row is None and len(rows) % 2 == 1:
                row = len(rows) // 2
    if row is None and len(rows) == 1:
        row = 0
    if column is None and len(columns) == 1:
        column = 0
    if row is None or column is None:
        return None
    return _at(rows, columns, row, column)


def code_keys(codes: tuple[tuple[str, ...], ...], refs: Referents, notes: list[str] | None = None) -> list[Part]:
    """The keypad's keys for ``codes``, in order; GroundingError when a key cannot be placed. A keypad read as a phone
    layout only once keys outside its grid were left out is a guess: said in ``notes``."""
    keys = refs.of_kind(PartKind.BUTTON)
    if len(keys) < 2:
        raise refs.refuse(f"{refs.asset.name} has no keypad to enter a code on")
    rows, columns = _grid(keys, refs)
    left_out = sorted(k.link for k in keys if not any(k in row for row in rows))
    if left_out and notes is not None and any(code[0] == "digit" for code in codes):
        notes.append(f"read the keypad as a phone layout (1 2 3 / 4 5 6 / 7 8 9 / * 0 #) without {', '.join(left_out)}, which sit outside its grid: "
                     "check the keys, or name them by place")
    out: list[Part] = []
    for code in codes:
        if code[0] == "digit":
            if not _phone(rows, columns) or (code[1] == "0" and len(rows) != 4):
                raise refs.refuse(f"cannot tell which key is '{code[1]}' on a keypad of {len(rows)} rows and {len(columns)} columns; "
                                  "name keys by place instead (e.g. 'the top-left key')")
            row, column = _PHONE[code[1]]
            key = _at(rows, columns, row, column)
        else:
            key = _place(code[1:], rows, columns)
        if key is None:
            raise GroundingError(f"no key at '{' '.join(code[1:])}' on the keypad of {refs.asset.name}",
                                 movable_parts=[p.describe(refs.asset) for p in refs.parts])
        out.append(key)
    return out
