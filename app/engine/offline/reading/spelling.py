"""Spelling correction against the domain lexicon and the asset's own part names.

A word is left alone when the lexicon knows it, when it names a part of the asset, or when
it is a common English word (``pyspellchecker``'s frequency list). Otherwise it is replaced
by the closest domain word (optimal string alignment distance from ``rapidfuzz``: 1 edit for
short words, 2 for longer ones) when exactly one word is closest; the token records what was
typed, and the perceiver warns about every correction.
"""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache
from typing import TYPE_CHECKING

from app.engine.lexicon.kinds import REGISTRY
from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import (
    AMOUNTS,
    ANGLE_UNITS,
    COLLECTIVE,
    DETERMINERS,
    DIRECTIONS,
    EVERYDAY_WORDS,
    FILLERS,
    LENGTH_UNITS,
    MULTIWORD,
    NEGATIONS,
    NUMBER_WORDS,
    OBJECT_NOUNS,
    ORDINALS,
    OTHER_WORDS,
    PRONOUNS,
    ROTATION_SENSE,
    SIZES,
    SPATIAL,
    SPEEDS,
    STATES,
    TIME_UNITS,
    TURN_UNITS,
)

if TYPE_CHECKING:
    from app.engine.offline.reading.tokens import Token

ENGLISH_MIN_COUNT = 20
"""A word seen at least this often in the English frequency list is a real word, never corrected."""
MIN_LENGTH = 3
_FUNCTION = (
    "to", "of", "on", "in", "at", "by", "with", "from", "into", "onto", "and", "or", "so", "then", "while", "after", "before", "until",
    "once", "when", "it", "is", "are", "be", "for", "its", "that", "which", "way", "as", "far", "more", "another", "further", "again",
    "around", "round", "about", "over", "through", "using", "down", "up", "out", "off", "back", "open", "shut", "closed", "side",
    "row", "column", "one", "ones", "go", "goes", "toward", "towards", "till", "home", "degree", "degrees", "seconds", "second", "times", "by", "same", "time",
    "either", "any", "whichever", "direction",
)


@lru_cache(maxsize=1)
def domain_words() -> frozenset[str]:
    """Every single word the lexicon uses."""
    words: set[str] = set(_FUNCTION)
    for entry in REGISTRY.values():
        for phrase in entry.words:
            words.update(phrase.replace("-", " ").split())
    for table in (VERBS, SPATIAL, ORDINALS, SIZES, AMOUNTS, SPEEDS, ROTATION_SENSE, DIRECTIONS, LENGTH_UNITS, ANGLE_UNITS,
                  TURN_UNITS, TIME_UNITS, STATES, NUMBER_WORDS):
        for key in table:
            words.update(str(key).replace("-", " ").split())
    for group in (COLLECTIVE, DETERMINERS, PRONOUNS, OTHER_WORDS, NEGATIONS, FILLERS, OBJECT_NOUNS, MULTIWORD, EVERYDAY_WORDS):
        for phrase in group:
            words.update(phrase.replace("-", " ").split())
    return frozenset(w for w in words if w.isalpha())


@lru_cache(maxsize=1)
def _targets() -> frozenset[str]:
    """Words a typo may be corrected to: not unit abbreviations ("Game dev here" is not "deg")."""
    return domain_words() - {k for table in (LENGTH_UNITS, ANGLE_UNITS, TIME_UNITS) for k in table if len(k) <= 3}


@lru_cache(maxsize=1)
def _english() -> object:
    from spellchecker import SpellChecker

    return SpellChecker(distance=1).word_frequency


def _is_english(word: str) -> bool:
    frequency = _english()
    return int(frequency[word]) >= ENGLISH_MIN_COUNT  # type: ignore[index]


def _budget(word: str) -> int:
    return 1 if len(word) <= 5 else 2


def suggest(word: str, vocabulary: frozenset[str], budget: int | None = None) -> str | None:
    """The closest word of ``vocabulary`` within the edit budget, else ``None``.

    Ties on the edit distance go to a word with the same letters (a swap: "opne" -> "open"),
    then to the higher Jaro-Winkler similarity, then to the commoner English word ("bak" -> "back", not
    "bank"); a remaining tie is no correction.
    """
    from rapidfuzz.distance import OSA, JaroWinkler

    budget = _budget(word) if budget is None else budget
    scored: list[tuple[int, bool, float, int, str]] = []
    for candidate in vocabulary:
        if abs(len(candidate) - len(word)) > budget or len(candidate) < MIN_LENGTH:
            continue
        distance = OSA.distance(word, candidate, score_cutoff=budget)
        if distance <= budget:
            scored.append((distance, sorted(candidate) != sorted(word), -round(JaroWinkler.similarity(word, candidate), 6),
                           -_frequency(candidate), candidate))
    if not scored:
        return None
    scored.sort()
    best = scored[0]
    if len(scored) > 1 and scored[1][:4] == best[:4]:
        return None
    return best[4]


