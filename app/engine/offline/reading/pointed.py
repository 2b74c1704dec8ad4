"""A part pointed out before it is worked ("See the dial sitting off on its own to the left? Give it a half turn."): the
clause names the part, and where it is, for the next clause's "it"; it moves nothing itself."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.words import SPATIAL
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.quantities import Quantities

_PERCEIVING = frozenset({"see", "notice", "spot", "find", "locate"})


def pointed_out(frame: Frame, after: list[Frame]) -> Frame | None:
    """``frame`` as a heading that names the part seen (with the side its words give it), when it is a verb of seeing on
    one part and the next clause works "it"; else None."""
    if frame.verb not in _PERCEIVING or len(frame.themes) != 1 or frame.themes[0].kind is None or not after:
        return None
    if not any(m.pronoun and not m.plural for m in after[0].themes):
        return None
    seen = frame.themes[0]
    where = SPATIAL.get(frame.quantities.direction or "")
    if where is not None and where not in seen.sides:
        seen = replace(seen, sides=(*seen.sides, where))  # "the dial sitting off on its own to the left": the left one
    return replace(frame, heading=True, verb=None, sense=None, particle=None, themes=(seen,), quantities=Quantities())
