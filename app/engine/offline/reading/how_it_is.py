"""Clauses that tell how things are or keep being, not a step: "while it is spinning", "the door is sitting open",
"it keeps popping open on its own" (a habit the user complains of), "the kids keep mashing the keys" (what people keep doing)."""

from __future__ import annotations

import re
from dataclasses import replace

from app.engine.lexicon.people import PERSON_NOUNS
from app.engine.lexicon.words import DIRECTIONS, POSTURES
from app.engine.offline.reading.clauses import Clause, Link
from app.engine.offline.reading.quantities import Quantities
from app.engine.offline.reading.token import Token

_HABIT_VERBS = frozenset({"keeps", "kept"})
_HABIT_ENDS = frozenset({"open", "opened", "shut", "closed", "out", "up", "down", "loose", "off", "ajar"})


def _progressive(tokens: list[Token], verb_index: int, clause: Clause, wish: bool) -> bool:
    if verb_index > 1 and tokens[verb_index].text.endswith("ing") and tokens[verb_index - 1].text in ("is", "are") and (
            clause.link not in (Link.RESULT, Link.PURPOSE, Link.CONDITION, Link.PARALLEL)):
        return True  # "while it is spinning" as a condition stays a step's timing; "the screen is leaning back" is how it is
    return not wish and clause.link not in (Link.RESULT, Link.PURPOSE, Link.CONDITION) and any(
        tokens[k].text in ("is", "are") and tokens[k + 1].text in POSTURES for k in range(verb_index - 1))  # "the door is sitting ... open"


def _habit(tokens: list[Token], verb_index: int) -> bool:
    """ "it keeps popping open", "the lid kept sliding off": a subject, then keeps + a gerund ending in a state."""
    if verb_index < 1 or verb_index + 1 >= len(tokens):
        return False
    people = tokens[verb_index - 1].text in PERSON_NOUNS  # "the kids keep mashing the keys": what people keep doing, a reason
    if tokens[verb_index].text not in _HABIT_VERBS and not (people and tokens[verb_index].text == "keep"):
        return False
    return tokens[verb_index + 1].text.endswith("ing") and verb_index + 2 < len(tokens) and (
        tokens[verb_index + 2].text in _HABIT_ENDS or people)  # not "keeps bumping the lid up"


def how_it_is(tokens: list[Token], verb_index: int | None, clause: Clause, wish: bool) -> bool:
    """Whether the clause whose verb is at ``verb_index`` describes a state or a habit rather than asking for a motion."""
    return verb_index is not None and (_progressive(tokens, verb_index, clause, wish) or _habit(tokens, verb_index))


_RELATIVES = frozenset({"that's", "which's", "that", "which", "that're"})
_BE_HAVE = frozenset({"is", "are", "has", "have", "was", "were", "had", "got"})


def told_state_words(tokens: list[Token], ends: set[int]) -> set[int]:
    """Indices of a relative clause after a part that tells its state ("the slab that's flopped forward", "the door that
    is hanging open"): its words say how the part is, never where the verb takes it. ``ends`` are where mentions end."""
    out: set[int] = set()
    for k in sorted(ends):
        if k >= len(tokens) or tokens[k].text not in _RELATIVES:
            continue
        j = k + 1
        if tokens[k].text in ("that", "which"):
            if j >= len(tokens) or tokens[j].text not in _BE_HAVE:
                continue
            j += 1
        if j >= len(tokens) or not (tokens[j].text.endswith(("ed", "en", "ing")) or tokens[j].text in _HABIT_ENDS):
            continue
        j += 1
        if j < len(tokens) and tokens[j].text in _STATE_AFTER and not (j + 1 < len(tokens) and tokens[j].text == "back"):
            j += 1
        out.update(range(k, j))
    return out


_STATE_AFTER = frozenset({"forward", "forwards", "backward", "backwards", "open", "shut", "closed", "out", "down", "up", "over", "off", "loose",
                          "ajar", "sideways", "back"})


_OBJECT_DETS = frozenset({"the", "a", "an", "my", "your", "our", "their", "his", "her", "some"})


def does_to_a_thing(tokens: list[Token]) -> int | None:
    """Where a part's own verb is in a clause that tells what the part does to something that is no part ("the left one
    hides the dove", "the lid keeps the dust out"): the verb is one we do not know, after the part and before the thing.
    Such a clause says how things are; it asks for no motion (before this, the step before lent it its verb)."""
    from app.engine.offline.reading.part_words import kind_of_word
    from app.engine.offline.reading.word_class import inflected_verb

    for k in range(2, len(tokens) - 2):
        word, before = tokens[k].text, tokens[k - 1].text
        if not (word.endswith("s") and word.isalpha() and inflected_verb(word) and kind_of_word(word) is None):
            continue
        if (before in ("one", "ones") or kind_of_word(before) is not None) and tokens[k + 1].text in _OBJECT_DETS and (
                kind_of_word(tokens[k + 2].text) is None and tokens[k + 2].text.isalpha()):
            return k
    return None


def told_way(tokens: list[Token], quantities: Quantities, told: set[int]) -> Quantities:
    """``quantities`` without a way said only inside a relative clause of state ("the slab that's flopped forward | back up":
    forward is how it is, not where it goes)."""
    if quantities.direction is None or not told:
        return quantities
    said = [k for k, t in enumerate(tokens) if DIRECTIONS.get(t.text, t.text) == quantities.direction]
    return replace(quantities, direction=None) if said and all(k in told for k in said) else quantities


ENDS_AS_BEGAN = re.compile(r"^((it|they) (ends|end|finishes|finish|stops|stop|winds up|comes to rest)( up)?( exactly| right| back)? where (it|they) "
                            r"(began|started|was|were)|(all the way|right) back (to )?where it started)$")
"""A clause that says a part ends where it began ("Expected: it ends exactly where it began", "Right back where it started!")."""
