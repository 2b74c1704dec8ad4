"""Token rewrites: words that say what the lexicon already knows in another form.

Chat shorthand ("cn u" -> "can you"), the viewer's side ("to my left" -> "to the left"), corrections ("60 degrees... no
wait, make it 45" -> a clause ``instead 45``), politeness and asides dropped ("please", "for me", "could you"), what is to
be left alone ("leave the lid as it is", "the plate stays still", "neither knob" -> ``without``). They run on tokens, after
the raw text is split (:mod:`.tokens`), so every rewritten token keeps the span of the words it stands for.
"""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache

from app.engine.lexicon.kinds import info
from app.engine.lexicon.said_otherwise import ADVERB_PARTICLES, SAME_MEANING, SHORTHAND
from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import (
    ANGLE_UNITS,
    ASIDE_PHRASES,
    ASIDE_WORDS,
    CORRECTION_LEADS,
    CORRECTIONS,
    DETERMINERS,
    OBJECT_NOUNS,
    OTHER_WORDS,
    REQUEST_PHRASES,
    SPATIAL,
    VIEWER_POSSESSIVES,
)
from app.engine.offline.reading.far_side import far_side
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

_JOINT_WORDS = frozenset({"hinge", "hinges", "joint", "pivot", "axle", "slide", "slides", "runners"})
_NEAR_WORDS = frozenset({"nearest", "closest", "near", "nearer", "closer", "next_to", "beside", "by", "from", "furthest", "farthest", "farther", "further"})
"""Before "the lid's hinge" they place another part by that hinge ("the knob nearest the lid's hinge")."""
_AFTER_HAND = frozenset({"to", "and", "then", "on", "with", "while", "side", "so", "until", "as"})
_KNOWN_NOUNS = frozenset({"ceiling", "opening", "housing", "casing", "railing", "fitting", "setting", "bearing", "mounting", "coupling"})
_STAYS = frozenset({"stays_where_it_is", "stay_where_it_is", "stays_put", "stay_put", "stays_as_it_is", "stay_as_it_is"})
_STAYING = frozenset({"stays", "stay", "remains", "remain"})
_AS_IT_IS = frozenset({"still", "put", "alone", "untouched", "unchanged", "motionless", "unmoved", "closed", "shut", "in_place", "stationary", "fixed",
                       "seated", "docked", "parked", "planted", "attached", "mounted"})


def _kept_as_is(tokens: list[Token], i: int) -> bool:
    """"(the plate) stays still / (exactly) put / shut / as is", "the screen angle stays." with no time said: left as it
    is, not a hold ("stays shut for 2 s")."""
    j = i + 1 + (i + 1 < len(tokens) and tokens[i + 1].text == "exactly")
    if j >= len(tokens) or tokens[j].is_punct:
        return True
    if [t.text for t in tokens[j:j + 2]] == ["as", "is"] or [t.text for t in tokens[j:j + 3]] in (["where", "it", "is"], ["where", "they", "are"]):
        return True
    if tokens[j].text not in _AS_IT_IS:
        return False
    return not any(t.number is not None or t.text in ("for", "while", "until") for t in tokens[j + 1:j + 5])


_VIEWING = frozenset({"face", "look", "see", "stand", "view", "watch"})
_CLAUSE_BREAKS = frozenset({",", ";", ".", "and", "then", "but", "while", "with"})

_AS_IS = (("as", "it", "is"), ("as", "they", "are"), ("where", "it", "is"), ("where", "they", "are"), ("way", "it", "is"), ("way", "they", "are"),
          ("how", "it", "is"), ("how", "they", "are"), ("as", "found", "."), ("as", "found", ","), ("as", "you", "found"))


def _as_they_are(tokens: list[Token], i: int) -> bool:
    """"leave X (exactly) as it is / where they are", within the next ten words and before any other clause."""
    for j in range(i + 2, min(i + 12, len(tokens))):
        if tokens[j].is_sentence_end or tokens[j].text in ("then", "but"):
            return False
        if tuple(t.text for t in tokens[j:j + 3]) in _AS_IS or (tuple(t.text for t in tokens[j:j + 2]) == ("as", "is") and (
                j + 2 == len(tokens) or tokens[j + 2].is_punct)):
            return True  # "leave the door as it is", "leave door as is"
    return False


@lru_cache(maxsize=4096)
def motion_verb(word: str) -> bool:
    from lemminflect import getAllLemmas

    return word in VERBS or any(lemma in VERBS for lemma in getAllLemmas(word).get("VERB", ()))


