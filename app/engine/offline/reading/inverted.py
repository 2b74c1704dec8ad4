"""Motion told with the way first, the way a story says it: "Round and round went the glass plate", "Up came the lid",
"Open swung the door", "and down it went again". Rewritten in the plain order ("the glass plate went round and round",
"it went down again"). Before this stage the way was read as the verb: "round went the plate" opened the plate and was
refused, "down it went" opened the lid again."""

from __future__ import annotations

from app.engine.offline.reading.token import Token

_WAYS = frozenset({"up", "down", "open", "shut", "closed", "out", "in", "back", "off", "round", "around", "away", "over", "forward",
                   "backward", "backwards", "upward", "upwards", "downward", "downwards"})
_GOING = frozenset({"went", "go", "goes", "came", "come", "comes", "flew", "flies", "swung", "swings", "popped", "pops", "slid", "slides",
                    "rolled", "rolls", "spun", "spins", "sprang", "springs", "snapped", "snaps", "shot", "shoots", "flipped", "flips",
                    "dropped", "drops", "fell", "falls", "swept", "sweeps", "glided", "glides", "whirled", "whirls", "creaked", "creaks"})
_PRONOUNS = frozenset({"it", "they", "she", "he"})
_STARTS = frozenset({",", ".", ";", ":", "!", "?", "and", "then", "so"})
_ENDS = frozenset({",", ".", ";", ":", "!", "?", "and", "then", "while", "before", "after", "until", "so", "but"})


def _ways(tokens: list[Token], k: int) -> int:
    """The end of a run of ways starting at ``k`` ("round and round", "up and up", "up"), else ``k``."""
    if k < len(tokens) and tokens[k].text in _WAYS:
        if k + 2 < len(tokens) and tokens[k + 1].text == "and" and tokens[k + 2].text == tokens[k].text:
            return k + 3
        return k + 1
    return k


def _inverted(tokens: list[Token], k: int) -> tuple[int, list[Token]] | None:
    """The end and plain order of an inverted clause starting at ``k``, else None."""
    end = _ways(tokens, k)
    if end == k or end >= len(tokens):
        return None
    ways = tokens[k:end]
    if tokens[end].text in _GOING and end + 1 < len(tokens) and tokens[end + 1].text in ("the", "my", "this", "that", "its", "his", "her", "our", "their"):
        stop = next((j for j in range(end + 2, len(tokens)) if tokens[j].text in _ENDS), len(tokens))
        return stop, [*tokens[end + 1:stop], tokens[end], *ways]  # "round went the plate": the plate went round
    if tokens[end].text in _PRONOUNS and end + 1 < len(tokens) and tokens[end + 1].text in _GOING:
        return end + 2, [tokens[end], tokens[end + 1], *ways]  # "down it went": it went down
    return None


def inverted(tokens: list[Token]) -> list[Token]:
    """``tokens`` with each clause that says its way before its verb and subject put in the plain order."""
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        found = _inverted(tokens, k) if (k == 0 or tokens[k - 1].text in _STARTS) else None
        if found is None:
            out.append(tokens[k])
            k += 1
            continue
        stop, plain = found
        out += plain
        k = stop
    return out
