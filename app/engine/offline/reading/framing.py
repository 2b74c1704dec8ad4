"""Words that frame a command without adding a motion to it, dropped before clauses are split.

- Where the user stands or looks: "when you stand facing the dishwasher", "as seen when looking at the front", ", my
  left, standing in front of the machine" (left, right and clockwise are always meant as seen facing the front).
- Comparisons and asides: "like you're starting a batch of toast", "what I'd love is (for the door to ...)", "I'm
  interested in (the smaller one)", "the way you'd hold it to carry it", "I think", ", ready for carrying", ", it is for
  the browning level", ", i.e. away from the side where the lid opens".
- Afterthoughts: "about 20 cm? not all the way", "either direction is fine", "- just that one", "its half open rn",
  "- open a door first if you have to" (the agent opens what blocks the way itself), "Start them together."
- Who acts and what is only carried or resting: "one gripper ... the other arm", "The lid is sitting on the jug, so it
  rides up along with it".
"""
from __future__ import annotations

from collections.abc import Callable

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import PARALLEL, SEQUENCE, SIMULTANEOUS, WISHES
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.word_class import lemma_of

_VIEW_LEADS = frozenset({"as", "when", "while", "if"})
_VIEWERS = frozenset({"i", "you", "we", "one", "someone", "they", "you're", "i'm", "we're", "they're", "are", "am", "is", "the", "viewer", "user",
                      "operator", "camera", "person"})
_VIEW_VERBS = frozenset({"face", "faces", "facing", "look", "looks", "looking", "see", "seen", "seeing", "stand", "stands", "standing",
                         "view", "viewed", "viewing", "watch", "watching", "sit", "sitting"})
_SIMILE_PEOPLE = frozenset({"you", "you're", "you'd", "you'll", "i'm", "i'd", "we're", "we'd", "someone", "somebody", "a", "one", "they're",
                            "they'd", "people", "anyone", "he", "she", "he'd", "she'd", "i", "we", "they"})
_SIMILE_ENDS = frozenset({".", ";", "!", "?", "then", "and_then"})
_BOUNDS = frozenset({"all_the_way", "fully", "completely", "entirely", "too", "the_whole_way", "to_the_end", "to_the_limit", "wide_open",
                     "all", "far", "much", "the", "way", "out", "open", "in", "quite", "whole"})
_SIDE_WORDS = frozenset({"left", "right", "and", "or", "/", ",", "left-hand", "right-hand"})
_SAID_SIDES = _SIDE_WORDS | {"the", "my", "your", "is", "means", "="}
"""What a sentence that only says how a side is meant starts with ("Left = my left", "Right is your right")."""
_HEDGES = frozenset({"think", "guess", "suppose", "believe", "reckon", "figure", "imagine"})
_CARRIED = frozenset({"rides", "ride", "riding", "comes", "come", "goes", "go", "travels", "travel", "moves", "move", "up", "along"})
_LEAVING = frozenset({"stepping", "walking", "heading", "leaving", "running", "popping", "nipping"})
_AWAY_WORDS = frozenset({"away", "out", "off", "home", "to", "from", "for", "into"})
_REASON_SUBJECTS = frozenset({"it's", "it'll", "it'd", "they're", "they'll", "they'd", "that's", "that'll", "that'd"})
_CLAUSE_ENDS = frozenset({".", ";", "!", "?", ",", "so", "and", "so_that"})
_RESTING_WORDS = frozenset({"sitting", "resting", "lying", "perched", "seated", "loose", "attached"})
_POSTURES = frozenset({"stand", "standing", "kneel", "kneeling", "crouch", "crouching", "sit", "sitting"})
_HANDS = frozenset({"gripper", "arm", "hand", "robot", "effector", "manipulator", "finger"})
_NOW_WORDS = frozenset({"half", "partly", "partially", "already", "still", "slightly", "a_bit", "a_little", "open", "closed", "shut", "ajar", "up",
                        "down", "rn", "now", "right_now", "currently", "at_the_moment", "wide_open", "all_the_way", "half_open"})
_FREE_SENSE = (("either", "direction"), ("either", "way"), ("any", "direction"), ("whichever", "direction"), ("whichever", "way"))
_FINE = frozenset({"is", "fine", "ok", "okay", "works", "will", "do", "is_fine", "'s", "'ll", "'d", "would"})


