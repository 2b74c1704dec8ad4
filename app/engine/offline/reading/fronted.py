"""What is said first and pointed back to. Amounts: "About halfway - that's how far I want the drawer slid open", "45
degrees - tilt the window open to that", "Half a turn on the browning dial, please - twist it". Purposes: "To open the
dishwasher door, press the release button", "I want the door to drop open - press the release button so that it does".
The words are rewritten in the plain order the clause splitter reads ("I want the drawer slid open about halfway", "tilt
the window open to 45 degrees", "twist the browning dial half a turn", "press the release button to open the dishwasher
door", "press the release button to make the door drop open"); sentences of any other shape are left as they are."""

from __future__ import annotations

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import AMOUNTS, DETERMINERS, OBJECT_NOUNS, SPATIAL, WISHES
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.word_class import can_be_verb, lemma_of

_BREAKS = frozenset({",", ":"})
_HOW = frozenset({"far", "high", "much", "wide", "long", "low"})
_BACK = frozenset({"that", "this"})
"""The word that points back to the amount ("to that", "by about that")."""
_HEDGES = frozenset({"about", "roughly", "around", "approximately"})
_ON = frozenset({"on", "for", "to"})
_IT = frozenset({"it", "that", "this"})
_STEP_JOINS = frozenset({",", "and", "then", "and_then", "once", "after", "before", "when", "while"})
_POINTED_BACK = (("to", "make", "that", "happen"), ("to", "make", "it", "happen"), ("so_that", "it", "does"), ("so", "it", "does"),
                 ("so_that", "happens"), ("to", "do", "that"))
"""A purpose that only points back to the wish before ("... press the button to make that happen")."""


_OPENS_AMOUNT = frozenset({"a", "an", "one", "half", "about", "roughly", "around", "approximately", "exactly", "another", "just"})


def _amount(words: list[Token]) -> bool:
    """A measure said first: a number, or an amount word ("halfway", "half a turn", "all the way"), from the first word on."""
    return bool(words) and (words[0].number is not None or words[0].text in AMOUNTS or words[0].text in _OPENS_AMOUNT) and any(
        t.number is not None or t.text in AMOUNTS for t in words) and all(not t.is_punct for t in words)


def _sentences(tokens: list[Token]) -> list[tuple[int, int]]:
    out, start = [], 0
    for k, token in enumerate(tokens):
        if token.is_sentence_end:
            out.append((start, k))
            start = k + 1
    if start < len(tokens):
        out.append((start, len(tokens)))
    return out


def _rewritten(sentence: list[Token]) -> list[Token] | None:
    split = next((k for k, t in enumerate(sentence) if t.text in _BREAKS), None)
    if split is None or split == 0:
        return None
    head = sentence[:split]
    rest = sentence[split:]
    while rest and (rest[0].text in _BREAKS or rest[0].text in ("just", "then", "now")):
        rest = rest[1:]  # "one full revolution on the turntable, just spin it"
    if not rest:
        return None
    on = next((k for k, t in enumerate(head) if t.text in _ON), None)
    amount, place = (head[:on], head[on + 1:]) if on is not None else (head, [])
    if not _amount(amount):
        return None
    words = [t.text for t in rest]
    told = next((k for k in range(len(words) - 2) if words[k:k + 2] == ["that's", "how"] and words[k + 2] in _HOW and (
        k == 0 or rest[k - 1].text in _BREAKS)), None)
    if not place and told is not None:
        # "that's how far I want the drawer slid open": ... slid open about halfway ("30 cm - a foot - off the rim: that's
        # how high ...": the first measure; what restates it is dropped)
        return [*rest[told + 3:], *amount]
    if not place and (back := next((k for k in range(len(rest) - 1, 0, -1) if words[k] in _BACK), None)) is not None and (
            words[back - 1] in _HEDGES or words[back - 1] in ("to", "by")):
        start = back - 1 if words[back - 1] in _HEDGES else back  # "up to about that": up to roughly 90 degrees
        return [*rest[:start], *amount, *rest[back + 1:]]
    if place and len(rest) > 1 and words[1] in _IT and (len(rest) == 2 or rest[2].is_punct or words[2] in ("and", "then")):
        return [rest[0], *place, *amount, *rest[2:]]  # "half a turn on the browning dial - twist it": twist the dial half a turn
    return None