_CONVENTION = frozenset({"left", "right", "and", "/", "or", "as", "seen", "viewed", "looking", "from", "the", "front", "viewer", "outside",
                         "is", "are", "means", "mean", "sides", "side", ",", "facing", "it", "camera", "'s", "view", "point", "of"})


def _side_convention(tokens: list[Token], i: int) -> int:
    """The length of a sentence at ``i`` that only says how left and right are meant ("Left/right from the front."), else 0."""
    end = next((k for k in range(i, len(tokens)) if tokens[k].is_sentence_end), len(tokens))
    words = {t.text for t in tokens[i:end]}
    viewpoint = words & {"front", "viewer", "outside", "camera"}
    return end - i + (end < len(tokens)) if viewpoint and words & {"left", "right"} and words <= _CONVENTION else 0


def drop_asides(tokens: list[Token]) -> list[Token]:
    """Politeness and the beneficiary say nothing about the motion: "please", "for me"."""
    out: list[Token] = []
    skip = 0
    for i, token in enumerate(tokens):
        if skip:
            skip -= 1
            continue
        if token.text in ASIDE_WORDS or (token.text == "so" and (not out or out[-1].is_sentence_end) and i and tokens[i - 1].text in ASIDE_WORDS):
            continue  # "ok so bottom drawer, open it 40 cm": the "so" of a filler
        if (not out or out[-1].is_sentence_end) and (convention := _side_convention(tokens, i)):
            skip = convention - 1  # "Left and right as seen from the front.": how sides are meant (always so), no step
            continue
        after = tokens[i + 1].text if i + 1 < len(tokens) else ""
        if token.text == "al" and after == "the":
            token = replace(token, text="all", lemma="all", corrected_from="al")  # "open it al the way"
        if token.text in ("left_hand", "right_hand") and after.isalpha() and after not in _AFTER_HAND:
            side = token.text.split("_")[0]
            token = replace(token, text=f"{side}-hand", lemma=f"{side}-hand")  # "the right hand fridge door"
        if token.text == "'s" and after in _JOINT_WORDS and out and out[-1].text.isalpha() and not any(t.text in _NEAR_WORDS for t in out[-4:]):
            skip = 1  # "drive the pail handle's hinge to its far limit": the part on that hinge
            continue
        if token.text == "out_of" and [t.text for t in tokens[i + 1:i + 3]] == ["the", "way"] and any(
                (kind := kind_of_word(t.text)) is not None and info(kind).hinged for t in out[-3:]):
            token, skip = replace(token, text="open", lemma="open"), 2  # "get the door out of the way": open it
        elif token.text == "out_of" and after in ("the", "its") and i + 2 < len(tokens) and tokens[i + 2].text in OBJECT_NOUNS and any(
                kind_of_word(t.text) is not None for t in out[-4:]) and (i + 3 == len(tokens) or tokens[i + 3].is_punct):
            token, skip = replace(token, text="out", lemma="out"), 2  # "get the top tray out of the oven": out, from the object itself
        if token.text in ("do", "doing") and after == "up" and i + 2 < len(tokens) and (tokens[i + 2].text in DETERMINERS or tokens[i + 2].text in (
                "both", "all", "each", "every")):
            token, skip = replace(token, text="fasten", lemma="fasten"), 1  # "then do up the left clasp": fasten it
        if token.text == "like" and i + 1 < len(tokens) and tokens[i + 1].number is not None:
            if out and out[-1].text == "," and any(t.text == "right_angle" for t in out) and i + 2 < len(tokens) and tokens[i + 2].text in ANGLE_UNITS:
                out.pop()  # "so it sits at a right angle to the keyboard, like 90°": the right angle said again
                skip = 2
                continue
            token = replace(token, text="about", lemma="about")  # "..., like 90°", "something like 45 degrees": about 90 degrees
            if out and out[-1].text in ("something", "somewhere"):
                out.pop()
        if token.text == "going" and (not after or after in (".", ",", "!", "now", "again", "please")) and any(t.lemma == "get" for t in out[-4:]):
            token = replace(token, text="running", lemma="run", corrected_from="going")  # "get the dishwasher going": running
        if token.text == "by" and after in ("itself", "themselves"):
            skip = 1  # "both of them snap shut by themselves": on their own, no step of the user's
            continue
        if [t.text for t in tokens[i:i + 3]] in (["both", "of", "them"], ["all", "of", "them"]) and (not out or out[-1].text in _SUBJECT_BEFORE) and (
                i + 3 < len(tokens) and tokens[i + 3].lemma in VERBS and tokens[i + 3].text == tokens[i + 3].lemma):
            token, skip = replace(token, text="they", lemma="they"), 2  # "so both of them snap shut": they snap shut
        if token.text in ("itself", "themselves") and out and out[-1].lemma not in VERBS and out[-1].text.isalpha():
            continue  # "lift the jug itself": emphasis, the jug
        if token.text == "its" and i + 1 < len(tokens) and ((tokens[i + 1].text.endswith("ing") and tokens[i + 1].text not in _KNOWN_NOUNS) or (
                tokens[i + 1].text in _STATE_AFTER_ITS)) and (
                i + 2 >= len(tokens) or tokens[i + 2].is_punct or tokens[i + 2].text in ("and", "so", "then", "outside", "again", "now", "hard")):
            token = replace(token, text="it's", lemma="it's")  # "its raining": the apostrophe left out
        request = next((p for p in REQUEST_PHRASES if tuple(t.text for t in tokens[i:i + len(p)]) == p), None)
        if request is not None:  # "could you open ...", "would you mind opening ...": the request itself
            skip = len(request) - 1
            if out and request[0] in ("can", "could", "would", "will") and not out[-1].is_punct and out[-1].text not in ("and", "then", "so", "now", "but", "ok", "okay"):
                out.append(Token(",", ",", token.start, token.start))  # "... two things you can turn can you spin the upper one": a new clause
            since = next((k for k in range(len(out) - 1, -1, -1) if out[k].is_sentence_end or out[k].text == ":"), -1)
            if request[-1] == ":" and 0 < len(out) - since - 1 <= 2:
                del out[since + 1:]  # "Robot task: ...": the heading's own words go too
            continue
        if token.text == "as" and after in ("i", "you", "we") and i + 2 < len(tokens) and tokens[i + 2].text in _VIEWING:
            end = next((k for k in range(i + 3, len(tokens)) if tokens[k].is_punct or tokens[k].text in ("and", "then", ":")), len(tokens))
            skip = end - i - 1  # "crank it 90 degrees counter-clockwise as I face the door": how the user looks, not a part
            if out and out[-1].text in ("left", "right") and (len(out) == 1 or out[-2].is_sentence_end):
                out.pop()  # "Left as you face the cabinet.": which way "left" was meant, said again
            continue
        if token.text == "where" and i + 2 < len(tokens) and tokens[i + 1].number == 0 and tokens[i + 2].text in ("means", "is", "="):
            end = next((k for k in range(i + 3, len(tokens)) if tokens[k].is_sentence_end), len(tokens))
            skip = end - i - 1  # ", where zero means the lid is fully down": what the angle is measured from (closed, as always)
            if out and out[-1].text == ",":
                out.pop()
            continue
        if token.text in ("leave", "leaving") and _as_they_are(tokens, i):
            out.append(replace(token, text="without", lemma="without"))  # "leave the latch and the lid as they are"
            continue
        if token.text in ("leave", "leaving") and any(t.text == "alone" or (t.text == "hanging" and (k + 1 == len(tokens) or tokens[k + 1].is_punct))
                                                      for k, t in enumerate(tokens[i + 1:i + 7], start=i + 1)):  # "... hanging": as it is
            out.append(replace(token, text="without", lemma="without"))  # "leave the button alone": do not touch it
            continue
        if token.text in ("alone", "hanging") and out and any(t.text == "without" for t in out[-6:]):
            continue
        if tuple(t.text for t in tokens[i:i + 3]) in _AS_IS and any(t.text == "without" for t in out[-10:]):
            skip = 2  # the rest of "leave X as they are"
            continue
        if tuple(t.text for t in tokens[i:i + 2]) == ("as", "is") and any(t.text == "without" for t in out[-10:]):
            skip = 1  # "leave door as is"
            continue
        left = token.text == "left" and 0 < i < len(tokens) - 1 and (
            tokens[i - 1].text not in DETERMINERS and tokens[i - 1].lemma not in VERBS and tokens[i - 1].text.isalpha()) and tokens[i + 1].text in ("where", "alone", "as")
        if (token.text in _STAYING or left) and _kept_as_is(tokens, i):  # "door left where it is": stays
            token = replace(token, text="stays_put", lemma="stays_put")  # "the plate inside stays still", "door stays shut"
            skip = next((k for k in range(i + 1, len(tokens)) if tokens[k].is_punct or tokens[k].text in _CLAUSE_BREAKS), len(tokens)) - i - 1
        if token.text in ("untouched", "unmoved", "unchanged") and (i + 1 == len(tokens) or tokens[i + 1].is_punct):
            token = replace(token, text="stays_put", lemma="stays_put")  # "lid and clasps untouched"
        if token.text in _STAYS and out and out[-1].text in ("and", "then", ",") and any(motion_verb(t.text) for t in out[-8:]):
            out += [replace(token, text="stays", lemma="stay"), replace(token, text="there", lemma="there")]
            continue  # "the drawer comes out 20 cm and stays put for 1.5 s": no subject of its own, so it holds what just moved
        if token.text in _STAYS:  # "the lid stays where it is": the subject is left untouched
            start = max((k + 1 for k, t in enumerate(out) if t.text in _CLAUSE_BREAKS), default=0)
            wider = max((k + 1 for k, t in enumerate(out) if t.text in _CLAUSE_BREAKS and t.text != "and"), default=0)
            if not any(t.lemma in VERBS and t.text not in SPATIAL and kind_of_word(t.text) is None for t in out[wider:]):
                # "lid and left latch stay put": "left" is a side, "latch" a part
                start = wider  # "lid and clasps untouched": both
            out.insert(start, replace(token, text="without", lemma="without"))
            continue
        hands = tuple(t.text for t in tokens[i:i + 4])
        off = next((k for k, word in enumerate(hands) if word == "off"), None)
        if off is not None and (hands[:3] in (("keep", "your", "hands"), ("keep", "hands", "off")) or hands[:2] == ("hands", "off")):
            out.append(replace(token, text="without", lemma="without"))  # "keep your hands off the drawer"
            skip = off
            continue
        phrase = next((p for p in ASIDE_PHRASES if tuple(t.text for t in tokens[i:i + len(p)]) == p), None)
        if phrase is None and tuple(token.text.split("_")) in ASIDE_PHRASES:
            phrase = (token.text,)  # joined as one expression
        if phrase is not None:  # "and when I'm done close that door": then
            out.append(replace(token, text="then", lemma="then"))
            skip = len(phrase) - 1
            continue
        if token.text == "for" and i + 1 < len(tokens) and tokens[i + 1].text in ("me", "you", "us", "them"):
            skip = 1
            continue
        out.append(token)
    return out

