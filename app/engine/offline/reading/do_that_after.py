"""The order told in a sentence of its own that points back ("Turn the big knob ... Do that after you've shut the lid,
obviously", "Do all of this before you open the door"): the step it names goes first (after) or last (before), said as
a plain command ("shut the lid. Turn the big knob ...")."""

from __future__ import annotations

from app.engine.offline.reading.token import Token

_POINTERS = frozenset({"that", "this", "it", "all", "those", "these", "them", "of", "everything", "both"})
_SUBJECTS = (("you've",), ("you", "have"), ("you",), ("i've",), ("i", "have"), ("we've",), ("we", "have"), ("you're", "done"), ("it's", "been"))
_TAILS = frozenset({"obviously", "please", "of", "course", "of_course", "naturally", "though", "first"})


def _sentences(tokens: list[Token]) -> list[list[Token]]:
    out: list[list[Token]] = [[]]
    for t in tokens:
        out[-1].append(t)
        if t.is_sentence_end:
            out.append([])
    return [s for s in out if s]


def _command(words: list[Token]) -> list[Token]:
    """"you've shut the lid": "shut the lid"."""
    texts = tuple(t.text for t in words)
    said = next((len(s) for s in _SUBJECTS if texts[:len(s)] == s), 0)
    core = [t for t in words[said:] if not t.is_sentence_end]
    while core and (core[-1].text in _TAILS or core[-1].text == ","):
        core.pop()
    return core


def do_that_after(tokens: list[Token]) -> list[Token]:
    sentences = _sentences(tokens)
    if len(sentences) < 2:
        return tokens
    for k, sentence in enumerate(sentences[1:], start=1):
        words = [t.text for t in sentence]
        if words[:1] != ["do"] or len(words) < 4:
            continue
        at = next((j for j in range(1, min(len(words), 6)) if words[j] in ("after", "before")), None)
        if at is None or not all(w in _POINTERS for w in words[1:at]) or at == 1:
            continue
        step = _command(sentence[at + 1:])
        if not step:
            continue
        end = Token(".", ".", step[-1].end, step[-1].end)
        rest = [t for s in sentences[:k] + sentences[k + 1:] for t in s]
        return [*step, end, *rest] if words[at] == "after" else [*rest, *step, end]
    return tokens
