"""A state said as where a part or the object starts: "the safe has to start sealed", "the lid should begin closed", "it
starts out open". That is how it is at the start, said as "be": "has to be sealed", "is open". Before this stage "start"
was read as running the object (the safe's dial spun)."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.words import MODALS
from app.engine.offline.reading.spans import replace_spans
from app.engine.offline.reading.token import Token

_STARTS = frozenset({"start", "starts", "started", "begin", "begins", "began"})
_STATES = frozenset({"sealed", "locked", "closed", "shut", "latched", "open", "unlocked", "empty", "folded", "ajar", "opened", "raised",
                     "lowered", "down", "up", "out", "in"})
_BARE = MODALS | frozenset({"to"})


def _start_at(tokens: list[Token], k: int) -> int | None:
    """The end of "start (out|off)" at ``k`` when a starting state follows, else None."""
    t = tokens[k]
    after = tokens[k + 1].text if k + 1 < len(tokens) else ""
    filler = after in ("out", "off") and k + 2 < len(tokens) and tokens[k + 2].text in _STATES
    state = tokens[k + 2].text if filler else after
    if t.text in _STARTS and k > 0 and state in _STATES and state not in ("out", "in") and not tokens[k - 1].is_punct:
        return k + 1 + filler
    return None


def _be(tokens: list[Token], k: int, _end: int) -> list[Token]:
    t = tokens[k]
    be = "be" if tokens[k - 1].text in _BARE else ("was" if t.text.endswith("ed") or t.text == "began" else "is")
    return [replace(t, text=be, lemma="be")]


def starts_as(tokens: list[Token]) -> list[Token]:
    """``tokens`` with "start (out|off) <state>" said as "be <state>" (or "is" after its subject)."""
    return replace_spans(tokens, _start_at, _be)
