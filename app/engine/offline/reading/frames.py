"""Stage 3 — frames: one :class:`Frame` per clause — verb sense, theme, instrument, end state, amount, manner, order,
negation, holds and waits. A frame says what the clause asks in the lexicon's terms; it does not know the asset. The verb's
sense may still depend on what it acts on ("push" a button presses it, a drawer closes it, the cart moves it): grounding
refines it with the theme's kind."""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.verbs import (
    GENERIC,
    PARTICLES,
    STATE_PARTICLES,
    VERBS,
    WISHED_SENSES,
    VerbSense,
    ends_after_back,
)
from app.engine.lexicon.words import (
    ASPECT_VERBS,
    BRIEF_VERBS,
    BRIEF_WORDS,
    CAUSATIVES,
    CAUSER_NOUNS,
    CENTRE_WORDS,
    DETERMINERS,
    FUNCTION_VERBS,
    INSTRUMENT,
    OBJECT_NOUNS,
    PLACES,
    SAME_WAY,
    SIMULTANEOUS,
    SPATIAL,
    STATIVE_VERBS,
    TOLD_CAUSATIVES,
)
from app.engine.offline.reading.clauses import Clause, Link, verb_at
from app.engine.offline.reading.codes import code_items
from app.engine.offline.reading.first_one import first_of
from app.engine.offline.reading.held_for import held_for
from app.engine.offline.reading.how_it_is import does_to_a_thing, how_it_is, told_state_words, told_way
from app.engine.offline.reading.light_verbs import light_verb
from app.engine.offline.reading.mentions import Mention, parse_mentions
from app.engine.offline.reading.numbers import Unit, said_unit
from app.engine.offline.reading.part_words import kind_of_word, shape_adjective
from app.engine.offline.reading.quantities import Quantities, read_quantities
from app.engine.offline.reading.said_again import ends_the_same
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.verb_cues import aside, letting_go, side_of_part, unknown_verb
from app.engine.offline.reading.verb_cues import intransitive as after_subject
from app.engine.offline.reading.wishes import wished_state
from app.engine.offline.reading.word_class import actor_verb, finite_unknown_verb

_END_PARTICLES = frozenset({"shut", "closed", "open", "into_place"})  # "the latch clicks closed": there to stay, not a tap
_BODY_PARTS = frozenset({"foot", "feet", "finger", "fingers", "hand", "hands", "thumb", "toe", "weight"})
_LETTING_GO = frozenset({"take", "lift", "remove", "move", "pull", "raise", "get", "let"})
_RETURN_WORDS = frozenset({"original", "starting", "initial", "previous", "former", "rest", "resting", "neutral", "home", "where_it_started",
                           "the_way_it_was_before", "the_way_it_was", "as_it_was_before", "as_it_was", "as_before", "how_it_was", "how_it_was_before",
                           "how_they_were", "like_it_was_before", "like_it_was", "like_they_were", "where_it_was", "where_it_began", "where_they_started", "where_they_were", "where_you_started"})
_RETURN_ADJECTIVES = frozenset({"original", "starting", "initial", "previous", "former"})
_POSSESSIVE_DETS = frozenset({"its", "the", "their", "his", "her", "your", "my", "to", "at", "in", "from"})
_HAVING = frozenset({"has", "have", "had", "there's", "there_is", "there_are"})
_MANUAL = frozenset({"manually", "by_hand"})
_PLACEHOLDERS = frozenset({"something", "anything", "stuff", "thing", "things", "item", "items"})
_CONTAINERS = frozenset({"keypad", "key pad", "number pad", "panel", "control panel", "console"})
_REFERENCE_PREPS = frozenset({"out_of", "off", "from", "onto", "into", "against", "over", "past", "toward", "towards", "across", "along", "behind", "under", "beneath", "below", "above", "beside", "next_to", "in_front_of", "on_top_of", "around", "away", "clear", "near"})
_REGION_WORDS = frozenset({"top", "bottom", "side", "front", "back", "middle", "edge", "corner", "centre", "center", "rear", "left", "right"})
_INSTRUMENT_PREPS = INSTRUMENT | frozenset({"by", "on", "holding", "gripping"})


