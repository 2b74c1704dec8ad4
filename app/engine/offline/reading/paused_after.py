"""A wait said inside the clause it comes before ("close it again after a short pause", "then after 2 seconds close
it"): read as a pause of its own before that clause ("pause briefly, then close it again"). Before this stage "a short
pause" was read as a part (refused) and "after 2 seconds" as how long the step takes."""

from __future__ import annotations

from app.engine.offline.reading.framing import scan
from app.engine.offline.reading.token import Token

_ARTICLES = frozenset({"a", "an", "one"})
_SHORT = frozenset({"short", "brief", "quick", "little", "small", "slight", "moment's", "second's", "tiny"})
_PAUSES = frozenset({"pause", "moment", "beat", "break", "bit", "while", "sec", "second", "breath"})
_SECONDS = frozenset({"seconds", "second", "s", "secs", "sec"})
_BOUNDS = frozenset({",", "and", "then", "and_then", ".", ";", "but", "!", "?"})


def _pause_at(tokens: list[Token], i: int) -> tuple[int, list[str]] | None:
    """(the index after it, the wait's words) of "after a short pause" / "after 2 seconds" at ``i``, else None."""
    if tokens[i].text != "after":
        return None
    j = i + 1
    if j + 1 < len(tokens) and tokens[j].number is not None and tokens[j + 1].text in _SECONDS:
        return j + 2, ["pause", tokens[j].text, "seconds"]
    j += j < len(tokens) and tokens[j].text in _ARTICLES
    j += j < len(tokens) and tokens[j].text in _SHORT
    if j < len(tokens) and tokens[j].text in _PAUSES and not (j + 1 < len(tokens) and tokens[j + 1].text in ("of", "the")):
        return j + 1, ["pause", "briefly"]
    return None


def _paused_step(tokens: list[Token], i: int, out: list[Token]) -> int | None:
    found = _pause_at(tokens, i)
    if found is None:
        return None
    end, words = found
    start = max((k + 1 for k, t in enumerate(out) if t.text in _BOUNDS), default=0)
    at = tokens[i]
    wait = [Token(w, w, at.start, tokens[end - 1].end, number=float(w) if w.replace(".", "").isdigit() else None) for w in words]
    out[start:start] = [*wait, Token(",", ",", at.start, at.start), Token("then", "then", at.start, at.start)]
    return end


def paused_after(tokens: list[Token]) -> list[Token]:
    return scan(tokens, _paused_step)
