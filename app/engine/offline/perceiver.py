"""The offline perceiver: prompt + asset -> the contract (Causal.json with its ``artimo`` block).

Stages, each reading only the typed output of the one before:
normalise (:mod:`.reading.tokens`) -> clauses (:mod:`.reading.clauses`) -> frames
(:mod:`.reading.frames`) -> acts (:mod:`.reading.acts`) -> grounding and causal completion
(:mod:`.builder`) -> contract (:mod:`.contract_io`). A prompt it cannot ground raises
:class:`GroundingError` naming the problem (a missing part, the candidates of an ambiguous one).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.steps import Extension
from app.engine.errors import GroundingError
from app.engine.offline.builder import Builder
from app.engine.offline.geometry import object_category
from app.engine.offline.intent import Intent
from app.engine.offline.naming import GENERIC, tokens
from app.engine.offline.reading.acts import build_acts
from app.engine.offline.reading.clauses import split_clauses
from app.engine.offline.reading.frames import read_frames
from app.engine.offline.reading.tokens import Token, tokenize
from app.engine.offline.tracker import resolve_steps


@dataclass(frozen=True)
class Reading:
    extension: Extension
    intent: Intent
    understanding: list[dict[str, Any]]
    notes: tuple[str, ...]


@lru_cache(maxsize=64)
def asset_words(asset: ArticulatedAsset) -> frozenset[str]:
    """Words of the asset's own part names (never corrected; misspellings may be corrected to them)."""
    words: set[str] = set()
    for name, link in asset.links.items():
        for source in (link.semantics.label or "", name, *link.semantics.visual_names):
            if source and not GENERIC.match(source.lower()):
                words.update(w for w in tokens(source) if len(w) >= 3)
    category = object_category(asset)
    if category:
        words.update(tokens(category))
    return frozenset(words)


def _corrections(tokens_: list[Token]) -> list[str]:
    return [f"read '{t.corrected_from}' as '{t.text.replace('_', ' ')}'" for t in tokens_ if t.corrected_from]


def read_prompt(prompt: str, asset: ArticulatedAsset) -> Reading:
    """Deterministic reading of ``prompt`` on ``asset``.

    Raises
    ------
    GroundingError
        Nothing in the prompt maps to a movable part, a named part is missing, or a mention is
        ambiguous (the message lists the candidates and how to name each).
    """
    words = tokenize(prompt, asset_words(asset))
    acts = build_acts(read_frames(split_clauses(words)))
    builder = Builder(asset)
    builder.refs.plan([m for act in acts for frame in act.frames for m in (*frame.themes, *frame.instruments)])
    if not builder.parts and not any(a.goal.verb for a in acts):
        raise GroundingError(f"{asset.name} has no movable parts to animate", movable_parts=[])
    for act in acts:
        if act.goal.heading and act is not acts[-1]:
            try:
                builder.add(act)
            except GroundingError:
                builder.notes.append(f"read '{act.goal.text}' as a heading for what follows")
            continue
        builder.add(act)
    if not builder.steps:
        raise builder.refs.refuse(f"could not find an action in '{prompt}'")
    extension = Extension(steps=builder.steps)
    notes = tuple(dict.fromkeys([*_corrections(words), *builder.notes]))
    return Reading(extension=extension, intent=resolve_steps(extension, asset, prompt, notes), understanding=builder.explanation.entries(), notes=notes)