def _amount_is_where(sentence: list[Token]) -> list[Token] | None:
    """"90 degrees is where I want the screen", "15 cm up is where the lid should go": I want the screen at 90 degrees,
    the lid should go 15 cm up."""
    words = [t.text for t in sentence]
    at = next((k for k in range(1, min(len(words) - 2, 6)) if words[k:k + 2] == ["is", "where"]), None)
    if at is None or not _amount(sentence[:at]):
        return None
    rest = sentence[at + 2:]
    end = next((k for k, t in enumerate(rest) if t.text in (";", ",", "-")), len(rest))
    angle = any(t.lemma in ("degree", "degrees") or t.text in ("degrees", "degree", "°") for t in sentence[:at])
    lead = [Token("at", "at", sentence[at].start, sentence[at].end)] if angle and not any(t.text in ("up", "down", "out", "open") for t in sentence[:at]) else []
    return [*rest[:end], *lead, *sentence[:at], *rest[end:]]


def _purpose_first(sentence: list[Token]) -> list[Token] | None:
    """"To open the door, press the button": press the button to open the door."""
    if len(sentence) < 4 or sentence[0].text != "to" or not can_be_verb(sentence[1].text):
        return None
    comma = next((k for k, t in enumerate(sentence) if t.text == ","), None)
    if comma is None or comma + 1 >= len(sentence) or not can_be_verb(sentence[comma + 1].text):
        return None
    if any(t.text in ("it", "them", "that", "one", "ones") for t in sentence[comma + 1:]) or any(
            t.text in _STEP_JOINS for t in sentence[comma + 1:]) or any(t.text in ("it", "them") for t in sentence[:comma]):
        return None  # "To get at the top rack, pull it out 20 cm": "it" is the rack the purpose names; "To unlock it, punch
        # in ..., and once that's done pull the door open": the purpose of more than one step
    return [*sentence[comma + 1:], *sentence[:comma]]


def _wish_then_means(sentence: list[Token]) -> list[Token] | None:
    """"I want the door to drop open, press the release button so that it does", "the door needs to unlatch and swing
    open, so press the release button": press the release button to make the door drop open."""
    words = tuple(t.text for t in sentence)
    back = next((len(words) - len(tail) for tail in _POINTED_BACK if words[-len(tail):] == tail), None)
    needs = next((k for k in range(1, min(len(words) - 1, 6)) if words[k] in ("needs", "need") and words[k + 1] == "to"), None)
    if not words or (words[0] not in WISHES and (needs is None or not all(w in DETERMINERS or kind_of_word(w) is not None or w in OBJECT_NOUNS
                                                                            or w == "'s" for w in words[:needs]))):
        return None
    comma = next((k for k in range(2, len(words)) if words[k] == ","), None)
    so = comma is not None and comma + 1 < len(words) and words[comma + 1] in ("so", "then", "just")
    if back is None and not so:
        return None
    back = back if back is not None else len(words)
    to = needs + 1 if needs is not None else next((k for k in range(2, back) if words[k] == "to"), None)
    subject = sentence[:needs] if needs is not None else sentence[1:to] if to is not None else []
    if to is None or comma is None or comma < to + 2 or comma + 1 + so >= back or sentence[comma + 1 + so].lemma not in VERBS or not subject:
        return None
    if subject[0].text not in DETERMINERS:
        subject = [Token("the", "the", subject[0].start, subject[0].start), *subject]  # "door needs to ...": the door
    wanted = sentence[to + 1:comma]
    joined = max((k for k, t in enumerate(wanted) if t.text == "and"), default=None)
    wanted = wanted[joined + 1:] if joined is not None else wanted  # "to unlatch and swing down open": where it ends
    return [*sentence[comma + 1 + so:back], sentence[to], Token("make", "make", sentence[to].start, sentence[to].end), *subject, *wanted]