_SIDES = frozenset({"left", "right", "left-hand", "right-hand"})
_DISTANCE_WORDS = frozenset({"cm", "mm", "m", "metre", "meter", "metres", "meters", "inch", "inches", "foot", "feet", "bit", "little", "slightly", "way", "over",
                             "move", "slide", "push", "shift", "nudge", "roll", "drag", "scoot"})


def expand(tokens: list[Token], known: frozenset[str]) -> list[Token]:
    """Chat shorthand to words ("cn u" -> "can you"): one token per word, the span of the shorthand."""
    out: list[Token] = []
    for token in tokens:
        if (word := ADVERB_PARTICLES.get(token.text) or SAME_MEANING.get(token.text)) is not None:
            out.append(Token(word, word, token.start, token.end))
            continue
        full = SHORTHAND.get(token.text) if token.text not in known else None
        if full is None:
            out.append(token)
            continue
        said = None if "'" in token.text and not token.text.startswith("'") else token.text  # "it'll" is English, no slip to note
        out.extend(Token(word, word, token.start, token.end, corrected_from=said) for word in full.split())
    return out


def _other_part(tokens: list[Token], j: int) -> bool:
    """"the other one", "the left one", "that other drawer": a part told apart from the one just said."""
    words = [t.text for t in tokens[j:j + 4]]
    return len(words) >= 2 and words[0] in DETERMINERS and any(w in OTHER_WORDS or w in SPATIAL for w in words[1:3])


