"""Everyday ways of saying what the lexicon has a word for, rewritten token by token before phrases are joined:
"the drawer's sticking out" (is), "push it home" (shut), "into its locked position" (shut), "the knob furthest to the
left" (leftmost), "lever: full left", "max cold" (a mixer tap: hot is the viewer's left), "to the midpoint of its
travel" (halfway), "give it two seconds" (wait), "no need to touch the dial" (don't), "unlatch nothing", "forget the
pedal", "one full counterclockwise turn" (the turn, then its sense), "180 clockwise" (degrees), "back the cap off" (loosen
it), "in the unscrewing direction" (counterclockwise), "as far left as it will go" / "all the way left" / "hard left" (a way, not a part), "the ketchup, which
lives in the door" (a sentence of its own: where it is kept)."""

from __future__ import annotations

from app.engine.lexicon.relations import VIEWER_WORDS
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import (
    GENERIC_PART_NOUNS,
    NUMBER_WORDS,
    OBJECT_NOUNS,
    PERSON_NOUNS,
    ROTATION_SENSE,
    SCREWING_SENSES,
    TURN_UNITS,
)
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

_STATE_AFTER_IS = frozenset({"open", "closed", "shut", "stuck", "ajar", "jammed", "still", "already", "halfway", "partly", "wide", "up", "down"})


_NOT_BEFORE_HOME = frozenset({"back", "to", "the", "its", "a", "at", "from", "go", "goes", "come", "comes", "return", "returns"})


_KEPT = frozenset({"is", "are", "lives", "live", "sits", "sit", "lies", "lie", "stays", "belongs", "goes", "'s", "was"})


_KEPT_AT = frozenset({"in", "on", "inside", "behind", "at", "under", "within"})


_SPELLS = frozenset({"moment", "second", "sec", "couple", "few", "beat", "minute"})
"""What follows "give it a ..." when it is a wait ("give it a couple of seconds")."""


_TAP_SIDES = {"hot": "left", "cold": "right", "hottest": "left", "coldest": "right"}


_POSITION_STATES = {"locked": "shut", "latched": "shut", "closed": "shut", "shut": "shut", "unlocked": "open", "unlatched": "open", "open": "open"}


_ON_THE_SIDE = frozenset({"on", "to", "down", "onto", "toward", "towards", "over"})
_SITS = frozenset({"sits", "is", "lies", "sitting", "located"})
_PLACED_AT = frozenset({"at", "on", "in", "inside", "by", "near", "beside", "behind", "in_front_of", "on_top_of"})


_LEAVERS = PERSON_NOUNS | frozenset({"i", "you", "we", "they", "he", "she", "who", "someone", "somebody", "people", "everyone", "everybody", "nobody"})
"""Who leaves a part as it is ("somebody's left the door open"): "left" after them is a verb, not a side."""


def _facing_viewer(tokens: list[Token], i: int) -> int:
    """The index after "(that's) facing (the) me" / "nearest (to) me" at ``i`` (after "the side"), else 0."""
    k = i + (i < len(tokens) and tokens[i].text in ("that's", "that", "which", "which's", "is"))
    k += k < len(tokens) and tokens[k].text == "is"
    if k >= len(tokens) or tokens[k].text not in ("facing", "nearest", "closest", "near", "nearer", "closer", "toward", "towards"):
        return 0
    k += 1
    while k < len(tokens) and tokens[k].text in ("to", "the"):
        k += 1
    return k + 1 if k < len(tokens) and tokens[k].text in VIEWER_WORDS else 0


def _state_position(tokens: list[Token], i: int) -> tuple[str, int] | None:
    """"into its locked position", "to the unlatched state": (the end state as a particle, how many tokens from ``i``)."""
    words = [t.text for t in tokens[i + 1:i + 4]]
    k = 1 if words[:1] and words[0] in ("its", "the", "their") else 0
    if len(words) > k + 1 and words[k] in _POSITION_STATES and words[k + 1] in ("position", "state", "setting"):
        return _POSITION_STATES[words[k]], k + 3
    return None

