"""Part kinds of links from every name source: semantics.txt labels, link and visual names."""

from __future__ import annotations

import re
from functools import lru_cache
from typing import TYPE_CHECKING

from app.engine.asset.model import ArticulatedAsset
from app.engine.lexicon.kinds import REGISTRY, PartKind, kind_of_label

if TYPE_CHECKING:
    from app.engine.offline.grounding import Part

GENERIC = re.compile(r"^(?:link|joint|part|base|visual|geom|mesh|obj|original|node|l|j)?\d*$")


def tokens(name: str) -> list[str]:
    """Lower-case word tokens of an identifier ("drawer_top", "wheelFrontLeft", "door-1")."""
    spaced = re.sub(r"([a-z])([A-Z])", r"\1 \2", name)
    return [t for t in re.split(r"[^a-z]+", spaced.lower()) if t]


@lru_cache(maxsize=1)
def _phrases() -> tuple[tuple[tuple[str, ...], PartKind], ...]:
    pairs = [(tuple(tokens(word)), entry.kind) for entry in REGISTRY.values() for word in entry.words]
    return tuple(sorted(pairs, key=lambda pair: -len(pair[0])))


def kind_of_text(text: str) -> PartKind | None:
    """Kind named by a label or identifier: a PartNet label, else its words (latch words win,
    then multi-word names, then the last word that names a kind, plurals included)."""
    label = kind_of_label(text)
    if label is not None:
        return label
    words = tokens(text)
    if any(w in ("latch", "lock") for w in words):
        return PartKind.LATCH  # a latch knob or latch handle behaves as a latch (springs back)
    for phrase, kind in _phrases():
        if len(phrase) > 1 and any(tuple(words[i:i + len(phrase)]) == phrase for i in range(len(words))):
            return kind
    singles = {phrase[0]: kind for phrase, kind in _phrases() if len(phrase) == 1}
    for word in reversed(words):
        if word in singles:
            return singles[word]
        if word.endswith("s") and word[:-1] in singles:
            return singles[word[:-1]]
    return None


def link_kind(asset: ArticulatedAsset, link: str) -> PartKind | None:
    """Best kind of ``link``: semantics label, then link name, then visual names."""
    spec = asset.links[link]
    for source in (spec.semantics.label or "", link, *spec.semantics.visual_names):
        if source and not GENERIC.match(source.lower()):
            kind = kind_of_text(source)
            if kind is not None:
                return kind
    return None


def link_words(asset: ArticulatedAsset, link: str, *, visuals: bool = True) -> set[str]:
    """Words naming ``link`` (label, link name and, if asked, visual names)."""
    spec = asset.links[link]
    words: set[str] = set()
    for source in (spec.semantics.label or "", link, *(spec.semantics.visual_names if visuals else ())):
        words.update(tokens(source))
    return words


def describe_link(asset: ArticulatedAsset, link: str) -> str:
    """Human label of a link for messages: "door (link_0)"."""
    spec = asset.links[link]
    kind = link_kind(asset, link)
    label = spec.semantics.label or (kind.value if kind is not None else None)
    return f"{label} ({link})" if label and label != link else link


def did_you_mean(word: str, parts: list[Part], asset: ArticulatedAsset) -> str:
    """" (did you mean 'door'?)" when a part name of this asset is a few letters away."""
    from rapidfuzz.distance import Levenshtein

    names = {p.kind.value for p in parts if p.kind is not None}
    for part in parts:
        names.update(w for w in link_words(asset, part.link, visuals=False) if len(w) >= 3 and not w.isdigit())
    scored = sorted((Levenshtein.distance(word, n), n) for n in names if n != word)
    if scored and scored[0][0] <= max(2, len(word) // 3):
        close = [n for d, n in scored if d == scored[0][0]][:2]
        return " (did you mean " + " or ".join(f"'{n}'" for n in close) + "?)"
    return ""
