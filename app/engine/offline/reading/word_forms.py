"""Phrases that say what the lexicon knows in another form, rewritten before clauses are split.

"let it sit there for 2 s" (keep it there), "at the very same moment" (at the same time), "the middle one of the three
knobs" (the middle knob), "swing the lever right as far as it goes" (to the right), "; that unlatches the door, which then
drops down open" (so it unlatches the door and the door drops), "press it down until it catches" (all the way), "the
door carries a wheel and a dial" (has), "make one full revolution" / "give it one complete revolution" (turn one full
revolution), "the knob which is low on the front" (the lower knob), "Enter a code on the keypad: top-left key, then ..."
(press each), "the upper half of the laptop" (the upper part), "the rack in that upper compartment" (the upper
compartment's rack), "the knob on the left side of the handle" (left of it), "once it is open the left drawer follows"
(the condition ends after "open"), "put a bowl of soup in the microwave" / "get it out of the oven" (open the microwave /
the oven: what holds a thing that is no part is opened; the note says so), "the glass plate inside turned once" (the plate
turned once), "135 degrees from the keyboard" (from closed), "On the keypad hit ..." (On the keypad, hit ...),
"let some fresh air in" (open it), "the bigger, lower one" (one part, two qualifiers).
"""

from __future__ import annotations

import itertools
from dataclasses import replace

from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import ANGLE_UNITS, CLOSED_AGAINST, LENGTH_UNITS, OBJECT_NOUNS, SIZES, SPATIAL
from app.engine.offline.reading.framing import scan, until_break
from app.engine.offline.reading.holders import (
    COMPARTMENTS,
    SIDE_OF,
    accessed,
    asked_after,
    going_in,
    heated,
    inside_end,
    looked_inside,
    looked_into,
    names_kind,
    packed,
    stowed,
)
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.rewrites import motion_verb
from app.engine.offline.reading.token import Token

_STILL_VERBS = frozenset({"sit", "stay", "rest", "remain", "hang", "stand"})
_SINGLE_COUNTED = frozenset({"turn", "revolution", "rotation", "spin", "twist", "press", "tap", "click", "push", "pull", "notch", "step",
                             "second", "degree", "full", "quarter", "half", "time", "stroke", "motion", "movement", "go", "smooth", "quick"})
_NO_SELECTORS = frozenset({"the", "a", "an", "any", "each", "every", "no", "which", "just", "only", "and", "or", "of", "that", "this"})
_NOT_BEFORE_SIDE = frozenset({"the", "to", "on", "at", "its", "their", "his", "her", "my", "your", "our", "a", "far", "top", "bottom", "upper", "lower",
                              "front", "back", "rear", "middle", "centre", "center", "and", "or", "is", "are", "was", "be", "from", "then", "in",
                              "of", "turned", "extreme", "hard", "full", "fully", "all", "most", "very", "this", "that", "which", "one"})
_AFTER_SIDE = frozenset({"as_far_as_it_goes", "as_far_as_possible", "as_far_as_it_will_go", "as_far_as", "all_the_way", "fully", "completely", "until",
                         "till", ".", ",", ";", "!", "then", "and_then", "to_the_limit", "to_the_end", "to_the_stop", "a_bit", "a_little",
                         "slightly", "by", "hard", "again"})
_INTRANSITIVE_ENDS = frozenset({"open", "down", "up", "out", "shut", "closed", "away", "back", "forward", "free", "ajar", ".", ",", "!"})
_CATCHES = frozenset({"catches", "clicks", "latches", "locks", "engages", "bottoms", "stops", "snaps", "seats", "detents"})
_ENABLING = frozenset({"lets", "allows", "enables", "permits", "frees", "causes", "makes"})
_DESCRIBING = frozenset({"carries", "features", "sports", "bears", "houses", "holds", "includes", "contains"})
_PLACED = frozenset({"is", "sits", "sitting", "mounted", "placed", "located", "set", "that's", "which's"})
_END_STATES = frozenset({"open", "opened", "closed", "shut", "down", "up", "out", "done", "finished", "there", "clear", "in"})
_ENTERING = frozenset({"enter", "punch", "type", "key", "input", "dial", "tap", "press"})
_TRIGGERS = frozenset({"trips", "triggers", "disengages", "frees", "springs", "kicks"})
_REGION_OF = frozenset({"half", "part", "section", "portion", "piece", "bit", "panel"})
_MOMENTS = frozenset({"moment", "instant", "time"})


