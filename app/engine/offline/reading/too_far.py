"""A part said to be too far one way, with no action asked ("the screen is tilted too far toward me", "the drawer is
pulled out too far", "the lid is open way too far"): read as moving it back the other way a little ("tilt the screen
back a little"). The words are rewritten so that the clause reads as that request; the frame reader does the rest."""

from __future__ import annotations

from app.engine.lexicon.verbs import VERBS
from app.engine.offline.reading.token import Token

_BE = frozenset({"is", "are", "was", "were", "'s", "sticks", "stick", "juts", "pokes", "stands", "sits"})
_OPPOSITE = {"toward": "back", "towards": "back", "forward": "back", "forwards": "back", "back": "forward", "backward": "forward",
             "backwards": "forward", "out": "in", "in": "out", "up": "down", "down": "up", "left": "right", "right": "left"}
"""The way back from a way said too far ("toward me" is toward the user: the part goes back)."""
_STATES = {"open": ("close", None), "opened": ("close", None), "ajar": ("close", None), "closed": ("open", None), "shut": ("open", None)}
"""A state said too far ("open too far") and the verb that goes back from it."""
_FILLERS = frozenset({"way", "much", "a", "bit", "little", "just", "slightly"})
_ENDS = frozenset({".", ",", "!", ";", "-", "and", "so", "but", "then"})


def too_far(tokens: list[Token]) -> list[Token]:
    """``tokens`` with each "<part> is <done> too far <way>" rewritten as "<do> <part> <the way back> a little"."""
    out = list(tokens)
    k = 0
    while k < len(out):
        found = _said_too_far(out, k)
        if found is None:
            k += 1
            continue
        start, be, end, verb, back, amount = found
        said = " ".join(t.text for t in out[start:end])
        subject = out[start:be]
        if end + 1 < len(out) and out[end].text in (".", "!", ";") and (out[end + 1].text in VERBS or out[end + 1].lemma in VERBS):
            out[start:end] = subject  # "The screen is tilted back too far. Bring it forward so ...": what to do is said next
            k = start + len(subject)
            continue
        at = out[start]
        rewritten = [Token(verb, verb, at.start, at.end, corrected_from=said), *subject]
        if back is not None:
            rewritten.append(Token(back, back, at.start, at.end))
        rewritten.extend(amount or [Token("a_little", "a_little", at.start, at.end)])  # "sticks out 10 cm too far": by that much
        out[start:end] = rewritten
        k = start + len(rewritten)
    return out


def _said_too_far(tokens: list[Token], k: int) -> tuple[int, int, int, str, str | None, list[Token]] | None:
    """At the start of a clause ``k``: (start, the "is", the end, the verb, the way back, the amount said) of "the screen is
    tilted too far toward me", "this cabinet sticks out ten centimetres too far from the wall", else None."""
    if k and tokens[k - 1].text not in _ENDS:
        return None
    if k >= len(tokens) or tokens[k].text not in ("the", "this", "that", "my", "its"):
        return None
    be = next((j for j in range(k + 1, min(len(tokens), k + 6)) if tokens[j].text in _BE), None)
    if be is None or be == k + 1:
        return None
    j = be + 1
    done = tokens[j].text if j < len(tokens) else ""
    verb: str | None = None
    way: str | None = None
    if done in _STATES:
        verb, j = _STATES[done][0], j + 1
    elif done.endswith("ed") and _lemma(done) in VERBS:
        verb, j = _lemma(done), j + 1
    if j < len(tokens) and tokens[j].text in _OPPOSITE:
        way, j = tokens[j].text, j + 1  # "pulled out too far"
    amount: list[Token] = []
    if j + 1 < len(tokens) and tokens[j].number is not None and tokens[j + 1].text.isalpha():
        amount, j = tokens[j:j + 2], j + 2  # "sticks out ten centimetres too far"
    while j < len(tokens) and tokens[j].text in _FILLERS:
        j += 1
    if j + 1 >= len(tokens) or tokens[j].text != "too" or tokens[j + 1].text not in ("far", "much"):
        return None
    j += 2
    if way is None and j < len(tokens) and tokens[j].text in _OPPOSITE:
        way, j = tokens[j].text, j + 1  # "tilted too far toward me"
        if j < len(tokens) and tokens[j].text in ("me", "us", "you", "the_front", "the_user"):
            j += 1
    if [t.text for t in tokens[j:j + 3]] == ["from", "the", "wall"]:
        way, j = "forward", j + 3  # "sticks out too far from the wall": it goes back toward the wall
    if verb is None and way is None:
        return None
    back = _OPPOSITE[way] if way is not None else None
    if verb is None:
        verb = "push" if back in ("back", "in") else "move"
    elif verb in ("close", "open") and back is not None:
        back = None  # "open too far out": the state says it
    if j < len(tokens) and tokens[j].text not in _ENDS:
        return None
    return k, be, j, verb, back, amount


def _lemma(word: str) -> str:
    """"tilted" -> tilt, "pulled" -> pull, "raised" -> raise (a verb of the lexicon), else the word."""
    return next((word[:-cut] for cut in (2, 1, 3) if word[:-cut] in VERBS), word)