def corrections(tokens: list[Token]) -> list[Token]:
    """"60 degrees... no wait, make it 45", "20 cm on the right drawer, no wait, I meant the other one": a new clause
    that starts with ``instead`` and gives the new amount or the other part. Only a correction followed (after its
    lead words) by a number, or by a part told apart ("the other one"), after an amount, counts."""
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        said = next((p for p in CORRECTIONS if tuple(t.text for t in tokens[i:i + len(p)]) == p), None)
        if said is not None and out and any(t.number is not None for t in out):
            j = i + len(said)
            while j < len(tokens) and tokens[j].text in (",", ".", "!", "-"):
                j += 1
            lead = next((p for p in CORRECTION_LEADS if tuple(t.text for t in tokens[j:j + len(p)]) == p), ())
            j += len(lead)
            if j < len(tokens) and (tokens[j].number is not None or (said != ("no",) and _other_part(tokens, j))):
                start = tokens[i].start
                out.extend((Token(".", ".", start, start), Token("instead", "instead", start, tokens[j - 1].end)))
                i = j
                continue
        out.append(tokens[i])
        i += 1
    return out


_LIMITS = frozenset({"top", "bottom", "limit", "stop", "end", "max", "maximum", "min", "minimum"})
_ALL_THE_WAY = frozenset({"back", "up", "down", "open", "out", "over", "round", "around"})
_SUBJECT_BEFORE = frozenset({"so", ",", "and", ".", ";", "then", "once", "when", "until"})
_STATE_AFTER_ITS = frozenset({"shut", "closed", "open", "opened", "done", "flush", "flat", "level", "upright", "vertical", "horizontal",
                              "halfway", "all_the_way", "fully", "straight"})