_LENGTHS = frozenset({"m", "cm", "mm", "metre", "metres", "meter", "meters", "inch", "inches", "foot", "feet", "centimetres", "centimeters"})


def _same_moment(tokens: list[Token], i: int) -> int:
    """The length of "at the (very / exact) same moment / instant" at ``i``, else 0."""
    words = [t.text for t in tokens[i:i + 5]] + ["", "", "", "", ""]
    if words[:2] != ["at", "the"] and words[:3] != ["at", "exactly", "the"]:
        return 0
    k = 3 if words[2] in ("very", "exact") else 2
    if words[1:3] == ["exactly", "the"]:
        k = 3  # "at exactly the same moment"
    return k + 2 if words[k] == "same" and words[k + 1] in _MOMENTS else 0


def _one_of_counted(tokens: list[Token], i: int, out: list[Token]) -> tuple[int, list[Token]] | None:
    """"the middle one of the three knobs" at "one" -> (tokens read, [knob]); "... one of the three" -> (4, [one])."""
    words = [t.text for t in tokens[i:i + 5]] + ["", "", "", "", ""]
    if words[0] != "one" or words[1:3] != ["of", "the"] or i + 3 >= len(tokens) or tokens[i + 3].number is None:
        return None
    if len(out) < 2 or not out[-1].text.isalpha() or out[-1].text in _NO_SELECTORS or "the" not in [w.text for w in out[-3:-1]]:
        return None  # "one of the three knobs": any one, said so
    nouns = list(itertools.takewhile(lambda w: w.text.isalpha(), tokens[i + 4:i + 7]))
    from lemminflect import getLemma

    for k in range(len(nouns), 0, -1):  # "the bottom one of the two microwave dials": the bottom microwave dial
        lemmas = getLemma(nouns[k - 1].text, upos="NOUN")
        if nouns[k - 1].text.endswith("s") and lemmas and lemmas[0] != nouns[k - 1].text and (k > 1 or not motion_verb(nouns[0].text)):
            return 4 + k, [*nouns[:k - 1], replace(nouns[k - 1], text=lemmas[0], lemma=lemmas[0])]
    return 4, [tokens[i]]


def _finite(token: Token) -> bool:
    """"unlatches", "releases": a verb of the third person (a word of a known verb ending in -s)."""
    return token.text.endswith("s") and len(token.text) > 3 and motion_verb(token.text)


def _which_then(tokens: list[Token], i: int, out: list[Token]) -> Token | None:
    """At "which" in "..., which then drops down open" right after "the X" (X a noun): X, else None."""
    if tokens[i].text != "which" or len(out) < 3 or out[-1].text != "," or out[-3].text != "the" or not out[-2].text.isalpha():
        return None
    j = i + 1 + (i + 1 < len(tokens) and tokens[i + 1].text in ("then", "in_turn"))
    if j + 1 >= len(tokens) or not _finite(tokens[j]) or tokens[j + 1].text not in _INTRANSITIVE_ENDS:
        return None
    return out[-2]


def _laps(tokens: list[Token], i: int) -> bool:
    """At "make": "make one full revolution", "do two complete turns", "complete a rotation" (a turn told as a noun)."""
    words = [t.text for t in tokens[i + 1:i + 4]]
    k = 1 if words[:1] and (words[0] in ("a", "an", "one", "two", "three", "half") or tokens[i + 1].number is not None) else 0
    if not k:
        return False
    k += words[k:k + 1] in (["full"], ["complete"], ["whole"])
    return words[k:k + 1] != [] and words[k].rstrip("s") in ("revolution", "turn", "rotation", "spin", "circle", "lap")