def _frequency(word: str) -> int:
    return int(_english()[word])  # type: ignore[index]


def correct(token: Token, known: frozenset[str]) -> Token:
    """``token`` with its word corrected when it is not a known word (see the module docstring)."""
    word = token.text
    if len(word) < MIN_LENGTH or word in known or word in domain_words():
        return token
    from app.engine.offline.reading.word_class import lemma_of

    lemma, _ = lemma_of(word)
    if lemma in domain_words() or lemma in known:
        return token
    if word.endswith("in") and len(word) > 4 and not _is_english(word) and _is_english(word + "g"):
        return replace(token, text=word + "g", lemma=word + "g", corrected_from=word)  # "stickin out", "bumpin into it": the g dropped
    fixed = suggest(word, _targets() | known)
    if fixed is None and word.endswith("s") and len(word) > MIN_LENGTH:
        single = suggest(word[:-1], _targets() | known)  # "dors" -> "doors": the plural of a misspelt part word
        fixed = single + "s" if single is not None else None
    if fixed is None:
        return token
    if _is_english(word) and not _rare_beside(word, fixed):
        return token
    return replace(token, text=fixed, lemma=fixed, corrected_from=word)


RARE_WORD_COUNT = 1000
MUCH_COMMONER = 10
RARE_LONGER_COUNT = 100
"""A real word one letter longer than a domain word is taken for a typo of it only when rarer than this."""


def _rare_beside(word: str, candidate: str) -> bool:
    """A rare English word one slip away from a much commoner domain word is a typo of it ("dor" -> "door",
    "pul" -> "pull", "trey" -> "tray"); a common word, or a real word two edits away ("basting", not "basin"), is left alone."""
    from rapidfuzz.distance import OSA

    frequency = _english()
    own, other = int(frequency[word]), int(frequency[candidate])  # type: ignore[index]
    if (len(word) > len(candidate) or word[0] != candidate[0]) and own >= RARE_LONGER_COUNT:
        return False  # "baste" is a word of its own, not "base" with a letter too many; "gasket" is no slip of "basket"
    return OSA.distance(word, candidate) == 1 and own < RARE_WORD_COUNT and other >= MUCH_COMMONER * max(own, 1) and candidate in content_words()


@lru_cache(maxsize=1)
def content_words() -> frozenset[str]:
    """Domain words that name parts, objects and actions (never function words)."""
    words: set[str] = set()
    for entry in REGISTRY.values():
        for phrase in entry.words:
            words.update(phrase.replace("-", " ").split())
    words.update(VERBS)
    words.update(OBJECT_NOUNS)
    words.update(w for w in SPATIAL if w.isalpha())
    return frozenset(words)


@lru_cache(maxsize=1)
def _nouns() -> frozenset[str]:
    """Part and object nouns of the lexicon (single words)."""
    words = {w for entry in REGISTRY.values() for phrase in entry.words for w in phrase.replace("-", " ").split()}
    return frozenset(w for w in words | set(OBJECT_NOUNS) if w.isalpha() and len(w) >= MIN_LENGTH + 1)


def correct_noun(token: Token, known: frozenset[str]) -> Token:
    """After a determiner a part or an object is expected: "the dore" is "the door" (two edits away), not "done"."""
    typed = token.corrected_from or token.text
    if token.text in SPATIAL or token.text in ORDINALS or token.text in SIZES or token.text in OTHER_WORDS or token.text in COLLECTIVE:
        return token  # "the rihgt" -> "the right": a side may follow a determiner
    if len(typed) < MIN_LENGTH + 1 or typed in known or token.text in _nouns() or token.text in known or (
            token.corrected_from is None and (typed in domain_words() or _is_english(typed))):
        return token
    fixed = suggest(typed, _nouns() | known, budget=2)
    if fixed is None or fixed == token.text:
        return token
    return replace(token, text=fixed, lemma=fixed, corrected_from=typed)
