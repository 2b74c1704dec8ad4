"""Audit of a reading against the words it came from: what the prompt said that the reading did not use.

The front end may misread a clause and still produce a clean, valid plan — the worst outcome, a wrong
animation without a warning. This stage looks back at each clause that produced motion, with the typed
tokens of the normaliser (never the raw text), and warns where the reading and the words disagree:

- a measured amount the user gave ("35 cm", "one full turn", "for 3 s") that no goal, hold, wait,
  duration or whole-object motion of the reading carries;
- a clause that names only one end state ("shut", "open") while its part moves toward the other end.

It never changes the reading; it adds notes that name the words and what was done instead, so a user
can tell a misreading from a correct one without opening the trajectory.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

from app.engine.contracts.steps import Extension
from app.engine.offline.geometry import ObjectGeometry
from app.engine.offline.reading.clauses import Clause, Link
from app.engine.offline.reading.numbers import RELATIVE_AFTER, rate_at, unit_factor
from app.engine.offline.reading.tokens import Token

CLOSING_WORDS = frozenset({"shut", "closed", "close"})
OPENING_WORDS = frozenset({"open", "opened", "ajar", "reopen", "out"})
_BOTH_WAYS = frozenset({"again", "back", "previous", "original", "where", "partly", "nearly", "almost", "until", "till"})
"""Words after which a clause may name one end and move toward the other ("close it back to where it was")."""
RELATIVE_TOLERANCE = 0.03
ABSOLUTE_TOLERANCE = {"rad": 0.01, "m": 0.002, "s": 0.05, "fraction": 0.01}
MOVED = 0.02
"""Share of a joint's range a move must cover to count as a motion."""


_UNIT_SKIP = frozenset({"full", "complete", "whole", "more", "further", "extra", "clockwise", "anticlockwise", "counterclockwise",
                        "anti-clockwise", "counter-clockwise", "of", "a"})


def said_amounts(clauses: Sequence[Clause]) -> dict[int, list[tuple[str, float, str]]]:
    """Per clause, (kind, SI value, words) of every number with a unit ("35 cm", "1.5 turns", "3 s", "40%"); a bare
    "20 more" takes the unit of the amount before it."""
    out: dict[int, list[tuple[str, float, str]]] = {}
    last: tuple[str, float] | None = None
    for clause in clauses:
        tokens = clause.tokens
        found = out.setdefault(clause.index, [])
        for i, token in enumerate(tokens):
            if token.number is None or rate_at(list(tokens), i) is not None:  # "5 cm per second": a speed, not how far
                continue
            after = tokens[i + 1:i + 4]
            k = next((k for k, t in enumerate(after) if t.lemma not in _UNIT_SKIP), None)
            unit = unit_factor(after[k].lemma) if k is not None else None
            if unit is not None and k is not None:
                last = unit if unit[0] in ("rad", "m") else last
                found.append((unit[0], token.number * unit[1], " ".join(t.text for t in tokens[i:i + k + 2])))
            elif last is not None and after and after[0].lemma in RELATIVE_AFTER:
                found.append((last[0], token.number * last[1], f"{token.text} {after[0].text}"))
    return out


def _names_a_reference(before: Sequence[Token]) -> bool:
    """The state word after these is a reference or a measure, not the goal: "40 degrees from (fully) shut", "30 degrees open"."""
    return any(t.text == "from" for t in before[-2:]) or (bool(before) and unit_factor(before[-1].lemma) is not None)


def _step_numbers(extension: Extension) -> dict[str, list[float]]:
    found: dict[str, list[float]] = {"rad": [], "m": [], "s": [], "fraction": []}
    for step in extension.steps:
        found["s"].extend(v for v in (step.duration_s, step.hold_s, step.wait_before_s) if v)
        for move in (*step.controls, *step.effects):
            goal = move.goal
            if goal.amount is not None and goal.unit is not None:
                found[goal.unit].append(goal.amount)
            if goal.value is not None:
                found["rad"].append(abs(goal.value))
                found["m"].append(abs(goal.value))
            if goal.duration_s:
                found["s"].append(goal.duration_s)
                if goal.omega_radps is not None:
                    found["rad"].append(abs(goal.omega_radps) * goal.duration_s)
        if step.base is not None:
            found["m"].append(step.base.distance_m)
            found["rad"].append(abs(step.base.yaw_rad))
    return found


