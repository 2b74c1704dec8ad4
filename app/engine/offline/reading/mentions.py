"""Noun phrases of a clause -> :class:`Mention` records (what part, where, how many, whose).

A noun phrase is a run of determiners, qualifiers and nouns whose last noun is the head: "the upper-left door", "the door
release button" (head: button), "the safe door" (head: door, the object word only says whose). Heads are part-kind words
(the registry), object nouns, pronouns, anaphoric "one" / "the other", or an unknown noun (grounded by the asset's own part
names, else refused). Trailing phrases qualify or own it: "the knob on the left", "the knob on the door", "the second
drawer from the top", "the middle key in the bottom row", "the middle one of the top row"."""

from __future__ import annotations

from dataclasses import replace
from itertools import takewhile

from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.relations import RELATION_ADVERBS, RELATIONS, RELATIVE, RESTING, VIEWERS
from app.engine.lexicon.verbs import PARTICLES, VERBS
from app.engine.lexicon.words import (
    AMOUNTS,
    BELONGING_KEYS,
    COLLECTIVE,
    DEFINITES,
    DETERMINERS,
    FACE_RELATIONS,
    GENERIC_PART_NOUNS,
    HEDGE_ADVERBS,
    MODALS,
    NOT_PART_NOUNS,
    OBJECT_SUFFIXES,
    OPPOSITE_SIDES,
    ORDINALS,
    OTHER_WORDS,
    PERSON_NOUNS,
    PERSONS,
    PHRASE_BREAKS,
    PLACE_SIDES,
    PRONOUNS,
    SIZES,
    SPATIAL,
    STATIVE_VERBS,
    Side,
)
from app.engine.offline.reading.mention import ALTERNATE, Mention, apposed
from app.engine.offline.reading.part_words import (
    OBJECT_WORDS,
    control_name,
    kind_at,
    line_index,
    lined,
    noun_continues,
    object_after,
    shape_adjective,
    side_run,
)
from app.engine.offline.reading.part_words import (
    phrase_words as _words,
)
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.word_class import (
    actor_verb,
    can_be_verb,
    finite_unknown_verb,
    nounless,
    verb_ing,
    verb_only,
)

__all__ = ["Mention", "kind_at", "parse_mentions"]

_REGION_NOUNS = frozenset({"half", "part", "section", "portion", "side", "end"})
_GROUPS = frozenset({"row", "pair", "set", "bank", "stack", "line", "group", "column", "couple"})
_OWNER_PREPS = frozenset({"of", "on", "in", "at", "from", "inside"})
_LINE_WORDS = frozenset({"row", "column"})
_ING_NOUNS = frozenset({"opening", "housing", "casing", "ceiling", "railing", "fitting", "setting", "bearing", "mounting", "coupling"})
_STOP = PHRASE_BREAKS
_NOT_HEADS = NOT_PART_NOUNS
_SITS = frozenset({"is", "'s", "stands", "sits", "sitting", "standing", "placed", "located", "set"})
_KEY_OWNERS = frozenset({"my", "your", "our", "his", "her", "their", "car", "house", "spare", "front-door", "door", "office"})


def _nominal(token: Token) -> bool:
    word = token.text
    if token.ident:
        return True  # "joint_1", "link_0": a part by its URDF name
    if word in OBJECT_WORDS or word in ALTERNATE:
        return True  # "chest_of_drawers", "every_other"
    return (token.number is None and not token.is_punct and word not in _STOP and word not in AMOUNTS and "_" not in word
            and word not in STATIVE_VERBS and word not in PERSONS and word not in HEDGE_ADVERBS and word not in PERSON_NOUNS)


