"""Part categories of links from every name source: semantics.txt, link and visual names."""

from __future__ import annotations

import re

from app.engine.asset.model import ArticulatedAsset
from app.engine.offline.vocabulary import CATEGORY_WORDS, LABEL_CATEGORY

_WORD_CATEGORY: dict[str, str] = {}
for _category, _words in CATEGORY_WORDS.items():
    for _word in _words:
        _WORD_CATEGORY.setdefault(_word, _category)
_WORD_CATEGORY.update({"turntable": "turntable", "foot": "pedal", "pad": "pedal", "tray": "tray"})
GENERIC = re.compile(r"^(?:link|joint|part|base|visual|geom|mesh|obj|original|node|l|j)?\d*$")


def tokens(name: str) -> list[str]:
    """Lower-case word tokens of an identifier ("drawer_top", "wheelFrontLeft", "door-1")."""
    spaced = re.sub(r"([a-z])([A-Z])", r"\1 \2", name)
    return [t for t in re.split(r"[^a-z]+", spaced.lower()) if t]


def category_of_text(text: str) -> str | None:
    """Category named by a label or identifier, longest phrase first."""
    label = text.lower().strip()
    if label in LABEL_CATEGORY:
        return LABEL_CATEGORY[label]
    words = tokens(label)
    if "latch" in words:  # a latch knob or latch handle behaves as a latch (springs back)
        return "latch"
    joined = " ".join(words)
    for phrase in sorted(_WORD_CATEGORY, key=len, reverse=True):
        if " " in phrase and re.search(r"\b" + re.escape(phrase) + r"\b", joined):
            return _WORD_CATEGORY[phrase]
    for word in reversed(words):  # the head noun is usually last ("drawer_top" is an exception handled below)
        if word in _WORD_CATEGORY:
            return _WORD_CATEGORY[word]
        if word.endswith("s") and word[:-1] in _WORD_CATEGORY:
            return _WORD_CATEGORY[word[:-1]]
    return None


def link_category(asset: ArticulatedAsset, link: str) -> str | None:
    """Best category of ``link``: semantics label, then link name, then visual names."""
    spec = asset.links[link]
    sources = [spec.semantics.label or "", link, *spec.semantics.visual_names]
    for source in sources:
        if source and not GENERIC.match(source.lower()):
            category = category_of_text(source)
            if category is not None:
                return category
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
    label = spec.semantics.label or link_category(asset, link)
    return f"{label} ({link})" if label and label != link else link
