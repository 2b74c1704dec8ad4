"""What the object takes, told as a hint before the steps: "Hint: the safe wants three keys. Start with ...", "the lock
needs four digits". It describes how many steps follow; it asks for none. Before this stage "the safe wants three keys"
pressed every key of the keypad, silently."""

from __future__ import annotations

from app.engine.lexicon.words import OBJECT_NOUNS
from app.engine.offline.reading.spans import drop_spans
from app.engine.offline.reading.token import Token

_TAKES = frozenset({"wants", "needs", "takes", "requires", "uses", "expects", "accepts"})
_OWNERS = frozenset({"the", "this", "that", "my", "our", "your", "its"})
_HOLDERS = frozenset({"lock", "code", "combination", "keypad", "pad", "password", "pin"})
_ENDS = frozenset({".", ",", ":", ";", "!", "-", "—"})


def _hint_end(tokens: list[Token], k: int) -> int | None:
    """The index after "(the) safe wants three keys (.)" starting at ``k`` (a sentence start), else None."""
    if k and tokens[k - 1].text not in _ENDS:
        return None
    j = k + (tokens[k].text in _OWNERS)
    if j + 3 >= len(tokens) + 1 or j + 2 >= len(tokens):
        return None
    noun, verb, count = tokens[j].text, tokens[j + 1].text, tokens[j + 2]
    if not (noun in OBJECT_NOUNS or noun in _HOLDERS) or verb not in _TAKES or count.number is None:
        return None
    end = j + 4  # the noun counted ("keys", "digits", "presses")
    if end > len(tokens) or (end < len(tokens) and tokens[end].text not in _ENDS):
        return None
    return end + (end < len(tokens))


def object_wants(tokens: list[Token]) -> list[Token]:
    """``tokens`` without such hints."""
    return drop_spans(tokens, _hint_end)
