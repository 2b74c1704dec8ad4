"""A light verb with a deverbal noun: "give the car a push" is pushing the car, "give the dial half a turn" turning it
(the amount stays)."""

from __future__ import annotations

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import LIGHT_VERBS, PAUSE_NOUNS
from app.engine.offline.reading.token import Token

_PAUSE_TAKERS = frozenset({"make", "take", "have", "do"})
""""make a pause of 2 s", "take a short break": the noun is the wait."""

_MANNER_ADJECTIVES = frozenset({"quick", "gentle", "little", "good", "hard", "firm", "slight", "small", "short", "light", "brief", "sharp"})
_AS_ADVERB = {"good": "", "hard": "", "gentle": "gently", "firm": "firmly", "sharp": "sharply", "light": "lightly", "brief": "briefly"}
"""A manner adjective said after the part once the noun is the verb ("give the drawer a gentle tug": tug the drawer gently)."""
_LIGHT_OBJECT_WORDS = frozenset({"a", "an", "half", "quarter", "full", "little", "good", "quick", "gentle", "hard", "firm", "slight", "small",
                                 "big", "another", "a_quarter", "one", "complete", "whole", "two", "three", "2", "3", "degree", "degrees",
                                 "clockwise", "anticlockwise", "counterclockwise", "anti-clockwise", "counter-clockwise"})


def light_verb(tokens: list[Token]) -> list[Token]:
    """"give the car a push" -> "push the car a push": the deverbal noun is the action (its amount stays:
    "give the dial half a turn")."""
    if tokens and tokens[0].lemma in _PAUSE_TAKERS:
        for k in range(1, min(len(tokens), 4)):
            if tokens[k].text in PAUSE_NOUNS and all(t.text in ("a", "an") or t.text in _MANNER_ADJECTIVES for t in tokens[1:k]):
                return [Token("pause", "pause", tokens[0].start, tokens[k].end), *tokens[k + 1:]]  # "make (a) pause of 2 s": pause 2 s
    if not tokens or tokens[0].lemma not in LIGHT_VERBS:
        return tokens
    for i in range(2, len(tokens)):
        if tokens[i].lemma in VERBS and tokens[i - 1].text in _LIGHT_OBJECT_WORDS and i + 1 < len(tokens) and tokens[i + 1].text == "to":
            return [tokens[i], *tokens[i + 2:]]  # "give a quick tap to the top key": tap the top key
        if tokens[i].lemma in VERBS and tokens[i - 1].text in _LIGHT_OBJECT_WORDS:
            anaphor = tokens[i - 2].text == "one" and i >= 4 and tokens[i - 3].text not in _LIGHT_OBJECT_WORDS  # "give the bigger one a spin"
            bare = tokens[i - 1].text in ("a", "an") and (tokens[i - 2].text not in _LIGHT_OBJECT_WORDS or anaphor)  # "a flush" is no part
            if tokens[i - 1].text in _MANNER_ADJECTIVES and tokens[i - 2].text in ("a", "an"):
                manner = _AS_ADVERB.get(tokens[i - 1].text, tokens[i - 1].text)
                said = [Token(manner, manner, tokens[i - 1].start, tokens[i - 1].end)] if manner else []  # "a good shove": no manner
                return [tokens[i], *tokens[1:i - 2], *said, *tokens[i + 1:]]  # "give the pedal a quick tap": tap the pedal quick ("a quick tap" names
                # no tap of a sink)
            return [tokens[i], *tokens[1:i - 1], *tokens[i + 1:]] if bare else [tokens[i], *tokens[1:]]
    return tokens
