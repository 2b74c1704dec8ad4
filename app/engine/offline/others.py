""""The other one" after a part the prompt only named ("The top drawer only has socks in it, so leave that one alone and
open the other one", "leave the top drawer alone and open the other one"): the part named before, though no step worked
it, is the one "other" excludes, and its kind is the kind "one" stands for."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import PartKind
from app.engine.offline.reading.mention import Mention

if TYPE_CHECKING:
    from app.engine.offline.referents import Referents


def _before(refs: Referents, mention: Mention) -> list[Mention]:
    at = next((k for k, m in enumerate(refs.said) if m.other and m.words == mention.words), len(refs.said))
    return [m for m in refs.said[:at] if m.kind is not None and not (m.pronoun or m.anaphor or m.other or m.is_object or m.plural)]


def other_than_said(refs: Referents, mention: Mention, kind: PartKind | None) -> tuple[PartKind | None, set[str], list[str]]:
    """(the kind "the other one" stands for, the joints of the single parts named before it, a note saying so). Only when no step has worked
    a part of that kind yet: "open the top drawer, then the other one" is the one the step did not work."""
    if not mention.other or (kind is not None and any(p.joint in refs.referenced for p in refs.of_kind(kind))):
        return kind, set(), []
    named = _before(refs, mention)
    if kind is None and mention.anaphor:
        kind = named[-1].kind if named else None
    joints: set[str] = set()
    for said in named:
        if said.kind is not kind:
            continue
        try:
            parts = refs.ground(said).parts
        except GroundingError:
            continue
        if len(parts) == 1:
            joints.add(parts[0].joint)
    links = sorted(p.link for p in refs.parts if p.joint in joints)
    return kind, joints, [f"read '{mention.words}' as other than {', '.join(links)}, named before"] if links else []