@dataclass(frozen=True)
class Frame:
    clause: int
    text: str
    verb: str | None
    """Lemma of the clause's main verb."""
    sense: VerbSense | None
    """The verb's sense after its particle (before the theme refines it)."""
    particle: str | None = None
    themes: tuple[Mention, ...] = ()
    instruments: tuple[Mention, ...] = ()
    subject_theme: bool = False
    """The subject is what moves ("the lid opens", "the door is open")."""
    quantities: Quantities = field(default_factory=Quantities)
    returning: bool = False
    """Back to where it was ("push it back", "to its original position")."""
    hold: bool = False
    """Kept in its end state ("press and hold", "keep it pressed for 2 s")."""
    let: bool = False
    """The user lets it move on its own ("let the lid drop", "let go of the pedal")."""
    link: Link = Link.FIRST
    goes_first: bool = False
    conjoined: bool = False
    marker: str = ""
    heading: bool = False
    simultaneous: bool = False
    manual: bool = False
    stative: bool = False  # describes a state ("the door is open"), not a motion
    aside: bool = False  # said about the user or the story, not the asset ("so I can put my plate in", "so they can air-dry")
    same_direction: bool = False
    """"another 40 degrees in the same direction": the direction of the clause before."""
    guessed_verb: str | None = None
    """A verb we do not know, read from its particle ("fling it back": open)."""
    extra_verbs: tuple[str, ...] = ()
    codes: tuple[tuple[str, ...], ...] = ()
    """Keys of a code, in order: ("digit", "4") or ("place", "top", "left") ("enter 1-2-3", "type top-left, bottom-middle")."""
    first: Mention | None = None
    """"open both doors, left one first": which of the themes goes first."""
    brief: bool = False
    """A brief press ("tap", "briefly", "a quick press"): a control that would hold is let go at once."""
    same: bool = False
    """"do the same (with the other one)", "the same amount": the previous act's verb and amount."""
    in_turn: str | None = None
    """"one by one", "left to right": the themes move one after another, in this order."""
    wish: bool = False
    """"I need the rack out": the clause names the end state wanted (its state word gives the sense)."""
    explicit_return: bool = False
    correction: bool = False
    """"... no wait, make it 45": the clause replaces the amount of the act before (it moves nothing of its own)."""
    """Said in words ("to where it was", "its original angle"), not only a "back" particle."""


_STATE_WORDS = frozenset({"open", "closed", "shut", "up", "down", "on", "off", "out", "in"})


def _find_verb(tokens: list[Token]) -> int | None:
    for i in range(len(tokens)):
        if tokens[i].text in CAUSATIVES and (i == 0 or (i == 1 and tokens[0].text in ("first", "then", "now", "just", "next", "finally"))):
            return i
        if i > 0 and tokens[i - 1].text in ("is", "are", "was", "were", "be", "stays", "remains", "from", "since") and tokens[i].text in _STATE_WORDS:
            continue  # "the door is open", "100 degrees from closed": a state, not a verb
        if verb_at(tokens, i, strict=True):
            return i
    for i in range(1, len(tokens)):
        token = tokens[i]
        if tokens[i - 1].text in ("from", "since"):
            continue  # "100 degrees from closed": where it is counted from
        progressive = token.text.endswith("ing") and tokens[i - 1].text in ("is", "are", "was", "were", *ASPECT_VERBS)
        if token.lemma in VERBS and token.text != token.lemma and verb_at(tokens, i) and (not token.text.endswith("ing") or progressive):
            return i  # "the lid opens", "the door swings open", "the plate starts turning" (not "its vent setting")
        if i > 1 and token.lemma in VERBS and tokens[i - 1].text == "to" and tokens[i - 2].text in ASPECT_VERBS:
            return i  # "the plate begins to turn"
    return None


