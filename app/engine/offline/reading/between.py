"""A pause said to go between the presses of the step before ("enter 8 1 6, pausing a moment between each digit",
"…, waiting a second between keys"): not a step of its own and no part, but the wait before each press after the first
of that step. Before this stage "each digit" was read as a part the asset does not have, and the prompt refused. And the
order of a step's parts said once more ("open the drawers one after another, each one fully out before the next one
starts"): the steps already run one after another, so the clause about "the next one" is no step of its own."""

from __future__ import annotations

from app.engine.lexicon.verbs import VerbSense
from app.engine.offline.reading.acts import Act

MOMENT_S = 0.5
"""The pause when none is said ("pausing a moment between each digit")."""
_EACH = frozenset({"each", "every"})


def _between(act: Act) -> bool:
    """A wait whose only words after "between" are "each X", "every X" or a plural ("between presses")."""
    frame = act.goal
    words = frame.text.split()
    if frame.sense is not VerbSense.WAIT or act.means is not None or act.results or "between" not in words:
        return False
    after = words[words.index("between") + 1:]
    themes = (*frame.themes, *frame.instruments)
    return bool(after) and (after[0] in _EACH or all(m.plural for m in themes)) and all(
        m.start >= words.index("between") for m in themes)


_STARTS = frozenset({"start", "starts", "begin", "begins", "go", "goes", "moves", "opens", "comes"})


def _next_one(act: Act, before: Act) -> bool:
    """"(…, each one fully out before) the next one starts", after a step whose parts go one after another."""
    frame = act.goal
    words = frame.text.split()
    return bool(before.goal.in_turn) and "next" in words and bool(frame.themes) and all(
        m.anaphor or m.pronoun for m in frame.themes) and (frame.verb is None or words[-1] in _STARTS) and not frame.quantities.amount


def paused_between(acts: list[Act]) -> tuple[list[Act], dict[int, float]]:
    """``acts`` without the pauses said to go between the presses of the act before, and {index in the returned list of
    that act: the pause}."""
    kept: list[Act] = []
    gaps: dict[int, float] = {}
    for act in acts:
        if kept and _between(act):
            gaps[len(kept) - 1] = act.goal.quantities.duration_s or MOMENT_S
            continue
        if kept and _next_one(act, kept[-1]):
            continue
        kept.append(act)
    return kept, gaps
