"""What English uses a word as (lemminflect's readings): a verb form, a noun, only a modifier. The reading stages ask
these questions of words the lexicon does not know."""

from __future__ import annotations

from functools import lru_cache

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import CAUSER_NOUNS
from app.engine.offline.reading.token import Token


@lru_cache(maxsize=4096)
def lemma_of(word: str) -> tuple[str, bool]:
    """(lemma, plural): the verb lemma when ``word`` is a form of a known verb, else the noun lemma."""
    if word in VERBS or not word.isalpha() or len(word) < 2:
        return word, False  # "s", "m": units, not words to lemmatise
    from lemminflect import getLemma  # imported when first needed (data loads on first use)

    nouns = getLemma(word, upos="NOUN")
    plural = bool(nouns) and nouns[0] != word and word.endswith("s")
    for lemma in getLemma(word, upos="VERB"):
        if lemma in VERBS:
            return lemma, plural
    if nouns and nouns[0] != word:
        return nouns[0], True
    return word, False


_AUXILIARIES = frozenset({"be", "have", "do", "need", "seem", "look", "want", "stay", "remain", "sit", "stand", "hang", "say", "mean",
                          "use", "let", "get", "make", "keep", "happen", "start", "begin", "stop", "go", "come"})


@lru_cache(maxsize=4096)
def finite_unknown_verb(word: str) -> bool:
    """A finite form of a verb the lexicon does not know and that is no noun ("the lever waggles")."""
    if word in VERBS or not word.isalpha() or not (word.endswith("s") or word.endswith("ed")):
        return False
    from lemminflect import getAllLemmas

    lemmas = getAllLemmas(word)
    return "VERB" in lemmas and "NOUN" not in lemmas and "ADJ" not in lemmas and not set(lemmas["VERB"]) & _AUXILIARIES


@lru_cache(maxsize=4096)
def inflected_verb(word: str) -> bool:
    """An inflected form of some English verb ("faces", "looking", "brewed")."""
    from lemminflect import getAllLemmas

    return word.isalpha() and any(lemma != word for lemma in getAllLemmas(word).get("VERB", ()))


@lru_cache(maxsize=4096)
def verb_only(word: str) -> bool:
    """A word English uses only as a verb form ("counted", "allows", "looking"), and no part word: never a part's head."""
    from lemminflect import getAllLemmas

    from app.engine.offline.reading.part_words import kind_of_word

    lemmas = getAllLemmas(word)
    return "VERB" in lemmas and "NOUN" not in lemmas and "ADJ" not in lemmas and kind_of_word(word) is None


@lru_cache(maxsize=4096)
def nounless(word: str) -> bool:
    """A word English uses only as a modifier ("chilly", "simultaneously", "travel-ready": the last piece of a compound),
    and no part word: a remark or a manner, never a part's head ("shut the window, it's chilly")."""
    from lemminflect import getAllLemmas

    from app.engine.offline.reading.part_words import kind_of_word

    last = word.split("-")[-1]
    lemmas = getAllLemmas(last)
    return bool(lemmas) and "NOUN" not in lemmas and "PROPN" not in lemmas and ("VERB" not in lemmas or "-" in word) and (
        kind_of_word(word) is None and kind_of_word(last) is None)  # not "temp", "browning": a verb form may name a part


@lru_cache(maxsize=4096)
def can_be_verb(word: str) -> bool:
    """A word the lexicon or English uses as a verb ("travel" after "it can")."""
    from lemminflect import getAllLemmas

    return word in VERBS or "VERB" in getAllLemmas(word)


@lru_cache(maxsize=4096)
def verb_ing(word: str) -> bool:
    """A verb's -ing form ("going", "spinning")."""
    if not word.endswith("ing") or not word.isalpha():
        return False
    from lemminflect import getAllLemmas

    return any(lemma != word for lemma in getAllLemmas(word).get("VERB", ()))


@lru_cache(maxsize=1024)
def inflected_form(word: str, tag: str) -> str | None:
    """``word`` in the Penn tag ``tag`` ("VBZ": "stand" -> "stands", "JJR": "high" -> "higher"), if English has one."""
    from lemminflect import getInflection

    forms = getInflection(word, tag=tag)
    return forms[0] if forms else None


_COPULAS = frozenset({"is", "was", "has", "does", "seems", "looks", "needs", "wants", "gets", "keeps", "stays", "remains"})


def actor_verb(tokens: list[Token], k: int) -> bool:
    """A verb the lexicon does not know, right after a thing or animal acting in a scene ("the cat jumps onto the
    screen"): its verb, though it could be a noun ("jumps"); or a thing acting, right before its verb ("the steam keeps ...")."""
    from app.engine.offline.reading.part_words import kind_of_word

    word = tokens[k].text
    if word in CAUSER_NOUNS and k + 1 < len(tokens) and tokens[k + 1].text.endswith("s") and inflected_verb(tokens[k + 1].text):
        return True  # "the steam keeps bumping the lid": the one acting, never a part (but "let the steam out": a stray word)
    return 0 < k and tokens[k - 1].text in CAUSER_NOUNS and word.endswith("s") and kind_of_word(word) is None and inflected_verb(word) and (
        word not in _COPULAS)  # not "the user is done"