def _particle(tokens: list[Token], verb: int, mentions: list[Mention]) -> tuple[str | None, int | None]:
    inside = {i for m in mentions for i in range(m.start, m.end)} | told_state_words(tokens, {m.end for m in mentions})  # not "that's flopped forward"
    reach = verb + 9 + sum(verb < i < verb + 9 for i in inside)  # a long part name does not use up the words after it
    for i in range(verb + 1, min(len(tokens), reach)):
        word = tokens[i].text
        if i in inside or (i >= verb + 9 and not any(m.end == i for m in mentions)):
            continue  # past the usual reach only right after a long part name ("snap the clasp on the front of the chest shut")
        if (word in ("down", "up") and any((m.ordinal is not None or (tokens[i + 1:i + 2] and tokens[i + 1].text in ("by", "near", "at") and (
                m.anaphor or (tokens[i + 2:i + 3] and tokens[i + 2].text == "the")))) and m.end == i for m in mentions)) or shape_adjective(tokens, i):
            continue  # "the third drawer down": how it is counted, not where it goes; "the one down by the base": where it is
        own = VERBS.get(tokens[verb].lemma)
        if word == "back" and [t.text for t in tokens[i + 1:i + 3]] == ["down", "on"] and own is not None and "down" in own.particles:
            return "down", i + 1  # "set it back down on the pot": resting on it (its closed end), not where it was (``back_before``)
        if word == "back" and i + 1 < len(tokens) and ends_after_back(own, tokens[i + 1].text):
            return tokens[i + 1].text, i + 1  # "shove it back in": the end state (the return is said too); "spring back up" keeps "back"
        if word == "back" and i > 0 and (tokens[i - 1].text in ("the", "its", "toward", "towards") or (
                tokens[i - 1].text == "all_the_way" and own is not None and (own.lemma == "open" or own.sense is VerbSense.RECLINE))):
            continue  # "toward the back", "along its back": a place; "open the lid all the way back": how far it opens
        if word in ("wide_open", "all_the_way_open") and own is not None and "open" in own.particles:
            return "open", i  # "push the window wide open": the end it opens to
        if word == "out_of" and (i + 1 == len(tokens) or tokens[i + 1].text in ("there", "here", "it", "them") or tokens[i + 1].is_punct):
            return "out", i  # "get it out of there": out, from wherever it is
        if word in ("up", "down") and [t.text for t in tokens[i + 1:i + 3]] == ["and", "over"]:
            return "over", i + 2  # "swing the handle up and over": over is where it ends ("over the top of ...": the way it goes)
        if word in PARTICLES:
            if word == "back" and i + 1 < len(tokens) and tokens[i + 1].text not in ("to", "in", "down", "up", "out", "into", "on") and tokens[i + 1].text not in DETERMINERS and not tokens[i + 1].is_punct and tokens[i + 1].number is None:
                continue
            if word in ("in", "over") and i + 1 < len(tokens) and (tokens[i + 1].text in DETERMINERS or tokens[i + 1].number is not None):
                continue  # "in the top row", "in 2 seconds", "over the top of the bucket"
            info = VERBS.get(tokens[verb].lemma)
            adjacent = i == verb + 1 and info is not None and word in info.particles
            if word == "on" and not adjacent and i + 1 < len(tokens) and (tokens[i + 1].text in DETERMINERS or tokens[i + 1].text in OBJECT_NOUNS):
                continue  # "push the bin on its wheels", "turn the knob furthest left on washer ..."
            if word == "off" and i + 1 < len(tokens) and tokens[i + 1].text in DETERMINERS:
                place = next((t for t in tokens[i + 1:i + 4] if t.text not in DETERMINERS), None)
                if place is not None and place.lemma in PLACES:
                    continue  # "lift the pot off the stove": where from, not a particle
                return "off", i  # "take the lid off the box"
            return word, i
        if word in ("backward", "backwards") and own is not None and "back" in own.particles and own.motion == "hinge":
            return "back", i  # "fold the screen backwards": a hinge verb's "back"
        if word in ("to", "by", "so", "and", "then", "while", "until") and i > verb + 1:
            break
    return None, None


_FURTHER = frozenset({"further", "farther", "more"})
"""Before "back": a direction ("5 cm further back"), not a return."""
_SWITCHED = frozenset({"on", "off"})


def _sense(verb: str | None, particle: str | None, themes: list[Mention] | None = None) -> VerbSense | None:
    if verb is None:
        return None
    info = GENERIC if verb == GENERIC.lemma else VERBS[verb]
    if particle in ("up", "down") and themes and all(m.kind is PartKind.LATCH for m in themes) and info.sense is VerbSense.TOGGLE:
        return VerbSense.RAISE if particle == "up" else VerbSense.LOWER  # "flip up the clasp": where it goes, not unlatched
    if particle is not None and particle in info.particles:  # not "turn the turntable round half a turn": a part turns, the object yaws
        return info.sense if info.particles[particle] is VerbSense.YAW and themes and all(m.kind is not None for m in themes) else info.particles[particle]
    if particle in STATE_PARTICLES and info.sense not in (VerbSense.HOLD, VerbSense.WAIT, VerbSense.RETURN, VerbSense.GRASP, VerbSense.OPEN,
                                                          VerbSense.CLOSE, VerbSense.RECLINE):
        return GENERIC.particles[particle]  # "shove the drawer shut", "nudge the lid open": the particle names the end state
    return info.sense