"""After "its" with nothing after: the apostrophe left out ("slide it in till its shut")."""
_TO = frozenset({"the", "its", "a", "an", "their", "my", "your", "left", "right", "middle", "centre", "center"})
_ARRANGED = frozenset({"above", "below", "over", "under", "beneath", "behind", "beside", "atop", "next_to", "on_top_of", "alongside"})
"""Relations of "one ... the other" that say how parts are arranged ("one after the other" is an order, not one of them)."""
_VIEWERS = frozenset({"viewer", "camera", "audience", "observer", "onlooker", "spectator", "operator", "user", "person", "robot"})
_SITTING = frozenset({"sits", "sitting", "lies", "located", "placed", "positioned"})
_WHERE = ("at", "on", "in", "near")


def _placed_relative(tokens: list[Token], i: int) -> int:
    """How many words at ``i`` say "(that / which) sits / is" between a noun and where it is ("at the upper right"), or 0."""
    words = [t.text for t in tokens[i:i + 3]]
    if (words[:1] in (["that"], ["which"]) and len(words) == 3 and words[1] in {*_SITTING, "is", "sits"} and words[2] in _WHERE) or (
            words[:1] == ["is"] and len(words) == 3 and words[1] in _SITTING and words[2] in _WHERE):
        count = 2  # "the key (that) sits at ...", "whatever piece is sitting on the very top"
    elif len(words) > 1 and (words[0] in _SITTING or words[0] in ("that's", "which's")) and words[1] in _WHERE:
        count = 1  # "the door (that's) on the left"
    else:
        return 0
    if i == 0 or not tokens[i - 1].text.isalpha() or tokens[i - 1].text in ("it", "they", "and", "then"):
        return 0
    start = max((k + 1 for k in range(i) if tokens[k].is_punct), default=0)
    # "tap the key that sits ...", not "the drawer sits on the left; ...": a verb before makes the noun its object
    return count if any(motion_verb(t.text) for t in tokens[start:i - 1]) else 0