def _moves_of(understanding: Iterable[dict[str, Any]]) -> dict[int, list[dict[str, Any]]]:
    return {entry["clause"]: [move for step in entry.get("steps", []) for move in step.get("moves", [])] for entry in understanding}


def _travel_numbers(moves: Iterable[dict[str, Any]], obj: ObjectGeometry) -> dict[str, list[float]]:
    """How far each move went, from where it started and from the closed end (what an amount may be measured from)."""
    found: dict[str, list[float]] = {"rad": [], "m": []}
    for move in moves:
        geometry = obj.joints.get(move["joint"])
        if geometry is None or "value" not in move:
            continue
        unit = "m" if geometry.type == "prismatic" else "rad"
        value = move["value"]
        found[unit].append(abs(value - move.get("from_value", value)))
        found[unit].append(abs(value))
        if geometry.closed_value is not None:
            found[unit].append(abs(value - geometry.closed_value))
    return found


def _carried(kind: str, value: float, pools: Sequence[dict[str, list[float]]]) -> bool:
    value = abs(value)
    tolerance = max(ABSOLUTE_TOLERANCE[kind], RELATIVE_TOLERANCE * value)
    return any(abs(abs(v) - value) <= tolerance for pool in pools for v in pool.get(kind, ()))


def _absolute(goal: str) -> bool:
    return goal in ("vertical", "flat", "upper", "lower") or goal.startswith("to ")


def _toward_closed(move: dict[str, Any], obj: ObjectGeometry) -> bool | None:
    """Whether the move went toward its part's closed end (``None``: not a real move, or no closed/open end)."""
    geometry = obj.joints.get(move["joint"])
    if geometry is None or geometry.closed_value is None or geometry.open_value is None or "value" not in move or "from_value" not in move:
        return None
    span = abs(geometry.open_value - geometry.closed_value)
    step = move["value"] - move["from_value"]
    if span <= 0 or abs(step) < MOVED * span:
        return None
    return (step > 0) == (geometry.closed_value > geometry.open_value)


def audit(clauses: Sequence[Clause], extension: Extension, understanding: list[dict[str, Any]], obj: ObjectGeometry,
          turned: frozenset[int] = frozenset()) -> list[str]:
    """Warnings where the reading does not carry what a clause said (see the module docstring). ``turned``: clauses
    whose told state was put the other way on purpose (a complaint, :mod:`..complaints`), not checked for direction."""
    notes: list[str] = []
    moves = _moves_of(understanding)
    numbers = _step_numbers(extension)
    every_move = [move for clause_moves in moves.values() for move in clause_moves]
    travel = _travel_numbers(every_move, obj)
    amounts = said_amounts(clauses)
    corrected = {c.index - 1 for c in clauses if c.tokens and c.tokens[0].text == "instead"}  # "15 cm - no wait, make that 20 cm"
    for clause in clauses:
        if clause.index not in moves or clause.link is Link.NEGATED:
            continue
        for kind, value, words in amounts[clause.index] if clause.index not in corrected else ():
            if not _carried(kind, value, (numbers, travel)):
                notes.append(f"did not use '{words}' in '{clause.text}': check the result")
        said = {t.text for k, t in enumerate(clause.tokens) if not _names_a_reference(clause.tokens[max(0, k - 2):k])}
        if said & _BOTH_WAYS or clause.index in turned:
            continue
        closing, opening = bool(said & CLOSING_WORDS), bool(said & OPENING_WORDS)
        if closing == opening:
            continue
        for move in moves[clause.index]:
            if move.get("role") == "control" or move.get("measured_from") == "closed" or _absolute(move["goal"]):
                continue  # a goal measured from closed, or an orientation, may lie either way
            toward = _toward_closed(move, obj)
            if toward is not None and toward != closing:
                way = "closes" if toward else "opens"
                word = next(t.text for t in clause.tokens if t.text in (CLOSING_WORDS if closing else OPENING_WORDS))
                notes.append(f"'{word}' in '{clause.text}', but {move['link']} ({move['joint']}) {way}: check the result")
    return notes
