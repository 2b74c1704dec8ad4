"""Where a step stops, said after it as what to leave: "Push it in, but leave it open a crack - about two centimetres
short of shut", "close it, leaving it 5 degrees off closed". Read as the end of that step ("push it in to 2 cm from shut").
"Lower the door to just short of flat" is almost flat. Without a measure, "..., but leave it open a crack" / "slightly open" / "ajar" stops the step almost shut, and "..., but not
all the way" stops it partway (with the agent's note on the amount). Before this stage the words after "but" were dropped and
the drawer was pushed shut, silently."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.words import STATES
from app.engine.offline.reading.token import Token

_LEADS = ((",", "but", "leave", "it"), (",", "but", "leave", "them"), (",", "leaving", "it"), (",", "leaving", "them"), ("but", "leave", "it"),
          (",", "stopping"), (",", "but", "stop"))
_SHORT = (("short", "of"), ("from",), ("off",), ("shy", "of"), ("before",))
_LOOSE = frozenset({"open", "a", "crack", "a_crack", "ajar", "just", "about", "around", "roughly", "approximately", ",", "-", "—", "slightly", "only"})


def _lead(tokens: list[Token], k: int) -> int | None:
    for lead in _LEADS:
        if tuple(t.text for t in tokens[k:k + len(lead)]) == lead:
            return k + len(lead)
    return None


def _stop(tokens: list[Token], j: int) -> tuple[list[Token], int] | None:
    """The amount and the index after "<N unit> short of <closed>" from ``j`` (loose words skipped), else None."""
    while j < len(tokens) and tokens[j].text in _LOOSE:
        j += 1
    if j + 2 >= len(tokens) or tokens[j].number is None:
        return None
    amount = tokens[j:j + 2]
    j += 2
    for short in _SHORT:
        if tuple(t.text for t in tokens[j:j + len(short)]) == short and j + len(short) < len(tokens) and (
                STATES.get(tokens[j + len(short)].text) == "closed"):
            return amount, j + len(short) + 1
    return None


_AJAR = (("open", "a_crack"), ("open", "a", "crack"), ("a_crack", "open"), ("slightly", "open"), ("ajar",), ("open", "a_little"),
         ("open", "a_little_bit"), ("open", "a", "bit"), ("a_little", "open"), ("just", "ajar"), ("open", "slightly"))
_NOT_ALL = ((",", "but", "not", "all_the_way"), (",", "but", "not", "fully"), (",", "but", "not", "completely"), ("but", "not", "all_the_way"),
            (",", "not", "all_the_way"))
_ENDS = frozenset({".", "!", ";", "?"})


def _said_end(tokens: list[Token], k: int) -> tuple[list[str], int] | None:
    """"..., but leave it open a crack" -> almost shut; "..., but not all the way" -> partway (words, end), else None."""
    for lead in _NOT_ALL:
        end = k + len(lead)
        if tuple(t.text for t in tokens[k:end]) == lead and (end == len(tokens) or tokens[end].text in _ENDS):
            return ["partway"], end
    j = _lead(tokens, k)
    if j is None or (j - k == 2 and tokens[k + 1].text == "stopping"):
        return None
    for ajar in _AJAR:
        end = j + len(ajar)
        if tuple(t.text for t in tokens[j:end]) == ajar and (end == len(tokens) or tokens[end].text in _ENDS):
            return ["almost", "closed"], end
    return None


_STATE_WORDS = frozenset({"flat", "closed", "shut", "open", "upright", "vertical", "horizontal", "level"})


def _just_short(tokens: list[Token], k: int) -> int | None:
    """The index after "just short of flat" at ``k`` (no measure said before it), else None."""
    j = k + (tokens[k].text in ("just", "only"))
    if [t.text for t in tokens[j:j + 2]] in (["short", "of"], ["shy", "of"]) and j + 2 < len(tokens) and tokens[j + 2].text in _STATE_WORDS:
        return j + 2
    return None


def left_short(tokens: list[Token]) -> list[Token]:
    """``tokens`` with ", but leave it ... N cm short of shut" said as "to N cm from shut"."""
    out = list(tokens)
    k = 0
    while k < len(out):
        j = _lead(out, k)
        found = _stop(out, j) if j is not None else None
        if out[k].text == "shut" and k > 0 and out[k - 1].text in ("almost", "nearly"):
            out[k] = replace(out[k], text="closed", lemma="closed")  # "until it's nearly shut": nearly closed (the state, not a verb)
        short = _just_short(out, k) if found is None and (k == 0 or out[k - 1].number is None) else None
        if short is not None:
            out[k:short] = [Token("almost", "almost", out[k].start, out[short - 1].end)]  # "(to) just short of flat": almost flat
            k += 1
            continue
        said = _said_end(out, k) if found is None else None
        at = out[k]
        if found is not None:
            amount, end = found
            out[k:end] = [Token("to", "to", at.start, at.end), *amount, Token("from", "from", at.start, at.end), out[end - 1]]
        elif said is not None:
            words, end = said
            out[k:end] = [Token(w, w, at.start, out[end - 1].end) for w in words]
        k += 1
    return out
