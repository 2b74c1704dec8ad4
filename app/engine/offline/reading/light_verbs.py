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


_APPLYING = frozenset({"apply", "perform", "execute", "do"})
_NOUN_VERBS = {"rotation": "rotate", "translation": "move", "yaw": "yaw", "turn": "turn", "twist": "twist", "push": "push", "pull": "pull",
               "lift": "lift", "spin": "spin", "press": "press", "tap": "tap", "nudge": "nudge", "tilt": "tilt", "slide": "slide", "shove": "shove"}
_UNIT_WORDS = frozenset({"degree", "degrees", "deg", "°", "cm", "mm", "m", "metre", "metres", "meter", "meters", "inch", "inches", "quarter", "half",
                         "turn", "turns"})
_ENDS = frozenset({",", ".", ";", "about", "around", "round", "along", "with", "while", "and", "then", "so", "without"})


def _applied(tokens: list[Token]) -> list[Token] | None:
    """"apply a pure yaw of 90 degrees to the stapler about the vertical axis" -> "yaw the stapler 90 degrees about ...":
    a motion said as a noun applied to a part or the object."""
    if len(tokens) < 5 or tokens[0].lemma not in _APPLYING or tokens[1].text not in ("a", "an"):
        return None
    k = next((k for k in range(2, min(6, len(tokens))) if tokens[k].lemma in _NOUN_VERBS), None)
    to = next((j for j in range(k + 1, len(tokens)) if tokens[j].text in ("to", "on")), None) if k is not None else None
    if k is None or to is None or to + 1 >= len(tokens):
        return None
    end = next((j for j in range(to + 1, len(tokens)) if tokens[j].text in _ENDS or tokens[j].is_punct), len(tokens))
    amount = [t for t in tokens[2:k] if t.number is not None or t.text in _UNIT_WORDS] + [t for t in tokens[k + 1:to] if t.text != "of"]
    verb = _NOUN_VERBS[tokens[k].lemma]
    return [Token(verb, verb, tokens[0].start, tokens[k].end), *tokens[to + 1:end], *amount, *tokens[end:]]


def light_verb(tokens: list[Token]) -> list[Token]:
    """"give the car a push" -> "push the car a push": the deverbal noun is the action (its amount stays:
    "give the dial half a turn")."""
    if (applied := _applied(tokens)) is not None:
        return applied
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
