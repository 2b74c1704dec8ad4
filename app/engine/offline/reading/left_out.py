"""Words a speaker leaves out, put back. Voice transcripts and learners run clauses together; the clause stage splits at
punctuation and joining words, so this stage puts the missing comma back where English grammar says a clause starts:

- a part said first and taken up again by a pronoun: "drawer on left open it" -> "open drawer on left",
  "the fridge door on the right can you swing it open" -> "can you swing the fridge door on the right open",
  "the dishwasher can you lower its door" -> "the dishwasher , can you lower its door";
- a second command run into the first: "turn it on leave it on for 2.5 seconds" -> "turn it on , leave it on ...",
  "push it fully closed wait 1 second" -> "push it fully closed , wait 1 second".

An inverted clause after "only once ..." or "only then" is put the plain way: "only once it has popped out does the door
swing down" -> "only once it has popped out , the door swings down". It also names the noun a count stands for: "the higher of the two drops down" -> "the higher of the two ones drops down"
(else "drops" is read as the noun). Each added token has no width; no word is removed.
"""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import (
    AGENT_NOUNS,
    DETERMINERS,
    FILLERS,
    MODALS,
    OBJECT_NOUNS,
    OBJECT_SUFFIXES,
    PERSON_NOUNS,
    PERSONS,
    SIZES,
    SPATIAL,
)
from app.engine.offline.reading.light_verbs import LIGHT_VERBS
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.verb_position import AUX, NOT_BEFORE_VERB
from app.engine.offline.reading.word_class import inflected_form, inflected_verb

_PRONOUNS = frozenset({"it", "them", "its"})
"""What takes up a part said before ("the drawer, open it")."""
_REQUESTS = frozenset({"can", "could", "would", "will"})
""""can you swing it open": a request that starts a clause."""
_SUBORDINATORS = frozenset({"where", "when", "until", "till", "while", "whilst", "if", "as", "so", "because", "since", "that", "once", "how",
                            "before", "after"})
_HOLDS = frozenset({"wait", "pause", "hold", "keep", "leave", "stay", "rest"})
"""Verbs of a hold or a wait, which may take a time straight after them ("wait 1 second", "hold it 2 seconds")."""
_AFTER_COUNT = frozenset({"to", "by", "into", "down", "up", "out", "open", "shut", "closed", "all_the_way", "halfway", "fully", "and", "then",
                          "and_then", "a", "an", "first", "last"})
"""Words that may follow "the upper of the two" when no noun does."""
_STARTS = frozenset({"and", "then", "and_then", "or", "but"})
"""Words after which a clause starts anyway (the clause stage splits there)."""
_NOT_BEFORE_COMMAND = NOT_BEFORE_VERB | MODALS | AUX | PERSONS | _STARTS | frozenset(
    {"to", "it", "them", "let", "make", "help", "have", "has", "had", "not", "don't", "dont", "will", "does", "do", "did", "i'll", "you'll",
     "we'll", "let's", "lets", "can't", "cannot", "won't", "would", "could", "should", "must", "might", "may", "also", "by", "gonna", "wanna",
     "gotta", "need", "needs", "want", "wants", "like"})


def _count_alone(tokens: list[Token], i: int) -> bool:
    """``tokens[i]`` is the count of "the higher of the two | drops down": no noun follows, a verb or the end does."""
    if tokens[i].number is None or i < 3 or [t.text for t in tokens[i - 2:i]] != ["of", "the"] or (tokens[i - 3].text not in SIZES and tokens[i - 3].text not in SPATIAL):
        return False  # "the upper of the two | drops" (not "the key left of the 9")
    if i >= 5 and tokens[i - 5].text in ("on", "at", "in", "from", "to", "of"):
        return False  # "the knob on the leftmost of the 3": the noun was said before
    after = tokens[i + 1] if i + 1 < len(tokens) else None
    if after is not None and after.text.endswith("s") and after.lemma != after.text and kind_of_word(after.lemma) is not None:
        return False  # "the upper of the two dials": the noun is said
    return after is None or after.is_punct or after.text in _AFTER_COUNT or (after.lemma in VERBS and after.text != after.lemma and after.text.endswith("s"))