def _condition_open(out: list[Token]) -> bool:
    """``out`` ends in "once / when / after <a few words> is" (a condition whose end state comes next)."""
    since = next((k for k in range(len(out) - 1, max(len(out) - 7, -1), -1) if out[k].text in ("once", "when", "after", "as_soon_as")), None)
    return since is not None and len(out) - since >= 3 and out[-1].text in ("is", "are", "'s", "it's", "fully", "all_the_way", "completely") and not any(
        w.is_punct for w in out[since:])


def _code_heading(tokens: list[Token], i: int) -> int:
    """The length of "Enter a (three-key) code on the keypad:" at ``i`` (a code told key by key after the colon), else 0."""
    colon = next((k for k in range(i, min(i + 12, len(tokens))) if tokens[k].text == ":" or tokens[k].is_sentence_end), None)
    if colon is None or tokens[colon].text != ":":
        return 0
    words = [t.text for t in tokens[i:colon]]
    told = any(w in ("code", "combination", "pin", "passcode", "sequence") for w in words) and not any(t.number is not None for t in tokens[i:colon])
    return colon - i + 1 if told and words[0] in _ENTERING else 0


def _in_compartment(tokens: list[Token], i: int, out: list[Token]) -> tuple[int, int, list[Token]] | None:
    """At "in" of "the (upper) rack in that upper compartment" / "out of the upper oven compartment": (tokens read, where
    the phrase starts in ``out``, its tokens: "the upper compartment 's (upper) rack"); "the rack in that compartment": "its
    rack" (the compartment last opened). Else None."""
    words = [t.text for t in tokens[i:i + 5]] + ["", ""]
    the = len(out) - 2
    while the >= 0 and out[the].text in SIDE_OF | {"middle"}:
        the -= 1  # "the upper rack in the bottom compartment"
    inside = 1 if words[0] in ("inside", "within") else 2 if words[:2] == ["in", "there"] else 0  # "the rack in there (all the way) out"
    clause = out[max((n + 1 for n, t in enumerate(out) if t.is_punct), default=0):][-6:]
    out_before = any(t.text in ("out", "remove", "withdraw") for t in clause)  # "slide out the rack inside it" (this clause's own)
    if inside and out and names_kind(out[-1].text) and ("out" in words[inside:inside + 3] or out_before):
        first = next((k for k in range(len(out) - 1, max(-1, len(out) - 7), -1) if out[k].text == "the"), None)  # "the higher of the 2 racks"
        if first is not None:  # "open the door and slide the rack inside (all the way) out": the rack behind that door
            return inside + (inside == 1 and words[1] in ("it", "there")), first, [replace(out[first], text="its", lemma="its"), *out[first + 1:]]
    if the < 0 or out[the].text != "the":
        return None
    if words[0] not in ("in", "inside", "of", "out_of", "from") or words[1] not in ("the", "that", "this"):
        return None
    if words[2] in COMPARTMENTS and words[1] != "the":  # "in that compartment": the one just opened
        return 3 + (words[3] in COMPARTMENTS), the, [replace(out[the], text="its", lemma="its"), *out[the + 1:]]
    sized = int(words[2] in SIZES)  # "in the small top compartment"
    words = words[:2] + words[2 + sized:] + [""]
    if words[2] not in ("upper", "lower", "top", "bottom", "left", "right", "middle") or words[3] not in COMPARTMENTS:
        return None
    last = i + 3 + sized + (words[4] in COMPARTMENTS)  # "the upper oven compartment"
    out_word = [replace(tokens[i], text="out", lemma="out")] if tokens[i].text == "out_of" else []  # "get the tray out of the top oven"
    return last + 1 - i, the + 1, [tokens[i + 2 + sized], tokens[last], Token("'s", "'s", tokens[last].end, tokens[last].end), *out[the + 1:], *out_word]


