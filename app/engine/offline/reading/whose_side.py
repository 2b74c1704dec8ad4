"""A side of the object said with its owner: "the wheel on the bin's right side", "the knob at the toaster's front end".
The owner is the object itself, so the words are rewritten as the plain side ("on the right side"), which the mention
parser reads as a place among the parts. A key's row said first ("press bottom row middle key") is put after it ("the
middle key in the bottom row"), "the knob that's second from the top" as "the knob second from the top", and "the button that releases the latch" as
"the button"."""

from __future__ import annotations

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import DETERMINERS, OBJECT_NOUNS, ORDINALS, SPATIAL
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.word_class import lemma_of

_PLACES = frozenset({"on", "at", "to", "toward", "towards", "from", "by"})
_REGIONS = frozenset({"side", "end", "half", "part", "section", "corner", "edge"})
_LINES = frozenset({"row", "column"})
_KEYS = frozenset({"key", "button", "keys", "buttons"})


_OBJECTS = frozenset(OBJECT_NOUNS)


def whose_side(tokens: list[Token]) -> list[Token]:
    """``tokens`` with "PLACE the OBJECT 's SIDE REGION" said as "PLACE the SIDE REGION"."""
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        words = [t.text for t in tokens[k:k + 7]]
        own = next((j for j in (3, 4) if len(words) > j + 2 and words[j] == "'s"), 0)  # "the bin's", "the trash can's"
        if own and words[0] in _PLACES and words[1] in ("the", "its") and words[own - 1] in _OBJECTS and words[own + 1] in SPATIAL and (
                words[own + 2] in _REGIONS):
            out += [tokens[k], tokens[k + 1]]  # "on the bin's right side": on the right side
            k += own + 1
            continue
        out.append(tokens[k])
        k += 1
    return out


def row_first(tokens: list[Token]) -> list[Token]:
    """``tokens`` with "(the) bottom row middle key" said as "the middle key in the bottom row"."""
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        words = [t.text for t in tokens[k:k + 4]]
        line = words[0] in SPATIAL or words[0] in ORDINALS
        if len(words) == 4 and line and words[1] in _LINES and words[2] in SPATIAL and words[3] in _KEYS and not (out and out[-1].text in DETERMINERS):
            at = tokens[k]
            out += [Token("the", "the", at.start, at.start), tokens[k + 2], tokens[k + 3], Token("in", "in", at.start, at.start),
                    Token("the", "the", at.start, at.start), tokens[k], tokens[k + 1]]
            k += 4
            continue
        if words[0] in ("that", "which") and len(words) > 1 and out and kind_of_word(out[-1].text) is not None and tokens[k + 1].text.endswith("s") and (
                lemma_of(tokens[k + 1].text)[0] in VERBS and lemma_of(tokens[k + 1].text)[0] != tokens[k + 1].text):
            # "the button that releases the latch": the button (what it does is how it is known, not another part)
            end = next((j for j in range(k + 1, len(tokens)) if tokens[j].is_punct or tokens[j].text in ("and", "then", "and_then", "so")), len(tokens))
            named = tokens[k + 2:end]  # "... that releases the door so it drops open": "it" is the door
            if end + 1 < len(tokens) and tokens[end].text in ("so", "and") and tokens[end + 1].text == "it" and named[:1] and named[0].text == "the":
                out += [tokens[end], *named]
                end += 2
            k = end
            continue
        if words[0] in ("that's", "which's", "that", "which") and out and (out[-1].text == "one" or kind_of_word(out[-1].text) is not None) and (
                next_word := words[1 + (words[0] in ("that", "which") and words[1:2] == ["is"])] if len(words) > 2 else "") and (
                next_word in ORDINALS or next_word in SPATIAL):
            k += 1 + (words[0] in ("that", "which") and words[1:2] == ["is"])  # "the knob that's second from the top"
            continue
        out.append(tokens[k])
        k += 1
    return out
