"""Orders and times told after the fact: "close the window, but before that, open it all the way", "seat the lid at the end, but first raise it", "open the safe door,
but turn the little knob before you do" (the second step goes first), "hold it there while I count to five" (five
seconds), "for just a sec" (one second). The words are rewritten as the plain form the clause splitter reads ("before A, B"; "for 5 seconds")."""

from __future__ import annotations

from app.engine.offline.reading.token import Token

_THAT = frozenset({"that", "this", "then", "doing_that", "you_do"})
_DOERS = frozenset({"you", "i", "we"})
_DOES = frozenset({"do", "did", "does"})
_JOINS = frozenset({",", "but", "and", "then"})
_COUNTING = frozenset({"while", "as", "whilst"})


def told_order(tokens: list[Token]) -> list[Token]:
    """``tokens`` with steps told in reverse order put as "before A, B", a count said as seconds, and "A, and B after
    that" (B verbless) as both in the order said."""
    out = _after_that(_a_second(_counted(tokens)))
    k = 0
    while k < len(out):
        moved = _before_that(out, k) or _before_you_do(out, k) or _but_first(out, k)
        if moved is not None:
            start, end, first, then = moved
            at = out[start]
            out[start:end] = [Token("before", "before", at.start, at.end), *first, Token(",", ",", at.start, at.end), *then]
            k = end
        k += 1
    return out


def _sentence(tokens: list[Token], k: int) -> tuple[int, int]:
    """The start and end of the sentence around ``k``."""
    start = max((j + 1 for j in range(k) if tokens[j].is_sentence_end), default=0)
    end = next((j for j in range(k, len(tokens)) if tokens[j].is_sentence_end), len(tokens))
    return start, end


def _trimmed(tokens: list[Token]) -> list[Token]:
    while tokens and tokens[0].text in _JOINS:
        tokens = tokens[1:]
    while tokens and tokens[-1].text in _JOINS:
        tokens = tokens[:-1]
    return tokens


def _before_that(tokens: list[Token], k: int) -> tuple[int, int, list[Token], list[Token]] | None:
    """"A, but before that, B" at "before" ``k``: B goes first."""
    if tokens[k].text != "before" or k + 1 >= len(tokens) or tokens[k + 1].text not in _THAT or not k or tokens[k - 1].text not in _JOINS:
        return None
    start, end = _sentence(tokens, k)
    first, then = _trimmed(tokens[start:k]), _trimmed(tokens[k + 2:end])
    return (start, end, first, then) if first and then else None


def _but_first(tokens: list[Token], k: int) -> tuple[int, int, list[Token], list[Token]] | None:
    """"I want the lid seated back at the end, but first raise it 6 cm" at "but" ``k``: B goes first."""
    if tokens[k].text != "but" or k + 1 >= len(tokens) or tokens[k + 1].text != "first":
        return None
    start, end = _sentence(tokens, k)
    first, then = _trimmed(tokens[start:k]), _trimmed(tokens[k + 2:end])
    return (start, end, first, then) if first and then else None


def _before_you_do(tokens: list[Token], k: int) -> tuple[int, int, list[Token], list[Token]] | None:
    """"A, but B before you do (that)" at "before" ``k``: B goes first."""
    if tokens[k].text != "before" or [t.text in s for t, s in zip(tokens[k + 1:k + 3], (_DOERS, _DOES), strict=False)] != [True, True]:
        return None
    tail = k + 3 + (k + 3 < len(tokens) and tokens[k + 3].text in ("that", "it", "so", "this"))
    start, end = _sentence(tokens, k)
    if tail != end:
        return None
    split = max((j for j in range(start, k) if tokens[j].text in (",", "but")), default=None)
    if split is None:
        return None
    first, then = _trimmed(tokens[start:split]), _trimmed(tokens[split + 1:k])
    return (start, end, first, then) if first and then else None


def _counted(tokens: list[Token]) -> list[Token]:
    """"while I count to five", "for a five count", "for a count of five": for five seconds."""
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        words = [t.text for t in tokens[k:k + 4]]
        if len(words) == 4 and words[0] in _COUNTING and words[1] in _DOERS and words[2] == "count" and words[3] == "to" and (
                k + 4 < len(tokens) and tokens[k + 4].number is not None):
            number, at = tokens[k + 4], tokens[k]
            out += [Token("for", "for", at.start, at.end, corrected_from=" ".join(t.text for t in tokens[k:k + 5])), number,
                    Token("seconds", "second", number.start, number.end)]
            k += 5
            continue
        if len(words) >= 3 and words[0] in ("a", "an") and tokens[k + 1].number is not None and words[2] == "count":
            number = tokens[k + 1]  # "for a five count": five seconds
            out += [number, Token("seconds", "second", number.start, tokens[k + 2].end)]
            k += 3
            continue
        if len(words) == 4 and words[:3] == ["a", "count", "of"] and tokens[k + 3].number is not None:
            number = tokens[k + 3]  # "for a count of five"
            out += [number, Token("seconds", "second", number.start, number.end)]
            k += 4
            continue
        out.append(tokens[k])
        k += 1
    return out


def _after_that(tokens: list[Token]) -> list[Token]:
    """"lock the left latch, and the right one after that": both, in the order said."""
    from app.engine.lexicon.verbs import VERBS

    out = list(tokens)
    for k, token in enumerate(tokens):
        if token.text not in ("after_that", "afterwards", "afterward", "after") or not (k + 1 == len(tokens) or tokens[k + 1].is_sentence_end):
            continue
        start, _ = _sentence(tokens, k)
        joined = max((j for j in range(start, k) if tokens[j].text in ("and", ",")), default=None)  # "right drawer first, left drawer after"
        if joined is not None and joined + 1 < k and not any(t.lemma in VERBS or t.text in VERBS for t in tokens[joined + 1:k]):
            out[k] = Token("in_the_order_said", "in_the_order_said", token.start, token.end)
    return out


def _a_second(tokens: list[Token]) -> list[Token]:
    """"for (just) a second", "for a sec": for 1 second."""
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        skip = 2 if k + 1 < len(tokens) and tokens[k + 1].text in ("just", "only") else 1
        words = [t.text for t in tokens[k + skip:k + skip + 3]]
        if tokens[k].text == "for" and words[:2] in (["a", "second"], ["a", "sec"]) and (len(words) < 3 or words[2] not in ("time", "one", "go")):
            at = tokens[k + skip]
            out += [tokens[k], Token("1", "1", at.start, at.end, number=1.0), Token("second", "second", at.start, at.end)]
            k += skip + 2
            continue
        out.append(tokens[k])
        k += 1
    return out
