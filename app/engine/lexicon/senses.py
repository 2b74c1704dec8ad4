"""What a verb sense does to each class of part: the end state it names.

A part's class comes from its kind entry: an openable part (door, drawer, lid), a control
pressed into its face (button, switch), a control pressed down (pedal, lever, handle), a
control that turns (knob, latch), a part that spins (wheel, turntable) or anything else.
The table answers "press + button" -> ``pressed``, "push + drawer" -> ``closed``,
"raise + lid" -> ``open``; the resolver turns the state into a joint value from geometry.
"""

from __future__ import annotations

from collections.abc import Mapping
from enum import StrEnum
from types import MappingProxyType

from app.engine.contracts.steps import GoalState
from app.engine.lexicon.kinds import KindInfo
from app.engine.lexicon.verbs import VerbSense


class PartClass(StrEnum):
    OPENABLE = "openable"
    PUSHED = "pushed"
    """Pressed into the face it sits on (buttons, switches)."""
    LEVERED = "levered"
    """Pressed down (pedals, levers, handles)."""
    TURNED = "turned"
    """Turned (knobs, latches)."""
    SPINNER = "spinner"
    OTHER = "other"


def part_class(info: KindInfo | None) -> PartClass:
    if info is None:
        return PartClass.OTHER
    if info.openable:
        return PartClass.OPENABLE
    if info.press == "into_face":
        return PartClass.PUSHED
    if info.press == "down":
        return PartClass.LEVERED
    if info.press == "turn":
        return PartClass.TURNED
    if info.spins:
        return PartClass.SPINNER
    return PartClass.OTHER


S, C = VerbSense, PartClass
_ANY = (C.OPENABLE, C.PUSHED, C.LEVERED, C.TURNED, C.SPINNER, C.OTHER)


def _row(default: GoalState, **per_class: GoalState) -> Mapping[PartClass, GoalState]:
    table: dict[PartClass, GoalState] = dict.fromkeys(_ANY, default)
    table.update({PartClass(k): v for k, v in per_class.items()})
    return MappingProxyType(table)


END_STATE: Mapping[VerbSense, Mapping[PartClass, GoalState]] = MappingProxyType({
    S.OPEN: _row("open", turned="ccw", pushed="pressed", levered="up"),
    S.CLOSE: _row("closed", turned="cw", pushed="rest", levered="rest"),
    S.PRESS: _row("pressed", openable="closed", turned="cw"),
    S.PULL_OUT: _row("open", pushed="rest", levered="up", turned="cw"),
    S.PUSH_IN: _row("closed", pushed="pressed", levered="pressed", turned="cw"),
    S.TURN: _row("cw", openable="open", pushed="pressed"),
    S.SPIN: _row("velocity", openable="open", pushed="pressed", levered="pressed"),
    S.RAISE: _row("up", openable="open", turned="cw"),  # "turn up the browning knob": more
    S.LOWER: _row("down", openable="closed", turned="ccw"),
    S.TOGGLE: _row("pressed", openable="open", turned="cw"),
    S.MOVE: _row("open", pushed="pressed", levered="pressed", turned="cw"),
    S.UNLATCH: _row("pressed", turned="cw", levered="pressed", openable="open"),
    S.LOCK: _row("rest", openable="closed"),
    S.OPERATE: _row("pressed", turned="cw", openable="open", spinner="velocity"),
    S.RELEASE: _row("rest"),
    S.RECLINE: _row("open"),
    S.SWITCH_ON: _row("pressed", turned="cw", openable="open"),
    S.SWITCH_OFF: _row("rest"),
    S.RETURN: _row("previous"),
    S.HOLD: _row("pressed", openable="open", turned="cw"),
    S.YAW: _row("cw"),
    S.GRASP: _row("rest"),
})
"""Sense -> part class -> the end state it means (SPIN and friends on a part that cannot spin do the nearest thing)."""

CLOSING_STATES = frozenset({"closed", "rest", "down", "previous"})
"""States that undo an opening: an amount is then measured from where the part is now."""