def _extreme_side(tokens: list[Token], i: int) -> tuple[str, int] | None:
    """"furthest to the left", "farthest right": (the side, how many tokens from ``i``)."""
    words = [t.text for t in tokens[i + 1:i + 4]]
    for lead in (["to", "the"], ["on", "the"], []):
        k = len(lead)
        if words[:k] == lead and len(words) > k and words[k] in ("left", "right"):
            return words[k], k + 2
    return None


_SIDES = frozenset({"left", "right"})
_FULL_SIDE = frozenset({"full", "fully", "hard", "max", "maximum"})
_AMOUNT_ENDS = frozenset({"way", "bit", "little", "tad", "slightly", "halfway", "further", "farther", "more", "somewhat"})
"""Words that end an amount: a bare side right after one is where the part goes ("all the way left", "a bit right")."""
_CLAUSE_ENDS = frozenset({"and", "then", "so", "until", "while", "before", "after", "once", "as", "side", "position", "too", "for", "with", "please"})
_FAR_SIDES = frozenset({"left", "right", "up", "down", "back", "forward", "out", "open", "in"})
_AS_FAR_TAIL = frozenset({"it", "they", "you", "i", "we", "will", "'ll", "can", "could", "would", "goes", "go", "possible", "get", "gets",
                          "allows", "lets", "let", "turns", "turn", "swings", "swing", "moves", "move", "slides", "slide"})


_BACKED_OFF_STARTS = frozenset({"it", "them", "the", "this", "that", "its", "my", "your"})
_CLAUSE_STARTS = frozenset({"", ",", ".", ";", ":", "!", "then", "and", "to", "please", "just", "lol"})


def _backed_off(tokens: list[Token], i: int) -> int:
    """"back it off", "back the cap off": the index of "off" when the words between name what is backed off, else 0
    ("then back to off" is a return)."""
    if i + 1 >= len(tokens) or tokens[i + 1].text not in _BACKED_OFF_STARTS:
        return 0
    for k in range(i + 2, min(i + 6, len(tokens))):
        if tokens[k].text == "off":
            return k if all(t.text.isalpha() and t.text not in ("and", "then", "from", "of") for t in tokens[i + 1:k]) else 0
        if tokens[k].is_punct:
            return 0
    return 0


def _side_ends(tokens: list[Token], i: int) -> bool:
    """Whether the clause's phrase ends at ``i``: the side before it names a way, not a part ("a bit left door")."""
    return i >= len(tokens) or tokens[i].is_punct or tokens[i].text in _CLAUSE_ENDS


def _as_far_side(tokens: list[Token], i: int) -> tuple[str, int] | None:
    """"as far left as it will go" at ``i``: (the way, the index of its last word), else ``None``."""
    words = [t.text for t in tokens[i:i + 4]]
    if len(words) < 4 or words[1] not in ("far", "farther", "further") or words[2] not in _FAR_SIDES or words[3] != "as":
        return None
    last = i + 3
    while last + 1 < len(tokens) and tokens[last + 1].text in _AS_FAR_TAIL:
        last += 1
    return (words[2], last) if last > i + 3 else None


_MOVERS = frozenset({"mover", "removal", "client", "director", "animator", "designer", "customer", "kid", "guest", "tester"})
_PARTICIPLES = frozenset({"fallen", "stuck", "broken", "bent", "swung", "sprung", "slid", "gone", "come", "dropped", "flopped", "popped", "shot", "worn", "snapped", "bust", "busted", "seized", "jammed"})


_NOT_NAMES = frozenset({"it", "this", "that", "he", "she", "they", "who", "which", "what", "everything", "nothing", "something", "one", "each",
                        "then", "and", "now", "just", "also", "still", "there", "here", "gravity", "time"})