def scan(tokens: list[Token], step: Callable[[list[Token], int, list[Token]], int | None]) -> list[Token]:
    """Tokens rewritten left to right: ``step`` at each index writes to the output and returns the index after what it
    read, or None to keep the token as it is."""
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        moved = step(tokens, i, out)
        if moved is None:
            out.append(tokens[i])
        i = i + 1 if moved is None else max(moved, i + 1)
    return out


def until_break(tokens: list[Token], start: int, ends: frozenset[str]) -> int:
    return next((k for k in range(start, len(tokens)) if tokens[k].text in ends), len(tokens))


def _viewpoint(tokens: list[Token], i: int) -> int:
    """The length of "when you stand facing the dishwasher" / "as seen when looking at the front" at ``i``, else 0."""
    if tokens[i].text not in _VIEW_LEADS:
        return 0
    j = i + 1
    while j < len(tokens) and j < i + 4 and tokens[j].text in _VIEWERS:
        j += 1
    if j >= len(tokens) or tokens[j].text not in _VIEW_VERBS or (j == i + 1 and tokens[i].text != "as"):
        return 0  # "while facing": no subject, may be the part's ("the lid, while facing up, ...")
    end = until_break(tokens, j, frozenset({",", ";", ".", "!", "?", ":", "then", "and_then", "and"}))  # "as you face it: swing it ..."
    verb = next((k for k in range(j + 1, end) if tokens[k].text.endswith("s") and tokens[k].text not in _VIEW_VERBS
                 and lemma_of(tokens[k].text)[0] in VERBS and lemma_of(tokens[k].text)[0] != tokens[k].text), end)
    return verb - i  # "the drawer on the left as seen from the front | slides out halfway": the aside ends before the main verb


def _simile(tokens: list[Token], i: int) -> int:
    """The length of a comparison at ``i`` ("like you're starting a batch", "the way you'd hold it", "as if ...", ", like
    folding it all the way around"), else 0."""
    words = [t.text for t in tokens[i:i + 4]]
    person = next((k for k, w in enumerate(words) if w in _SIMILE_PEOPLE), None)
    gerund = words[:1] == ["like"] and len(words) > 1 and words[1].endswith("ing") and i > 0 and tokens[i - 1].text == ","
    if words[:2] in (["as", "if"], ["as", "though"]) or (words[:1] == ["like"] and person == 1) or gerund or (
            words[:2] == ["the", "way"] and person == 2) or (words[:2] == ["as", "you"] and len(words) > 2 and words[2] in ("would", "do", "might")):
        if i == 0 or tokens[i - 1].is_sentence_end:
            return 0  # "Like you're ...": a sentence of its own may set a scene that names parts; keep it
        return until_break(tokens, i, _SIMILE_ENDS) - i
    return 0


def _bound_only(tokens: list[Token], i: int) -> int:
    """The length of a sentence at ``i`` that only bounds the amount before it ("not all the way", "but not fully"), else 0."""
    if i == 0 or (not tokens[i - 1].is_sentence_end and tokens[i - 1].text != ","):
        return 0
    j = i + (tokens[i].text == "but")
    if j >= len(tokens) or tokens[j].text != "not":
        return 0
    end = until_break(tokens, j + 1, frozenset({".", ";", "!", "?"}))
    words = {t.text for t in tokens[j + 1:end]}
    return end - i + (end < len(tokens)) if words and words <= _BOUNDS and words & {"all_the_way", "fully", "completely", "entirely", "too",
                                                                                     "the_whole_way", "to_the_end", "to_the_limit", "wide_open", "whole"} else 0


def _free_sense(tokens: list[Token], i: int) -> int:
    """The length of "either direction is fine" at ``i``, else 0."""
    if tuple(t.text for t in tokens[i:i + 2]) not in _FREE_SENSE and not (tokens[i].text == "either" and i + 1 < len(tokens) and tokens[i + 1].text.isalpha()):
        return 0  # "either direction is fine", "either end is fine"
    j = i + 2
    while j < len(tokens) and tokens[j].text in _FINE:
        j += 1
    return j - i if j > i + 2 else 0


