""""it" after a clause that only describes a part by a word that names no kind: "on the wooden crate, the panel that
forms the top - tip it back". The description is what "it" stands
for, read as if said in its place ("tip the panel that forms the top back"), so that the verb can pick the part. Before this stage "it" named nothing and the prompt was refused."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.words import GENERIC_PART_NOUNS
from app.engine.offline.reading.acts import Act


def named_before_it(acts: list[Act]) -> list[Act]:
    """``acts`` with a lone "it" right after such a description replaced by the description's own mentions."""
    out = list(acts)
    for k in range(len(out) - 1):
        described, then = out[k].goal, out[k + 1].goal
        if not (out[k].condition or described.heading) or described.verb is not None or described.stative:  # "there's a piece on top": placed
            continue
        themes = tuple(m for m in described.themes if m.kind is None and m.head in GENERIC_PART_NOUNS and not (
            m.is_object or m.anaphor or m.pronoun or m.plural or m.sides or m.relation or m.owner or m.region))  # placed: its topic is "it"  # not "the milk is in the left-hand door and I need it": a thing kept
        if not themes or len(then.themes) != 1 or then.themes[0].head != "it" or not then.themes[0].pronoun:
            continue
        out[k + 1] = replace(out[k + 1], goal=replace(then, themes=themes))
    return out