def _only_before(tokens: list[Token], i: int) -> bool:
    """The sentence before ``i`` opens with "only once / when / after / then / if"."""
    start = max((k for k in range(i) if tokens[k].is_sentence_end or tokens[k].text == ":"), default=-1) + 1
    return any(t.text == "only" and n.text in ("once", "when", "after", "then", "if") for t, n in zip(tokens[start:i], tokens[start + 1:i], strict=False))


def _inverted_told(tokens: list[Token], i: int) -> int | None:
    """Where "to be" is when ``tokens[i]`` is the "is" of "only after ... is the tray to be extended"."""
    if tokens[i].text not in ("is", "are") or i < 2 or tokens[i - 1].is_punct or i + 1 >= len(tokens) or tokens[i + 1].text not in ("the", "its", "both"):
        return None
    told = next((k for k in range(i + 2, min(i + 9, len(tokens) - 1)) if tokens[k].text == "to" and tokens[k + 1].text == "be"), None)
    return told if told is not None and _only_before(tokens, i) else None


def _inverted(tokens: list[Token], i: int) -> int | None:
    """Where the verb is when ``tokens[i]`` is the "does" of "only once ... does the door swing": the subject follows."""
    if tokens[i].text not in ("does", "do") or i < 2 or tokens[i - 1].is_punct:
        return None
    if not _only_before(tokens, i):
        return None
    if i + 1 >= len(tokens) or tokens[i + 1].text not in ("the", "its", "both", "this", "that"):
        return None
    return next((k for k in range(i + 2, min(i + 8, len(tokens))) if tokens[k].text == tokens[k].lemma and tokens[k].lemma in VERBS
                 and tokens[k].text not in SPATIAL and kind_of_word(tokens[k].text) is None), None)


def _command_at(tokens: list[Token], i: int) -> bool:
    """A base-form verb the lexicon knows, not a part word or a side ("lower", "switch", "left") unless a pronoun follows
    ("lower it")."""
    token = tokens[i]
    pronoun = i + 1 < len(tokens) and tokens[i + 1].text in _PRONOUNS
    return (token.number is None and token.text == token.lemma and (token.lemma in VERBS or token.lemma in LIGHT_VERBS)
            and (pronoun or (token.text not in SPATIAL and kind_of_word(token.text) is None)))


def _nounish(token: Token) -> bool:
    return kind_of_word(token.text) is not None or token.lemma in OBJECT_NOUNS or token.text in OBJECT_NOUNS or token.text in AGENT_NOUNS or (
        token.text.isalpha() and len(token.text) > 4 and token.text.endswith(OBJECT_SUFFIXES))


def _topic(tokens: list[Token], start: int, i: int) -> bool:
    """``tokens[start:i]`` is a noun phrase alone: it names a part or the object and holds no verb, pronoun or auxiliary."""
    span = tokens[start:i]
    if not span or len(span) > 8 or not any(_nounish(t) for t in span):
        return False
    for t in span:
        if t.is_punct or t.text in PERSONS or t.text in PERSON_NOUNS or t.text in _PRONOUNS or t.text in AUX or t.text in MODALS or t.text in _SUBORDINATORS or t.text == "to":
            return False  # not "key in 0 to | unlock it": a purpose
        if (t.lemma in VERBS or t.lemma in LIGHT_VERBS) and t.text not in SPATIAL and kind_of_word(t.text) is None and not _nounish(t):
            return False
    return True


def _takes_up(tokens: list[Token], i: int) -> int | None:
    """Where the verb of a command taking up a part said before is, when the command starts at ``i``: "open it", "just let it drop", "can you swing it open"."""
    j = i
    if tokens[j].text in _REQUESTS and j + 1 < len(tokens) and tokens[j + 1].text == "you":
        j += 2
    while j < len(tokens) and tokens[j].text in FILLERS and tokens[j].text not in _STARTS:
        j += 1
    if j + 1 < len(tokens) and _command_at(tokens, j) and tokens[j + 1].text in _PRONOUNS:
        return j
    return None


