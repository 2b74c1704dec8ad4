"""Requests told as states or as what was left undone, rewritten as the plain request the frame reader knows:

- "somebody forgot to flush", "I forgot to lock it": flush, lock it;
- "don't leave the door hanging open" (after a step that opened it): then close the door;
- "keep the heat in", "keep the cold in": close it;
- "the lid isn't sitting right", "the lid is not on properly": the lid is open (a complaint: it is shut);
- "I need to get at the bottom rack": open it;
- "make sure it can't pop open on the way": lock it (shut, then fastened);
- "then leave it as it was", "leave the door the way you found it": put it back;
- "Where did I put the cleaning stuff? Have a look in ...": the question asks for no step (it goes);
- "the case shouldn't be gaping open", "I can't stack buckets with that handle sticking straight up": the part is open
  (up), told as a complaint;
- "I need it half a metre closer", "it should sit 40 cm further back": move it so;
- "I'd rather have the lid side of the suitcase facing the wall", "I want to see the back of the suitcase": turn it around.
"""

from __future__ import annotations

from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.words import ASIDE_WORDS
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

_SOMEONE = frozenset({"somebody", "someone", "i", "you", "we", "they", "he", "she", "the_kids", "kids"})
_FORGOT = frozenset({"forgot", "forget", "forgets"})
_DONT = (("don't",), ("dont",), ("do", "not"), ("never",))
_LEFT_OPEN = (("hanging", "open"), ("open",), ("ajar",), ("wide", "open"), ("sticking", "out"), ("out",), ("sticking", "up"), ("standing", "up"),
              ("up",))
_KEPT_IN = frozenset({"heat", "warmth", "cold", "steam", "smell", "flies", "bugs"})
_NOT = (("isn't",), ("is", "not"), ("aren't",), ("are", "not"), ("not",))
_SEATED = frozenset({"sitting", "seated", "on", "closed", "shut", "sealed"})
_RIGHT = frozenset({"right", "to_the_right", "properly", "straight", "flat", "all_the_way", "fully", "tight"})


def told_states(tokens: list[Token]) -> list[Token]:
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        step = (_forgot_to(tokens, k, out) or _dont_leave(tokens, k, out) or _keep_in(tokens, k, out) or _not_seated(tokens, k, out)
                or _get_at(tokens, k, out) or _cannot_open(tokens, k, out) or _left_as_found(tokens, k, out) or _asked_where(tokens, k, out)
                or _should_not_be(tokens, k, out) or _with_sticking(tokens, k, out) or _placed_wish(tokens, k, out)
                or _facing_wall(tokens, k, out) or _see_the_back(tokens, k, out) or _to_state(tokens, k, out)
                or _bare_state(tokens, k, out) or _relative_to(tokens, k, out) or _shut_and_locked(tokens, k, out)
                or _is_to_be(tokens, k, out))
        if step:
            k += step
            continue
        out.append(tokens[k])
        k += 1
    return out


def _words(tokens: list[Token], k: int, n: int) -> tuple[str, ...]:
    return tuple(t.text for t in tokens[k:k + n])


def _said(tokens: list[Token], k: int, n: int) -> str:
    return " ".join(t.text for t in tokens[k:k + n])


