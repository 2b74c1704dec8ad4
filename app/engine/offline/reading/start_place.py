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


_HOW = (("the", "way"), ("how",), ("as",), ("where",), ("like",))
_FOUND = frozenset({"you", "i", "we"})
_NOW = (("is", "right", "now"), ("is", "now"), ("sits", "now"), ("sits", "right", "now"), ("'s", "now"), ("'s", "right", "now"))


def _found_at(tokens: list[Token], k: int) -> int | None:
    """The index after "(the way | how | as) you found it" or, after "to", "(the way | how) it is (right) now": the pose
    before the prompt's steps."""
    words = [t.text for t in tokens[k:k + 6]]
    how = next((len(h) for h in _HOW if tuple(words[:len(h)]) == h), 0)
    if not how or len(words) < how + 2:
        return None
    if words[how] in _FOUND and words[how + 1] == "found" and len(words) > how + 2 and words[how + 2] in ("it", "them"):
        return k + how + 3
    if k and tokens[k - 1].text == "to" and words[how] in ("it", "they"):
        now = next((len(n) for n in _NOW if tuple(words[how + 1:how + 1 + len(n)]) == n), 0)
        return k + how + 1 + now if now else None
    return None


def start_place(tokens: list[Token]) -> list[Token]:
    """``tokens`` with each place said as where a part started read as ``where_it_started``."""
    said = replace_spans(tokens, lambda ts, k: _said_at(ts, k) if k and ts[k - 1].text in ("to", "into", "in") else None,
                         lambda ts, k, end: [Token("where_it_started", "where_it_started", ts[k].start, ts[end - 1].end)])
    return replace_spans(said, _found_at, lambda ts, k, end: [Token("where_it_started", "where_it_started", ts[k].start, ts[end - 1].end)])
