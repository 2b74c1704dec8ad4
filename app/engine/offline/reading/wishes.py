"""A wish instead of a command: "I need the rack out", "the oven door needs to be halfway down", "drawer needs to
come out 8 inches". The wish words go; what is left names a part and its wanted state."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.verbs import VERBS, WISHED_SENSES, VerbSense
from app.engine.lexicon.words import DETERMINERS, EVERYDAY_WORDS, PERSON_NOUNS, PERSONS, SPATIAL, STATES, WISHES
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

_STATE_OF = {VerbSense.CLOSE: "closed", VerbSense.OPEN: "open", VerbSense.RAISE: "up", VerbSense.LOWER: "down", VerbSense.PULL_OUT: "out",
             VerbSense.PUSH_IN: "in"}
_WISH_LEADS = frozenset({"but", "so", "and", "ok", "okay", "for", "now", "right", "well", "anyway"})
_WISH_ADVERBS = frozenset({"just", "really", "only", "also", "still", "actually"})


def wished_state(tokens: list[Token]) -> tuple[bool, list[Token]]:
    """"I need the rack out": drop the wish; what is left names a part and its wanted state."""
    k = 0
    while k < len(tokens) - 1 and tokens[k].text in _WISH_LEADS:
        k += 1  # "but for now I just need its drawer ...", "so I want ..."
    if k < len(tokens) and (tokens[k].text in WISHES or (tokens[k].text in ("need", "needs", "want") and k + 1 < len(tokens)
                                                          and tokens[k + 1].text in ("the", "this", "that", "both", "its", "my"))):
        return True, _done_to(tokens[k + 1:])  # "I need ...", "need the whole microwave flipped round"
    if k + 2 < len(tokens) and tokens[k].text in ("i", "we") and tokens[k + 1].text in _WISH_ADVERBS and tokens[k + 2].text in ("need", "want"):
        return True, tokens[k + 3:]
    words = [t.text for t in tokens]
    ing = next((j for j in range(k + 1, len(tokens) - 1) if words[j] in ("needs", "need") and words[j + 1].endswith("ing") and (
        tokens[j + 1].lemma in VERBS)), None)
    if ing is not None and not any(t.lemma in VERBS for t in tokens[k:ing]):
        # "pot needs lifting 15 cm off the stove": lift the pot 15 cm
        the = [] if words[k] in DETERMINERS else [Token("the", "the", tokens[k].start, tokens[k].start)]
        return True, [replace(tokens[ing + 1], text=tokens[ing + 1].lemma), *the, *tokens[k:ing], *tokens[ing + 2:]]
    for j in range(k + 1, len(tokens) - 1):
        must = 3 if words[j:j + 3] in (["needs", "to", "be"], ["need", "to", "be"], ["has", "to", "be"], ["have", "to", "be"]) else (
            2 if words[j:j + 2] in (["should", "be"], ["must", "be"]) else 0)
        if must and (words[k] in DETERMINERS or (words[k] in ("it", "they") and j == k + 1)) and j + must < len(tokens) and (
                tokens[j + must].text not in ("a", "an", "the")):  # "then it should be shut again"
            done = tokens[j + must]
            if done.text in WISHED_SENSES and done.text not in STATES:  # "the pot needs to be covered": closed
                done = replace(done, text=_STATE_OF[WISHED_SENSES[done.text]], lemma=_STATE_OF[WISHED_SENSES[done.text]])
            return True, [*tokens[k:j], done, *tokens[j + must + 1:]]  # "the oven door needs to be halfway down": the part and its wanted state
    if len(words) >= 2 and words[-1] in ("needs", "has") and (words[k] in DETERMINERS or kind_of_word(words[-2]) is not None or (
            len(words) == 2 and words[0] not in PERSONS and words[0] not in PERSON_NOUNS and words[0] not in EVERYDAY_WORDS)):
        # "drawer needs | to come out 8 inches": the part, then what it should do ("toggle needs | to go ...": a noun, not the verb)
        the = [Token("the", "the", tokens[0].start, tokens[0].start)] if len(words) == 2 and words[k] not in DETERMINERS else []
        return True, [*the, *tokens[:-1]]
    return False, tokens


def _done_to(tokens: list[Token]) -> list[Token]:
    """"the cupboard at the bottom opened", "the door closing": what is wished done, told as a command ("open the cupboard ...")
    when the done word ends the clause after a longer phrase (a short one, "the door opened", is read as it stands)."""
    while tokens and tokens[0].text in _WISH_ADVERBS:
        tokens = tokens[1:]  # "I need just the microwave door closing"
    done = next((j for j in range(2, len(tokens)) if _participle(tokens[j]) and tokens[j - 1].text not in DETERMINERS), None)
    if done is not None and tokens[0].text in DETERMINERS | {"only"} and not any(t.lemma in VERBS for t in tokens[1:done]):
        # "I'd like the casement swung open by 0.52 rad", "the drawer up top extended to its maximum": swing the casement open ...
        return [replace(tokens[done], text=tokens[done].lemma), *tokens[:done], *tokens[done + 1:]]
    last = tokens[-1] if len(tokens) > 3 and tokens[0].text in DETERMINERS else None
    if last is None or last.lemma not in VERBS or last.lemma == last.text or not last.text.endswith(("ed", "ing")):
        return tokens
    return [replace(last, text=last.lemma), *tokens[:-1]]  # "... the door closing": close the door


def _participle(token: Token) -> bool:
    """A past participle of a verb the lexicon knows, said after the part it is done to ("swung", "extended", "given";
    not a state word such as "closed", which the wish reads as the state wanted)."""
    return token.lemma in VERBS and (token.text != token.lemma or token.text in ("put", "set")) and token.text not in SPATIAL and not token.text.endswith("ing") and token.text not in STATES