def _forgot_to(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"somebody forgot to flush": the step left undone (the person and "forgot to" go)."""
    if k + 2 >= len(tokens) or tokens[k].text not in _SOMEONE or tokens[k + 1].text not in _FORGOT or tokens[k + 2].text != "to":
        return 0
    if out and not (out[-1].is_punct or out[-1].text in ("and", "but", "so")):
        return 0
    if k + 3 >= len(tokens) or tokens[k + 3].is_punct:
        return 0
    done = tokens[k + 3]
    out.append(Token(done.text, done.lemma, done.start, done.end, corrected_from=_said(tokens, k, 4)))  # the step: "flush"
    return 4


def _dont_leave(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"(and) don't leave the door hanging open": close the door, as the next step."""
    lead = next((len(d) for d in _DONT if _words(tokens, k, len(d)) == d), 0)
    if not lead or _words(tokens, k + lead, 1) != ("leave",) or not out:
        return 0
    j = k + lead + 1
    end = next((e for e in range(j + 1, min(len(tokens), j + 6)) for s in _LEFT_OPEN if _words(tokens, e, len(s)) == s), None)
    if end is None:
        return 0
    state = next(s for s in _LEFT_OPEN if _words(tokens, end, len(s)) == s)
    at = tokens[k]
    if out[-1].text not in (",", "and", "then", "but"):
        out.append(Token(",", ",", at.start, at.end))
    out += [Token("then", "then", at.start, at.end), Token("close", "close", at.start, at.end, corrected_from=_said(tokens, k, end + len(state) - k)),
            *tokens[j:end]]
    return end + len(state) - k


def _keep_in(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"keep the heat in": close it."""
    words = _words(tokens, k, 4)
    if words[:1] != ("keep",) or len(words) < 3:
        return 0
    n = 3 if words[1] in _KEPT_IN and words[2] == "in" else 4 if len(words) == 4 and words[1] == "the" and words[2] in _KEPT_IN and words[3] == "in" else 0
    if not n:
        return 0
    at = tokens[k]
    out += [Token("close", "close", at.start, at.end, corrected_from=_said(tokens, k, n)), Token("it", "it", at.start, at.end)]
    return n


def _not_seated(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"the lid isn't sitting right": the lid is open (told as a complaint)."""
    lead = next((len(n) for n in _NOT if _words(tokens, k, len(n)) == n), 0)
    if not lead or not out or out[-1].is_punct or _words(tokens, k + lead, 1)[:1] == () or tokens[k + lead].text not in _SEATED:
        return 0
    if _words(tokens, k + lead + 1, 1)[:1] == () or tokens[k + lead + 1].text not in _RIGHT:
        return 0
    at = tokens[k]
    out += [Token("is", "is", at.start, at.end), Token("open", "open", at.start, at.end, corrected_from=_said(tokens, k, lead + 2))]
    return lead + 2


def _get_at(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"I need to get at the bottom rack": open it (a rack or drawer comes out) to reach it; a control is only reached."""
    if tokens[k].text != "get_at" or not _words(tokens, k + 1, 1) or tokens[k + 1].text not in ("the", "that", "this", "my", "its"):
        return 0
    if out and out[-1].text == "to" and (len(out) == 1 or out[-2].is_punct):
        return 0  # "To get at the lowest rack you have to drop the lower door first": why, told first
    kinds = [kind for t in tokens[k + 2:k + 6] if (kind := kind_of_word(t.text)) is not None]
    if not kinds or kinds[0] not in _REACHED_BY_OPENING:
        return 0
    at = tokens[k]
    out.append(Token("open", "open", at.start, at.end, corrected_from="get at"))
    return 1


_REACHED_BY_OPENING = frozenset({PartKind.SHELF, PartKind.TRAY, PartKind.DRAWER, PartKind.DOOR, PartKind.LID, PartKind.FLAP})


_CANNOT = frozenset({"can't", "cannot", "won't", "doesn't", "don't", "wont", "cant"})
_COMES_OPEN = frozenset({"pop", "come", "fall", "swing", "spring", "fly", "slide", "get", "flop", "flip", "drop"})


def _cannot_open(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"make sure it can't pop open (on the way)": lock it."""
    if _words(tokens, k, 2) != ("make", "sure"):
        return 0
    neg = next((j for j in range(k + 2, min(len(tokens), k + 7)) if tokens[j].text in _CANNOT), None)
    if neg is None or neg == k + 2:
        return 0
    j = neg + 1 + (neg + 1 < len(tokens) and tokens[neg + 1].text in _COMES_OPEN)
    if _words(tokens, j, 1) != ("open",):
        return 0
    end = next((e for e in range(j + 1, len(tokens)) if tokens[e].is_punct), len(tokens))  # "on the way": when, not what
    at = tokens[k]
    out += [Token("lock", "lock", at.start, at.end, corrected_from=_said(tokens, k, end - k)), *tokens[k + 2:neg]]
    return end - k


_AS_FOUND = (("as_it_was",), ("as_they_were",), ("where_it_started",), ("the", "way", "it", "was"), ("the", "way", "you", "found", "it"), ("how", "you", "found", "it"),
             ("as", "you", "found", "it"), ("the", "way", "they", "were"), ("the", "way", "you", "found", "them"), ("how", "it", "was"))


def _left_as_found(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"then leave it as it was", "leave the door the way you found it": put it back (where it was before)."""
    if tokens[k].text != "leave":
        return 0
    for n in range(1, 5):
        said = next((a for a in _AS_FOUND if _words(tokens, k + 1 + n, len(a)) == a), None)
        if said is not None:
            at = tokens[k]
            out += [Token("put", "put", at.start, at.end, corrected_from=_said(tokens, k, 1 + n + len(said))), *tokens[k + 1:k + 1 + n],
                    Token("back", "back", at.start, at.end)]
            return 1 + n + len(said)
    return 0


def _asked_where(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"Where did I put the cleaning stuff?" followed by a request: the question goes."""
    if tokens[k].text not in ("where", "what") or (out and not out[-1].is_sentence_end):
        return 0
    end = next((j for j in range(k, len(tokens)) if tokens[j].is_sentence_end), len(tokens))
    return end + 1 - k if end < len(tokens) - 1 and (tokens[end].text == "?" or ((tokens[end].text in ("...", "…") or tokens[end + 1].text == ".") and tokens[k + 1].text in (
        "did", "do", "is", "are", "was", "were"))) else 0  # "Where did I leave my keys... probably in the drawer"


_HOW_IT_HANGS = frozenset({"gaping", "hanging", "standing", "sitting", "left", "wide", "sticking", "poking", "straight"})
_STATE_WORDS = {"open": "open", "up": "up", "out": "out", "ajar": "ajar", "straight_up": "up"}


def _should_not_be(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"the case shouldn't be gaping open like that": the case is open (a complaint)."""
    lead = 2 if _words(tokens, k, 2) == ("shouldn't", "be") else 3 if _words(tokens, k, 3) == ("should", "not", "be") else 0
    if not lead or not out:
        return 0
    j = k + lead
    while j < len(tokens) and tokens[j].text in _HOW_IT_HANGS:
        j += 1
    if j >= len(tokens) or tokens[j].text not in _STATE_WORDS:
        return 0
    at = tokens[k]
    out += [Token("is", "is", at.start, at.end), Token(_STATE_WORDS[tokens[j].text], _STATE_WORDS[tokens[j].text], at.start, at.end,
                                                         corrected_from=_said(tokens, k, j + 1 - k))]
    end = j + 1 + (j + 1 < len(tokens) and tokens[j + 1].text in ("like_that", "like", "again"))
    return end - k


def _with_sticking(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"... with that handle sticking straight up": a clause of its own, "that handle is up" (a complaint)."""
    if tokens[k].text != "with" or not _words(tokens, k + 1, 1) or tokens[k + 1].text not in ("that", "the", "this", "its", "my"):
        return 0
    verb = next((j for j in range(k + 2, min(len(tokens), k + 6)) if tokens[j].text in ("sticking", "poking", "standing", "hanging")), None)
    if verb is None:
        return 0
    j = verb + 1 + (verb + 1 < len(tokens) and tokens[verb + 1].text == "straight")
    if j >= len(tokens) or tokens[j].text not in _STATE_WORDS or (j + 1 < len(tokens) and not tokens[j + 1].is_punct):
        return 0
    at = tokens[k]
    out += [Token(",", ",", at.start, at.end), *tokens[k + 1:verb], Token("is", "is", at.start, at.end),
            Token(_STATE_WORDS[tokens[j].text], _STATE_WORDS[tokens[j].text], at.start, at.end, corrected_from=_said(tokens, k, j + 1 - k))]
    return j + 1 - k


_SHOULD = (("should",), ("must",), ("needs", "to"), ("has", "to"), ("ought", "to"))
_PLACED = frozenset({"sit", "be", "go", "stand", "move", "end_up"})
_WAYS = frozenset({"closer", "nearer", "back", "forward", "further", "farther", "away", "left", "right", "backward", "forwards", "backwards"})


def _placed_wish(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"I need it half a metre closer", "it should sit 40 cm further back": move it so (a length and a way said)."""
    if out and not (out[-1].is_punct or out[-1].text in ("and", "so", "but")):
        return 0
    if tokens[k].text in ("i_need", "i_want", "i'd_like") and _words(tokens, k + 1, 1) == ("it",):
        subject, j = [tokens[k + 1]], k + 2
    elif tokens[k].text == "it" and (lead := next((len(m) for m in _SHOULD if _words(tokens, k + 1, len(m)) == m), 0)) and (
            _words(tokens, k + 1 + lead, 1)[:1] and tokens[k + 1 + lead].text in _PLACED):
        subject, j = [tokens[k]], k + 2 + lead
    else:
        return 0
    end = next((e for e in range(j, len(tokens)) if tokens[e].is_punct), len(tokens))
    rest = tokens[j:end]
    if not any(t.text in _WAYS for t in rest) or not any(t.lemma in _LENGTHS or t.text in _LENGTHS for t in rest):
        return 0
    at = tokens[k]
    toward_user = [Token("forward", "forward", t.start, t.end, corrected_from=t.text) if t.text in ("closer", "nearer") and (
        n + 1 == len(rest) or rest[n + 1].text != "to" or _words(rest, n + 2, 1) in (("me",), ("you",))) else t for n, t in enumerate(rest)]
    out += [Token("move", "move", at.start, at.end, corrected_from=_said(tokens, k, j - k)), *subject, *toward_user]  # "closer": to the user
    return end - k


_LENGTHS = frozenset({"cm", "centimetre", "centimeter", "centimetres", "centimeters", "metre", "meter", "metres", "meters", "m", "mm", "inch",
                      "inches", "foot", "feet", "ft"})


_WISHING = (("i_want",), ("i_need",), ("i'd_like",), ("i'd", "rather", "have"), ("i'd", "prefer"), ("i'd_prefer",), ("i", "want"))


def _facing_wall(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"I'd rather have the lid side of the suitcase facing the wall (instead of facing me)": turn it around."""
    lead = next((len(w) for w in _WISHING if _words(tokens, k, len(w)) == w), 0)
    if not lead or (out and not out[-1].is_punct):
        return 0
    end = next((e for e in range(k, len(tokens)) if tokens[e].is_sentence_end), len(tokens))
    facing = next((j for j in range(k + lead, end - 2) if tokens[j].text in ("facing", "faces") and _words(tokens, j + 1, 2) == ("the", "wall")), None)
    if facing is None or "side" not in [t.text for t in tokens[k + lead:facing]]:
        return 0
    at = tokens[k]
    out += [Token("turn", "turn", at.start, at.end, corrected_from=_said(tokens, k, end - k)), Token("it", "it", at.start, at.end),
            Token("around", "around", at.start, at.end)]
    return end - k


def _see_the_back(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"I want to see the back of the suitcase": turn it around (the object, not a part)."""
    if tokens[k].text not in ("see", "view", "show") or _words(tokens, k + 1, 3) != ("the", "back", "of"):
        return 0
    end = next((e for e in range(k, len(tokens)) if tokens[e].is_punct), len(tokens))
    if end - k > 7 or any(kind_of_word(t.text) is not None for t in tokens[k + 4:end]):
        return 0  # "see the back of the drawer": a part
    at = tokens[k]
    out += [Token("turn", "turn", at.start, at.end, corrected_from=_said(tokens, k, end - k)), *tokens[k + 4:end], Token("around", "around", at.start, at.end)]
    return end - k


_FULLY = frozenset({"completely", "fully", "all_the_way", "totally", "entirely", "right"})
_ENDS = frozenset({"closed", "shut", "open", "opened"})


def _to_state(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"drive the lid to (completely) closed", "set it to fully open": the state itself, not "to" a measure of the range."""
    if tokens[k].text != "to" or not out or out[-1].is_punct:
        return 0
    j = k + 1 + (k + 1 < len(tokens) and tokens[k + 1].text in _FULLY)
    if j >= len(tokens) or tokens[j].text not in _ENDS or (j + 1 < len(tokens) and not (tokens[j + 1].is_punct or tokens[j + 1].text in (
            "then", "and", "and_then", "position", "pose", "state", "again") or tokens[j + 1].text in ASIDE_WORDS)):
        return 0
    out.extend(tokens[k + 1:j + 1])
    return j + 1 - k


def _bare_state(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"once open, extend the left drawer": once it is open."""
    if tokens[k].text not in ("once", "when", "after") or k + 2 >= len(tokens) or tokens[k + 1].text not in _ENDS | {"down", "up", "done", "in", "out"} or (
            tokens[k + 2].text != ","):
        return 0
    at = tokens[k + 1]
    out.extend([tokens[k], Token("it", "it", at.start, at.start), Token("is", "is", at.start, at.start), at])
    return 2


def _relative_to(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"90 degrees relative to closed": from closed."""
    if tokens[k].text != "relative" or k + 1 >= len(tokens) or tokens[k + 1].text != "to":
        return 0
    out.append(Token("from", "from", tokens[k].start, tokens[k + 1].end))
    return 2


_FASTENED = {"latched": "latch", "locked": "lock", "fastened": "fasten", "clasped": "fasten"}


def _shut_and_locked(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"Toolbox -> shut and latched": shut it, then latch it."""
    if k + 2 >= len(tokens) or tokens[k].text not in ("shut", "closed") or tokens[k + 1].text != "and" or tokens[k + 2].text not in _FASTENED:
        return 0
    done = tokens[k + 2]
    out.extend([tokens[k], Token("then", "then", done.start, done.start), Token(_FASTENED[done.text], _FASTENED[done.text], done.start, done.end)])
    return 3


def _is_to_be(tokens: list[Token], k: int, out: list[Token]) -> int:
    """"The drawer is (then) to be pushed in": it needs to be pushed in (a step asked in the passive)."""
    if tokens[k].text not in ("is", "are") or not out or out[-1].is_punct:
        return 0
    j = k + 1 + (k + 1 < len(tokens) and tokens[k + 1].text == "then")
    if [t.text for t in tokens[j:j + 2]] != ["to", "be"]:
        return 0
    at = tokens[k]
    out.extend([Token("needs", "need", at.start, at.end), Token("to", "to", at.start, at.end), Token("be", "be", at.start, at.end)])
    return j + 2 - k