def parse_mentions(tokens: list[Token], start: int, used: frozenset[int] = frozenset()) -> list[Mention]:
    """Every noun phrase in ``tokens[start:]`` (quantity tokens in ``used`` are skipped)."""
    mentions: list[Mention] = []
    i = start
    while i < len(tokens):
        if i in used or not _nominal(tokens[i]) or actor_verb(tokens, i):  # not "jumps" in "the cat jumps onto the screen"
            i += 1
            continue
        mention, i = _phrase(tokens, i, used)
        if mention is None:
            continue
        if mention.anaphor and mention.sides and i + 1 < len(tokens) and tokens[i].text == "'s" and (
                (owned := _phrase(tokens, i + 1, used)[0]) is not None and owned.kind is not None):  # "the left one's door": that unit's
            mention, i = replace(owned, region=mention.sides, start=mention.start, words=_words(tokens, mention.start, owned.end)), owned.end
        mention = _trailing(tokens, mention, used, mentions)
        i = max(i, mention.end)
        if mention.head and mentions and apposed(tokens, mentions[-1], mention):
            before = mentions.pop()  # "the big knob, the one on the left": one knob, told twice
            mention = replace(before, sides=(*before.sides, *mention.sides), ordinal=before.ordinal if before.ordinal is not None else mention.ordinal,
                              ordinal_from=before.ordinal_from or mention.ordinal_from, size=before.size or mention.size, end=mention.end,
                              words=_words(tokens, before.start, mention.end), relation=before.relation or mention.relation)
        if mention.anaphor and mention.kind is None and mentions and mentions[-1].kind is not None:
            mention = replace(mention, kind=mentions[-1].kind)  # "lock the left latch, and the right one": a latch
        if mention.head:
            mentions.append(mention)
    return mentions