def _only_that(tokens: list[Token], i: int) -> int:
    """The length of "just that one" / "only that piece" / "that one only" at ``i``, else 0."""
    words = [t.text for t in tokens[i:i + 3]]
    if words[:3] in (["just", "that", "one"], ["only", "that", "one"], ["just", "the", "one"], ["that", "one", "only"]) or (
            words[:2] in (["only", "that"], ["just", "that"]) and len(words) == 3 and (i + 3 == len(tokens) or tokens[i + 3].is_punct)):
        return 3
    if words[:2] in (["just", "one"], ["only", "one"]) and len(words) == 3 and kind_of_word(words[2]) is not None and (
            i + 3 == len(tokens) or tokens[i + 3].is_punct):
        return 3  # ", just one lever."
    return 0


def _resting_part(tokens: list[Token], i: int) -> int:
    """The length of a clause at ``i`` that says where a part rests ("the lid is just sitting on the jug"), else 0."""
    words = [t.text for t in tokens[i:i + 6]] + ["", "", "", "", "", ""]
    k = 1 if words[0] in ("the", "its", "a") else 0
    if kind_of_word(words[k]) is None or words[k + 1] not in ("is", "are", "sits", "rests"):
        return 0
    k += 2 if words[k + 1] in ("is", "are") else 1
    k += words[k] == "just"
    if (words[k] not in ("sits", "rests") and words[k] not in _RESTING_WORDS) or words[k + 1] in _NOW_WORDS:
        return 0  # not "the door is sitting open": a state, told as a complaint
    end = until_break(tokens, i, frozenset({",", ".", ";", "!", "?", "so", "and"}))
    return end - i + (end < len(tokens) and tokens[end].text == ",")


def _state_now(tokens: list[Token], i: int) -> bool:
    """At "it's": "it's half open rn", "its still closed" (how the part is now) up to the end of the clause."""
    words = [t.text for t in tokens[i + 1:until_break(tokens, i, _SIMILE_ENDS)]]
    return bool(words) and set(words) <= _NOW_WORDS and bool(set(words) & {"open", "closed", "shut", "ajar", "up", "down", "half_open", "wide_open"})