def _a_name(word: str) -> bool:
    """A word no dictionary of ours knows, said before a verb (a person's name in a story: "Mia", "Grandad Joe")."""
    from app.engine.offline.reading.spelling import domain_words

    return word not in domain_words() and kind_of_word(word) is None and word not in OBJECT_NOUNS and word not in _NOT_NAMES


def _first_person(out: list[Token]) -> bool:
    """The sentence written so far begins with the user ("I'm wrapping a present and ...")."""
    start = max((k + 1 for k, w in enumerate(out) if w.is_sentence_end), default=0)
    return start < len(out) and out[start].text in ("i", "i'm", "i've", "we", "we're")


def everyday_words(tokens: list[Token]) -> list[Token]:
    """``tokens`` with the everyday phrasings of this module's docstring rewritten (new tokens keep the offsets of the
    words they replace)."""
    out: list[Token] = []
    skip = -1  # the last token already written with one before it
    for i, t in enumerate(tokens):
        before, after = (tokens[i - 1].text if i else ""), (tokens[i + 1].text if i + 1 < len(tokens) else "")
        if i <= skip:
            continue
        if t.text.endswith("-most") and t.text[:-5] in ("top", "bottom", "left", "right", "front", "back", "upper", "lower", "inner", "outer"):
            word = t.text.replace("-", "")
            t = Token(word, word, t.start, t.end)  # "the bottom-most rack": the bottommost
        way = next((k for k in (i + 1, i + 2) if k + 1 < len(tokens) and tokens[k].text in SCREWING_SENSES and tokens[k + 1].text == "direction"), None)
        if t.text == "in" and way is not None and (way == i + 1 or after == "the"):
            sense = SCREWING_SENSES[tokens[way].text]  # "rotate the cap half a turn in the unscrewing direction": counterclockwise
            out.append(Token(sense, sense, t.start, tokens[way + 1].end))
            skip = way + 1
            continue
        if t.text in ("should", "must") and out and kind_of_word(before) is None and before not in ("i", "you", "we", "it", "they") and (
                after in VERBS and VERBS[after].sense in (VerbSense.RAISE, VerbSense.LOWER, VerbSense.MOVE) and before.isalpha()):
            from lemminflect import getInflection

            said = getInflection(after, "VBZ")  # "the bucket should rise straight up": the bucket rises
            out.append(Token(said[0] if said else after, after, tokens[i + 1].start, tokens[i + 1].end))
            skip = i + 1
            continue
        if t.text in ("down", "up") and after == "at" and i + 3 < len(tokens) and tokens[i + 2].text == "the" and tokens[i + 3].text in (
                "bottom", "top", "base", "foot") and out and kind_of_word(out[-1].text) is not None:
            continue  # "the lid down at the bottom": at the bottom (a place, not the way the verb goes)
        if t.text == "'s" and out and kind_of_word(out[-1].text) is not None and (after.endswith("ed") or after in _PARTICIPLES):
            out.append(Token("has", "has", t.start, t.end))  # "the handle's flopped over the side": has flopped
            continue
        if t.text in ("want", "wants", "need", "needs") and len(out) > 1 and out[-2].text in ("the", "my", "our") and (
                out[-1].text in PERSON_NOUNS or (out[-1].text.endswith("s") and out[-1].text[:-1] in PERSON_NOUNS | _MOVERS)):
            out[-2:] = [Token("i", "i", out[-2].start, out[-1].end, corrected_from=f"{out[-2].text} {out[-1].text}")]
            t = Token("want", "want", t.start, t.end)  # "the movers want the fridge turned right round": a wish, said for them
        if t.text in ("shown", "displayed", "pictured", "rendered", "depicted") and after == "with" and out and out[-1].text not in ("is", "be", "was"):
            continue  # "I want the bedside table shown with its drawer pulled open": with its drawer open
        if t.text == "release" and out and out[-1].text in ("door", "lid") and before == out[-1].text and kind_of_word(after) is None:
            out.pop()  # "press the door release": the release (a part named by what it does: its own name, else a button)
        if before in ("", ",", ".", "and", "then", "when", "as") and t.text.isalpha() and len(t.text) > 2 and after.endswith("s") and after[:-1] in VERBS and (
                _a_name(t.text)):
            t = Token("someone", "someone", t.start, t.end)  # "Mia stamps on the pedal of the kitchen bin": a person in the story
        if t.text == "whoever" and (not out or out[-1].is_sentence_end) and (left := next((k for k in range(i + 2, min(len(tokens), i + 9))
                                                                                         if tokens[k].text == "left"), None)) is not None:
            out.append(Token("somebody", "somebody", t.start, tokens[left - 1].end, corrected_from=" ".join(w.text for w in tokens[i:left])))
            skip = left - 1  # "Whoever used the toolbox last left the lid standing up": somebody left it
            continue
        if t.text in ("need", "want") and before == "and" and out and _first_person(out):
            out.append(Token("i", "i", t.start, t.start))  # "I'm wrapping a present and need the scissors": and I need them
        if t.text == "lower" and before in ("", ",", ".", ";", ":", "then", "and", "first", "please") and kind_of_word(after) is not None and (
                i + 2 < len(tokens) and tokens[i + 2].text in ("until", "till", "to", "slowly", "gently", "fully", "flat", "completely")):
            out.extend((t, Token("the", "the", t.end, t.end)))  # "Lower door until flat": lower the door (no lower one of several)
            continue
        if t.text == "to" and after in ("left", "right") and before not in ("left", "right") and i + 2 < len(tokens) and tokens[i + 2].text in (
                "limit", "stop", "end", "side", "edge"):
            out.extend((t, Token("the", "the", t.end, t.end)))  # "flick the lever to left limit": to the left limit
            continue
        if t.text == "prop" and before in OBJECT_NOUNS and after == "'s":
            continue  # "the safe prop's combo dial": the safe's (a prop of a game scene)
        if t.text in ("joint", "joints") and i and kind_of_word(before) is not None and not (after and kind_of_word(after) is not None):
            continue  # "turn the faucet handle joint 1 rad": the handle on it
        if t.text in ("full", "complete", "whole") and before in ("a", "one") and i > 1 and tokens[i - 2].text == "of" and after in TURN_UNITS:
            continue  # "three-quarters of a full turn": of a turn
        if t.text == "flush" and before in ("the", "a") and (not after or not after.isalpha() or after in ("then", "and", "once", "twice")):
            out.extend((t, Token("button", "button", t.start, t.end)))  # "press the flush": its flush button
            continue
        if t.text == "cover" and before in ("", ",", ".", "then", "and", "to", "please", "just") and after in ("it", "them", "the", "its", "that"):
            t = Token("close", "close", t.start, t.end)  # "then cover it again": put its lid back on
        if t.text == "up" and after == "top" and (before in GENERIC_PART_NOUNS or kind_of_word(before) is not None):
            out.extend(Token(w, w, t.start, tokens[i + 1].end) for w in ("at", "the", "top"))  # "the small knob up top": at the top
            skip = i + 1
            continue
        if t.text == "right" and after in _PLACED_AT and (before in GENERIC_PART_NOUNS or kind_of_word(before) is not None):
            continue  # "the piece right at the very top": where it is, "right" only sharpens it
        if t.text == "just" and after == "enough" and i + 2 < len(tokens) and tokens[i + 2].text in ("that", "so"):
            out.append(Token("so_that", "so_that", t.start, tokens[i + 2].end))  # "..., just enough that I can reach past it": why
            skip = i + 2 + (i + 3 < len(tokens) and tokens[i + 2].text == "so" and tokens[i + 3].text == "that")
            continue
        just_far = int(t.text == "just" and after == "far")  # "just far enough to peek"
        if t.text in ("just", "far", "only") and [w.text for w in tokens[i + 1 + just_far:i + 3 + just_far]] == ["enough", "to"]:
            if out and out[-1].text == ",":
                out.pop()  # "open the door ~45 deg, just enough to see inside": the amount said, then why
            clause = next((j for j in range(len(out) - 1, -1, -1) if out[j].text in (".", ";", "!", "?", "then", "and_then")), -1)
            if clause < len(out) - 1 and not any(w.number is not None for w in out[clause + 1:]):
                out.append(Token("partway", "partway", t.start, t.end))  # "let the door down just far enough to peek": partway
            skip = i + 1 + just_far
            continue
        if t.text == "foot" and after in ("down", "off") and before in ("", ",", ".", ";", "then", "and", ":"):
            out.append(Token("step", "step", t.start, t.end))  # "foot down on the pedal", "then foot off": step on / off it
            skip = i + (after == "down" and i + 2 < len(tokens) and tokens[i + 2].text == "on")
            continue
        if t.text == "nothing" and after in ("else", "more") and (i + 2 >= len(tokens) or tokens[i + 2].is_punct):
            if out and out[-1].text == ",":
                out.pop()  # "200 degrees counter clockwise, nothing else": a remark, no step
            skip = i + 1
            continue
        elif t.text in ("into", "to") and (position := _state_position(tokens, i)) is not None:
            state, length = position
            out.append(Token(state, state, t.start, tokens[i + length - 1].end))  # "flip the catch into its locked position": shut
            skip = i + length - 1
            continue
        elif t.text in ("furthest", "farthest", "furthermost") and (extreme := _extreme_side(tokens, i)) is not None:
            side, length = extreme
            while out and (out[-1].text in ("that's", "which's", "that", "which") or (out[-1].text in _SITS and len(out) > 1 and out[-2].text in ("that", "which"))):
                out.pop()  # "the knob (that sits) furthest to the left"
            out.append(Token(f"{side}most", f"{side}most", t.start, tokens[i + length - 1].end))  # "the knob furthest to the left"
            skip = i + length - 1
            continue
        elif t.text == "'s" and (after in _STATE_AFTER_IS or (after.endswith("ing") and len(after) > 4 and not (
                i + 2 < len(tokens) and kind_of_word(tokens[i + 2].text) is not None))):  # "the toaster's browning knob": whose
            t = Token("is", "be", t.start, t.end)  # "the drawer's sticking out", "the lid's open": is, not a possessive
        elif t.text == "home" and (before in ("it", "them", "fully", "it's", "is", "they're", "are") or (before == "way" and i > 1 and tokens[i - 2].text == "the") or (
                before.isalpha() and before not in _NOT_BEFORE_HOME and (not after or after in (".", ",", ";", "!", "so", "and", "then")))):
            t = Token("shut", "shut", t.start, t.end)  # "shove it (all the way) home": in as far as it goes
        elif t.text.startswith("hand-") and t.text[5:] in VERBS:
            t = Token(t.text[5:], t.text[5:], t.start, t.end, corrected_from=t.text)  # "hand-lift the lid": lift it by hand
        elif t.text == "back" and before in _CLAUSE_STARTS and (off := _backed_off(tokens, i)):
            out.append(Token("loosen", "loosen", t.start, t.end))  # "back the cap off 90 degrees": loosen it
            out.extend(tokens[i + 1:off])
            skip = off
            continue
        elif t.text in _FULL_SIDE and after in _SIDES and before != "the" and _side_ends(tokens, i + 2):
            if out and out[-1].text == "to":
                out.pop()  # "set the lever to full left"
            out.extend(Token(w, w, t.start, t.end) for w in ("fully", "to", "the"))  # "lever: full left", "hard left": as far left as it goes
            continue
        elif t.text in _AMOUNT_ENDS and after in _SIDES and _side_ends(tokens, i + 2):
            out.extend((t, Token("to", "to", t.start, t.end), Token("the", "the", t.start, t.end)))  # "all the way left", "a bit right"
            continue
        elif t.text == "as" and (far := _as_far_side(tokens, i)) is not None:
            side, last = far  # "as far left as it will go": all the way to the left
            words = ("all", "the", "way", "to", "the", side) if side in _SIDES else ("all", "the", "way", side)
            out.extend(Token(w, w, t.start, tokens[last].end) for w in words)
            skip = last
            continue
        elif t.text == "full" and after in ("up", "down", "open", "on", "off"):
            t = Token("fully", "fully", t.start, t.end)  # "full open": as far as it goes
        elif t.text == "no" and after == "need" and i + 2 < len(tokens) and tokens[i + 2].text == "to":
            out.append(Token("don't", "don't", t.start, tokens[i + 2].end))  # "no need to touch the dial": do not
            skip = i + 2
            continue
        elif t.text == "," and after in ("which", "that") and i + 3 < len(tokens) and tokens[i + 2].text in _KEPT and tokens[i + 3].text in _KEPT_AT:
            out.extend(Token(w, w, t.start, tokens[i + 2].end) for w in (".", "it", "is"))  # "the ketchup, which lives in the door"
            skip = i + 2
            continue
        elif t.number is not None and 10 <= abs(t.number) <= 1080 and after in ROTATION_SENSE:
            out.extend((t, Token("degree", "degree", t.start, t.end)))  # "top knob 180 clockwise": degrees, the only unit that size
            continue
        elif t.text == "nothing" and out and out[-1].text in VERBS and before not in ("do", "does"):
            verb = out.pop()  # "unlatch nothing, just fold the lid down": do not unlatch
            out.extend((Token("don't", "don't", verb.start, verb.start), verb))
            continue
        elif t.text == "forget" and before in ("", ",", ".", ";", ":", "!") and after in ("the", "about", "its", "that"):
            out.extend((Token("don't", "don't", t.start, t.end), Token("use", "use", t.start, t.end)))  # "Forget the pedal - ..."
            skip = i + (after == "about")
            continue
        elif t.text in ("along", "against", "over") and after in ("the", "its") and i + 2 < len(tokens) and tokens[i + 2].text in ("back", "front"):
            t = Token("toward", "toward", t.start, t.end)  # "lies flat along the back side": toward the back
        elif t.text == "side" and before == "the" and len(out) > 1 and out[-2].text in _ON_THE_SIDE and (viewer := _facing_viewer(tokens, i + 1)):
            del out[-2:]  # "let it fall down on the side that's facing me": toward me
            out.extend((Token("toward", "toward", t.start, t.end), Token("me", "me", t.start, tokens[viewer - 1].end)))
            skip = viewer - 1
            continue
        elif t.text == "left" and (before in _LEAVERS or (out and out[-1].text in _LEAVERS) or after in ("me", "us", "him", "her", "them") or (before in ("'s", "has", "have", "'ve", "had", "'d") and i > 1 and tokens[i - 2].text in _LEAVERS)):
            t = Token("had", "have", t.start, t.end)  # "somebody left this door open": a verb, no side
        elif t.text in _TAP_SIDES and after == "water" and before in ("the", "me", "some"):
            if [w.text for w in out[-2:]] == ["give", "me"]:
                out[-2:] = [Token("run", "run", out[-2].start, out[-2].end, corrected_from="give me")]  # "give me cold water": run it
            if out and out[-1].text == "some":
                out.pop()
            if [w.text for w in out[-2:]] in (["i'd", "like"], ["i", "want"], ["i", "need"], ["we", "need"]):  # "I'd like some cold water": run it
                out[-2:] = [Token("run", "run", out[-2].start, out[-1].end, corrected_from=f"{out[-2].text} {out[-1].text}")]
            out += [Token("the", "the", t.start, t.start)] if not out or out[-1].text != "the" else []
            out += [Token("water", "water", t.start, t.end), *(Token(w, w, t.start, t.end) for w in ("to", "the")),
                    Token(_TAP_SIDES[t.text], _TAP_SIDES[t.text], t.start, t.end, corrected_from=f"{t.text} water")]
            skip = i + 1
            continue  # "run the hot water", "give me cold water": the water, run on that side
        elif t.text in _TAP_SIDES and before in ("toward", "towards", "to", "max", "full", "fully", "the", "all_the_way"):
            side = _TAP_SIDES[t.text]  # a mixer tap: hot is the viewer's left, cold the right (the convention the notes state)
            if before in ("max", "full", "fully") or t.text.endswith("est"):
                while out and out[-1].text in ("max", "full", "fully", "the", "to", "toward", "towards"):
                    out.pop()  # "swing it across to full cold", "to the hottest setting"
                out.extend(Token(w, w, t.start, t.end) for w in ("fully", "to", "the"))
            elif before in ("to", "toward", "towards"):
                out.append(Token("the", "the", t.start, t.start))
            out.append(Token(side, side, t.start, t.end, corrected_from=t.text))
            skip = i + (after in ("side", "end", "water", "position", "setting"))
            continue
        elif t.text in ("midpoint", "mid-point", "middle", "half-way", "halfway") and before == "the" and [x.text for x in tokens[i + 1:i + 3]] in (
                ["of", "its"], ["of", "the"]) and i + 3 < len(tokens) and tokens[i + 3].text in ("travel", "range", "stroke", "track", "slide", "swing", "way"):
            if len(out) >= 2 and out[-2].text in ("to", "at"):
                del out[-2:]
            else:
                out.pop()
            out.append(Token("halfway", "halfway", t.start, tokens[i + 3].end))  # "to the midpoint of its travel": halfway
            skip = i + 3
            continue
        elif t.text == "got" and before in ("it's", "that's", "she's", "he's") and out:
            out[-1] = Token(before[:-2], before[:-2], out[-1].start, out[-1].end)
            t = Token("has", "has", t.start, t.end)  # "it's got commitment issues": it has (a description, not "get")
        elif t.text == "be" and after in ("", ".", ",", ";", "!", "and", "then") and any(w.text in ("leave", "let") for w in tokens[max(i - 5, 0):i - 1]):
            t = Token("alone", "alone", t.start, t.end)  # "leave the drawer be": leave it alone
        elif t.text in ("swing", "swung") and after in ("the", "this", "that") and i + 2 < len(tokens) and tokens[i + 2].text in ("whole", "entire"):
            t = Token("turn", "turn", t.start, t.end, corrected_from=t.text)  # "swing the whole desk a quarter turn": the object turns
        elif t.text == "straight" and (after in ("across", "over", "through") or (after == "back" and before in ("it", "them"))):
            continue  # "swing it straight across to full cold": all the way over, not upright; "flick it straight back": back at once
        elif t.text == "in" and before == "back" and after == "the" and i + 2 < len(tokens) and tokens[i + 2].text in ("middle", "centre", "center"):
            t = Token("to", "to", t.start, t.end)  # "park it back in the middle": back to the middle
        elif t.text == "give" and after in ("it", "them") and i + 2 < len(tokens) and ((
                i + 3 < len(tokens) and (tokens[i + 2].number is not None or tokens[i + 2].text in NUMBER_WORDS)
                and tokens[i + 3].text.rstrip("s") in ("second", "sec", "s", "minute", "moment")) or (
                i + 3 < len(tokens) and tokens[i + 2].text == "a" and tokens[i + 3].text in _SPELLS)):
            out.append(Token("wait", "wait", t.start, tokens[i + 1].end))  # "give it two seconds": wait
            skip = i + 1
            continue
        elif t.text in ROTATION_SENSE and i + 1 < len(tokens) and tokens[i + 1].text.removesuffix("s") in TURN_UNITS and (out and (
                out[-1].number is not None or out[-1].text in ("full", "complete", "whole", "quarter", "half", "a", "one", "single"))):
            out.append(tokens[i + 1])  # "one full counterclockwise turn": the turn, then which way
            out.append(t)
            skip = i + 1
            continue
        out.append(t)
    return out