def _said_before_verb(tokens: list[Token], start: int, i: int) -> bool:
    """The clause from ``start`` opens with a command and has said what it works on before ``i``."""
    k = start
    while k < i and tokens[k].text in FILLERS:
        k += 1
    if k >= i - 1:
        return False
    if not _command_at(tokens, k):  # or a state told first: "the drawer is out push it closed"
        return tokens[k].text in DETERMINERS and any(t.text in ("is", "are", "was", "were") for t in tokens[k + 1:i]) and (
            not any(t.text in _SUBORDINATORS or t.text in PERSONS for t in tokens[k:i]))
    open_subordinate = False
    for j in range(k + 1, i):
        t = tokens[j]
        if t.text in _SUBORDINATORS:
            open_subordinate = True  # "to where it stops": a clause of its own, complete once its verb is said
        elif open_subordinate and ((t.text != t.lemma and (t.lemma in VERBS or inflected_verb(t.text))) or tokens[j - 1].text in MODALS):
            open_subordinate = False  # "where it stops", "as far as it will go"
    return not open_subordinate


def _second_command(tokens: list[Token], start: int, i: int) -> bool:
    """A command run into the one before it: "turn it on leave it on for 2.5 seconds", "push it closed wait 1 second"."""
    if not _command_at(tokens, i) or tokens[i - 1].text in _NOT_BEFORE_COMMAND or tokens[i - 1].is_punct:
        return False
    after = tokens[i + 1] if i + 1 < len(tokens) else None
    if after is None:
        return False
    works_on = after.text in _PRONOUNS or after.text in ("the", "both", "this", "that")
    timed = tokens[i].text in _HOLDS and (after.number is not None or after.text in ("for", "a", "there", "like_that"))
    return (works_on or timed) and _said_before_verb(tokens, start, i)


def left_out(tokens: list[Token]) -> list[Token]:
    """The tokens with a comma where a clause was run into the one before it, a part said first and taken up by "it" or
    "them" put in the pronoun's place ("drawer on left open it" -> "open drawer on left"), and "ones" after a count with
    no noun ("the higher of the two | drops")."""
    out: list[Token] = []
    start = 0
    i = 0
    while i < len(tokens):
        token = tokens[i]
        if (told := _inverted_told(tokens, i)) is not None:
            out += [Token(",", ",", token.start, token.start), *tokens[i + 1:told], token]  # "only then is the door to be opened": the door is to be
            start, i = i + 1, told
            continue
        if token.text in ("do", "does") and i + 2 < len(tokens) and tokens[i + 1].text in ("you", "we", "i") and i > 1 and not tokens[i - 1].is_punct and (
                _only_before(tokens, i) and _command_at(tokens, i + 2)):
            out.append(Token(",", ",", token.start, token.start))  # "only once it's off do you lift the jug": ", lift the jug"
            start, i = i + 2, i + 2
            continue
        if (inverted := _inverted(tokens, i)) is not None and (form := inflected_form(tokens[inverted].text, "VBZ")):
            out += [Token(",", ",", token.start, token.start), *tokens[i + 1:inverted], replace(tokens[inverted], text=form)]
            start, i = i + 1, inverted + 1
            continue
        verb = _takes_up(tokens, i) if i > start else None
        if verb is not None and _topic(tokens, start, i):
            topic = tokens[start:i]
            if tokens[verb + 1].text in ("it", "them"):
                del out[len(out) - len(topic):]
                said = [t for t in topic if t.text not in FILLERS]
                article = [] if said and (said[0].text in DETERMINERS or said[0].text.endswith("'s")) else [Token("the", "the", said[0].start, said[0].start)]
                out += [*tokens[i:verb + 1], *article, *said]  # "door of dishwasher lower it" -> "lower the door of dishwasher"
                start, i = i, verb + 2
                continue
            out.append(Token(",", ",", token.start, token.start))
            start = i
        elif token.is_punct or token.text in _STARTS:
            start = i + 1
        elif i > start and _second_command(tokens, start, i):
            out.append(Token(",", ",", token.start, token.start))
            start = i
        out.append(token)
        if _count_alone(tokens, i):
            out.append(Token("ones", "one", token.end, token.end))
        i += 1
    return out
