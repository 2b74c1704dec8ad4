"""Where a part started, said as a place ("back to the spot it started from", "to the position they were in", "the
angle it sat at before"): read as the return phrase "where it started" (``where_it_started``), which the frame
reader knows. Before this stage "then back to the spot it started from" repeated the step before it."""

from __future__ import annotations

from app.engine.offline.reading.spans import replace_spans
from app.engine.offline.reading.token import Token

_PLACES = frozenset({"spot", "place", "position", "point", "angle", "height", "pose", "setting", "location"})
_RELATIVES = frozenset({"that", "which", "where"})
_WHO = frozenset({"it", "they", "it's", "they're"})
_WAS = frozenset({"started", "was", "were", "began", "sat", "rested", "stood", "had", "been"})
_AT = frozenset({"from", "at", "in", "on", "out", "before", "originally", "initially", "earlier"})


def _said_at(tokens: list[Token], k: int) -> int | None:
    """The index after "(the) spot (that) it started (from)" at ``k``, else None."""
    j = k + (tokens[k].text in ("the", "its", "their"))
    if j >= len(tokens) or tokens[j].text not in _PLACES:
        return None
    j += 1
    j += j < len(tokens) and tokens[j].text in _RELATIVES
    if j >= len(tokens) or tokens[j].text not in _WHO:
        return None
    j += 1
    if j >= len(tokens) or tokens[j].text not in _WAS:
        return None
    j += 1
    while j < len(tokens) and tokens[j].text in _AT:
        j += 1
    return j


def start_place(tokens: list[Token]) -> list[Token]:
    """``tokens`` with each place said as where a part started read as ``where_it_started``."""
    return replace_spans(tokens, lambda ts, k: _said_at(ts, k) if k and ts[k - 1].text in ("to", "into", "in") else None,
                         lambda ts, k, end: [Token("where_it_started", "where_it_started", ts[k].start, ts[end - 1].end)])