def _place_first(sentence: list[Token]) -> list[Token] | None:
    """"On the washing machine (,) rotate the knob furthest left": the object said first only sets the scene. "On the
    left-hand fridge, open the right door": one of the object's units said first is a heading ("left-hand fridge: ...")."""
    comma = next((k for k, t in enumerate(sentence[:10]) if t.text == ","), None)
    if comma is not None and len(sentence) > comma + 2 and sentence[0].text in ("in", "on", "among", "across", "along") and (
            sentence[1].text in DETERMINERS and sentence[2].text in _GROUP_WORDS and sentence[3].text == "of"):
        return sentence[comma + 1:]  # "In the column of four drawers, open the second one from the top": how they stand, no step
    if len(sentence) < 4 or sentence[0].text not in ("on", "for", "with") or sentence[1].text not in DETERMINERS:
        return None
    comma = next((k for k, t in enumerate(sentence[:7]) if t.text == ","), None)
    if comma is not None and any(t.text in SPATIAL or t.text.split("-")[0] in SPATIAL for t in sentence[2:comma]) and any(
            t.lemma in OBJECT_NOUNS or t.text in OBJECT_NOUNS for t in sentence[2:comma]):  # "For the microwave on the right, .."
        return [*sentence[2:comma], Token(":", ":", sentence[comma].start, sentence[comma].end), *sentence[comma + 1:]]
    verb = next((k for k in range(2, len(sentence) - 1) if sentence[k].lemma in VERBS and sentence[k].text not in OBJECT_NOUNS and (
        sentence[k + 1].text not in OBJECT_NOUNS)), None)  # not "washing" in "the washing machine"
    if verb is None or sentence[verb - 1].text in DETERMINERS or not any(t.text in OBJECT_NOUNS for t in sentence[2:verb]) or not all(
            t.text in OBJECT_NOUNS or t.text in DETERMINERS or t.text == "," or sentence[k + 1].text in OBJECT_NOUNS for k, t in enumerate(
                sentence[2:verb], start=2)):
        return None
    return sentence[verb:]


_EMPTY_TAILS = (("make", "it", "happen"), ("make", "that", "happen"), ("make", "this", "happen"), ("do", "it"), ("do", "that"),
                ("handle", "it"), ("sort", "it"), ("sort", "it", "out"), ("get", "it", "done"), ("get", "that", "done"), ("set", "it", "like_that"),
                ("make", "it", "like_that"), ("put", "it", "like_that"), ("get", "it", "like_that"), ("set", "it", "that_way"), ("make", "it", "that_way"),
                ("make", "it", "so"), ("set", "it", "to", "that"), ("put", "it", "there"), ("set", "it", "there"),
                *((verb, "the", made) for verb in ("generate", "create", "make", "render", "produce", "animate", "show")
                  for made in ("motion", "animation", "movement", "trajectory", "clip")))
"""A last clause that only asks for what was said before it ("I want some toast, make it happen")."""


_GROUP_WORDS = frozenset({"column", "row", "stack", "set", "bank", "line", "pair", "group", "tower"})
_ORDERS = frozenset({"left_to_right", "right_to_left", "top_to_bottom", "bottom_to_top", "one_by_one", "one_after_another",
                     "one_after_the_other", "one_at_a_time", "in_turn"})
_ORDER_LEADS = frozenset({"going", "working", "moving", "from", "and", "in", "order", "work", "go", "move", "your", "way", "along", "across", "the",
                          "row", "line", "of", "down", "up", "them", "each", "every"})


def _order_first(sentence: list[Token]) -> list[Token] | None:
    """"Going from left to right, open the four drawers one by one": the order said first goes after the step."""
    comma = next((k for k, t in enumerate(sentence[:14]) if t.text == ","), None)
    if comma is None or comma + 2 >= len(sentence) or not any(t.text in _ORDERS for t in sentence[:comma]) or not all(
            t.text in _ORDERS or t.text in _ORDER_LEADS or lemma_of(t.text)[0] in OBJECT_NOUNS for t in sentence[:comma]):  # "Work your way along the row of fridges from right to left, ..."
        return None
    return [*sentence[comma + 1:], *(t for t in sentence[:comma] if t.text in _ORDERS)]


_FROM_END = {"top": "top_to_bottom", "bottom": "bottom_to_top", "left": "left_to_right", "right": "right_to_left", "leftmost": "left_to_right",
             "rightmost": "right_to_left", "topmost": "top_to_bottom", "bottommost": "bottom_to_top", "lowest": "bottom_to_top",
             "highest": "top_to_bottom", "uppermost": "top_to_bottom"}
_START_WORDS = frozenset({"starting", "beginning", "start", "begin"})
_ORDER_FILLERS = frozenset({"at", "with", "from", "the", "one", "very", "and", "working", "going", "moving", "your", "way", "down", "up",
                            "across", "along", "to", "over", "then", "on", "side", "end", "drawer", "door", "switch", "lever", "knob",
                            "to_the_bottom", "to_the_top", "to_the_left", "to_the_right", "to_the_end"})