def _of_the_object(tokens: list[Token], j: int) -> int:
    """The length of "of the laptop" / "of the microwave's front" at ``j`` (the whole object named), else 0."""
    words = [t.text for t in tokens[j:j + 6]] + ["", "", "", "", "", ""]
    if words[0] != "of" or words[1] not in ("the", "this", "its", "that") or words[2] not in OBJECT_NOUNS:
        return 0
    return 5 if words[3] == "'s" and words[4] in ("front", "face", "side", "body") else 3


def _amount_said(out: list[Token]) -> list[Token]:
    """The last amount said before ("halfway", "30 cm"), or nothing."""
    for k in range(len(out) - 1, -1, -1):
        if out[k].text in ("halfway", "all_the_way"):
            return [out[k]]
        if out[k].number is not None and k + 1 < len(out) and (out[k + 1].text in ANGLE_UNITS or out[k + 1].lemma in _LENGTHS):
            return out[k:k + 2]
    return []


_LENGTHS = frozenset(LENGTH_UNITS) - {"in"}
"""Units of a distance said before "that far" ("in" after a number is mostly "in 2 seconds")."""


def _let_through(tokens: list[Token], i: int) -> int:
    """The index after "let (some fresh) air in" / "let the steam out" at ``i`` when that is the whole request (something
    that is no part let through the object, and no motion said with it), else 0."""
    k = i + 1
    while k < len(tokens) and k < i + 5 and tokens[k].text not in ("in", "out", "inside", "escape", "out_of") and not tokens[k].is_punct:
        k += 1
    thing = [w.text for w in tokens[i + 1:k]]
    if not thing or k >= len(tokens) or tokens[k].is_punct or any(w in ("it", "them", "go") or kind_of_word(w) is not None or w in OBJECT_NOUNS for w in thing):
        return 0
    if i and tokens[i - 1].text in ("to", "and", "so"):
        return 0  # "hold the lid up to let the steam out": why, the motion is said
    end = k + 1
    if tokens[k].text == "out_of" and [t.text for t in tokens[end:end + 1]] in (["the"], ["its"]) and end + 1 < len(tokens) and tokens[end + 1].text in OBJECT_NOUNS:
        end += 2  # "let a bit of steam out of the pot"
    elif [t.text for t in tokens[end:end + 2]] in (["from", "the"], ["out_of", "the"], ["from", "its"]) and end + 2 < len(tokens) and (
            tokens[end + 2].text in OBJECT_NOUNS):
        end += 3  # "let a bit of steam escape from the pot"
    elif [t.text for t in tokens[end:end + 2]] == ["through", "the"] and end + 2 < len(tokens) and (
            tokens[end + 2].text in OBJECT_NOUNS or kind_of_word(tokens[end + 2].text) is not None):
        end += 3  # "let some fresh air in through the window"
    end += end < len(tokens) and tokens[end].text in ("please", "pls", "plz")  # "let some fresh air in please"
    return end if end == len(tokens) or tokens[end].is_sentence_end else 0  # "let some steam out - crack the lid 3 cm": the how follows


