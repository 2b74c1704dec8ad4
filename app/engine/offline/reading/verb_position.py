"""Where a word is a verb: "lower", "switch", "step" start a clause only where a verb can ("lower the lid", not "the
lower drawer"); a strict reading also wants a cue before it ("and", "then", "is")."""

from __future__ import annotations

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import DETERMINERS, ORDINALS, SIZES, SPATIAL, STATIVE_VERBS
from app.engine.offline.reading.mentions import kind_at
from app.engine.offline.reading.token import Token

NOT_BEFORE_VERB = DETERMINERS | frozenset(SPATIAL) | frozenset(ORDINALS) | frozenset(SIZES) | frozenset(
    {"of", "each", "every", "both", "all", "another", "other", "this", "that", "no", "any", "some", "toggle", "rocker", "light", "power",
     "control", "wall"})
VERB_CUES = frozenset({"and", ",", "then", "but", "to", "by", "after", "before", "once", "when", "while", "whilst", "so", "please", "now",
                       "first", "firstly", "just", "only", "simply", "kindly", "also", "and_then", "next", "finally", "lastly", "afterwards", "afterward",
                       "after_that", "subsequently", "in_order_to", "so_as_to", "without", "until", "or", "as", "at_the_same_time",
                       "simultaneously", "which", "that", "then,", "gently", "slowly", "quickly", "carefully", "fully",
                       "don't", "dont", "not", "never", "do", "again", "meanwhile", "i", "you", "we", "let's", "lets", "using",
                       "immediately", "briefly", "partially", "halfway", "slightly", "completely", "thereafter",
                       "he", "she", "he'd", "she'd", "i'd", "you'd", "we'd", "would", "he'll", "she'll", "i'll", "you'll", "we'll"})
AUX = frozenset({"is", "are", "was", "were", "be", "being", "been", "stays", "remains", "stay", "remain", "gets", "get"})


def after_side_noun(tokens: list[Token], i: int) -> bool:
    """``tokens[i]`` is a finite verb after a side said as a noun: "the drawer on the left | slides out"."""
    token = tokens[i]
    return i > 1 and tokens[i - 1].text in SPATIAL and tokens[i - 2].text == "the" and token.text != token.lemma and token.text.endswith("s")


def verb_at(tokens: list[Token], i: int, *, strict: bool = False) -> bool:
    """Whether ``tokens[i]`` is a verb here (not a noun that looks like one: "the switch", "the left")."""
    token = tokens[i]
    if token.lemma not in VERBS or token.number is not None:
        return False
    previous = tokens[i - 1].text if i > 0 else ""
    if previous in NOT_BEFORE_VERB and not after_side_noun(tokens, i):
        return False  # "the left switch"
    if token.text != token.lemma and token.text.endswith("ed") and i > 1 and tokens[i - 2].text in ("the", "its", "a", "an") and (
            tokens[i - 1].text.endswith("ly") or tokens[i - 1].text == "half"):
        return False  # "from the fully closed position": a participle said of a noun
    if token.text in STATIVE_VERBS and (token.text.endswith("ing") or token.text != token.lemma):
        return False  # "standing at the sink, ...": where the user is, not an action
    if token.text in SPATIAL and token.text != token.lemma:
        return False  # "left" is not "leave"
    if token.text in SPATIAL or kind_at(tokens, i) is not None:
        # "lower", "step", "switch", "dial": a verb only where a verb must start
        return i == 0 or previous in VERB_CUES
    if strict:
        return i == 0 or previous in VERB_CUES or previous in AUX
    return True
