"""A wait told by what the object is making ("when the toast is done", "once the coffee is ready", "after the food has
cooked"): no part of the object is in that state; the step after it comes next. Read as "then", like the user's own
progress ("when I'm done", :data:`~app.engine.lexicon.words.ASIDE_PHRASES`). Before this stage "when the toast is done"
read "the toast" as the lever that carries it and made "done" a state to reach first."""

from __future__ import annotations

from dataclasses import replace

from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.spans import replace_spans
from app.engine.offline.reading.token import Token

_WHEN = frozenset({"when", "once", "after", "as_soon_as"})
_OWNERS = frozenset({"the", "its", "my", "your", "our"})
_IS = frozenset({"is", "are", "'s", "has", "have"})
_MADE = frozenset({"done", "ready", "finished", "cooked", "toasted", "brewed", "baked", "heated", "hot", "warm", "dry", "clean", "washed"})


def _made_at(tokens: list[Token], k: int) -> int | None:
    """The index after "when the toast is done" at ``k``, else None."""
    if tokens[k].text not in _WHEN or k + 2 >= len(tokens):
        return None
    if tokens[k + 1].text in ("it's", "they're") and tokens[k + 2].text in _MADE:
        return k + 3  # "when it's done": whatever it makes, or its step, is over
    if k + 3 >= len(tokens) or (tokens[k + 1].text not in _OWNERS and tokens[k + 1].text not in ("both", "all")):
        return None
    j = k + 2
    j += tokens[j - 1].text in ("both", "all") and tokens[j].text in ("the", "of")  # "once both knobs are done", "once all the keys are done"
    j += tokens[j - 1].text == "of" and tokens[j].text == "the"
    part = kind_of_word(tokens[j].text) is not None
    if (part and not _over(tokens, j + 1)) or not tokens[j].text.isalpha():
        return None  # "when the door is open": a part's state, read by the condition stages; not "once both knobs are done": finished with
    j += 1
    if j < len(tokens) and tokens[j].text in _IS:
        j += 1
    if j < len(tokens) and tokens[j].text == "been":
        j += 1
    return j + 1 if j < len(tokens) and tokens[j].text in _MADE else None


def _over(tokens: list[Token], j: int) -> bool:
    """"(are) done", "(are) finished": the work on the part is over, not a state of it."""
    j += j < len(tokens) and tokens[j].text in _IS
    return j < len(tokens) and tokens[j].text in ("done", "finished", "through")


def waits_out(tokens: list[Token]) -> list[Token]:
    """``tokens`` with each wait for what the object makes read as "then"."""
    return replace_spans(tokens, _made_at, lambda ts, k, _end: [replace(ts[k], text="then", lemma="then")])