def _split_roles(tokens: list[Token], mentions: list[Mention], prior: list[Mention]) -> tuple[list[Mention], list[Mention]]:
    """(themes, instruments): a phrase after "with", "using", "by its", "on its" is how, not what;
    an object named after a reference preposition ("out of the oven") is where. ``prior``: a subject
    already named ("the lid is lifted 20 cm off the jar")."""
    themes: list[Mention] = list(prior)
    instruments: list[Mention] = []
    for mention in mentions:
        if mention.end < len(tokens) and tokens[mention.end].text in ("and_all", "included", "attached", "too") and (
                themes or tokens[mention.end].text != "too"):
            continue  # "lift the pot, lid and all": what comes along, not what moves ("..., then the back lever too": the next)
        before = mention.start - 1
        while before >= 0 and tokens[before].text in DETERMINERS:
            before -= 1
        preposition = tokens[before].text if before >= 0 else ""
        if mention.is_object and themes and preposition in _INSTRUMENT_PREPS | _REFERENCE_PREPS:
            continue  # "rotate the box on the table": where, not what
        if mention.kind is PartKind.BODY and preposition in ("in", "into", "against", "onto", "on", "inside", "to") and (themes or preposition != "on"):
            continue  # "so it sits flush in its frame": where it ends, the body does not move
        if preposition == "of" and themes and before > 0 and tokens[before - 1].text in _REGION_WORDS:
            continue  # "the small dial near the top of the door": where the dial is
        if preposition in ("for", "like", "than") and mention.kind is None and not mention.pronoun and not mention.anaphor:
            continue  # "swing the handle left for hot water": why, not what ("do the same for the other one" names a part)
        if {t.text for t in tokens[max(0, mention.start - 3):mention.start]} & {"on", "onto"} and themes and mention.kind is None and (
                not mention.pronoun and not mention.possessive and not mention.is_object):
            continue  # "lay the handle down on the back rim": where it ends, not a second part
        if preposition in _INSTRUMENT_PREPS and (themes or preposition in INSTRUMENT):
            instruments.append(mention)
        elif preposition in _REFERENCE_PREPS and themes and mention.is_object:
            continue
        elif preposition in _REFERENCE_PREPS and themes:
            continue  # "lift the lid off the box": a place, not another theme
        elif preposition in ("onto", "into", "against") and mention.kind is None and not mention.pronoun:
            continue  # "(and) shut onto the keyboard", "comes back down onto the pot": where it ends, not what moves
        elif mention.anaphor and not mention.sides and not mention.ordinal and preposition == "," and themes and not (
                mention.relation is not None and mention.relation[1].pronoun):  # "top-left key, the one right under it": the next
            continue  # "the left door, the one with the handle,": an apposition describing the door
        else:
            themes.append(mention)
    return themes[len(prior):], instruments


_SAME = frozenset({"do_the_same", "the_same_amount", "the_same_way", "as_much", "the_same_distance", "the_same_angle"})
_IN_TURN = {"in_the_reverse_order": "reverse", "in_reverse_order": "reverse", "one_by_one": "reading", "one_after_the_other": "reading", "one_after_another": "reading", "one_at_a_time": "reading", "in_turn": "reading",
            "in_sequence": "reading", "in_order": "reading", "in_that_order": "reading", "in_this_order": "reading", "left_to_right": "left_to_right", "right_to_left": "right_to_left",
            "top_to_bottom": "top_to_bottom", "bottom_to_top": "bottom_to_top", "in_the_order_said": "said"}


