"""A learner's grammar, said the way the later stages read it. Someone writing in a second language drops the verb's
"-s", puts a side after the noun or says "more high"; the meaning is plain, so the words are put in the usual order:

- "so it stand 90 degrees open" -> "so it stands ...", "until it don't go more" -> "until it doesn't go more", "Oven have
  three racks" -> "Oven has three racks";
- "pull out the rack of middle" -> "pull out the middle rack", "tray of top" -> "top tray";
- "three sliding rack": three racks;
- "the drawer more high of the two" -> "the higher drawer of the two";
- "hold for 2 s, after close it" -> "..., then close it" ("after" before a command: afterwards);
- "move it to direction of hot for 30 degrees" -> "move it toward hot by 30 degrees", "half metre" -> "half a metre".
"""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import OBJECT_NOUNS, SPATIAL, STATIVE_VERBS
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.word_class import inflected_form

_SUBORDINATORS = frozenset({"so", "until", "till", "when", "once", "because", "as", "where", "while", "if", "so_that"})
"""After these, "it" is the subject of a clause of its own ("so it stand", "until it don't")."""
_SIDES_AFTER = frozenset({"top", "middle", "bottom", "left", "right", "front", "back"})
"""Sides a learner puts after the noun with "of" ("the rack of middle")."""
_COMPARED = frozenset({"high", "low", "far", "near", "big", "small", "wide", "long", "short", "tall"})


def _agrees(tokens: list[Token], i: int) -> Token | None:
    """``tokens[i]`` is a bare verb after "so it" / "until it", or "have" after one thing: its "-s" form."""
    token = tokens[i]
    if token.text == "have" and i >= 1 and not tokens[i - 1].plural and (tokens[i - 1].lemma in OBJECT_NOUNS or kind_of_word(tokens[i - 1].lemma) is not None) and (
            i == 1 or tokens[i - 2].is_punct or tokens[i - 2].text in ("the", "this", "my", "our")):
        return replace(token, text="has", lemma="has")  # "Oven have three racks": the oven has
    if i < 2 or tokens[i - 1].text != "it" or tokens[i - 2].text not in _SUBORDINATORS or token.number is not None:
        return None
    if token.text == "don't":
        return replace(token, text="doesn't", lemma="doesn't")
    if token.text != token.lemma or not (token.text in VERBS or f"{token.text}s" in STATIVE_VERBS) or token.text in SPATIAL:
        return None
    form = inflected_form(token.text, "VBZ")
    return replace(token, text=form) if form else None


_MEASURES = frozenset({"degree", "degrees", "deg", "rad", "radian", "radians", "cm", "mm", "m", "metre", "meter", "metres", "meters", "inch",
                       "inches", "turn", "turns", "revolution", "revolutions"})


def _measure(tokens: list[Token], i: int) -> bool:
    """An angle or a length (no time) said from ``i``: "30 degrees", "half metre", "a quarter turn"."""
    return any(t.text in _MEASURES for t in tokens[i:i + 3])


def learner(tokens: list[Token]) -> list[Token]:
    """The tokens with a learner's word order and agreement put the usual way (see the module)."""
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        token = tokens[i]
        after = tokens[i + 1] if i + 1 < len(tokens) else None
        agreed = _agrees(tokens, i)
        counted = next((k for k in range(i + 1, min(i + 3, len(tokens))) if kind_of_word(tokens[k].lemma) is not None), None) if (
            token.number is not None and token.number > 1 and token.text.isdigit() and not (i and tokens[i - 1].text in ("the", "this", "that"))) else None
        if counted is not None and not tokens[counted].plural:
            out += [token, *tokens[i + 1:counted], replace(tokens[counted], plural=True)]  # "three sliding rack": racks
            i = counted + 1
            continue
        if agreed is not None:
            out.append(agreed)
        elif token.text == "the" and after is not None and after.text in ("half", "quarter") and [t.text for t in tokens[i + 2:i + 3]] == ["of"] and (
                [t.text for t in tokens[i + 4:i + 5]] == ["way"]):
            i += 1
            continue  # "until the half of its way": "the" dropped, half of its way
        elif token.text == "after" and after is not None and i + 2 < len(tokens) and after.text == after.lemma and after.lemma in VERBS and (
                tokens[i + 2].text in ("it", "them", "the")) and (i == 0 or tokens[i - 1].is_punct or tokens[i - 1].text == "and"):
            out.append(Token("then", "then", token.start, token.end))  # "..., after close it": then close it
        elif token.text == "of" and after is not None and after.text in _SIDES_AFTER and out and kind_of_word(out[-1].lemma) is not None and (
                i + 2 == len(tokens) or tokens[i + 2].is_punct or tokens[i + 2].text in ("and", "then", "and_then", "i", "we")):
            out.insert(len(out) - 1, after)  # "the rack of middle": the middle rack
            i += 2
            continue
        elif token.text in ("to", "in", "into") and [t.text for t in tokens[i + 1:i + 3]] in (["direction", "of"], ["the", "direction"]) and (
                tokens[i + 1].text == "direction" or (i + 3 < len(tokens) and tokens[i + 3].text == "of")):
            out.append(Token("toward", "toward", token.start, token.end))  # "to direction of hot", "in the direction of its front": toward
            i += 3 if tokens[i + 1].text == "direction" else 4
            continue
        elif token.text == "for" and after is not None and (after.number is not None or after.text in ("half", "a_quarter", "a", "one_quarter")) and (
                _measure(tokens, i + 1)):
            out.append(Token("by", "by", token.start, token.end))  # "move it ... for 30 degrees", "for half metre": by that much
        elif token.text == "half" and after is not None and not (i and tokens[i - 1].text in ("a", "an", "one", "and", "the")) and (after.text in _MEASURES or (after.text == "of" and i + 2 < len(tokens) and tokens[i + 2].text in _MEASURES)):
            out += [token, Token("a", "a", token.end, token.end)]  # "half metre", "half of metre": half a metre
            i += 1 + (after.text == "of")
            continue
        elif token.text == "more" and after is not None and after.text in _COMPARED and (form := inflected_form(after.text, "JJR")):
            compared = Token(form, form, token.start, after.end)  # "more high": higher
            if out and kind_of_word(out[-1].lemma) is not None:
                out.insert(len(out) - 1, compared)  # "the drawer more high of the two": the higher drawer of the two
            else:
                out.append(compared)
            i += 2
            continue
        else:
            out.append(token)
        i += 1
    return out
