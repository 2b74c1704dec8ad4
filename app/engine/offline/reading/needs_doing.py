"""Work inside the object said as what it needs: "The dishwasher needs loading", "the fridge needs to be cleaned out",
"the upper dishwasher has to be emptied". Rewritten as the request ("load the dishwasher", "load the upper dishwasher"),
which opens what holds the things. Before this stage "loading" was dropped as a stray word and the dishwasher's button
pressed (or nothing read and the prompt refused)."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.words import DETERMINERS, OBJECT_NOUNS
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.word_class import lemma_of

_DONE_INSIDE = {"loading": "load", "loaded": "load", "unloading": "unload", "unloaded": "unload", "emptying": "empty",
                "emptied": "empty", "filling": "fill", "filled": "fill", "cleaning": "clean", "cleaned": "clean",
                "restocking": "restock", "restocked": "restock", "stocking": "stock", "stocked": "stock"}
_NEEDS = (("needs", "to", "be"), ("need", "to", "be"), ("has", "to", "be"), ("have", "to", "be"), ("needs", "to_be"), ("need", "to_be"),
          ("has", "to_be"), ("have", "to_be"), ("needs",), ("need",), ("must", "be"), ("should", "be"), ("wants",))


def _object_phrase(tokens: list[Token], k: int) -> int | None:
    """The start of "the (upper) dishwasher" ending just before ``k``, else None."""
    if k == 0 or lemma_of(tokens[k - 1].text)[0] not in OBJECT_NOUNS:
        return None
    start = k - 1
    while start > 0 and not tokens[start - 1].is_punct and tokens[start - 1].text not in ("and", "so", "then", "but") and k - start < 5:
        start -= 1
        if tokens[start].text in DETERMINERS:
            return start
    return None


def needs_doing(tokens: list[Token]) -> list[Token]:
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        need = next((n for n in _NEEDS if tuple(t.text for t in tokens[k:k + len(n)]) == n), None)
        done = tokens[k + len(need)].text if need is not None and k + len(need) < len(tokens) else None
        start = _object_phrase(tokens, k) if done in _DONE_INSIDE and need is not None else None
        if start is None or need is None or done is None:
            out.append(tokens[k])
            k += 1
            continue
        phrase = out[len(out) - (k - start):]  # "the upper dishwasher", already written out
        del out[len(out) - (k - start):]
        verb = _DONE_INSIDE[done]
        out += [replace(tokens[k], text=verb, lemma=verb, corrected_from=" ".join(t.text for t in tokens[start:k + len(need) + 1])), *phrase]
        k += len(need) + 1
    return out