def build_frame(clause: Clause, carried: tuple[Unit, float] | None = None) -> Frame:
    correction = bool(clause.tokens) and clause.tokens[0].text == "instead"
    wish, wished = wished_state(list(clause.tokens[1:] if correction else clause.tokens))
    first, tokens = first_of(light_verb(wished))
    quantities = read_quantities(tokens, carried, correction=correction)
    verb_index = _find_verb(tokens)
    named_side = (clause.heading and len(tokens) > 1 and tokens[0].text in SPATIAL) or side_of_part(tokens)
    if verb_index == 0 and (named_side or (clause.heading and len(tokens) == 1 and tokens[0].text in OBJECT_NOUNS) or (
            clause.heading and kind_of_word(tokens[0].text) is not None and (
            len(tokens) == 1 or tokens[1].text in ("on", "at", "in", "of", "near", "by", "nearest", "closest")))):
        verb_index = None  # "Dial on the front: one full rotation": the part, not the verb  # "Lower knob: give it a 45 degree turn", "lower drawer out 0.5 m": "lower" is the part's side
    if verb_index is not None and verb_index > 1 and tokens[verb_index].text in ("closed", "shut", "open", "opened") and len(tokens) > 1 and (
            unknown_verb(tokens[0], tokens[1].text)):
        verb_index = None  # "clap the laptop closed": a verb we do not know, then the end state
    verb = tokens[verb_index].lemma if verb_index is not None else None
    guessed = None
    if verb_index is None and len(tokens) > 1 and tokens[1].text in ("it", "them") and tokens[0].text.isalpha() and tokens[0].text not in DETERMINERS and (
            not named_side and tokens[0].lemma not in VERBS):
        verb_index, verb, guessed = 0, GENERIC.lemma, tokens[0].text  # "seat it back down": a noun used as a verb
    if verb_index is None and len(tokens) > 1 and unknown_verb(tokens[0], tokens[1].text) and not named_side and tokens[0].text not in SPATIAL:
        verb_index, verb, guessed = 0, GENERIC.lemma, tokens[0].text  # "jiggle the lid open": a verb we do not know
    finite = next((k for k in range(1, len(tokens)) if (finite_unknown_verb(tokens[k].text) or actor_verb(tokens, k)) and tokens[k - 1].text not in DETERMINERS),
                  None) if verb_index is None else None
    described = finite is not None and (tokens[finite - 1].text in ("is", "are", "was", "were") or (  # "the door is hinged on the left"
        tokens[finite].text.endswith("ed") and any(t.text in _HAVING for t in tokens[:finite])))  # "it has two knobs stacked ..."
    described = described or (verb_index is None and finite is None and does_to_a_thing(tokens) is not None)  # "the left one hides the dove"
    if finite is not None and not described:
        verb_index, verb, guessed = finite, GENERIC.lemma, tokens[finite].text  # "the lever waggles 30 degrees left"
    progressive = how_it_is(tokens, verb_index, clause, wish)
    if progressive:
        verb_index, verb = None, None  # "the screen is leaning back too far": how things are, not a step
    causative = verb_index is not None and (tokens[verb_index].text in CAUSATIVES or (tokens[verb_index].lemma in TOLD_CAUSATIVES and any(
        t.lemma in VERBS and t.lemma not in TOLD_CAUSATIVES for t in tokens[verb_index + 1:])))  # not "as far as the hinge lets it"
    if verb_index is None:
        subject, objects = [], parse_mentions(tokens, 0, quantities.used)
    else:
        subject = [m for m in parse_mentions(tokens[:verb_index], 0, quantities.used) if m.head not in CAUSER_NOUNS]  # not "the steam"
        objects = parse_mentions(tokens, verb_index + 1, quantities.used)
    particle, particle_at = _particle(tokens, verb_index, objects) if verb_index is not None else (None, None)
    quantities = told_way(tokens, quantities, told_state_words(tokens, {m.end for m in objects}))  # not "that's flopped forward"
    if particle_at is not None:
        objects = [m for m in objects if not m.start <= particle_at < m.end]
    extra = tuple(t.lemma for t in tokens[(verb_index or 0) + 1:] if t.lemma in VERBS and t.lemma != verb and verb_at(tokens, tokens.index(t), strict=True))
    words = {t.text for t in tokens}
    existential = [t.text for t in tokens[:2]] in (["there", "is"], ["there", "are"]) or (tokens and tokens[0].text in ("there's", "there're"))
    stative = verb_index is None and not (tokens and tokens[0].text == "back") and (progressive or described or existential or any(
        t.text in STATIVE_VERBS for t in tokens))  # not "back up to the angle it started at"; "there's a lever at each end" says what is there
    intransitive = after_subject(tokens, verb_index) or finite is not None
    if subject and all(m.kind is None and not (m.pronoun or m.is_object) for m in subject) and any(m.kind is not None or m.anaphor or m.pronoun for m in objects):
        subject = []  # "the pirate closed the lid of his chest": who acts, on the part named after the verb
    themes, instruments = _split_roles(tokens, objects, subject if intransitive or stative else [])
    subject_theme = bool(subject) and (not themes or stative or intransitive or verb == "follow")
    themes = [] if verb == "follow" and subject else themes  # "the back lever follows it (down)": the subject moves, not "it"
    if subject_theme:
        themes = subject + themes
    if themes and all(m.head in _PLACEHOLDERS for m in themes):
        held = [m for m in objects if m.head not in _PLACEHOLDERS and not m.pronoun]
        themes = held[:1] or themes  # "I need something from the left drawer": the drawer
    if any(m.head in _BODY_PARTS and m.owner is not None for m in themes):
        themes = [m.owner if m.head in _BODY_PARTS and m.owner is not None else m for m in themes]  # "keep your finger on it": it
    elif verb in ("keep", "hold") and themes and all(m.head in _BODY_PARTS for m in themes):
        themes = [replace(themes[0], head="it", kind=None, pronoun=True, modifiers=())]  # "keep your foot down for 3 s": on what it pressed
    codes = code_items(tokens, (verb_index + 1) if verb_index is not None else 0, quantities.used) or (code_items(tokens[:verb_index], 0, quantities.used) if verb_index and any(
        m.kind in (PartKind.CODE, PartKind.BUTTON) for m in subject) else ())  # "the code 1-2-3 shall be entered": said before a passive verb
    if any(m.head not in _CONTAINERS and m.kind is not None for m in themes) or any(c[0] == "place" for c in codes):
        themes = [m for m in themes if m.head not in _CONTAINERS]  # "any key in the second row of the keypad", "bottom-left on the keypad"
    let, inner = causative or particle == "go", None
    if let and verb_index is not None:
        named = {k for m in objects for k in range(m.start, m.end)}  # "make the lower drawer come out": "lower" names the drawer
        inner = next((i for i in range(verb_index + 1, len(tokens)) if tokens[i].lemma in VERBS and tokens[i].lemma != "let"
                      and not (tokens[i].lemma == "go" and letting_go(tokens, i)) and i not in named), None)
        if inner is not None:  # "let the lid drop": the lid does what the inner verb says, on its own
            verb = tokens[inner].lemma
            particle, _ = _particle(tokens, inner, objects)
            themes = [m for m in themes if not m.start <= inner < m.end]  # "make some toast": toast is the action
    sense = _sense(verb, particle, themes) if verb in VERBS or verb == GENERIC.lemma else None
    if sense is VerbSense.RETURN and verb is not None and verb in VERBS and VERBS[verb].sense is VerbSense.OPEN and quantities.amount is not None and quantities.amount.unit == "fraction" and quantities.amount.value < 1:
        sense = VerbSense.OPEN  # "then open it back up halfway": half of its range, not half of the way back
    made = next((m for m in themes if m.kind is None and m.head in FUNCTION_VERBS and m.head in VERBS), None) if (
        wish and verb is None and particle is None and not any(t.text in WISHED_SENSES or t.text in STATE_PARTICLES for t in tokens)) else None
    if made is not None:  # "I'd like some toast": the wish is what the object makes, so it does its work
        verb, themes = made.head, [m for m in themes if m is not made]
        sense = _sense(verb, particle)
    elif wish and verb is None:
        sense = next((WISHED_SENSES[t.text] for t in tokens if t.text in WISHED_SENSES), VerbSense.OPEN)
    if let and verb in CAUSATIVES:  # "let the door down", "let go"; "get the lid off the pot": take it off
        sense = (VERBS["take"].particles.get(particle or "") if verb == "get" else None) or VERBS["let"].particles.get(particle or "", VerbSense.RELEASE)
    elif let and (sense is None or particle == "go" or (inner is not None and [t.text for t in tokens[inner + 1:inner + 3]] in (["back"], ["back", "up"], ["back", "down"]))):
        sense = VerbSense.RELEASE  # "let it flip back up": it goes back on its own
    if any(m.head in _BODY_PARTS for m in subject) and sense is VerbSense.RELEASE:
        themes, let = [], True  # "the foot comes off": the user lets go of what was pressed
    if verb in _LETTING_GO and any(m.head in _BODY_PARTS for m in themes):
        # "take your foot off the pedal", "lift your finger": the user lets go
        sense, let = VerbSense.RELEASE, True
        themes = [m for m in themes if m.head not in _BODY_PARTS] + _reference_mentions(objects, themes)
    inside = {k for m in objects for k in range(m.start, m.end)}
    if verb_index is None and any(t.text == "back" and k not in inside and not (k and tokens[k - 1].text in _FURTHER | {"the", "its", "their"}) for k, t in enumerate(tokens)):
        particle = "back"  # "then 0.3 m back" (not "the back one", not "down the back of the bucket")
        after = [tokens[k + 1].text for k, t in enumerate(tokens[:-1]) if t.text == "back"]
        if after and after[0] in ("in", "out", "up", "down"):
            particle, particle_at = after[0], next(k + 1 for k, t in enumerate(tokens) if t.text == "back")  # "then back in": back, and in
    elif verb_index is None and not objects and tokens and tokens[0].text in _SWITCHED:
        particle = tokens[0].text  # "flick it on and then off again": the verb of the clause before, this particle
    said_return = {t.text for k, t in enumerate(tokens) if t.text in _RETURN_WORDS and not (
        t.text in ("rest", "resting") and k > 0 and tokens[k - 1].text in ("it's", "is", "its", "where", "currently")) and not (
        t.text in _RETURN_ADJECTIVES and (k == 0 or tokens[k - 1].text not in _POSSESSIVE_DETS))}  # "from where it's resting now", "you're starting"
    back_before = particle in ("up", "down", "in", "out") and particle_at is not None and particle_at > 0 and tokens[particle_at - 1].text == "back" and (
        particle_at < 2 or tokens[particle_at - 2].text not in ("the", "its", "toward", "towards")) and not (
        particle == "down" and [t.text for t in tokens[particle_at + 1:particle_at + 2]] == ["on"]) and not (
        verb is not None and verb in VERBS and VERBS[verb].sense is VerbSense.CLOSE)  # "set it back down", not "the one at the back down"; "zip it back up": shut
    returning = sense is VerbSense.RETURN or bool(said_return) or (particle == "back" and sense in (VerbSense.RETURN, None)) or bool(
        words & CENTRE_WORDS) or back_before
    hold = sense is VerbSense.HOLD or verb in ("hold", "keep", "prop") or "hold" in extra or "keep" in extra or held_for(
        tokens, sense, quantities.speed_mps is not None or quantities.omega_radps is not None or quantities.speed_factor != 1.0)
    return Frame(
        clause=clause.index, text=clause.text, verb=verb, sense=sense, particle=particle, themes=tuple(themes), instruments=tuple(instruments),
        subject_theme=subject_theme, quantities=quantities, returning=returning, hold=hold, let=let, link=clause.link,
        goes_first=clause.goes_first, conjoined=clause.conjoined, marker=clause.marker, heading=clause.heading,
        simultaneous=bool(words & SIMULTANEOUS), manual=bool(words & _MANUAL), stative=stative, extra_verbs=extra, aside=aside(tokens),
        guessed_verb=guessed, same_direction=bool(words & SAME_WAY),
        codes=codes, first=first,
        same=bool(words & _SAME) or ends_the_same(tokens), in_turn=min((_IN_TURN[w] for w in words if w in _IN_TURN), key=lambda o: (o == "reading", o), default=None), wish=wish,
        explicit_return=bool((words - _RETURN_ADJECTIVES) & _RETURN_WORDS or said_return & _RETURN_ADJECTIVES), correction=correction,
        brief=(verb in BRIEF_VERBS and quantities.direction is None and not quantities.onto_body and particle not in _END_PARTICLES and not (
            quantities.amount is not None and quantities.amount.unit in ("rad", "turn"))) or bool(words & BRIEF_WORDS),  # not "click the dial a quarter turn"  # "flick it across to the left": stays
    )


def _reference_mentions(objects: list[Mention], themes: list[Mention]) -> list[Mention]:
    """Phrases after "off" / "from" that name what the user lets go of."""
    kept = {id(m) for m in themes}
    return [m for m in objects if id(m) not in kept and m.head not in _BODY_PARTS and (m.kind is not None or m.pronoun)]


def read_frames(clauses: list[Clause]) -> list[Frame]:
    frames: list[Frame] = []
    carried: tuple[Unit, float] | None = None
    for clause in clauses:
        frames.append(build_frame(clause, carried))
        carried = said_unit(list(clause.tokens)) or carried
    return frames
