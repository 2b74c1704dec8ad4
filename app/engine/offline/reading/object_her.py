"""The object called "her" or "she", as a sailor or a driver says of a boat or a car: "turn her round a full hundred and
eighty degrees where she sits", "let her spring back up". Read as "it". Only where no person can be meant: "her" right
after a verb with no noun of hers after it, "she" in "where she sits" (not "she opened the door", a person in a story)."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.verbs import PARTICLES, VERBS
from app.engine.offline.reading.token import Token

_AFTER_OBJECT = frozenset({*PARTICLES, ",", ".", ";", "!", "?", "a", "all", "the", "halfway", "gently", "slowly", "quickly", "fully", "right", "and",
                           "then", "to", "for", "about", "by", "again", "once", "twice", "where", "until", "till", "just", "so"})
_PLACED = frozenset({"sits", "stands", "is", "rests", "lies"})
_VERB_FORMS = frozenset({"let", "bring", "get", "make", "swing", "spin", "turn", "open", "shut", "close", "lift", "raise", "lower", "push", "pull",
                         "tip", "roll", "wheel", "drop", "pop", "flip", "crack", "ease", "set", "put", "move", "rotate", "slide", "give"})


def _verb(token: Token) -> bool:
    return token.text in VERBS or token.text in _VERB_FORMS


def object_her(tokens: list[Token]) -> list[Token]:
    """``tokens`` with "her" / "she" read as "it" where they can only name the object."""
    out = list(tokens)
    for k, t in enumerate(tokens):
        after = tokens[k + 1].text if k + 1 < len(tokens) else "."
        let = k > 0 and tokens[k - 1].text in ("let", "make", "watch", "help") and after in VERBS  # "let her spring back up"
        if t.text == "her" and k > 0 and _verb(tokens[k - 1]) and (let or after in _AFTER_OBJECT or tokens[k + 1].number is not None):
            out[k] = replace(t, text="it", lemma="it")  # "turn her round", "let her spring back up"
        elif t.text == "she" and k > 0 and tokens[k - 1].text == "where" and after in _PLACED:
            out[k] = replace(t, text="it", lemma="it")  # "where she sits"
    return out
