"""Part-kind words in tokens: which kind a word or a phrase of the prompt names ("door", "door release button"),
from the part-kind registry (:mod:`app.engine.lexicon.kinds`)."""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache

from app.engine.lexicon.kinds import REGISTRY, PartKind, info
from app.engine.lexicon.relations import PLACE_PREPS
from app.engine.lexicon.words import (
    DETERMINERS,
    OBJECT_NOUNS,
    ORDINALS,
    PHRASE_BREAKS,
    SHAPE_WORDS,
    SIZES,
    SPATIAL,
    Side,
)
from app.engine.offline.reading.mention import Mention
from app.engine.offline.reading.token import Token


@lru_cache(maxsize=1)
def _kind_phrases() -> list[tuple[tuple[str, ...], PartKind]]:
    phrases = [(tuple(w.replace("-", " ").split()), entry.kind) for entry in REGISTRY.values() for w in entry.words]
    return sorted(phrases, key=lambda p: -len(p[0]))


def kind_of_word(word: str) -> PartKind | None:
    """The kind a single word names ("door" -> DOOR; "push-button" as "push button"; "T-handle", a handle shaped so)."""
    said = tuple(word.split("-")) if "-" in word else (word,)
    for phrase, kind in _kind_phrases():
        if phrase == said:
            return kind
    return kind_of_word(said[-1]) if len(said) == 2 and len(said[0]) == 1 and said[0].isalpha() else None


def kind_at(tokens: list[Token], i: int) -> tuple[PartKind, int] | None:
    """(kind, length) of the longest part-kind phrase starting at ``tokens[i]``."""
    for phrase, kind in _kind_phrases():
        n = len(phrase)
        window = tokens[i:i + n]
        if len(window) == n and all(t.lemma == w or t.text == w for t, w in zip(window, phrase, strict=True)) and not (
                window[-1].text != phrase[-1] and window[-1].text.endswith("ed") and (i == 0 or tokens[i - 1].text in _COPULAS | _JOINED)):
            return kind, n  # not "so it's locked (shut)", "shut and latched": a state, no lock
    shaped = kind_of_word(tokens[i].text) if i < len(tokens) and "-" in tokens[i].text else None
    return (shaped, 1) if shaped is not None else None  # "the T-handle"


_COPULAS = frozenset({"it's", "is", "are", "they're", "was", "were", "be", "been", "gets", "get", "got", "stays", "remains"})
_JOINED = frozenset({"and", "or", ",", ":", "then", "fully", "properly", "securely"})
_PLACE_NOUNS = frozenset({"corner", "side", "end", "edge"})


_AFTER_PARTICLE = frozenset({"away", "toward", "towards", "down", "up", "over", "out", "in", "to", "against", "onto", "into", "flat", ",",
                             "and", "then", "so"})


def side_run(tokens: list[Token], j: int) -> tuple[tuple[tuple[Side, bool], ...], int]:
    """Two or more side words from ``j`` ("bottom left", "bottom-left", "top right corner"): (the sides, where the run
    ends, past a closing "corner"/"side"); one side word alone is not a run (``((), j)``)."""
    sides: list[tuple[Side, bool]] = []
    k = j
    while k < len(tokens) and all(part in SPATIAL for part in tokens[k].text.split("-")):
        if sides and tokens[k].text == "back" and k + 1 < len(tokens) and tokens[k + 1].text in _AFTER_PARTICLE:
            break  # "fold the handle on top back away from the lid": the way it goes, not a side
        sides.extend(SPATIAL[part] for part in tokens[k].text.split("-"))
        k += 1
    if len(sides) < 2:
        return (), j
    return tuple(sides), k + (k < len(tokens) and tokens[k].text in _PLACE_NOUNS)


def control_name(tokens: list[Token], i: int) -> bool:
    """"the start button", "the stop key": a word between a determiner and a control is what the control is for (a word of
    its name), even one that is elsewhere a verb or a place ("from the start")."""
    found = kind_at(tokens, i + 1) if i > 0 and tokens[i - 1].text in DETERMINERS and tokens[i].text.isalpha() else None
    return found is not None and info(found[0]).control


def shape_adjective(tokens: list[Token], i: int) -> bool:
    """``tokens[i]`` ("flat", "round") describes the noun that follows ("the long flat bar"), not an end state ("lay the
    lid flat"): a shape word after a determiner or another adjective, before a word that can head a noun phrase."""
    if tokens[i].text not in SHAPE_WORDS or i == 0 or i + 1 >= len(tokens):
        return False
    before, after = tokens[i - 1].text, tokens[i + 1]
    counted = tokens[i - 1].number is not None and i > 1 and tokens[i - 2].text in DETERMINERS  # "the two round dials"
    return (before in DETERMINERS or before in SIZES or before in SHAPE_WORDS or counted) and after.text.isalpha() and after.text not in PHRASE_BREAKS


def line_index(word: str) -> int | None:
    """The row or column a word names (1-based from the top / left; -1 last; 0 middle): "second", "top", "right"."""
    side = SPATIAL.get(word)
    return ORDINALS[word] if word in ORDINALS else None if side is None else {Side.TOP: 1, Side.LEFT: 1, Side.BOTTOM: -1, Side.RIGHT: -1,
                                                                              Side.MIDDLE: 0}.get(side[0])


OBJECT_WORDS = frozenset(OBJECT_NOUNS)


def object_after(tokens: list[Token], i: int, begin: int) -> bool:
    """"turn the (side) table around": the object itself, unless a preposition makes it a place ("push it along the table")."""
    if begin > 0 and tokens[begin - 1].text in PLACE_PREPS:
        return False
    j = i + 1 if tokens[i].lemma not in OBJECT_WORDS else i
    return j < len(tokens) and tokens[j].lemma in OBJECT_WORDS


def noun_continues(tokens: list[Token], i: int) -> bool:
    """A noun of the same phrase follows at ``i`` ("release | button")."""
    return i < len(tokens) and (kind_at(tokens, i) is not None or tokens[i].lemma in OBJECT_WORDS)


def phrase_words(tokens: list[Token], start: int, end: int) -> str:
    return " ".join(t.text.replace("_", " ") for t in tokens[start:end])


def lined(mention: Mention, line: str, index: int | None, end: int, tokens: list[Token]) -> Mention:
    """``mention`` in a row or column (1-based from the top / left; -1 last; 0 middle)."""
    row, column = (index, mention.column) if line == "row" else (mention.row, index)
    return replace(mention, row=row, column=column, end=end, words=phrase_words(tokens, mention.start, end))
