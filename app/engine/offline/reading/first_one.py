"""Which of several parts goes first: "open both doors, left one first" (a qualified "one" then "first" at a clause's end)."""

from __future__ import annotations

from app.engine.lexicon.words import SPATIAL
from app.engine.offline.reading.mention import Mention
from app.engine.offline.reading.mentions import parse_mentions
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

_THEN = frozenset({"after", "next", "second", "last", "afterwards", "afterward", "later"})


def first_of(tokens: list[Token]) -> tuple[Mention | None, list[Token]]:
    """"..., left one first": a qualified "one" followed by "first" at the end of the clause ("..., top shelf first and the
    lower one after": the one after is the rest)."""
    end = next((k for k in range(len(tokens) - 1, 1, -1) if tokens[k].text == "and" and tokens[k - 1].text == "first"), None)
    if end is not None and tokens[-1].text in _THEN:
        tokens = tokens[:end]
    if len(tokens) >= 3 and tokens[-1].text == "first" and (tokens[-2].text in ("one", "ones") or kind_of_word(tokens[-2].text) is not None):
        j = len(tokens) - 2
        while j > 0 and (tokens[j - 1].text in SPATIAL or tokens[j - 1].text in ("the",) or "-" in tokens[j - 1].text):
            j -= 1
        found = parse_mentions(tokens[j:-1], 0)
        several = any(t.plural or t.text in ("both", "all", "each") for t in tokens[:j])  # "shut the right one first": no list
        if found and (found[0].anaphor or found[0].kind is not None) and several:
            return found[0], tokens[:j]
    return None, tokens
