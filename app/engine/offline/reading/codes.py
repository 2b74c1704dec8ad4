"""Keys of a code typed on a keypad: digits ("1-2-3-4") or places ("top-left, then bottom-right")."""

from __future__ import annotations

from app.engine.lexicon.words import DEFINITES, DETERMINERS, ORDINALS, SPATIAL
from app.engine.offline.reading.tokens import Token

CODE_VERBS = frozenset({"type", "enter", "key", "punch", "input", "press", "tap", "push", "hit"})
_CODE_SEPARATORS = frozenset({",", "then", "and", "and_then", "followed_by", "-", "next"})


_KEY_WORDS = frozenset({"key", "button", "one", "on", "keypad", "of", "in", "at", "code", "combination", "sequence", "pin", "digit",
                        "number", "passcode", "keycode", "pad"})


_PLACING = frozenset({"next_to", "beside", "above", "below", "under", "over", "beneath", "left_of", "right_of", "near", "nearest",
                      "closest", "to_the_left", "to_the_right"})


def place_words(text: str) -> bool:
    """Only words that place a key ("second-row middle", "bottom-left")."""
    return all(w in SPATIAL or w in ORDINALS or w in ("row", "column") or (
        "-" in w and all(p in SPATIAL or p in ORDINALS or p in ("row", "column") for p in w.split("-"))) for w in text.split() if w not in DETERMINERS)


def _place_item(tokens: list[Token]) -> tuple[str, ...] | None:
    """("place", sides..., "row=N" / "column=N") of one key description ("bottom-left", "second-row middle")."""
    item: list[str] = []
    words = [t.text for t in tokens if t.text not in DETERMINERS and t.lemma not in _KEY_WORDS]
    for index, word in enumerate(words):
        parts = word.split("-")
        if len(parts) == 2 and parts[0] in ORDINALS and parts[1] in ("row", "column"):
            item.append(f"{parts[1]}={ORDINALS[parts[0]]}")
        elif word in ORDINALS and index + 1 < len(words) and words[index + 1] in ("row", "column"):
            item.append(f"{words[index + 1]}={ORDINALS[word]}")
        elif word in ("row", "column"):
            continue
        elif all(p in SPATIAL for p in parts):
            item.extend(SPATIAL[p][0].value for p in parts)
        else:
            return None
    return ("place", *item) if item else None


def code_items(tokens: list[Token], start: int, used: frozenset[int]) -> tuple[tuple[str, ...], ...]:
    """The keys of an entered code, in order: digits, or places on the keypad ("top-left", "second-row middle")."""
    items: list[tuple[str, ...]] = []
    segment: list[Token] = []
    for i in range(start, len(tokens) + 1):
        token = tokens[i] if i < len(tokens) else None
        if token is None or token.text in _CODE_SEPARATORS or token.is_punct:
            place = _place_item(segment) if segment else None
            if place is not None:
                items.append(place)
            segment = []
            continue
        if i in used:
            continue
        counts = i + 1 < len(tokens) and tokens[i + 1].lemma in ("key", "button") and (
            tokens[i + 1].plural or not (i and tokens[i - 1].text in DEFINITES))  # "the three keys of the top row": a count; "the 5 key": its label
        counts = counts or (i > 1 and tokens[i - 1].text in DEFINITES and tokens[i - 2].text in ("of", "among"))  # "the top button of the three"
        counts = counts or any(t.text in _PLACING for t in tokens[max(0, i - 2):i])  # "the key next to the 5": where, not a key to press
        if token.number is not None and token.number == int(token.number) and token.number >= 0 and not counts:
            items.extend(("digit", d) for d in token.text.split(".")[0])
            continue
        segment.append(token)
    return tuple(items)
