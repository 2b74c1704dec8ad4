"""Lines split by slashes that tell one step in fragments ("upper dial only / half a turn, clockwise / the lower one rests",
"pot lid lifts / a thin gap of steam / the pot stays still"): a line that starts with an amount, an article or a
participle goes on with the step before, as after a comma. A line that starts with a verb or a part is a step of its own
("drawer out 40cm / hold 3s / back in")."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import AMOUNTS, NUMBER_WORDS
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

_GOES_ON = frozenset({"a", "an", "the", "half", "quarter", "no", "its", "it", "nothing", "only", "slowly", "gently", "quickly", "all_the_way",
                      "a_quarter", "a_bit", "a_little", "fully", "halfway", "just"})


def _goes_on(token: Token) -> bool:
    word = token.text
    if word in VERBS or word == "back" or kind_of_word(word) is not None:
        return False
    return (word in _GOES_ON or token.number is not None or word in NUMBER_WORDS or word in AMOUNTS
            or (word.endswith("ed") and word.isalpha() and len(word) > 4))


def verse_lines(tokens: list[Token]) -> list[Token]:
    """``tokens`` with a slash before a line that goes on with the step before read as a comma."""
    return [replace(t, text=",", lemma=",") if t.lemma == "/" and k + 1 < len(tokens) and _goes_on(tokens[k + 1]) else t
            for k, t in enumerate(tokens)]