def _framing_step(tokens: list[Token], i: int, out: list[Token]) -> int | None:
    """At ``i``: the index after the framing words there (``out`` may lose a comma before them), or None."""
    t = tokens[i]
    after = [w.text for w in tokens[i + 1:i + 5]]
    view = _viewpoint(tokens, i)
    since = next((k + 1 for k in range(len(out) - 1, -1, -1) if out[k].is_sentence_end), 0)
    if not view and out[since:] and {w.text for w in out[since:]} <= _SAID_SIDES and t.text in _VIEW_LEADS and after[:1] and after[0] in _VIEW_VERBS:
        view = until_break(tokens, i, frozenset({".", "!", "?", ";"})) - i  # "Left = my left when facing the machine from the front."
    skip = view or _simile(tokens, i) or _bound_only(tokens, i) or _free_sense(tokens, i)
    if skip:
        if view and since < len(out) and {w.text for w in out[since:]} <= _SAID_SIDES:
            del out[since:]  # "Left as you face the cabinet.", "Left and right as seen from the front.": how sides are meant
        if out and out[-1].text in (",", "-") and not (i + skip < len(tokens) and tokens[i + skip].is_sentence_end):
            out.pop()
        return i + skip
    if t.text in _POSTURES and (not out or out[-1].is_sentence_end) and after[:1] and after[0] in ("in_front_of", "facing", "before", "at", "by") and (
            (end := until_break(tokens, i, frozenset({",", ".", ";", "!", "?", "and", "then", "and_then"}))) < len(tokens) and tokens[end].text in ("and", "and_then")):
        return end + 1  # "stand in front of the box and fasten ...": where the user is ("Standing in front of the fridge, slide it ..." names "it")
    here = next((k for k in (1, 2) if after[k - 1:k] == ["here"] and after[k:k + 1] and after[k] in (",", ":", "-", "—")), None)
    if not out and here is not None and all(kind_of_word(w.text) is None and w.text.isalpha() for w in tokens[i:i + here]):
        return i + here + 2  # "locksmith here - just the right-hand catch ...": who is asking, no part
    if t.text == "for" and (not out or out[-1].is_sentence_end) and after[:1] and after[0] in ("a", "an", "the", "my", "our", "this") and (
            wish := next((k for k in range(i + 2, min(len(tokens), i + 7)) if tokens[k].text in WISHES), None)) is not None and not any(
            tokens[k].is_punct or kind_of_word(tokens[k].text) is not None for k in range(i + 1, wish)):
        return wish  # "For a product shot I need the screen at 90 degrees": what it is for, then the wish
    if t.text == "ready" and out and out[-1].text == "," and after[:1] and after[0] in ("for", "to"):
        out.pop()  # ", ready for carrying": what the pose is for, no step
        return until_break(tokens, i, _SIMILE_ENDS)
    if (only := _only_that(tokens, i)) and out and (out[-1].text in (",", "-", "—") or out[-1].is_sentence_end):
        return i + only  # "press the key in the bottom-left corner - just that one, once"
    if t.text in ("left", "right", "clockwise", "anticlockwise", "counterclockwise") and out and out[-1].text == "," and after[:1] and (
            after[0] in ("meaning", "means", "being", "=", "i.e.", "ie")):
        out.pop()  # ", left meaning from the user's side of the sink": how the side is meant (as seen facing the object)
        return until_break(tokens, i, _SIMILE_ENDS)
    if t.text in ("start", "begin") and after[:1] and after[0] in ("them", "both", "these") and len(after) > 1 and after[1] in SIMULTANEOUS:
        return i + 1  # "Start them together.": both at the same time, no motion of its own
    if t.text in ("i.e.", "ie", "namely", "meaning") or (t.text == "it" and after[:2] in (["is", "for"], ["'s", "for"])) or (t.text == "it's" and after[:1] == ["for"]):
        if out and out[-1].text == ",":
            out.pop()  # ", i.e. away from the side where the lid opens", ", it is for the browning level", ", meaning the one on my right": said of it, no step
            return until_break(tokens, i, _SIMILE_ENDS)
    if (t.text in ("one", "another") and after[:1] and after[0] in _HANDS) or (t.text == "the" and after[:2] and after[0] == "other" and (
            len(after) > 1 and after[1] in _HANDS)):
        return i + (2 + (t.text == "the"))  # "one gripper pushes the button in while the other arm pulls the door": who acts
    if t.text in ("it's", "its") and _state_now(tokens, i) and out and out[-1].text == ",":
        out.pop()  # "cloes teh lid of the box pls, its half open rn": how it is now, no step
        return until_break(tokens, i, _SIMILE_ENDS)
    if (t.text == "if" and after[:3] in (["you", "have", "to"], ["you", "need", "to"], ["you", "must"], ["needed"], ["necessary"], ["required"])) or (
            t.text == "if" and after[:1] and after[0] in ("needed", "necessary", "required")):
        since = max((k for k, w in enumerate(out) if w.text in _CLAUSE_ENDS or w.text in ("-", "—")), default=-1)
        del out[since + 1:]  # "- open a door first if you have to": the agent opens what blocks the way itself
        while out and out[-1].text in (",", "-", "—", "and", "then"):
            out.pop()
        return until_break(tokens, i, _SIMILE_ENDS)
    told_side = until_break(tokens, i + 1, _SIMILE_ENDS)
    if t.text == "," and len(after) > 2 and after[1] in ("is", "=", "means") and {w.text for w in tokens[i + 3:told_side]} <= _SAID_SIDES | {"on"} and (
            {w.text for w in tokens[i + 3:told_side]} & {"left", "right"}):
        return told_side  # ", hot is the viewer's left": how a side is meant, no step
    if t.text in ("-", "—", ",") and after[:2] in (["the", "left"], ["the", "right"]) and (len(after) < 3 or after[2] in (",", ".", "!", ";")):
        return i + 3  # "... over to the left - my left, standing in front of the machine": which left, said again
    if t.text == "," and after[:1] and after[0] in ("standing", "facing", "looking", "seen", "viewed") and len(after) > 1 and (
            after[1] in ("in_front_of", "at", "toward", "towards", "from", "before")):
        return until_break(tokens, i + 1, _SIMILE_ENDS)  # ", standing in front of the machine": where the user is
    if t.text in ("along_with", "with") and after[:1] and after[0] in ("it", "them") and any(w.text in _CARRIED for w in out[-4:]):
        since = max((k for k, w in enumerate(out) if w.text in _CLAUSE_ENDS), default=-1)
        del out[since + 1:]  # "the lid ..., so it just rides up along with it": carried, no motion of its own
        while out and out[-1].text in ("so", "and", ","):
            out.pop()
        return until_break(tokens, i, frozenset({".", ";", "!", "?"}))
    if t.text in ("rides", "ride", "comes", "goes", "travels") and after[:1] == ["along"] and (len(after) < 2 or after[1] in _CLAUSE_ENDS) and (
            out and (out[-1].text in ("it", "they", "just") or kind_of_word(out[-1].text) is not None)):
        since = max((k for k, w in enumerate(out) if w.text in _CLAUSE_ENDS), default=-1)
        del out[since + 1:]  # "..., so it just rides along": carried, no motion of its own
        while out and out[-1].text in ("so", "and", ","):
            out.pop()
        since = max((k for k, w in enumerate(out) if w.text in _CLAUSE_ENDS), default=-1)
        if since >= 0 and _resting_part(out, since + 1) == len(out) - since - 1:
            del out[since:]  # "..., the lid's sitting on it, so it just rides along": the scene, then that it is carried
        return i + 2
    if t.text in ("i've", "we've") and after[:1] == ["got"] and (not out or out[-1].is_sentence_end) and (
            to := next((k for k in range(i + 2, until_break(tokens, i, _SIMILE_ENDS) - 1) if tokens[k].text == "to" and tokens[k + 1].lemma in VERBS), None)) and (
            until_break(tokens, to, _SIMILE_ENDS | {","}) == until_break(tokens, to, _SIMILE_ENDS)):  # not "..., get the bin open"
        out.append(Token("i_need", "i_need", t.start, tokens[to - 1].end))  # "I've got a stack of plates to load into it": I need to
        return to
    if t.text in ("i'm", "we're") and (after[:2] == ["going", "to"] or after[:1] == ["gonna"]) and len(after) > 2:
        return i + (3 if after[0] == "going" else 2)  # "I'm going to open the screen": open the screen
    if t.text in ("i'm", "we're") and (not out or out[-1].is_sentence_end) and after[:2] and after[0] in _LEAVING and after[1] in _AWAY_WORDS:
        end = until_break(tokens, i, frozenset({",", ".", ";", "!", "?", "so", "and"}))
        return end + (end < len(tokens) and tokens[end].text == ",")  # "I'm stepping away from my desk, ...": about the user
    if t.text == "otherwise" and after[:1] and (after[0] in _REASON_SUBJECTS or (after[:1] in (["it"], ["they"], ["that"]) and after[1:2] and (
            after[1] in ("is", "will", "would", "might", "could", "can", "gets", "get", "blocks", "block", "hits", "hit")))):
        while out and out[-1].text == ",":
            out.pop()  # "fold the handle back first, otherwise it's in the way, then ...": why, not a step
        return until_break(tokens, i, frozenset({",", ".", ";", "!", "?", "then", "and_then"}))
    if (not out or out[-1].is_sentence_end) and (told := _resting_part(tokens, i)):
        return i + told  # "The lid is (just) sitting on the jug, so ...": how the scene is, no step
    if t.text in ("i'm", "we're") and after[:2] in (["interested", "in"], ["talking", "about"], ["thinking", "of"], ["looking", "at"]):
        if out and out[-1].text in ("and", ","):
            out[-1] = Token(".", ".", out[-1].start, out[-1].end)  # "... two knobs, and I'm interested in ...": a sentence of its own
        return i + 3  # "I'm interested in the smaller one, the one higher up": that part is what the next sentence works
    if t.text == "what" and after[:1] and after[0] in WISHES and after[1:2] == ["is"]:
        out.append(tokens[i + 1])
        return i + 3  # "what I'd love is for the door to swing open": I'd love for the door to swing open
    if t.text in ("i", "we") and (not out or out[-1].is_sentence_end or out[-1].text == ",") and after[:1] and after[0] in _HEDGES:
        return i + (2 + (after[1:2] == ["that"]))  # "I think the handle should drop": the handle should drop
    return None


def drop_framing(tokens: list[Token]) -> list[Token]:
    """``tokens`` without the framing words above."""
    return scan(scan(tokens, _framing_step), _bare_connective)


def _bare_connective(tokens: list[Token], i: int, out: list[Token]) -> int | None:
    """"and, at the same time, the plate turns": the connective, not a clause of its own."""
    if tokens[i].text == "," and out and out[-1].text in ("and", "but") and i + 2 < len(tokens) and tokens[i + 2].text == "," and (
            tokens[i + 1].text in PARALLEL or tokens[i + 1].text in SEQUENCE):
        out.append(tokens[i + 1])
        return i + 3
    return None
