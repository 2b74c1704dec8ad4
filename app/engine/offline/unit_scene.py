"""Which of several like units the clauses are about, as the perceiver reads them in turn (:mod:`.units` says what a
unit is): the one unit a prompt names anywhere ("I'd like some toast out of the middle toaster"), the unit a clause
names ("the microwave on the right", "the one in the middle"), and the clauses that only set it — a description of the
units ("Two mixer taps side by side.") or a choice of one ("Take the left one and swing its lever") — which are no step."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.engine.lexicon.verbs import CHOOSING_VERBS
from app.engine.offline.reading.acts import Act
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.mentions import Mention
from app.engine.offline.units import like_units, unit_named, unit_topic

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder


def _mentions(frames: tuple[Frame, ...] | list[Frame]) -> tuple[Mention, ...]:
    return tuple(m for f in frames for m in (*f.themes, *f.instruments))


def prompt_unit(builder: Builder, frames: list[Frame]) -> None:
    """The scene is the one unit the prompt names, when it names exactly one."""
    if like_units(builder.parts, builder.asset) < 2:
        return
    named = {t for m in _mentions(frames) if (t := unit_named(m, True))}
    if len(named) == 1:
        builder.refs.scene = next(iter(named))


def unit_clause(builder: Builder, acts: list[Act], index: int, act: Act) -> bool:
    """Set the scene from the unit ``act`` (``acts[index]``, with any wait carried to it) names; True when that clause is
    no step of its own (with a note)."""
    part_said = any(m.kind is not None for m in _mentions([f for a in acts[:index] for f in a.frames]))  # "the top drawer, then the bottom one": a drawer
    topic = unit_topic(_mentions(act.frames), builder.parts, builder.asset, part_said)
    if topic:
        builder.refs.scene = topic
    if index + 1 >= len(acts):
        return False
    goal = act.goal
    if goal.verb is None and goal.themes and all(m.is_object and m.plural and not m.sides for m in goal.themes) and not (
            act.condition or goal.heading or act.wait_before_s or goal.stative):
        builder.notes.append(f"read '{goal.text}' as a description of {builder.asset.name}")
        return True
    if topic and goal.verb in CHOOSING_VERBS and all(m.is_object or m.anaphor for m in goal.themes) and not act.wait_before_s:
        builder.notes.append(f"read '{goal.text}' as which one the steps after it are on")
        return True
    return False