def _phrase(tokens: list[Token], i: int, used: frozenset[int]) -> tuple[Mention | None, int]:
    """The noun phrase starting at ``i`` and the index after it."""
    begin = i
    sides: list[tuple[Side, bool]] = []
    ordinal = size = None
    collective = other = alternate = False
    nouns: list[tuple[int, int, PartKind | None, bool]] = []  # (start, length, kind, is_object)
    unknown: list[int] = []
    determiner = possessive = chosen_freely = False
    whose: str | None = None
    owner: Mention | None = None
    region: tuple[tuple[Side, bool], ...] = ()
    while i < len(tokens) and i not in used and (_nominal(tokens[i]) or _inner(tokens, i, begin) or tokens[i].text == "'s"):
        token = tokens[i]
        word = token.text
        if word == "'s":
            # "the stapler's (staple) magazine", "the door's handle": what came before owns what follows
            if (nouns and nouns[-1][3]) or (not nouns and unknown):
                whose = tokens[nouns[-1][0]].lemma if nouns else tokens[unknown[-1]].lemma
                region = tuple(sides)  # "the top oven's door", "the lower compartment's rack": on that side of the object
            elif nouns:
                start_, length, kind, _ = nouns[-1]
                owner = Mention(head=" ".join(t.lemma for t in tokens[start_:start_ + length]), kind=kind, sides=tuple(sides), start=begin, end=i)
            nouns, unknown, sides, ordinal, size = [], [], [], None, None
            i += 1
            continue
        if (nouns or unknown) and (word in DETERMINERS or word in COLLECTIVE or word in ORDINALS or word in SPATIAL or word in SIZES or (
                word in RELATION_ADVERBS and i + 1 < len(tokens) and tokens[i + 1].text in RELATIONS)):
            break  # "open the right door | first": a qualifier after the head is not part of it; "the key | directly under .."
        if (token.lemma in _NOT_HEADS and token.lemma not in SPATIAL and word not in ORDINALS and word not in SIZES and kind_at(tokens, i) is None
                and not nouns and not object_after(tokens, i, begin) and not (i > begin and control_name(tokens, i))):
            return None, i + 1  # "the forward-rolling direction", "its travel": a place or a measure, not a part
        if token.ident:
            unknown.append(i)
            i += 1
            continue
        found = kind_at(tokens, i)
        if found is not None and word in BELONGING_KEYS and i > 0 and tokens[i - 1].text in _KEY_OWNERS:
            found = None  # "my keys are in the top drawer", "the car keys": a person's keys, no key of a keypad
        if found is not None and not (word in SPATIAL and i + 1 < len(tokens) and _nominal(tokens[i + 1]) and kind_at(tokens, i + 1)):
            nouns.append((i, found[1], found[0], False))
            i += found[1]
            continue
        if token.number is not None or word in ("open", "closed", "shut", "opened"):
            if nouns and token.number is None:
                break  # "swing the door shut first": the end state, after the part
            i += 1  # "all four wheels", "the closed pedal bin": a count or a state, the noun follows
            continue
        if word in DETERMINERS:
            determiner = True
            possessive = possessive or word in ("its", "their")
        elif word == "both" and (i + 1 == len(tokens) or tokens[i + 1].text in ("back", "in", "out", "up", "down", "shut", "closed", "open", ",", ".", "together")):
            return Mention(head="them", pronoun=True, plural=True, start=begin, end=i + 1, words=_words(tokens, begin, i + 1)), i + 1  # "then both back in"
        elif word in COLLECTIVE or word in ALTERNATE:
            collective, alternate, other = True, alternate or word in ALTERNATE, other or word in ALTERNATE
        elif word in OTHER_WORDS:
            other = True
        elif word in ORDINALS and not (word == "second" and i > 0 and tokens[i - 1].number is not None):
            ordinal = ORDINALS[word]
        elif (word in SIZES or word in SPATIAL) and not nouns and not unknown and i + 1 < len(tokens) and tokens[i + 1].text == "of":
            inner, _ = _phrase(tokens, i + 2, used)  # "the larger of the two knobs", "the upper of the doors": one of them
            if inner is None or not inner.plural:
                return None, i + 1
            inner = _trailing(tokens, inner, used, [])
            return replace(inner, plural=False, collective=False, start=begin, words=_words(tokens, begin, inner.end),
                           **({"size": SIZES[word]} if word in SIZES else {"sides": (*inner.sides, SPATIAL[word])})), inner.end
        elif word in SPATIAL:
            sides.append(SPATIAL[word])
        elif word in SIZES:
            size = SIZES[word]
        elif word in ("one", "any", "either") and not nouns and not unknown and i + 1 < len(tokens) and tokens[i + 1].text == "of":
            inner, _ = _phrase(tokens, i + 2, used)  # "one of the (two) knobs on the left": the user leaves the choice
            if inner is not None and inner.head in _LINE_WORDS and (inner.ordinal is not None or inner.sides):  # "the middle one of the top row"
                return lined(Mention(head="one", anaphor=True, sides=tuple(sides), start=begin), inner.head, inner.ordinal if inner.ordinal is not None else (
                    line_index(inner.sides[0][0].value)), inner.end, tokens), inner.end
            if inner is not None:
                inner = _trailing(tokens, inner, used, [])
                return replace(inner, one_of=not sides, sides=(*inner.sides, *sides), plural=False, collective=False, start=begin,  # "the
                               words=_words(tokens, begin, inner.end)), inner.end  # right-hand one of the doors": placed, not a free choice
            return None, i + 1
        elif word in ("any", "either", "whichever") and not nouns and not unknown:
            chosen_freely = True  # "press any key in the second row": the user leaves the choice
        elif word in PRONOUNS or (word in ("one", "ones") and (sides or other or ordinal or size or determiner)):
            pointed = word == "one" and i == begin + 1 and tokens[begin].text in ("that", "this")  # "give that one half a turn": it
            pronoun = Mention(head="it" if pointed else word, pronoun=word in PRONOUNS or pointed, anaphor=word in ("one", "ones") and not pointed, other=other, sides=tuple(sides),
                              ordinal=ordinal, size=size, plural=word in ("them", "they", "ones"), collective=collective,
                              start=begin, end=i + 1, words=_words(tokens, begin, i + 1))
            return pronoun, i + 1
        elif word in MODALS and i + 1 < len(tokens) and can_be_verb(tokens[i + 1].text) and tokens[i + 1].text != "'s" and not (i and tokens[i - 1].text in DETERMINERS):
            break  # "the entire 6 cm it can travel": a modal, not the noun "can"
        elif token.lemma in OBJECT_WORDS or word in OBJECT_WORDS:
            nouns.append((i, 1, None, token.lemma not in GENERIC_PART_NOUNS or not (size or any(shape_adjective(tokens, j) for j in range(begin, i)))))
        elif i > begin and control_name(tokens, i):
            unknown.append(i)  # "the start button": a word of the control's name
        elif token.lemma in VERBS and (i == begin or ((nouns or unknown) and not noun_continues(tokens, i + 1))):
            break  # a verb ends the phrase ("the lid | drops"); "the door release button" goes on
        elif "-" in word and all(part in SPATIAL or part in ("side", "hand") for part in word.split("-")) and word.split("-")[0] in SPATIAL:
            sides.extend(SPATIAL[part] for part in word.split("-") if part in SPATIAL)  # "upper-left", "bottom-right", "left-side"
        elif word in PARTICLES and not shape_adjective(tokens, i):
            break
        elif token.lemma not in _NOT_HEADS and any(token.lemma.endswith(s) and token.lemma != s for s in OBJECT_SUFFIXES) and word.isalpha():
            nouns.append((i, 1, None, True))  # "the toolbox", "the breadbin": a compound object name
        elif nouns and (finite_unknown_verb(word) or (word not in _ING_NOUNS and verb_ing(word)) or nounless(word)):
            break  # "the lever | waggles 30 degrees left": a verb the lexicon does not know; "the bin lid | manually"
        elif ((token.lemma not in _NOT_HEADS and word.isalpha()) or "-" in word) and not (
                (verb_only(word) or nounless(word)) and not nouns and not unknown and not determiner):
            unknown.append(i)
        elif token.lemma in _NOT_HEADS and not nouns and not unknown and not (sides or ordinal):
            i += 1
            return None, i
        i += 1
    end = i
    if not nouns and not unknown:
        at_end = end >= len(tokens) or tokens[end].is_punct or tokens[end].text in ("then", "and", "and_then", "first", "too", "as_well", "to", "by", "half", "a", "a_quarter", "all_the_way", "halfway", "once", "twice") or (
            tokens[end].number is not None)
        facing = begin > 1 and tokens[begin - 1].text in ("of", "to", "with", "from") and tokens[begin - 2].text in FACE_RELATIONS
        if at_end and end == begin + 1 and tokens[begin].text in ("this", "that"):
            return Mention(head="it", pronoun=True, start=begin, end=end, words=tokens[begin].text), end  # "open this", "spin that half a turn"
        if not facing and (other or (determiner and (sides or ordinal or size) and at_end)):
            # "the other", "then the second": an anaphoric head with qualifiers
            return Mention(head="one", anaphor=True, other=other, sides=tuple(sides), ordinal=ordinal, size=size, collective=collective,
                           start=begin, end=end, words=_words(tokens, begin, end)), end
        return None, max(end, begin + 1)
    last_noun = nouns[-2] if len(nouns) > 1 and nouns[-2][2] is not None and tokens[nouns[-1][0]].lemma in GENERIC_PART_NOUNS and (
        nouns[-2][0] + nouns[-2][1] == nouns[-1][0]) else (nouns[-1] if nouns else None)  # "the pedal thing": the pedal
    if last_noun is not None and (not unknown or unknown[-1] < last_noun[0]):
        head_index, length, kind, is_object = last_noun
        head_tokens = tokens[head_index:head_index + length]
        modifiers = tuple(tokens[j].text for j in range(begin, head_index) if j not in used and tokens[j].text not in DETERMINERS
                          and not (tokens[j].lemma in OBJECT_WORDS and j + 1 < len(tokens) and tokens[j + 1].text == "'s")
                          and tokens[j].text not in COLLECTIVE and tokens[j].text not in SPATIAL and tokens[j].text not in ORDINALS
                          and tokens[j].text not in SIZES and tokens[j].text not in OTHER_WORDS)
        plural = head_tokens[-1].plural or collective or any((tokens[j].number or 0) > 1 and not (j and tokens[j - 1].text in DEFINITES)
                                                             for j in range(begin, head_index))  # "2 drawers", not "the 5 key"
        head_word = " ".join(t.lemma for t in head_tokens)
    else:
        head_index, kind, is_object = unknown[-1], None, False
        modifiers = tuple(tokens[j].text for j in unknown[:-1])
        plural = tokens[head_index].plural or collective
        head_word = tokens[head_index].lemma
    if possessive and kind is None and head_word in _REGION_NOUNS:
        # "press in its lower half": a place on the part "it" names
        return Mention(head="it", pronoun=True, sides=tuple(sides), start=begin, end=end, words=_words(tokens, begin, end)), end
    return Mention(head=head_word, kind=kind, is_object=is_object, other=other, sides=tuple(sides), ordinal=ordinal, size=size, plural=plural,
                   collective=collective, alternate=alternate, possessive=possessive, one_of=chosen_freely, modifiers=tuple(m for m in modifiers if m != "'s"), owner=owner, whose=whose, start=begin, end=end,
                   region=region, words=_words(tokens, begin, end)), end


