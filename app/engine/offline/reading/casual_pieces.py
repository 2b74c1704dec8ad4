"""Casual words for a piece and for how far it goes: "the top bit" is the top piece (not "a bit", an amount), and "lift the
top piece clean off" is lifting it off ("clean" says only that it comes away whole). Before this stage both were refused
as naming no part, as was "through its full closing range" (all the way shut). "flat on the floor" is flat. "Hold it way up high" is holding it up ("way" and "high" only stress the "up")."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.words import SPATIAL
from app.engine.offline.reading.token import Token

_AWAY = frozenset({"off", "out", "away", "through", "free"})
_NAMING = frozenset({"the", "that", "this", "its", "my", "your"})


_SPANS = frozenset({"range", "travel", "swing", "stroke", "arc", "motion", "movement"})
_WAYS = {"closing": "shut", "opening": "open", "": ""}


def _full_span(tokens: list[Token], k: int) -> tuple[list[str], int] | None:
    """"through its full (closing) range" at ``k``: the words it says ("all_the_way", "shut") and the index after it."""
    words = [t.text for t in tokens[k:k + 6]]
    if words[:2] != ["through", "its"] and words[:2] != ["through", "the"]:
        return None
    j = 2 + (words[2:3] in (["full"], ["whole"], ["entire"], ["complete"]))
    way = words[j] if words[j:j + 1] and words[j] in _WAYS else ""
    j += bool(way)
    if not (words[j:j + 1] and words[j] in _SPANS):
        return None
    return ["all_the_way", *([_WAYS[way]] if way else [])], k + j + 1


def casual_pieces(tokens: list[Token]) -> list[Token]:
    """``tokens`` with "the <place> bit" said as "the <place> piece", without "clean" before "off" / "out" and "way" / "high"
    around "up"."""
    out: list[Token] = []
    skip = -1
    for k, t in enumerate(tokens):
        if k < skip:
            continue
        if (span := _full_span(tokens, k)) is not None:
            words, skip = span  # "take the lid through its full closing range": all the way shut
            out += [Token(w, w, t.start, tokens[skip - 1].end) for w in words]
            continue
        if t.text in ("on", "against") and out and out[-1].text == "flat" and [w.text for w in tokens[k + 1:k + 3]] in (
                ["the", "floor"], ["the", "ground"], ["the", "table"], ["the", "counter"], ["the", "desk"]):
            skip = k + 3  # "lay the shell open, flat on the floor": flat (where it lies, not where it is put)
            continue
        after = tokens[k + 1].text if k + 1 < len(tokens) else ""
        if t.text == "clean" and k > 0 and after in _AWAY:
            continue  # "lift it clean off"
        if (t.text == "way" and after in ("up", "down") and k > 0 and tokens[k - 1].text in ("it", "them")) or (
                t.text == "high" and k > 0 and tokens[k - 1].text == "up" and (after in ("", ",", ".", "!", "and", "then") or tokens[k + 1].is_punct)):
            continue  # "hold it way up high": up
        if t.text in ("bit", "bits") and k > 1 and tokens[k - 1].text in SPATIAL and (
                tokens[k - 2].text in _NAMING or (tokens[k - 2].text == "very" and k > 2 and tokens[k - 3].text in _NAMING)):
            t = replace(t, text="piece" if t.text == "bit" else "pieces", lemma="piece")  # "the (very) top bit"
        out.append(t)
    return out