def _order_after(sentence: list[Token]) -> list[Token] | None:
    """"Open all six drawers one at a time, starting at the top and working down to the bottom": the end said to start
    from is the order ("top_to_bottom")."""
    at = next((k for k in range(1, len(sentence) - 2) if sentence[k].text == "," and sentence[k + 1].text in _START_WORDS), None)
    if at is None or not all(t.text in _ORDER_FILLERS or t.text in _FROM_END or t.text in _START_WORDS for t in sentence[at + 1:]):
        return None
    first = next((t for t in sentence[at + 1:] if t.text in _FROM_END), None)
    if first is None:
        return None
    return [*sentence[:at], Token(_FROM_END[first.text], _FROM_END[first.text], first.start, first.end)]


def _empty_tail(sentence: list[Token]) -> list[Token] | None:
    words = tuple(t.text for t in sentence)
    tail = next((tail for tail in _EMPTY_TAILS if words[-len(tail):] == tail), None)
    if tail is None or len(words) <= len(tail) + 2 or words[-len(tail) - 1] not in (",", "and", "so", "-", ";"):
        return None
    return sentence[:-len(tail) - 1]


def _duration_first(sentence: list[Token]) -> list[Token] | None:
    """"For four seconds I want the suitcase open, so open it up and keep it that way": ... keep it that way for 4 seconds."""
    if len(sentence) < 5 or sentence[0].text != "for" or sentence[1].number is None or sentence[2].text not in ("seconds", "second", "s", "secs"):
        return None
    rest = sentence[3:]
    while rest and rest[0].text in _BREAKS:
        rest = rest[1:]
    return [*rest, *sentence[:3]] if rest else None


def _asked_of_you(sentence: list[Token]) -> list[Token] | None:
    """"I'd like you to tap the centre button": tap the centre button."""
    words = [t.text for t in sentence[:3]]
    return sentence[3:] if len(sentence) > 3 and words[0] in WISHES and words[1] in ("you", "u") and words[2] == "to" else None


_PLACE_HEADS = frozenset({"row", "column", "level", "tier", "section", "half", "corner", "side", "end", "stack", "bank"})


def _place_heading(sentence: list[Token]) -> list[Token] | None:
    """"bottom row, left-hand drawer, all the way out": the place said first as a heading says where the part is (the
    bottom left-hand drawer, all the way out)."""
    comma = next((k for k, t in enumerate(sentence[:5]) if t.text in _BREAKS), None)
    if comma is None or comma < 2 or sentence[comma - 1].text not in _PLACE_HEADS:
        return None
    place = [t for t in sentence[:comma - 1] if t.text not in DETERMINERS]
    if not place or not all(t.text in SPATIAL or t.text.split("-")[0] in SPATIAL for t in place):
        return None
    end = next((k for k in range(comma + 1, len(sentence)) if sentence[k].text in _BREAKS), len(sentence))
    part = sentence[comma + 1:end]
    if not 1 <= len(part) <= 6 or all(kind_of_word(t.text) is None for t in part) or any(t.lemma in VERBS and kind_of_word(t.text) is None for t in part):
        return None
    said = 1 if part[0].text in DETERMINERS else 0
    return [*part[:said], *place, *part[said:], *sentence[end:]]


def fronted(tokens: list[Token]) -> list[Token]:
    """``tokens`` with each sentence that says its amount or purpose first rewritten in the plain order (see the module
    docstring)."""
    out: list[Token] = []
    for start, end in _sentences(tokens):
        sentence = tokens[start:end]
        if out and tuple(t.text for t in sentence if t.text not in ("please", "just", "now", "then")) in _EMPTY_TAILS:
            continue  # "90 degrees is where I want the screen; set it to that.": the sentence before says it
        out += (_rewritten(sentence) or _amount_is_where(sentence) or _purpose_first(sentence) or _wish_then_means(sentence) or _place_first(sentence) or _order_first(sentence) or _order_after(sentence) or _empty_tail(sentence) or _asked_of_you(sentence) or _duration_first(sentence) or _place_heading(sentence)
                or sentence)
        out += tokens[end:end + 1]
    return out
