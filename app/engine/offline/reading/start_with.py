"""Where a run of steps starts and ends, said with "start with" and "finish on": "Start with the middle one of the top
row, then the key right under it, and finish on the bottom-left key" is "first ..., then ..., and finally ...". Before
this stage "start" was read as setting the object going, and the keys were refused."""

from __future__ import annotations

from app.engine.offline.reading.framing import scan
from app.engine.offline.reading.token import Token

_OPENERS = frozenset({"start", "begin"})
_CLOSERS = frozenset({"finish", "end"})
_BEFORE = frozenset({"", ".", ",", ":", ";", "and", "then", "-", "—"})
_STATES = frozenset({"open", "opened", "closed", "shut", "up", "down", "in", "out", "off", "on", "pressed", "ajar"})
_MENTION_STARTS = frozenset({"the", "a", "an", "key", "button", "digit", "number"})


def _state_after(tokens: list[Token], k: int) -> bool:
    """"start with the lid open": how things begin, not the first step (a state word before the clause ends)."""
    for token in tokens[k:k + 8]:
        if token.is_punct or token.text in ("then", "and"):
            return False
        if token.text in _STATES:
            return True
    return False


def _marked(tokens: list[Token], k: int, out: list[Token]) -> int | None:
    """At ``k``: "start with" / "finish on" before a part written as "first" / "finally"; the index after it, or None."""
    t = tokens[k]
    before = tokens[k - 1].text if k else ""
    after = tokens[k + 1].text if k + 1 < len(tokens) else ""
    follows = tokens[k + 2] if k + 2 < len(tokens) else None
    opens = t.text in _OPENERS and after == "with"
    closes = t.text in _CLOSERS and after in ("on", "with", "up_with")
    if not (opens or closes) or before not in _BEFORE or follows is None or not (follows.text in _MENTION_STARTS or follows.number is not None) or (
            _state_after(tokens, k + 2)):
        return None
    word = "first" if opens else "finally"
    out.append(Token(word, word, t.start, tokens[k + 1].end))
    return k + 2


def start_with(tokens: list[Token]) -> list[Token]:
    return scan(tokens, _marked)