def _inner(tokens: list[Token], i: int, begin: int) -> bool:
    """A count or state adjective inside a phrase ("all four wheels", "the closed lid"): a noun follows."""
    token = tokens[i]
    if token.text == "back" and i > begin and i + 1 < len(tokens) and (kind_at(tokens, i + 1) is not None or tokens[i + 1].text in ("one", "ones")):
        return True  # "the back lever", "the back door": a side, not the particle
    if token.text == "half" and i > begin and tokens[i - 1].text in SPATIAL:
        return True  # "the front half of the case": a region, not an amount
    inside = i > begin and (token.number is not None or token.text in ("open", "closed", "shut", "opened") or shape_adjective(tokens, i))
    return inside and i + 1 < len(tokens) and _nominal(tokens[i + 1])


def _related(tokens: list[Token], mention: Mention, used: frozenset[int]) -> Mention | None:
    """"the key (right) below it", "the knob to the left of the dial": a part placed relative to another."""
    i = mention.end
    if i + 2 < len(tokens) and tokens[i].text in ("on", "at") and tokens[i + 1].text in DETERMINERS and tokens[i + 2].text in ("end", "side"):
        i += 3  # "the lever on the end closest to me"
    start = i
    while i < len(tokens) and tokens[i].text in RELATION_ADVERBS | RELATIVE:
        i += 1  # "the rack (that's) nearest the floor"
    if i + 2 < len(tokens) and tokens[i].text in ("up", "down", "above", "below") and tokens[i + 1].text == "and" and tokens[i + 2].text in RELATIONS:
        i += 2  # "the knob up and to the right of the wheel": to its right (the way across says which)
    resting = mention.kind is not None and any(tokens[k].text in RESTING for k in range(start, i)) and i < len(tokens) and (
        tokens[i].text in ("on", "atop", "on_top_of"))  # not "the roast sitting on the middle shelf": no part, the shelf is where it is
    beside = i + 1 < len(tokens) and tokens[i].text in ("left", "right") and tokens[i + 1].text == "of"  # "(just) left of the 9"
    if i >= len(tokens) or (tokens[i].text not in RELATIONS and not resting and not beside):
        return None
    relation = tokens[i].text if beside else "above" if resting else RELATIONS[tokens[i].text]  # "the little cap sitting on the jar": above the jar
    j = i + 1
    if j < len(tokens) and tokens[j].text in ("of", "to", "from"):
        j += 1
    k = j + (j < len(tokens) and tokens[j].text in DETERMINERS)
    if relation in ("near", "far") and k < len(tokens) and tokens[k].text in PLACE_SIDES:  # "the dial closest to the counter": the bottom one
        side = PLACE_SIDES[tokens[k].text] if relation == "near" else OPPOSITE_SIDES[PLACE_SIDES[tokens[k].text]]
        return replace(mention, sides=(*mention.sides, (side, True)), end=k + 1, words=_words(tokens, mention.start, k + 1))
    if relation in ("near", "far") and j < len(tokens) and tokens[j].text in VIEWERS:
        viewer = Mention(head="viewer", start=j, end=j + 1, words=tokens[j].text)  # "closest to me": the front; "furthest from me": the back
        return replace(mention, relation=(relation, viewer), end=j + 1, words=_words(tokens, mention.start, j + 1))
    bare_hinge = [t.text for t in tokens[j:j + 2]] in (["the", "hinge"], ["its", "hinge"]) or (tokens[j:j + 1] and tokens[j].text == "hinge")
    if bare_hinge:  # "the knob farther from the hinge": the hinge of the (one) door
        end = j + (1 if tokens[j].text == "hinge" else 2)
        door = Mention(head="door", kind=PartKind.DOOR, modifiers=("hinge",), start=j, end=end, words="the door")
        return replace(mention, relation=(relation, door), end=end, words=_words(tokens, mention.start, end))
    label = k if k < len(tokens) and tokens[k].number is not None and tokens[k].text.isdigit() and len(tokens[k].text) == 1 and (
        k + 1 == len(tokens) or not _nominal(tokens[k + 1])) else None  # "the 5", not "the 2 knobs"
    if label is not None and mention.kind is PartKind.BUTTON:  # "the key next to the 5": the key labelled 5 on a phone-style keypad
        key = Mention(head=tokens[label].text, kind=PartKind.CODE, start=label, end=label + 1, words=f"the {tokens[label].text}")
        return replace(mention, relation=(relation, key), end=label + 1, words=_words(tokens, mention.start, label + 1))
    owned = next((k for k in range(j, min(len(tokens) - 1, j + 5)) if tokens[k].text == "'s" and tokens[k + 1].text == "hinge"), None)
    if relation == "near" and owned is not None:  # "the knob nearest the lid's hinge"
        reference, _ = _phrase(tokens[:owned], j, used)
        end = owned + 1
    else:
        reference, end = _phrase(tokens, j, used)
    if reference is None or not (reference.pronoun or reference.kind is not None or reference.anaphor) or (reference.pronoun and tokens[i].text == "over"):
        return None  # "snap the left latch over it": where it goes, not which latch
    if reference.anaphor and reference.kind is None and not reference.pronoun and mention.kind is not None:
        reference = replace(reference, kind=mention.kind)  # "the key right above the bottom-right one": the bottom-right key
    if end < len(tokens) and tokens[end].text in ("of", "in") and not reference.pronoun:
        reference = _trailing(tokens, reference, used, [])  # "under the middle key of the top row"
        end = max(end, reference.end)
    if relation == "near" and end < len(tokens) and tokens[end].text == "hinge":
        end += 1  # "the knob nearest the door hinge"
    if relation == "near" and any(tokens[k].text == "hinge" for k in range(j, end)):
        reference = replace(reference, modifiers=(*reference.modifiers, "hinge"))
    return replace(mention, relation=(relation, reference), end=end, words=_words(tokens, mention.start, end))


