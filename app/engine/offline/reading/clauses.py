"""Stage 2 — clauses: tokens -> :class:`Clause` list, each with how it links to its neighbours.

Boundaries are sentence marks, sequence words ("then", "after that", "finally"), "and" or a comma before a new verb,
parallel words ("while", "at the same time as"), ordering words ("after ...ing", "before ...", "once ..."), purpose ("to
<verb>", "in order to"), means ("by ...ing", "using the X, ..."), results ("so the lid opens", "which swings open", "and
the lid lifts"), conditions ("while the door is open") and negations ("without touching the knob", "don't move it").
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from enum import StrEnum

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import (
    AFTER,
    ANGLE_UNITS,
    ASPECT_VERBS,
    BEFORE,
    CAUSATIVES,
    CENTRE_WORDS,
    DETERMINERS,
    FILLERS,
    LENGTH_UNITS,
    LIGHT_VERBS,
    MODALS,
    NEGATIONS,
    PARALLEL,
    PAUSE_NOUNS,
    PERSONS,
    PURPOSE,
    SEQUENCE,
    SIMULTANEOUS,
    SPATIAL,
    SPEEDS,
    STATIVE_VERBS,
    TOLD_CAUSATIVES,
    WISHES,
)
from app.engine.offline.reading.mentions import kind_at
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.verb_position import AUX, NOT_BEFORE_VERB, after_side_noun, verb_at
from app.engine.offline.reading.word_class import finite_unknown_verb, inflected_verb


class Link(StrEnum):
    """How a clause attaches to the clause before it (in the prompt's order)."""

    FIRST = "first"
    SEQUENCE = "sequence"
    PARALLEL = "parallel"
    PURPOSE = "purpose"
    """This clause is the goal the previous clause achieves ("press the pedal | to open the lid")."""
    MEANS = "means"
    """This clause is how the previous clause is achieved ("open the lid | by pressing the pedal")."""
    RESULT = "result"
    """This clause says what the previous one caused ("press the button | so the door pops open")."""
    CONDITION = "condition"
    """A state that must hold ("| while the door is open")."""
    NEGATED = "negated"
    """Something the user says not to do ("| without touching the knob")."""


@dataclass(frozen=True)
class Clause:
    index: int
    tokens: tuple[Token, ...]
    link: Link
    goes_first: bool = False
    """Ordered before the previous clause ("B after A-ing", "before B, A" puts A first)."""
    conjoined: bool = False
    """Joined to the previous clause by "and" or a comma (not by a sequence word)."""
    marker: str = ""
    """The connective that opened it ("after", "once", "while", ...)."""
    heading: bool = False
    """It ends in a colon: it may only name what the clauses after it do ("Lock up the safe: swing ...")."""

    @property
    def text(self) -> str:
        return " ".join(t.text.replace("_", " ") for t in self.tokens)


_PAUSES = frozenset({"pause", "wait", "beat", "hold", "break", "rest", "delay"})
_STAYS = frozenset({"rests", "stays", "sits", "remains", "waits", "pauses", "hangs"})
_CAUSING = frozenset({"make", "have", "help", "cause", "allow"})
_TOLD_ENDS = frozenset({"open", "shut", "closed", "up", "down", "out", "in"})


def _starts_clause(tokens: list[Token], i: int) -> bool:
    """A new clause starts at ``i`` (after "and" / a comma): a verb, or a subject followed by a verb."""
    j = i
    while j < len(tokens) and (tokens[j].text in FILLERS or tokens[j].text in SPEEDS or tokens[j].text in SEQUENCE):
        j += 1
    if j + 1 < len(tokens) and tokens[j].text in ("shut", "closed", "open") and tokens[j + 1].is_punct and any(t.text in ("is", "are", "was", "were") for t in tokens[max(0, i - 5):i]):
        return False  # "the dishwasher is loaded and shut, start it": how it is, said twice
    if j < len(tokens) and (verb_at(tokens, j, strict=True) or tokens[j].text in CAUSATIVES or tokens[j].lemma in LIGHT_VERBS):
        return True
    if j + 1 < len(tokens) and tokens[j].text == "back" and tokens[j + 1].text in ("in", "shut", "closed", "down", "up", "again", "home", "to", "into"):
        return True  # "slide the drawer out and back in": the way back is a step of its own
    if j < len(tokens) and (tokens[j].text in ("it's", "they're", "that's", "it'll") or tokens[j].text in WISHES):
        return True  # "so it's not in the way", "Game dev here - I need ..."
    if j + 2 < len(tokens) and tokens[j].number is not None and tokens[j + 2].text in _PAUSES:
        return True  # "up to vertical, 2 s pause, then ...": a wait
    if j + 1 < len(tokens) and tokens[j].text in _STAYS and tokens[j + 1].text in ("there", "for", "like_that", "open", "shut", "closed"):
        return True  # "the lid comes down, rests there for two seconds, ...": a hold
    if j + 1 < len(tokens) and (tokens[j].text in PERSONS or tokens[j].text in ("it", "they")) and (
            tokens[j + 1].text in MODALS or (tokens[j].text in PERSONS and (tokens[j + 1].lemma in VERBS or inflected_verb(tokens[j + 1].text)))):
        return True  # "so I can put my plate in", "so they can air-dry"
    if j + 1 < len(tokens) and tokens[j].text == "they" and tokens[j + 1].lemma in VERBS and tokens[j + 1].text == tokens[j + 1].lemma:
        return True  # "so they snap shut": a plural subject and its verb
    if j + 1 < len(tokens) and tokens[j].text in ("it", "this", "that") and tokens[j + 1].text in ("makes", "lets", "causes", "gets", "pops", "sends"):
        return True  # "press the pedal so that it makes the lid lift open"
    # "..., and the lid lifts", "so the door pops open": a subject noun phrase and a finite verb
    k = j
    while k < len(tokens) and k < j + 6 and not tokens[k].is_punct:
        if k > j and tokens[k].lemma in VERBS and tokens[k].text != tokens[k].lemma and (tokens[k - 1].text not in NOT_BEFORE_VERB or after_side_noun(tokens, k)):
            return tokens[j].text in DETERMINERS or tokens[j].text in ("it", "they") or (k == j + 1 and kind_of_word(tokens[j].text) is not None and tokens[k].text.endswith("s"))
        stative = tokens[k].text in STATIVE_VERBS and not tokens[k].text.endswith("ing")  # "so the drawer faces the wall"
        if (tokens[k].text in AUX or stative) and k > j:
            return tokens[j].text in DETERMINERS or tokens[j].text in ("it", "they", "both", "all")  # ", both doors are hanging open"
        if tokens[k].text in MODALS and k > j and (tokens[j].text in DETERMINERS or (k == j + 1 and kind_of_word(tokens[j].text) is not None)):
            return True  # "so the steam can escape", "so the camera can see inside", ", door should unlatch"
        if k > j + 1 and tokens[j].text in DETERMINERS and (finite_unknown_verb(tokens[k].text) or (
                k == j + 2 and tokens[k].text.endswith("s") and tokens[k].text != tokens[k].lemma and inflected_verb(tokens[k].text))):
            return True  # "so the steam clears / escapes": a verb the lexicon does not know
        if k == j + 2 and tokens[j].text in DETERMINERS and tokens[j + 1].plural and tokens[k].lemma in VERBS and tokens[k].text == tokens[k].lemma:
            return True  # "so that the bolts retract": a plural subject and its verb
        k += 1
    return False


def _segment(tokens: list[Token], i: int) -> list[Token]:
    """The tokens from ``i`` to the next punctuation mark."""
    end = i
    while end < len(tokens) and not tokens[end].is_punct:
        end += 1
    return tokens[i:end]


def _elaboration(current: list[Token]) -> bool:
    """A verbless part-and-amount clause ("the top one a quarter turn clockwise", "the left to 120 degrees")."""
    from app.engine.offline.reading.quantities import read_quantities

    return bool(current) and (current[0].text in DETERMINERS or current[0].text in SPATIAL) and not any(verb_at(current, k, strict=True) for k in range(len(current))) and (
        read_quantities(current).amount is not None)


def _other_verb(tokens: list[Token], i: int) -> bool:
    """"to check the food", "to rinse it": a verb we have no sense for, taking an object."""
    from lemminflect import getAllLemmas

    token = tokens[i]
    follows = tokens[i + 1].text if i + 1 < len(tokens) else ""
    lemmas = getAllLemmas(token.text)
    base = token.text in lemmas.get("VERB", ())
    gerund = i + 1 < len(tokens) and _ing(tokens[i + 1]) and tokens[i + 1].lemma in VERBS  # "to simulate setting the timer"
    return token.text.isalpha() and "VERB" in lemmas and (gerund or follows in DETERMINERS or follows in ("it", "them", "that", "this") or (
        base and follows in ("", ",", ".", ";", "!", "?", "and", "then", "on", "in", "at", "for", "inside", "up")))  # "to check on the dishes"


def _ing(token: Token) -> bool:
    return token.text.endswith("ing") and (token.lemma in VERBS or token.text == "giving")  # "by giving the knob a quarter turn"


_THEREFORE = ("causing", "making", "as_a_result", "because_of_that", "because_of_this", "as_a_consequence", "consequently")
"""Words after which what follows is what the clause before caused."""


def _told_after_gerund(current: list[Token], token: Token) -> bool:
    """A finite verb ("opens", "makes") after a clause that is a gerund and what it works: the gerund is the subject."""
    body = [t for t in current if t.text not in FILLERS]
    return (len(body) >= 3 and body[0] is current[0] and _ing(body[0]) and body[0].text != body[0].lemma and any(t.text in DETERMINERS for t in body[1:])
            and token.text.endswith("s") and token.text != token.lemma and (token.lemma in VERBS or token.lemma in TOLD_CAUSATIVES))


def _pause_at(tokens: list[Token], i: int) -> bool:
    """"(a) 4 second beat", "2 s pause" starts at ``i``."""
    i += i < len(tokens) and tokens[i].text in ("a", "an")
    return i + 2 < len(tokens) and tokens[i].number is not None and tokens[i + 1].lemma in ("second", "s", "sec", "minute") and (
        tokens[i + 2].text in PAUSE_NOUNS)


def split_clauses(tokens: list[Token]) -> list[Clause]:
    """The prompt's clauses in prompt order (``goes_first`` marks the ones to reorder)."""
    clauses: list[Clause] = []
    current: list[Token] = []
    link, marker, conjoined = Link.FIRST, "", False

    negated_here = False

    def close() -> None:
        nonlocal negated_here
        body = list(current)
        while body and body[0].is_punct:
            body.pop(0)
        while body and (body[-1].is_punct or body[-1].text in ("and", "or", "then")):
            body.pop()
        while body and body[0].text in FILLERS and not (len(body) > 1 and body[0].text == "first" and not verb_at(body, 1)
                                                        and body[1].lemma not in VERBS):
            body.pop(0)
        if body:
            first = Link.FIRST if link not in (Link.CONDITION, Link.NEGATED) else link
            here = Link.NEGATED if negated_here else (link if clauses else first)
            negated_here = False
            clauses.append(Clause(index=len(clauses), tokens=tuple(body), link=here, marker=marker,
                                  conjoined=conjoined))

    i = 0
    while i < len(tokens):
        token = tokens[i]
        word = token.text
        nxt = i + 1
        boundary: tuple[Link, str, bool] | None = None
        if token.is_sentence_end or word == ":":
            boundary = (Link.SEQUENCE, word, False)
        elif word in SEQUENCE and _subject_only(current) and nxt < len(tokens) and tokens[nxt].lemma in VERBS and (
                word == "then" or tokens[nxt].text != tokens[nxt].lemma):  # not "the key under it and then swing the door open"
            boundary = None  # "the door then unlocks": the sequence word sits between a subject and its verb
        elif word in SEQUENCE and (word != "next" or _starts_clause(tokens, nxt)):
            boundary = (Link.SEQUENCE, word, False)
        elif word in SIMULTANEOUS and not _starts_clause(tokens, nxt) and not (nxt < len(tokens) and _ing(tokens[nxt])):
            boundary = None  # "open both doors at the same time": how, not a second action
        elif word == "and" and current and nxt < len(tokens) and tokens[nxt].text in CENTRE_WORDS:
            boundary = (Link.SEQUENCE, word, True)  # "all the way to the left and back to centre"
        elif word == "," and current and _pause_at(tokens, nxt):
            boundary = (Link.SEQUENCE, word, True)  # "full open on the door, a 4-second beat, then back shut": a wait of its own
        elif word == "and" and current and current[0].text in DETERMINERS and not any(verb_at(current, k, strict=True) for k in range(len(current))) and any(
                t.text in ("are", "were") for t in tokens[nxt:nxt + 5]):
            boundary = None  # "the door and the drawer are both sitting open": one subject, two parts
        elif word == "and" and any(t.text == "between" for t in current[-4:]):
            boundary = None  # "until the angle between it and the keyboard is 45 degrees": one thing measured
        elif word == "as" and len(current) >= 2 and current[-2].text == "as":
            boundary = None  # "as wide as the hinge allows": a comparison, not a second event
        elif word in PARALLEL and (word != "as" or (_starts_clause(tokens, nxt) and not _as_whole(tokens, nxt)) or (nxt < len(tokens) and _ing(tokens[nxt]))) and current:
            boundary = (Link.PARALLEL, word, False)
        elif word in ("and", ",", "or") and current and _starts_clause(tokens, nxt) and not (_bare_verb(current) and not (
                link in (Link.NEGATED, Link.PURPOSE) and word == ",")) and not (
                word == "and" and link is Link.NEGATED and kind_at(tokens, nxt) is not None):  # "without the lid and latches"
            boundary = (Link.SEQUENCE, word, True)
        elif word in (",", "and") and current and (_elaboration(current) or _elaboration(_segment(tokens, nxt))) and nxt < len(tokens) and (
                tokens[nxt].text in DETERMINERS or tokens[nxt].text in SPATIAL):  # "bottom drawer out 40 cm and top drawer out 20 cm"
            boundary = (Link.SEQUENCE, word, True)  # "the top one a quarter turn, the bottom one half a turn": one part each
        elif word == "," and current and nxt + 1 < len(tokens) and kind_at(tokens, nxt) is not None and tokens[nxt + 1].text in _TOLD_ENDS and (
                current[-1].text in _TOLD_ENDS or (nxt + 2 < len(tokens) and tokens[nxt + 2].is_sentence_end)):  # "Door open, door shut.": step after step
            boundary = (Link.SEQUENCE, word, True)
        elif word == "but" and current and _starts_clause(tokens, nxt):
            boundary = (Link.SEQUENCE, word, True)  # "..., but leave the door open"
        elif word == "leaving" and not current and clauses and marker == "," and nxt < len(tokens) and tokens[nxt].text in ("it", "them", "the"):
            link, marker, conjoined = Link.RESULT, word, False  # "swing it almost shut, leaving it 10 degrees ajar": the end state
            i += 1
            continue
        elif link in (Link.PARALLEL, Link.CONDITION) and len(current) > 1 and _ing(current[-1]) and token.text == token.lemma and (
                token.lemma in VERBS and current[-1].text != current[-1].lemma):
            boundary = (Link.SEQUENCE, ",", True)  # "while it's opening | tip the handle back": the step that runs meanwhile
            nxt = i
        elif _told_after_gerund(current, token):
            boundary = (Link.RESULT, "", False)  # "pressing the pedal | opens the lid", "swinging the lever | makes the lid pop up"
            nxt = i
        elif word == "it's" and len(current) > 1 and verb_at(current, 0) and nxt < len(tokens) and tokens[nxt].text.endswith("ing") and (
                current[-1].text not in ("where", "what", "how", "when", "as", "that", "because", "since", "while", "from", "if")):
            boundary = (Link.SEQUENCE, word, True)  # "close the window it's raining": a run-on second sentence
            nxt = i
        elif word == "and" and _measure_at(current, 0) is not None and _measure_at(tokens, nxt) == nxt:
            boundary = (Link.SEQUENCE, word, True)  # "1 metre to the left and half a metre back": two moves
        elif word == "," and current and nxt < len(tokens) and tokens[nxt].text in _STAYS | _PAUSES | {"stay", "back", "wait"} and not (
                tokens[nxt].text == "back" and link is Link.NEGATED):
            boundary = (Link.SEQUENCE, word, True)  # "toilet lid up, stay 2.5 seconds, back down": one step after another
        elif word == "until" and current:
            boundary = (Link.RESULT, word, False)  # "raise it until it stands upright": the end state
        elif word in AFTER | BEFORE and (nxt < len(tokens) and (_ing(tokens[nxt]) or _starts_clause(tokens, nxt) or _someone_does(tuple(tokens[nxt:])))):
            boundary = (Link.SEQUENCE, word, False)
        elif marker in ("once", "when", "after") and len(current) >= 2 and current[-1].text in _DONE_STATES and (word == "," or (
                (verb_at(tokens, i) or tokens[i].lemma in LIGHT_VERBS or word == "do") and nxt < len(tokens) and tokens[nxt].text in ("the", "it", "its", "both", "them", "that")) or (
                word in ("you", "we") and nxt < len(tokens) and tokens[nxt].text in MODALS)):  # "once it's shut you can spin the wheel"
            boundary = (Link.SEQUENCE, ",", True)  # "once it's open(,) turn the tray", "when it gets there(,) do the right door"
            nxt = nxt if word == "," else (i + 2 if word in ("you", "we") else i)  # "once it's shut you can spin the wheel": spin the wheel
        elif word in ("the", "its") and link in (Link.PARALLEL, Link.CONDITION) and marker in ("while", "whilst", "as") and len(current) > 1 and (
                any(t.text.endswith("ing") for t in current[1:]) and _starts_clause(tokens, i)):
            boundary, nxt = (Link.SEQUENCE, ",", True), i  # "while it's still opening the plate starts turning": a comma left out
        elif word == "to" and any(not t.is_punct for t in current) and next(t for t in current if not t.is_punct).lemma in _CAUSING and nxt < len(tokens) and (
                verb_at(tokens, nxt, strict=True)):
            i += 1  # "make the safe door to open": make it open (the "to" of a learner's causative)
            continue
        elif word == "to" and current and current[-1].text in ASPECT_VERBS:
            boundary = None  # "the plate starts to turn": one verb, not a purpose
        elif word in PURPOSE and nxt < len(tokens) and (verb_at(tokens, nxt, strict=True) or _other_verb(tokens, nxt)) and current and not (
                len(current) > 1 and current[-2].text == "too") and current[-1].text != "not":  # "too low to grab": how low; "is not to move": a rule
            boundary = (Link.PURPOSE, word, False)
        elif word == "by" and nxt < len(tokens) and _ing(tokens[nxt]) and current:
            boundary = (Link.MEANS, word, False)
        elif word in ("so", "so_that", "which", *_THEREFORE) and current and (
                _starts_clause(tokens, nxt) or (nxt < len(tokens) and (tokens[nxt].lemma in VERBS or tokens[nxt].lemma in TOLD_CAUSATIVES))
                or word in _THEREFORE):
            boundary = (Link.RESULT, word, False)
        elif ((word in NEGATIONS and word not in ("without", "except", "but")) or (word in ("do", "does") and [t.text for t in tokens[nxt:nxt + 1]] == ["not"])) and current and _subject_only(current):
            negated_here = True  # "the wheels cannot roll", "they do not turn": this clause says what does not happen
            current.append(token)
            i += 1
            continue
        elif word in NEGATIONS and word not in ("but",) and current and not (i > 0 and tokens[i - 1].text in ("do", "does")):
            boundary = (Link.NEGATED, word, False)
        elif word in ("do", "does") and nxt < len(tokens) and tokens[nxt].text == "not":
            boundary = (Link.NEGATED, "not", False)
            nxt += 1
        elif word in ("don't", "dont", "never", "cannot", "can't", "without", "not") and not current:  # "... ? Not the drip tray."
            boundary = (Link.NEGATED, word, False)
        if boundary is None:
            current.append(token)
            i += 1
            continue
        count = len(clauses)
        close()
        if word == ":" and len(clauses) > count and not (clauses[-1].marker in ("then", "and_then", "and", "after_that", "finally") and any(
                t.lemma in VERBS and kind_of_word(t.text) is None for t in clauses[-1].tokens)):
            clauses[-1] = replace(clauses[-1], heading=True)  # not "..., then slams shut again: that's the jump scare"
        current = []
        link, marker, conjoined = boundary
        if word in ("while", "whilst", "as", "once", "when", "after") and _condition(tokens, nxt):
            link = Link.CONDITION
        i = nxt
    close()
    return _order(clauses)


_DONE_STATES = frozenset({"open", "opened", "closed", "shut", "up", "down", "out", "in", "done", "there", "finished", "over", "clear"})


def _measure_at(tokens: list[Token], start: int) -> int | None:
    """Where the first amount with a unit at or after ``start`` begins ("1 metre", "half a metre", "30 degrees")."""
    for i in range(start, len(tokens)):
        if tokens[i].number is None and tokens[i].text not in ("half", "a", "an", "a_quarter", "quarter"):
            continue
        unit = next((t for t in tokens[i + 1:i + 4] if t.number is None and t.text not in ("a", "an", "of")), None)
        metres = unit is not None and unit.text == "m" and tokens[i].number is not None and tokens[i + 1] is unit  # "0.1 m"
        if unit is not None and (unit.lemma in LENGTH_UNITS or unit.lemma in ANGLE_UNITS) and (unit.text not in ("in", "m") or metres):
            return i
    return None


def _subject_only(tokens: list[Token]) -> bool:
    """Only a noun phrase so far ("the door | then unlocks"; not "the one under it, | and after that swing ...")."""
    body = [t for t in tokens if not t.is_punct]
    return bool(body) and not tokens[-1].is_punct and body[0].text in DETERMINERS and not any(verb_at(body, i) for i in range(len(body)))


def _bare_verb(tokens: list[Token]) -> bool:
    """Only a verb so far ("press | and hold the button"): the verbs share what follows."""
    body = [t for t in tokens if t.text not in FILLERS]
    return len(body) == 1 and verb_at(body, 0)


_WHOLE = (("a", "whole"), ("one", "piece"), ("one", "unit"), ("a", "unit"))


def _as_whole(tokens: list[Token], i: int) -> bool:
    """"the bin as a whole is pushed": how much of the object moves, not a second clause."""
    return tuple(t.text for t in tokens[i:i + 2]) in _WHOLE


def _condition(tokens: list[Token], i: int) -> bool:
    """"while the door is open": a state, not a second action."""
    for k, token in enumerate(tokens[i:i + 8]):
        if token.is_punct:
            return False
        if token.text in AUX or token.text in ("it's", "they're"):  # "when it's fully open"
            after = tokens[i + k + 1:i + k + 3]
            return not any(t.text.endswith("ing") and t.lemma in VERBS for t in after)  # "while it is opening": at the same time
    return False


_DOERS = frozenset({"you", "we", "i", "you've", "we've", "i've", "someone", "somebody"})


def _someone_does(tokens: tuple[Token, ...]) -> bool:
    """"(after) you spin the handle", "(once) you've turned it": a person's action, told like a gerund."""
    if len(tokens) < 2 or tokens[0].text not in _DOERS:
        return False
    if any(verb_at(list(tokens), k, strict=True) for k in (1, 2) if k < len(tokens)):
        return True
    k = 2 if tokens[1].text == "have" else 1 if tokens[0].text.endswith("'ve") else 0
    return 0 < k < len(tokens) and verb_at(list(tokens), k)  # "after you've pulled out ...", "after you have closed ..."


def _order(clauses: list[Clause]) -> list[Clause]:
    """Mark clauses that run before the clause they follow in the text: "B after A-ing", "B once you A" and
    "before B, A" put A first."""
    out: list[Clause] = []
    for clause in clauses:
        first = clause.tokens[0] if clause.tokens else None
        gerund = first is not None and (_ing(first) or verb_at(list(clause.tokens), 0, strict=True) or _someone_does(clause.tokens))
        previous = clauses[clause.index - 1] if clause.index > 0 else None
        following = clauses[clause.index + 1] if clause.index + 1 < len(clauses) else None
        fronted = following is not None and following.conjoined and following.marker == ","  # "A, and after holding it 4 s, close it"
        after_gerund = clause.marker in AFTER and gerund and previous is not None and previous.marker not in AFTER and not fronted
        after_before = clause.index == 1 and previous is not None and previous.marker in BEFORE and previous.link is not Link.CONDITION
        if (after_gerund or after_before) and clause.link is not Link.CONDITION:
            clause = Clause(clause.index, clause.tokens, clause.link, goes_first=True, marker=clause.marker, conjoined=clause.conjoined)
        out.append(clause)
    return out
