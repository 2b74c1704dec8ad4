"""Cues for what is a verb in a clause: a verb the lexicon does not know ("jiggle the lid"), a side word before a part
that is not the verb "lower" ("lower drawer out 0.5 m"), a clause about a person ("so I can reach in"), a finite verb
after its subject ("the lid opens")."""

from __future__ import annotations

from app.engine.lexicon.verbs import PARTICLES, VERBS
from app.engine.lexicon.words import DETERMINERS, MODALS, OBJECT_NOUNS, ORDINALS, PERSONS, SPATIAL, STATIVE_VERBS
from app.engine.offline.reading.token import Token

_SIDE_CUES = frozenset({"out", "in", "back", "open", "shut", "closed", "clockwise", "anticlockwise", "counterclockwise", "anti-clockwise",
                        "counter-clockwise", "cw", "ccw", "of"})  # "of": "lower drawer of the two - pull it out"


def side_of_part(tokens: list[Token]) -> bool:
    """"lower drawer out 0.5 m", "upper knob 90 degrees clockwise": a side word before a part noun with no article, followed
    by what the part does (a particle, a turn sense) — the side of the part, not the verb "lower"."""
    from app.engine.offline.reading.mentions import kind_at

    if len(tokens) < 2 or tokens[0].text not in SPATIAL:
        return False
    j = 2 if tokens[1].text in OBJECT_NOUNS and len(tokens) > 2 and kind_at(tokens, 2) is not None else 1  # "lower oven door, ..."
    if kind_at(tokens, j) is None:
        return False
    return len(tokens) == j + 1 or any(t.text in _SIDE_CUES for t in tokens[j + 1:j + 5])  # "Lower knob - turn it ...": the part alone


_DETERMINING = frozenset({"the", "its", "this", "that", "your", "both", "each", "my"})


def unknown_verb(token: Token, following: str = "") -> bool:
    """An imperative verb the lexicon does not know ("jiggle", "nudge"): a base-form verb that is not a part name
    (nor an object's name, unless a determiner follows: "sink the toaster lever")."""
    from lemminflect import getAllLemmas

    from app.engine.offline.reading.part_words import kind_of_word

    word = token.text
    if not word.isalpha() or word in DETERMINERS or word in ORDINALS or word in PARTICLES or word in PERSONS or word in STATIVE_VERBS or kind_of_word(word) is not None or (
            word in OBJECT_NOUNS and following not in _DETERMINING) or (  # "bin lid: up to vertical": the object, not "to bin"
            word in SPATIAL and (kind_of_word(following) is not None or following in OBJECT_NOUNS)):  # "bottom door down flat", "right
        # fridge door, swing it ...": the part's side, not "to bottom" / "to right"
        return False
    lemmas = getAllLemmas(word)
    return word in lemmas.get("VERB", ())


def _unknown_verb_form(word: str) -> bool:
    from lemminflect import getAllLemmas

    return word.isalpha() and "VERB" in getAllLemmas(word)


def aside(tokens: list[Token]) -> bool:
    """The clause is about a person ("I can put my plate in", "you can reach in") or says what something
    else may then do ("they can air-dry"), or remarks on the request ("that's the whole anim", "nothing else")."""
    first = tokens[0].text if tokens else ""
    second = tokens[1].text if len(tokens) > 1 else ""
    weather = first == "it's" and second.endswith("ing") and len(tokens) > 1 and tokens[1].lemma not in VERBS  # "it's raining"
    if len(tokens) == 2 and first in ("it", "they") and tokens[1].lemma not in VERBS and _unknown_verb_form(second):
        return True  # "(while) it brews": what the object does, not a part's motion
    remark = first in ("that's", "nothing") or (first in ("that", "this") and second in ("is", "was", "will"))  # "that's the whole anim"
    remark = remark or (1 < len(tokens) <= 4 and tokens[-1].text == "here")  # "Game dev here - ...": who is asking
    kept = first == "my" and any(t.text in ("is", "are") for t in tokens[1:4]) and any(t.text in ("in", "inside", "on", "behind") for t in tokens[2:6])
    return (first in PERSONS and not kept) or (first in ("they", "it", "that") and second in MODALS) or weather or remark  # not "my socks
    # are in the lower drawer": where a thing is kept


def intransitive(tokens: list[Token], verb_index: int | None) -> bool:
    """A finite verb after its subject ("the lid opens", "the door swings open")."""
    if verb_index is None or verb_index == 0:
        return False
    token = tokens[verb_index]
    return token.text != token.lemma or tokens[verb_index - 1].text in ("is", "are", "gets", "get")


def letting_go(tokens: list[Token], i: int) -> bool:
    """At a "go": "let go (of it)", "let the lid go" (the user lets go), not "make the lid go up" (a motion)."""
    return tokens[i - 1].lemma == "let" or i + 1 == len(tokens) or tokens[i + 1].is_punct or tokens[i + 1].text in ("of", "again", "and", "then")