def _trailing(tokens: list[Token], mention: Mention, used: frozenset[int], earlier: list[Mention]) -> Mention:
    """Attach "on the left", "from the top", "in the bottom row", "of the door", "below it", "second from the right" after a phrase."""
    k = mention.end
    if mention.ordinal is None and k + 2 < len(tokens) and tokens[k].text in ORDINALS and tokens[k + 1].text == "from":
        j = k + 2 + (tokens[k + 2].text in DETERMINERS)
        if j < len(tokens) and tokens[j].text in SPATIAL:  # "the knob second from the right"
            return replace(mention, ordinal=ORDINALS[tokens[k].text], ordinal_from=SPATIAL[tokens[j].text][0], end=j + 1,
                           words=_words(tokens, mention.start, j + 1))
    related = _related(tokens, mention, used)
    if related is not None:  # "the key right next to it in the middle of the top row": where it is, said too
        return _trailing(tokens, related, used, earlier) if related.relation is not None and related.relation[1].pronoun else related
    i = mention.end
    if i < len(tokens) and tokens[i].text.endswith("most") and tokens[i].text in SPATIAL and not mention.sides:  # "the knob furthest left"
        return replace(mention, sides=(SPATIAL[tokens[i].text],), end=i + 1, words=_words(tokens, mention.start, i + 1))
    if i + 1 < len(tokens) and tokens[i].text == "on_top_of" and not mention.sides:  # "the lever on top of the machine": its top one
        return replace(mention, sides=(SPATIAL["top"],), end=i + 1, words=_words(tokens, mention.start, i + 1))
    k = i + 1 + sum(1 for _ in takewhile(lambda t: t.text in _SITS, tokens[i + 1:])) if i < len(tokens) and tokens[i].text in ("that", "which", "that's") else i
    i = k if k < len(tokens) and tokens[k].text in _OWNER_PREPS else i  # "the laptop that's sitting on the left": where it stands
    if i + 1 >= len(tokens) or tokens[i].text not in _OWNER_PREPS | {"from", "out_of", "across", "along"}:
        return mention
    prep = tokens[i].text
    j = i + 1
    while j < len(tokens) and tokens[j].text in DETERMINERS:
        j += 1
    if j >= len(tokens):
        return mention
    word = tokens[j].text
    nxt = tokens[j + 1].text if j + 1 < len(tokens) else ""
    run, end = side_run(tokens, j)
    if run and prep in ("on", "at", "in"):  # "the key in the bottom-left corner", "the knob at the top right"
        return replace(mention, sides=(*mention.sides, *run), end=end, words=_words(tokens, mention.start, end))
    if prep in ("across", "along") and not ((word in SPATIAL or word in ORDINALS) and nxt in _LINE_WORDS):
        return mention  # "across the top row" places keys; "across the room" says nothing of which part
    if (word in SPATIAL or word in ORDINALS) and nxt in _LINE_WORDS:  # "in the bottom row", "in the second column"
        return lined(mention, nxt, line_index(word), j + 2, tokens)
    if word in SPATIAL and not (j + 1 < len(tokens) and _nominal(tokens[j + 1]) and nxt not in ("side", "hand", "end", "one") and (
            nxt not in DETERMINERS)):  # "the wheel on the right a full turn": "a" opens the amount, it is no noun of the side
        end = j + 1 + (1 if nxt in ("side", "hand", "end") else 0)
        if prep == "from" and mention.ordinal is not None:  # "the second key from the left (in the top row)"
            counted = replace(mention, ordinal_from=SPATIAL[word][0], end=end, words=_words(tokens, mention.start, end))
            return _trailing(tokens, counted, used, earlier) if end < len(tokens) and tokens[end].text in ("in", "on", "of") else counted
        if prep in ("on", "at", "in", "to") or (prep == "of" and nxt in ("side", "hand", "end")):  # "the door of right side"
            placed = replace(mention, sides=(*mention.sides, SPATIAL[word]), end=end, words=_words(tokens, mention.start, end))
            return _trailing(tokens, placed, used, earlier) if end < len(tokens) and tokens[end].text == "of" else placed
        return mention
    if prep in ("of", "on", "in", "at", "inside", "out_of", "from"):
        owner, end = _phrase(tokens, i + 1 if tokens[j].number is not None else j, used)  # "the lids of the two outer boxes"
        if prep in ("out_of", "from") and not (owner is not None and owner.is_object and owner.sides):
            return mention  # "pull the tray out of the oven": where it goes, not which one
        if owner is not None and owner.head in _LINE_WORDS and (owner.ordinal is not None or owner.sides):
            index = owner.ordinal if owner.ordinal is not None else line_index(owner.sides[0][0].value)
            return lined(mention, owner.head, index, end, tokens)  # "the keypad's second row"
        if owner is not None and (owner.kind is not None or owner.is_object or owner.pronoun):
            owner = _trailing(tokens, owner, used, earlier)
            end = max(end, owner.end)
            if owner.is_object and mention.kind is None and (mention.head in _REGION_NOUNS or mention.head in _GROUPS):
                return replace(owner, sides=(*mention.sides, *owner.sides), start=mention.start, end=end, words=_words(tokens, mention.start, end),
                               collective=owner.collective or mention.head in _GROUPS)  # "the front half of the case", "the pair of safes"
            if owner.is_object:
                return replace(mention, end=end, words=_words(tokens, mention.start, end), whose=owner.head, region=owner.sides)
            return replace(mention, owner=owner, end=end, words=_words(tokens, mention.start, end))
        owner = _phrase(tokens, i + 1, used)[0] if word == "one" and mention.kind is not None else owner  # "the door of the one on the right"
        if owner is not None and owner.anaphor and not owner.other and mention.kind is not None and (owner := _trailing(tokens, owner, used, earlier)).sides:
            return replace(mention, end=owner.end, words=_words(tokens, mention.start, owner.end), region=owner.sides)  # "the door of the one on the right"
        if owner is not None and owner.kind is None and not owner.anaphor:
            return replace(mention, end=end)  # "the button on the control strip": a place on the object, not a part
    return mention