def _form_step(tokens: list[Token], i: int, out: list[Token]) -> int | None:
    """At ``i``: the index after a phrase there, once its known form is in ``out``, or None."""
    t = tokens[i]
    after = [w.text for w in tokens[i + 1:i + 5]]
    if t.text == "let" and len(after) >= 2 and after[0] in ("it", "them") and after[1] in _STILL_VERBS:
        out += [replace(t, text="keep", lemma="keep"), tokens[i + 1]]  # "let it sit there for two seconds": a hold
        return i + 3
    if moment := _same_moment(tokens, i):
        out.append(Token("at_the_same_time", "at_the_same_time", t.start, tokens[i + moment - 1].end))
        return i + moment  # "at the very same moment"
    if t.text == "single" and out and out[-1].text == "a" and after[:1] and after[0].isalpha() and after[0] not in _SINGLE_COUNTED:
        return i + 1  # "a single little button": one button, not a part called "single"
    if chosen := _one_of_counted(tokens, i, out):
        out.extend(chosen[1])
        return i + chosen[0]  # "the middle one of the three (knobs)": the middle knob
    if t.text == "to" and after[:2] in (["its", "left"], ["its", "right"]):
        side = after[1]  # "shift the cabinet half a metre to its left": read as the viewer's left, with a note that says so
        out.append(Token(f"to_the_{side}", f"to_the_{side}", t.start, tokens[i + 2].end, corrected_from=f"to its {side}"))
        return i + 3
    if t.text in ("left", "right") and out and out[-1].text.isalpha() and out[-1].text not in _NOT_BEFORE_SIDE and (
            not after or after[0] in _AFTER_SIDE):
        out.append(Token(f"to_the_{t.text}", f"to_the_{t.text}", t.start, t.end))  # "swing the lever right as far as it goes"
        return i + 1
    if t.text == "it" and out and out[-1].text in (":", ";", ",") and len(after) >= 2 and after[0] in ("should", "will", "must") and motion_verb(after[1]):
        out[-1] = replace(out[-1], text=",", lemma=",")
        out += [Token("so", "so", t.start, t.end), t]  # "hit the button to release the door - it should swing out to 60 degrees"
        return i + 2
    if t.text in ("that", "this") and out and out[-1].text in (";", ".", ":") and len(after) >= 2 and (
            _finite(tokens[i + 1]) or after[0] in _TRIGGERS) and after[1] != "is":  # "... - that trips the latch and the door swings open"
        out[-1] = replace(out[-1], text=",", lemma=",")
        out += [Token("so", "so", t.start, t.end), Token("it", "it", t.start, t.end)]  # "hit the button; that unlatches the door"
        return i + 1
    if t.text in ("that", "this") and out and out[-1].text in (",", ";", ".", "and") and after[:1] and after[0] in _ENABLING:
        which = Token("which", "which", t.start, t.end)  # "..., and that lets the door swing open": what the step before allows
        out[-1:] = [replace(out[-1], text=",", lemma=","), which] if out[-1].text != "," else [out[-1], which]
        return i + 1
    if (named := _which_then(tokens, i, out)) is not None:
        out[-1:] = [Token("and", "and", t.start, t.end), Token("the", "the", t.start, t.end), named]
        return i + 1  # "..., which then drops down open" after "the door": the door drops down open
    if t.text == "round" and out and out[-1].text.isalpha() and after[:1] and kind_of_word(after[0]) is not None and not motion_verb(out[-1].text):
        return i + 1  # "the small round dial": its shape, not "turn round"
    if t.text == "until" and after[:1] == ["it"] and len(after) > 1 and after[1] in _CATCHES:
        out.append(Token("all_the_way", "all_the_way", t.start, t.end))  # "press it down until it catches": all the way
        return until_break(tokens, i, frozenset({",", ";", ".", "!", "?", "then", "and_then", "and", "like"}))
    if t.text in _DESCRIBING and out and out[-1].text.isalpha() and kind_of_word(out[-1].text) is not None and after[:1] and (
            after[0] in ("a", "an", "two", "three", "four", "both") or tokens[i + 1].number is not None):
        out.append(replace(t, text="has", lemma="has"))  # "the safe door carries a three-spoke wheel and a dial": a description
        return i + 1
    if t.text in ("left", "kept", "held") and out and out[-1].text == "and" and after[:1] and after[0] in ("there", "open", "in_place", "like_that"):
        out += [replace(t, text="keep", lemma="keep"), Token("it", "it", t.start, t.end)]  # "... pulled out and left there for 4 s"
        return i + 1
    if t.text in ("make", "makes", "do", "does", "complete", "completes") and _laps(tokens, i):
        finite = t.text in ("makes", "does", "completes")  # "the turntable does one full revolution, the door closes": a clause of its own
        out.append(replace(t, text="turns" if finite else "turn", lemma="turn"))  # "let the turntable make one full revolution": turn one full revolution
        return i + 1
    if t.text in ("low", "high") and out and out[-1].text in _PLACED and after[:1] and after[0] in ("on", "down", "up", "in"):
        out.append(replace(t, text="lower" if t.text == "low" else "upper", lemma="lower" if t.text == "low" else "upper"))
        return i + (1 + (after[0] in ("down", "up")))  # "the knob which is low on the front": the lower knob
    if (not out or out[-1].is_sentence_end or out[-1].text in ("then", "and_then", ",", "and")) and (told := _code_heading(tokens, i)):
        out.append(Token("press", "press", t.start, tokens[i + told - 1].end))  # "Enter a code on the keypad: top-left key, then ..."
        return i + told
    if t.text in ("give", "gives") and any(w.text.rstrip("s") in ("revolution", "rotation") for w in tokens[i + 1:i + 7]):
        out.append(replace(t, text="turn", lemma="turn"))  # "give the turntable one complete revolution": turn it one revolution
        return i + 1
    if t.text in ("on", "at", "to") and after[:1] == ["the"] and len(after) >= 4 and after[1] in ("left", "right", "left-hand", "right-hand") and (
            after[2:4] == ["side", "of"]) and len(tokens) > i + 6 and kind_of_word(tokens[i + 6].text if tokens[i + 5].text in ("the", "its") else tokens[i + 5].text):
        side = after[1].split("-")[0]
        out.append(Token(f"{side}_of", f"{side}_of", t.start, tokens[i + 4].end))  # "the knob on the left side of the handle": left of it
        return i + 5
    if t.text in ("fly", "flies", "flew") and after[:1] and after[0] in ("open", "shut", "closed", "up", "out", "back", "wide_open"):
        said = {"flies": "swings", "flew": "swung"}.get(t.text, "swing")  # "the lid flies up": it swings up (its tense kept)
        out.append(replace(t, text=said, lemma="swing"))  # "both doors fly open": swing open ("fly the bin to the moon" is no motion)
        return i + 1
    if t.text == "complete" and after[:1] and after[0].rstrip("s") in ("revolution", "turn", "rotation", "spin"):
        out.append(replace(t, text="full", lemma="full"))  # "one complete revolution": a full one
        return i + 1
    if t.text == "very" and out and out[-1].text == "the" and after[:1] and after[0] in ("top", "bottom", "front", "back", "left", "right", "end", "rear"):
        return i + 1  # "the piece on the very top": on the top
    if t.text in _REGION_OF and out and out[-1].text in SIDE_OF and (whole := _of_the_object(tokens, i + 1)):
        out.append(replace(t, text="part", lemma="part"))  # "the upper half of the laptop": the upper part
        return i + (1 + whole)
    if t.text in _REGION_OF and out and out[-1].text in SIDE_OF and after[:2] == ["of", "the"] and any(
            kind_of_word(w) is PartKind.SWITCH for w in after[2:4]):
        out.append(replace(t, text="end", lemma="end"))  # "press the lower half of the rocker switch": its lower end
        return i + 1
    if (moved := _in_compartment(tokens, i, out)) is not None:
        out[moved[1]:] = moved[2]  # "the rack (that sits) in that upper compartment": the upper compartment's rack
        return i + moved[0]
    if t.text in _END_STATES and after[:1] and after[0] in ("the", "its", "a", "an") and _condition_open(out):
        out += [t, Token(",", ",", t.end, t.end)]  # "once it is open the left drawer follows": the condition ends here
        return i + 1
    if t.text == "that" and after[:1] and after[0] in ("much", "far") and (again := _amount_said(out)):
        out.extend(replace(w, start=t.start, end=tokens[i + 1].end, corrected_from=None if k else "that " + after[0]) for k, w in enumerate(again))
        return i + 2  # "I only need the drawer out about halfway, can you slide it out that much?": the amount said before
    if t.text == "straight_up" and ((i + 1 < len(tokens) and (after[0] == "by" or tokens[i + 1].number is not None)) or (
            i > 1 and tokens[i - 2].number is not None and tokens[i - 1].text in _LENGTHS)):  # "0.5 m straight up"
        out.append(Token("up", "up", t.start, t.end))  # "move the bucket straight up by 30 cm": the way it goes, not upright
        return i + 1
    if t.text.endswith("-spoke") and after[:1] == ["wheel"]:
        out.append(replace(t, text="spoke", lemma="spoke"))  # "a big three-spoke wheel": a spoke wheel (a handle)
        return i + 1
    if t.text in ("check", "look", "peek", "peep", "glance") and after[:1] and after[0] in ("on", "at", "in_on") and (end := inside_end(tokens, i)):
        out += [Token("open", "open", t.start, tokens[end - 1].end, corrected_from=" ".join(w.text for w in tokens[i:end])),
                Token("it", "it", t.start, t.start)]  # "let me check on the roast in there": open it to look inside
        return end
    if t.text in ("check", "look", "peek", "peep", "glance") and after[:1] and after[0] in ("inside", "into", "in") and (end := looked_into(tokens, i)):
        out += [Token("open", "open", t.start, tokens[i + 1].end, corrected_from=" ".join(w.text for w in tokens[i:end])), *tokens[i + 2:end]]
        return end  # "peek inside the microwave", "look in the cupboard at the bottom": open it to look in
    if t.text in ("see", "check") and after[:1] and after[0] in ("how", "if", "whether") and (end := asked_after(tokens, i)):
        out += [Token("open", "open", t.start, tokens[end - 1].end, corrected_from=" ".join(w.text for w in tokens[i:end])),
                Token("it", "it", t.start, t.start)]  # "let me see how the soup is doing": open it to look inside
        return end
    if (reached := accessed(tokens, i, out)) is not None:
        end, opened = reached
        out.append(Token("open", "open", t.start, tokens[end - 1].end, corrected_from=" ".join(w.text.replace("_", " ") for w in tokens[i:end])))
        out.extend(opened or [Token("it", "it", t.start, t.start)])  # "time to load the dishes", "wipe out the inside of the microwave"
        return end
    if (looked := looked_inside(tokens, i)) is not None:
        article = next((k for k in range(i + 1, looked) if tokens[k].text in ("a", "an")), i + 1)
        cleaned = tokens[i + 1:article] if article > i + 2 and any(w.text in OBJECT_NOUNS or names_kind(w.text) for w in tokens[i + 1:article]) else []
        out += [Token("open", "open", t.start, tokens[looked - 1].end, corrected_from=" ".join(w.text for w in tokens[i:looked])),
                *(cleaned or [Token("it", "it", t.start, t.start)])]
        return looked  # "give the soup a stir", "take a quick look": open it to reach in; "give the lower oven a clean": that oven
    if (stowing := packed(tokens, i, out)) is not None:
        start, name, end = stowing
        said = " ".join(w.text.replace("_", " ") for w in (*out[start:], *tokens[i:end]))
        del out[start:]
        out += [Token("close", "close", t.start, tokens[end - 1].end, corrected_from=said), Token("the", "the", t.start, t.start),
                Token(name, name, t.start, t.start)]
        return end  # "the laptop has to go in my bag": folded shut for it
    if (subject := going_in(tokens, i, out)) is not None:
        said = " ".join(w.text.replace("_", " ") for w in (*out[subject:], t, tokens[i + 1]))
        del out[subject:]
        out.append(Token("open", "open", t.start, tokens[i + 1].end, corrected_from=said))  # "plates that need to go in the dishwasher"
        return i + 2
    if (warmed := heated(tokens, i)) is not None:
        begin, end = warmed
        said = " ".join(w.text.replace("_", " ") for w in tokens[i:begin])
        out.append(Token("open", "open", t.start, tokens[begin - 1].end, corrected_from=said))  # "heat up my leftovers in the microwave"
        out.extend(tokens[begin:end])
        out += [Token(",", ",", tokens[end - 1].end, tokens[end - 1].end), Token("then", "then", t.start, t.start),
                Token(t.text, t.lemma, t.start, t.end), Token("it", "it", t.start, t.start)]
        return end
    if holder := stowed(tokens, i):
        said = " ".join(w.text.replace("_", " ") for w in tokens[i:holder])
        out.append(Token("open", "open", t.start, tokens[holder - 1].end, corrected_from=said))  # "put a bowl of soup in the microwave"
        if holder == len(tokens) or tokens[holder].is_punct or tokens[holder].text in ("to", "for", "and", "so", "without", "then", "before", "but"):
            out.append(Token("it", "it", t.start, t.start))  # "put my leftovers inside": the object holds them
        return holder
    if t.text in ("inside", "within", "in_there") and out and kind_of_word(out[-1].text) is not None and after[:1] and after[0].endswith("ed") and motion_verb(after[0]):
        return i + 1  # "the glass plate inside turned once": where the part is, before what it should do
    if t.text == "from" and out and (out[-1].text in ANGLE_UNITS or out[-1].text[:-1] in ANGLE_UNITS) and after[:1] and after[0] in ("the", "its") and after[1:2] and after[1] in CLOSED_AGAINST:
        out.append(t)
        out.append(Token("closed", "closed", tokens[i + 1].start, tokens[i + 2].end, corrected_from=f"the {after[1]}"))
        return i + 3  # "open to 135 degrees from the keyboard": from closed
    if t.text in ("on", "at") and (not out or out[-1].is_sentence_end) and after[:1] == ["the"] and len(after) > 2 and kind_of_word(after[1]) is not None and (
            after[2] in VERBS and after[2] not in SPATIAL):
        out += [*tokens[i:i + 3], Token(",", ",", tokens[i + 2].end, tokens[i + 2].end)]
        return i + 3  # "On the keypad hit the top-left button": where, then the command
    if t.text == "let" and (through := _let_through(tokens, i)):
        out += [Token("open", "open", t.start, tokens[through - 1].end, corrected_from=" ".join(w.text for w in tokens[i:through])),
                Token("it", "it", t.start, t.start)]
        return through  # "let some fresh air in", "let the steam out": open it
    if t.text == "," and out and (out[-1].text in SIZES or out[-1].text in SPATIAL) and after[:1] and (after[0] in SIZES or after[0] in SPATIAL) and (
            len(after) > 1 and (after[1] == "one" or kind_of_word(after[1]) is not None)):
        return i + 1  # "the bigger, lower one": two qualifiers of one part
    if t.text == "also" and out and not out[-1].is_punct:
        return i + 1  # "open also the small upper door"
    if t.text == "to" and len(after) >= 1 and any(w.text == "make" for w in out[-6:]) and out and out[-1].text.isalpha() and out[-1].text != "make" \
            and tokens[i + 1].text.isalpha() and tokens[i + 1].text in ("come", "go", "open", "close", "move", "slide", "swing", "turn", "rise",
                                                                        "drop", "fall", "pop", "spin", "lift", "shut"):
        return i + 1  # "make the lower drawer to come out": make it come out

    return None


def known_forms(tokens: list[Token]) -> list[Token]:
    """``tokens`` with the phrases above in the forms the lexicon knows."""
    return scan(tokens, _form_step)
