"""Which of several parts goes first: "open both doors, left one first" (a qualified "one" then "first" at a clause's end)."""

from __future__ import annotations

from app.engine.lexicon.words import SPATIAL
from app.engine.offline.reading.mention import Mention
from app.engine.offline.reading.mentions import parse_mentions
from app.engine.offline.reading.token import Token


def first_of(tokens: list[Token]) -> tuple[Mention | None, list[Token]]:
    """"..., left one first": a qualified "one" followed by "first" at the end of the clause."""
    if len(tokens) >= 3 and tokens[-1].text == "first" and tokens[-2].text in ("one", "ones"):
        j = len(tokens) - 2
        while j > 0 and (tokens[j - 1].text in SPATIAL or tokens[j - 1].text in ("the",) or "-" in tokens[j - 1].text):
            j -= 1
        found = parse_mentions(tokens[j:-1], 0)
        several = any(t.plural or t.text in ("both", "all", "each") for t in tokens[:j])  # "shut the right one first": no list
        if found and found[0].anaphor and several:
            return found[0], tokens[:j]
    return None, tokens
