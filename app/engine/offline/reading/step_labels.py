"""The labels of a numbered procedure ("Step 1: open the upper door. Step 2: only after step 1 has been completed is the
tray to be pulled out", "1. Open the door. 2. Pull out the tray.", "First step - ..."): the steps run in the order
written, so a label says nothing more than a sentence break and is dropped. A reference back to an earlier step ("only
after step 1 has been completed") reads as "that", the step before, when it names the step just before; a reference
to any other step is left as said (and refused when it cannot be read).

Before this stage "2. Pull out the tray" read the "2" as a clause of its own that repeated the step before it.
"""

from __future__ import annotations

from app.engine.lexicon.words import NUMBER_WORDS, ORDINALS
from app.engine.offline.reading.token import Token

_LABEL_ENDS = frozenset({":", ".", ")", "-", ","})
"""What may follow a step's number in its label ("1.", "2)", "Step 3:", "step one -", "step 2,")."""
_BREAKS = frozenset({".", ";", ":", "!", "?", ","})
_STEP = frozenset({"step", "stage", "beat", "phase"})
_BACK = frozenset({"after", "once", "when"})
"""Words before a step said by its number that make it the step waited for ("after step 1 has been completed")."""
MAX_STEPS = 20
_COMPLETED = frozenset({"completed", "complete", "done", "finished", "over", "performed", "executed"})


def step_label(text: str) -> bool:
    """Whether a clause's text is only a step's label kept as a heading ("step 2", "beat one")."""
    words = text.split()
    return len(words) == 2 and words[0] in _STEP and (words[1].isdigit() or words[1] in NUMBER_WORDS)


def _past_completion(tokens: list[Token], k: int) -> int:
    """The index after "has been completed" / "is done" / "is finished" at ``k`` (``k`` when none is said)."""
    j = k
    if j < len(tokens) and tokens[j].text in ("completes", "finishes", "ends"):
        return j + 1  # "after step 1 completes"
    if j < len(tokens) and tokens[j].text in ("has", "have", "is", "was", "'s"):
        j += 1
    if j < len(tokens) and tokens[j].text == "been":
        j += 1
    return j + 1 if j > k and j < len(tokens) and tokens[j].text in _COMPLETED else k


def _number(token: Token) -> int | None:
    value = token.number if token.number is not None else NUMBER_WORDS.get(token.text)
    if value is None or value != int(value) or not 1 <= value <= MAX_STEPS:
        return None
    return int(value)


def _label(tokens: list[Token], k: int) -> tuple[int, int] | None:
    """(the step's number, the index after its label) of a label starting at ``k``, else None."""
    if k and tokens[k - 1].text not in _BREAKS:
        return None
    first = tokens[k].text
    if first in _STEP and k + 1 < len(tokens) and (n := _number(tokens[k + 1])) is not None:
        end = k + 2  # "step 2 :", "step two -", "step 2 open ..."
    elif first in ORDINALS and ORDINALS[first] > 0 and k + 1 < len(tokens) and tokens[k + 1].text in _STEP:
        n, end = ORDINALS[first], k + 2  # "second step : ..."
        if end >= len(tokens) or tokens[end].text not in _LABEL_ENDS:
            return None  # "first step on the pedal": a verb
    elif tokens[k].number is not None and (n := _number(tokens[k])) is not None and k + 1 < len(tokens) and tokens[k + 1].text in (".", ")", ":"):
        end = k + 1  # "2. pull out the tray", "2) ..."
    else:
        return None
    if end < len(tokens) and tokens[end].text in _LABEL_ENDS:
        end += 1
    return (n, end) if end < len(tokens) else None


def step_labels(tokens: list[Token]) -> list[Token]:
    """``tokens`` without the labels of a numbered procedure, with "after step N" read as "after that" where N is the
    step just before the one it is said in ("once step 1 is done" too)."""
    labels: list[tuple[int, int, int]] = []
    k = 0
    while k < len(tokens):
        found = _label(tokens, k)
        if found is not None:
            labels.append((k, *found))
            k = found[1]
        else:
            k += 1
    if len(labels) == 1 and labels[0][1] != 1:
        labels = []  # one "2." alone is no procedure (its labels were read before: "1) ... 2) After step 1 completes, ...")
    out: list[Token] = []
    current = 0
    starts = {start: (n, end) for start, n, end in labels}
    k = 0
    while k < len(tokens):
        if k in starts and tokens[starts[k][1] - 1].text == ":":
            current = starts[k][0]  # "Step 1:" reads as a heading already: kept, its number counted
        elif k in starts:
            current, end = starts[k]
            if out and out[-1].text not in (".", ";"):
                out.append(Token(".", ".", tokens[k].start, tokens[k].start))
            if out and current > 1 and end < len(tokens) and tokens[end].text not in ("then", "and_then", "next", "finally"):
                out.append(Token("then", "then", tokens[k].start, tokens[k].start))  # "2) turntable 90 deg 3) door closed": a step, not an effect
            k = end
            continue
        token = tokens[k]
        if (token.text in _STEP and k + 1 < len(tokens) and out and out[-1].text in _BACK
                and (n := _number(tokens[k + 1])) is not None and (n == current - 1 or not starts)):
            before = out.pop()  # "after that", a phrase the stages before join
            out.append(Token("after_that", "after_that", before.start, tokens[k + 1].end))
            k = _past_completion(tokens, k + 2)
            continue
        out.append(token)
        k += 1
    return out