def same_words(tokens: list[Token]) -> list[Token]:
    """Words that say the same as a form the lexicon knows: "a metre to my left" (the viewer's side is the side as seen
    facing the object), "to its top" (to the top), "2 the left" (to), "the third knob counting from the left",
    "throw the lid right back" (all the way), "neither knob" (without both), "on the front face of" (on the front of)."""
    out: list[Token] = []
    skip = -1  # the last token already written with one before it
    for i, t in enumerate(tokens):
        if i <= skip:
            continue
        before = tokens[i - 1].text if i else ""
        after = tokens[i + 1].text if i + 1 < len(tokens) else ""
        if t.text == "on" and after in VIEWER_POSSESSIVES and i + 2 < len(tokens) and tokens[i + 2].text in _SIDES and (
                any(w.number is not None or w.text in _DISTANCE_WORDS for w in tokens[max(i - 3, 0):i])):
            t = replace(t, text="to", lemma="to")  # "25 cm on my right side": to my right (not "the door on my right")
        elif (t.text in VIEWER_POSSESSIVES and after in _SIDES) or (t.text == "its" and before == "to" and after in _LIMITS):
            t = replace(t, text="the", lemma="the")
        elif t.text in ("whichever", "whatever") and after.isalpha():
            t = replace(t, text="the", lemma="the")  # "tap whichever key sits at the upper right"
        elif placed := _placed_relative(tokens, i):
            skip = i + placed - 1
            continue  # "the key (that) sits at the upper right": the key at the upper right
        elif t.text == "one" and after in _ARRANGED and [w.text for w in tokens[i + 2:i + 4]] == ["the", "other"]:
            skip = i + 3  # "two knobs, one above the other": how they are arranged, no part of its own
            continue
        elif t.text in _VIEWERS and before == "the" and after == "'s" and i + 2 < len(tokens) and tokens[i + 2].text in _SIDES:
            skip = i + 1  # "toward the viewer's left": the left as seen facing the object
            continue
        elif t.number == 2 and t.text == "2" and after in _TO and before not in ("", ",", ".", "and"):
            t = Token("to", "to", t.start, t.end, corrected_from="2")
        elif t.text == "counting" and after == "from":
            continue
        elif t.text == "right" and after in _ALL_THE_WAY and before not in ("the", "to", "on", "at", "turn", "its", "", ",", ".", ";", "and"):
            out.extend((Token("all", "all", t.start, t.end), Token("the", "the", t.start, t.end), Token("way", "way", t.start, t.end)))
            continue
        elif far_side(out, t, before, after):
            continue
        elif (t.text in ("left", "right") and before == "far" and out and out[-1].text.endswith("most")) or (
                t.text in ("face", "surface") and before in ("front", "top", "back", "rear", "side") and after in ("of", ",", ".", "", "and")):
            continue  # "far right" (written as "rightmost" above); "the dial on the front face of the base": on its front
        elif t.text == "neither":
            out.extend((Token("without", "without", t.start, t.end), Token("both", "both", t.start, t.end)))
            continue
        out.append(t)
    return out


_YAW_VERBS = frozenset({"turn", "turned", "rotate", "rotated", "spin", "spun", "swivel", "pivot", "twist", "angle", "revolve"})
_FACES = frozenset({"faces", "face", "facing", "points", "point", "pointing", "looks", "look", "looking"})
_AWAY = frozenset({"away", "wall", "back", "backwards", "backward", "rear"})
_TOWARD_VIEWER = frozenset({"me", "us", "you", "camera", "viewer", "front", "forward", "forwards"})


def facing(tokens: list[Token]) -> list[Token]:
    """"turn the microwave so that its door faces the wall": the turn that makes the object's front (where its doors and
    controls are, which faces the viewer) face that way, as an angle and a sense ("180 degrees", "90 degrees clockwise")."""
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        token = tokens[i]
        turned = any(t.lemma in _YAW_VERBS or t.text in _YAW_VERBS for t in out[-12:]) and not any(t.is_sentence_end for t in out[-3:])
        if token.text in ("so", "so_that") and turned:
            end = next((k for k in range(i + 1, min(len(tokens), i + 10)) if tokens[k].is_punct or tokens[k].text in ("and", "then")), len(tokens))
            words = [t.text for t in tokens[i + 1:end]]
            verb_at = next((k for k, w in enumerate(words) if w in _FACES), None)
            if verb_at is not None:
                subject, target = set(words[:verb_at]), words[verb_at + 1:]
                degrees, sense = _facing_turn(target, back=bool(subject & {"back", "rear"}))
                angle_said = any(t.number is not None for t in out[-8:])
                if degrees is not None:
                    start, stop = token.start, tokens[end - 1].end
                    if degrees and not angle_said:
                        out.extend((Token(",", ",", start, start), Token(f"{degrees:g}", f"{degrees:g}", start, stop, number=float(degrees)),
                                    Token("degrees", "degree", start, stop)))
                    if sense:
                        out.append(Token(sense, sense, start, stop))
                    i = end
                    continue
        out.append(token)
        i += 1
    return out


def _facing_turn(target: list[str], *, back: bool) -> tuple[float | None, str]:
    """(degrees, sense seen from above) that turn the front (or the back) to face ``target``."""
    words = set(target)
    if words & {"left", "leftward", "leftwards"}:
        degrees, sense = 90.0, "clockwise"
    elif words & {"right", "rightward", "rightwards"}:
        degrees, sense = 90.0, "anticlockwise"
    elif words & _AWAY:
        degrees, sense = 180.0, ""
    elif words & _TOWARD_VIEWER:
        degrees, sense = 0.0, ""
    else:
        return None, ""
    if back:
        degrees, sense = (180.0 - degrees if degrees in (0.0, 180.0) else degrees), {"clockwise": "anticlockwise", "anticlockwise": "clockwise"}.get(sense, sense)
    return degrees, sense
