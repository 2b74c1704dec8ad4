"""Steps told after the step they come before: "let the lever go back up after holding it down for 2 s", "release the
lever, but only after you've depressed it fully and held it down for 3 s". The earlier step is put first; an "it" in it
points forward to the part of the step it precedes, and a step joined to it by "and" goes with it."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.offline.reading.clauses import Link

if TYPE_CHECKING:
    from app.engine.offline.reading.acts import Act


_BEFORE_ALL = (("before", "any", "of", "that"), ("before", "all", "that"), ("before", "all", "of", "that"), ("before", "anything", "else"),
               ("before", "everything"), ("before", "everything", "else"), ("before", "the", "rest"), ("first", "of", "all"),
               ("before", "any", "of", "this"), ("before", "all", "this"), ("before", "doing", "any", "of", "that"), ("before", "anything"))
"""A step told last that goes before every step told before it."""


_THEM = frozenset({"either", "both", "any", "all", "each", "of", "them", "those", "these", "one", "anything"})


def _before_them(words: tuple[str, ...]) -> bool:
    """"... before you touch either of them": before the steps told already."""
    at = max((k for k, w in enumerate(words) if w == "before"), default=None)
    if at is None:
        return False
    rest = words[at + 1:]
    rest = rest[1:] if rest[:1] and rest[0] in ("you", "i", "we") else rest
    return len(rest) >= 2 and all(w in _THEM for w in rest[1:]) and rest[-1] in ("them", "those", "these", "either", "both", "anything")


def put_in_order(acts: list[Act], act: Act, moved: int | None) -> int | None:
    """Put ``act`` in ``acts`` (in execution order); the index of a step put first, for the steps joined to it."""
    frame = act.goal
    words = tuple(frame.text.split())
    if acts and (any(words[-len(tail):] == tail for tail in _BEFORE_ALL) or _before_them(words)):
        acts.insert(0, act)  # "..., but press the button on the control panel before any of that": first of all
        return 0
    if frame.goes_first and acts:
        main = acts[-1].goal
        if frame.themes and all(m.pronoun for m in frame.themes) and main.themes and not any(m.pronoun for m in main.themes):
            act = replace(act, goal=replace(frame, themes=main.themes))  # "after holding it down": the lever of the step it precedes
        acts.insert(len(acts) - 1, act)
        return len(acts) - 2
    inflected = bool(words) and words[0] != frame.verb and (words[0].endswith("ing") or words[0] not in ("the", "then"))  # "... and spun the big dial"
    if moved is not None and frame.conjoined and frame.marker == "and" and frame.link is Link.SEQUENCE and frame.verb is not None and (
            not frame.themes or all(m.pronoun for m in frame.themes) or inflected):
        acts.insert(moved + 1, act)  # "after you've depressed it fully and held it down for 3 s": both go first
        return moved + 1
    acts.append(act)
    return None
