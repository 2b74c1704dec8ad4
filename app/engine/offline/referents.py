"""What a mention refers to in context: pronouns and "the other one" through the earlier clauses, kinds through the
registry, and a clear refusal when the asset lacks the part or several similar parts fit (naming each and how to ask)."""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import NAMED_BY_USE, PartKind, info
from app.engine.lexicon.objects import carrier_of
from app.engine.lexicon.words import FUNCTION_NAME_WORDS, GENERIC_PART_NOUNS, Side
from app.engine.offline.describe import name_each
from app.engine.offline.geometry import ObjectGeometry
from app.engine.offline.grounding import (
    Grounding,
    How,
    Part,
    by_kind,
    by_name,
    narrow,
    position,
    reading_order,
)
from app.engine.offline.lone_side import lone_compared, lone_side_refusal
from app.engine.offline.naming import did_you_mean
from app.engine.offline.one_kind import kind_of_one
from app.engine.offline.others import other_than_said
from app.engine.offline.placed import placed
from app.engine.offline.reading.mentions import Mention
from app.engine.offline.tiebreak import carried_alike, tie_break, wheel_shaped
from app.engine.offline.units import in_unit

EXTREME_GAP_M = 0.01
"""A part at least this much further toward the named side than the next one is "the bottom one"."""
_FEATURES = frozenset({PartKind.LATCH, PartKind.HANDLE})
"""Kinds a user may name as a feature of a part that is not movable on its own ("the door latch", "the lid handle")."""
_NUMBER_WORDS = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six", 7: "seven", 8: "eight", 9: "nine"}


@dataclass
class Referents:
    asset: ArticulatedAsset
    obj: ObjectGeometry
    parts: list[Part]
    last: list[Part] = field(default_factory=list)
    """What "it" / "them" means now: the parts the previous clause acted on."""
    last_controls: list[Part] = field(default_factory=list)
    last_kind: PartKind | None = None
    referenced: set[str] = field(default_factory=set)
    """Joints named so far ("the other door" is one not named yet)."""
    last_object: bool = False
    """The previous clause moved the whole object: "it" is the object."""
    topic: bool = False
    """``last`` was named by a heading ("Espresso machine lever: shift it 30 degrees left"): "it" is that part."""
    group: list[Part] = field(default_factory=list)
    """The last several parts one plural mention named ("both fridge doors")."""
    earlier: list[list[Part]] = field(default_factory=list)
    """Every earlier "it", most recent last: "close it" after spinning a turntable means the door opened before."""
    scene: tuple[tuple[Side, bool], ...] = ()
    """Sides of the object a heading named ("SHOT 4, top oven: door drops ..."): where a bare mention's parts are."""
    assigned: dict[str, Part] = field(default_factory=dict)
    eliminated: dict[str, str] = field(default_factory=dict)
    """Nouns that took the one part the prompt left them, with the note that says so ("the timer": the knob not named)."""
    said: list[Mention] = field(default_factory=list)
    """Every mention of the prompt in order: "pull that rack out" after "the middle rack" means the middle one."""
    """head noun -> part, when one prompt names several parts of one pool with different nouns ("the dial ... the handle")."""

    def refuse(self, why: str, candidates: list[Part] | None = None) -> GroundingError:
        movable = [p.describe(self.asset) for p in self.parts]
        if candidates:
            names = name_each(candidates, self.asset, self.obj)
            listing = "; ".join(movable)
            if len(names) == 1:
                return GroundingError(f"{why}: the only one is {names[0]}. Movable parts of {self.asset.name}: {listing}", movable_parts=movable,
                                      candidates=names)
            choice = ", ".join(names[:-1]) + f" or {names[-1]}"
            return GroundingError(f"{why}: say which — {choice}. Movable parts of {self.asset.name}: {listing}", movable_parts=movable, candidates=names)
        if not movable:
            return GroundingError(f"{why}: {self.asset.name} has no movable parts to animate (it can only move as a whole: push, lift or turn it)",
                                  movable_parts=[])
        return GroundingError(f"{why}. Movable parts of {self.asset.name}: {'; '.join(movable)}", movable_parts=movable)

    def of_kind(self, kind: PartKind) -> list[Part]:
        return [p for p in self.parts if p.kind is kind]

    def ground(self, mention: Mention, *, prefer: list[Part] | None = None) -> Grounding:
        """The parts ``mention`` names (pronouns and objects are the caller's: see :meth:`pronoun`)."""
        kind, said_before, notes = other_than_said(self, mention, mention.kind if not mention.anaphor else (mention.kind or self.last_kind))
        if kind is None and (kind := carrier_of(mention.head, self.obj.category, lambda k: bool(self.of_kind(k)))) is not None:
            notes.append(f"read '{mention.words or mention.head}' as the {kind.value} that carries it")
        if kind is None and (one := kind_of_one(mention, self.parts, self.asset.name)) is not None:
            kind, _ = one  # "On the chest of drawers, the upper one ...": its parts are all drawers
            notes.append(one[1])
        if not _qualified(mention) and not mention.plural and mention.head in self.assigned:
            return Grounding(parts=(self.assigned[mention.head],), how="kind", notes=tuple(filter(None, [self.eliminated.get(mention.head)])))
        exact = [p for p in self.parts if mention.head in (p.joint, p.link)]
        if exact:
            return Grounding(parts=tuple(exact[:1]), how="name")  # "joint_1", "link_0": the URDF's own name
        if kind is None:
            candidates = by_name(self.parts, (mention.head, *mention.modifiers[-1:]), self.asset) or (  # "the door release": a release button
                by_kind(self.parts, NAMED_BY_USE[mention.head], self.obj.up, singular=True)[0] if mention.head in NAMED_BY_USE else [])
            how: How = "name" if candidates else "none"
            generic = mention.head in GENERIC_PART_NOUNS or (mention.anaphor and "one" in mention.words.split() and (any(
                m.head in GENERIC_PART_NOUNS and m.plural for m in self.said) or not self.last))  # "the upper one"; "open the top one"
            if not candidates and generic and (mention.sides or mention.size or mention.relation is not None):
                candidates, how = list(self.parts), "kind"  # "the topmost piece", "the left-hand section": any movable part, placed
                if mention.anaphor:
                    notes.append(f"read '{mention.words}' among all the movable parts: nothing was named before")
        else:
            candidates, how = by_kind(self.parts, kind, self.obj.up, singular=not (mention.plural or mention.collective))
            if not candidates:
                named = [p for p in by_name(self.parts, (mention.head,), self.asset) if p.kind is None or p.kind is kind]
                candidates, how = (named, "name") if named else ([], "none")
            elif how == "related":
                shown = candidates[0].kind.value if candidates[0].kind is not None else "part"
                notes.append(f"read '{mention.words or mention.head}' as the {shown}: the asset has no {kind.value}")
        if not candidates:
            return Grounding()
        owners = list(self.ground(mention.owner).parts) if mention.owner is not None and not mention.owner.pronoun else (
            list(self.last) if mention.owner is not None else [])
        said = mention.words.split()
        refusal = lone_side_refusal(mention, kind, candidates, said, self.obj, self.parts, self.asset)
        if refusal is not None:
            raise self.refuse(refusal, candidates)
        if (lone := lone_compared(mention, kind, candidates, said, self.asset)) is not None:
            notes.append(lone)  # "the upper pane" of a window with one moving pane
        if (wheel := wheel_shaped(mention, candidates)) is not None:
            mention = replace(mention, size="large")  # "turn the wheel handle" among a wheel and a small dial: the wheel
            notes.append(wheel)
        said_first = mention.words.split()[:2]  # "there's a rack in the small top oven. Open that oven's door": the top oven's
        if not mention.region and len(said_first) == 2 and said_first[0] in ("that", "this") and (region := next((
                m.region for m in self.said if m.region and m.whose == said_first[1]), ())):
            mention = replace(mention, region=region)
        unit_named = mention.anaphor and mention.kind is None and bool(mention.sides)  # "then the right one": another unit, not the scene's
        if not mention.region and self.scene and len(candidates) > 1 and not unit_named and (unit := in_unit(self.scene, candidates, self.parts, self.asset, self.obj)):
            candidates = unit  # "Left-hand fridge: open the right door": the right door of that fridge
        elif not mention.region and self.scene and len(candidates) > 1 and not (mention.sides or mention.plural or mention.ordinal):
            mention = replace(mention, region=self.scene)  # under "top oven:", "the door" is the top oven's
            candidates = narrow(replace(mention, sides=self.scene), candidates, self.asset, self.obj, [], set())[0] or candidates
        if mention.region and len(candidates) > 1:
            candidates = in_unit(mention.region, candidates, self.parts, self.asset, self.obj) or self._compartment(mention, candidates) or candidates
        hosts = [p for p in (prefer or self.last) if p.kind is not None and info(p.kind).hinged and p not in candidates]
        if (mention.possessive or not (_qualified(mention) or mention.plural)) and mention.owner is None and len(candidates) > 1 and len(hosts) == 1:
            candidates = self._behind(hosts[0], candidates) or candidates  # "open the top door; its rack ...": the rack behind it
        inner = [p for p in (prefer or self.last) if not (p.kind is not None and info(p.kind).hinged) and p not in candidates]
        if mention.possessive and not hosts and len(inner) == 1 and len(candidates) > 1:  # "the rack of the bottom oven — drop its door"
            candidates = [p for p in candidates if p.kind is not None and info(p.kind).hinged and self._behind(p, inner)] or candidates
        if mention.owner is not None and mention.owner.pronoun and len(owners) == 1 and owners[0].kind is not None and info(owners[0].kind).hinged and (
                inside := self._behind(owners[0], candidates)):
            candidates, owners = inside, []  # "both shelves inside it": behind the door "it" is
        kept, overflow = narrow(mention, candidates, self.asset, self.obj, owners, self.referenced | said_before)
        if mention.relation is not None and kept:
            kept = placed(self, mention.relation, kept)
        if overflow is not None:
            return Grounding(how=how, ordinal_overflow=overflow, ambiguous=tuple(candidates))
        if not kept:
            return Grounding()
        if "both" in said and len(kept) > 2:
            return Grounding(how=how, ambiguous=tuple(kept), notes=tuple(notes))  # "both racks" among three: which two?
        if mention.plural or mention.collective or len(kept) == 1:
            return Grounding(parts=tuple(kept), how=how, notes=(*notes, *carried_alike(mention, kept, candidates, self.asset)))
        if self.assigned.get(mention.head) in kept:
            return Grounding(parts=(self.assigned[mention.head],), how=how, notes=tuple(notes))
        if mention.one_of:
            chosen = reading_order(kept, self.obj)[0]
            notes.append(f"'{mention.words}' leaves the choice: took {chosen.link} (the first in reading order)")
            return Grounding(parts=(chosen,), how=how, notes=tuple(notes))
        if mention.sides and not any(side is Side.MIDDLE for side, _ in mention.sides):
            extreme = self._most_extreme(mention, kept)
            if extreme is not None:
                notes.append(f"'{mention.words}' fits {len(kept)} parts; took the one furthest that way ({extreme.link})")
                return Grounding(parts=(extreme,), how=how, notes=tuple(notes))
        if prefer:
            preferred = [p for p in kept if p in prefer]
            if len(preferred) == 1:
                return Grounding(parts=(preferred[0],), how=how, notes=tuple(notes))
        seen = [p for p in kept if p.joint in self.referenced]
        if len(seen) == 1 and not _qualified(mention):
            notes.append(f"'{mention.words or mention.head}' fits {len(kept)} parts; took the one the prompt already worked ({seen[0].link})")
            return Grounding(parts=(seen[0],), how=how, notes=tuple(notes))
        broken = tie_break(mention, kind, kept, self.obj, self.asset)
        if broken is not None:
            notes.append(f"'{mention.words or mention.head}' fits {len(kept)} parts; took {broken[1]} ({broken[0].link})")
            return Grounding(parts=(broken[0],), how=how, notes=tuple(notes))
        return Grounding(how=how, ambiguous=tuple(kept), notes=tuple(notes))

    def stands_in(self, mention: Mention) -> bool:
        """A part the asset lacks, read as a control of another kind ("the bolts" as the knob; not "the rack" as the tray)."""
        try:
            found = self.ground(mention)
        except GroundingError:
            return False
        return found.how == "related" and mention.kind is not None and bool(found.parts) and all(
            p.kind is not None and p.kind is not mention.kind and info(p.kind).control for p in found.parts)

    def plan(self, mentions: list[Mention]) -> None:
        """Different nouns in one prompt name different parts: "spin the dial, then turn the spoked handle" on
        a safe whose two knobs are the dial and the (large, spoked) handle. Qualified mentions take their part
        first; a noun left with one part takes it."""
        self.said = list(mentions)
        pools: dict[tuple[str, ...], list[Mention]] = {}
        candidates_of: dict[tuple[str, ...], list[Part]] = {}
        for mention in mentions:
            if mention.pronoun or mention.is_object or mention.anaphor or mention.kind is None or mention.plural or mention.collective:
                continue
            candidates, _ = by_kind(self.parts, mention.kind, self.obj.up)
            if len(candidates) < 2:
                continue
            key = tuple(sorted(p.joint for p in candidates))
            pools.setdefault(key, []).append(mention)
            candidates_of[key] = candidates
        for key, group in pools.items():
            heads = {m.head for m in group}
            if len({h.split()[-1] for h in heads}) < 2:  # "the oven door ... the door": one noun, not two names
                continue
            taken: dict[str, Part] = {}
            for mention in group:
                if _qualified(mention):
                    kept, _ = narrow(mention, candidates_of[key], self.asset, self.obj, [], set())
                    if len(kept) == 1:
                        taken.setdefault(mention.head, kept[0])
            remaining = [p for p in candidates_of[key] if p not in taken.values()]
            unassigned = heads - set(taken)
            if len(unassigned) == 1 and len(remaining) == 1:
                head = unassigned.pop()
                taken[head] = remaining[0]
                if head in FUNCTION_NAME_WORDS:  # a name for what it does, not its shape: a guess worth saying
                    self.eliminated[head] = f"read 'the {head}' as {remaining[0].link}, the {remaining[0].kind} the prompt does not name otherwise"
            self.assigned.update({head: part for head, part in taken.items() if head not in self.assigned})

    def resolve(self, mention: Mention, *, prefer: list[Part] | None = None) -> tuple[list[Part], list[str]]:
        """``ground`` or refuse: the parts and the notes; raises GroundingError when the mention names
        nothing movable or is ambiguous."""
        found = self.ground(mention, prefer=prefer)
        if not found.parts and not found.ambiguous and found.ordinal_overflow is None and mention.kind in _FEATURES:
            host = self._host(mention, prefer)
            if host is not None:
                return host
        label = (mention.kind.value if mention.kind is not None else mention.head) if not mention.anaphor else (
            self.last_kind.value if self.last_kind is not None else "part")
        if found.ordinal_overflow is not None:
            count = found.ordinal_overflow
            raise self.refuse(f"'{mention.words}' asks for more than there are: {self.asset.name} has "
                              f"{_NUMBER_WORDS.get(count, str(count))} {label}{'s' if count != 1 else ''}", list(found.ambiguous) or None)
        if found.ambiguous and (named := self._named_before(mention)) is not None:
            return named
        if found.ambiguous:
            raise self.refuse(f"'{mention.words or mention.head}' could mean {len(found.ambiguous)} parts", list(found.ambiguous))
        if not found.parts:
            if mention.kind is not None and info(mention.kind).control and self.of_kind(mention.kind) == []:
                raise self.refuse(f"the prompt mentions a {label}, but {self.asset.name} has no movable {label}")
            hint = did_you_mean(mention.head, self.parts, self.asset)
            raise self.refuse(f"the prompt mentions '{mention.words or mention.head}', but {self.asset.name} has no such movable part{hint}")
        return list(found.parts), list(found.notes)

    def _named_before(self, mention: Mention) -> tuple[list[Part], list[str]] | None:
        """"that rack", "the same drawer", "the rack" with no qualifier of its own: the one part an earlier mention of that kind named
        with qualifiers ("baste the chicken on the middle rack, pull that rack out")."""
        words = mention.words.split()
        pointing = words[:1] in (["that"], ["this"], ["same"]) or words[:2] == ["the", "same"] or words == ["the", mention.head]
        if not pointing or _qualified(mention):
            return None
        before = self.said[:self.said.index(mention)] if mention in self.said else []
        owners = [m.owner for m in before if m.owner is not None]  # "the chicken on the middle rack": the rack
        owners += [m.relation[1] for m in before if m.relation is not None]  # "the rack behind the top door ... the door": that door
        for earlier in reversed([*owners, *before]):
            if earlier.kind is mention.kind and _qualified(earlier) and not earlier.plural:
                found = self.ground(earlier)
                if len(found.parts) == 1 and not found.ambiguous:
                    return list(found.parts), [f"'{mention.words}' is '{earlier.words}', said before"]
                return None
        return None

    def _host(self, mention: Mention, prefer: list[Part] | None) -> tuple[list[Part], list[str]] | None:
        """"the door latch", "the lid catch" on an asset whose latch is not a movable part: the part it
        belongs to, named by its modifier (with a note)."""
        from app.engine.offline.reading.part_words import kind_of_word

        for word in reversed(mention.modifiers):
            kind = kind_of_word(word)
            if kind is None or kind is mention.kind:
                continue
            found = self.ground(replace(mention, kind=kind, head=word, modifiers=()), prefer=prefer)
            if found.parts:
                note = f"{self.asset.name} has no movable {mention.kind.value if mention.kind else mention.head}: read '{mention.words}' as the {word}"
                return list(found.parts), [*found.notes, note]
        return None

    def _compartment(self, mention: Mention, candidates: list[Part]) -> list[Part]:
        """"the rack of the top oven": the candidates the door on that side of the object closes in; "the door of the top
        oven": the door on that side."""
        if all(p.kind is not None and info(p.kind).hinged for p in candidates):
            return narrow(replace(mention, sides=mention.region, region=()), candidates, self.asset, self.obj, [], set())[0]
        doors = [p for p in self.parts if p.kind is not None and info(p.kind).hinged and p not in candidates]
        door_mention = Mention(head="door", kind=doors[0].kind, sides=mention.region) if len(doors) >= 2 else None
        chosen = narrow(door_mention, doors, self.asset, self.obj, [], set())[0] if door_mention is not None else []
        behind = self._behind(chosen[0], candidates) if len(chosen) == 1 else []
        # "the lever on the left toaster" of toasters side by side: the one on that side, when no door closes them in
        return behind or narrow(replace(mention, sides=mention.region, region=()), candidates, self.asset, self.obj, [], set())[0]

    def _behind(self, door: Part, candidates: list[Part]) -> list[Part]:
        """The candidates ``door`` closes in (its closed leaf blocks their way out)."""
        from app.engine.offline.collisions import blocking_joints
        from app.engine.offline.resolve import closed_of, open_of

        state = {door.joint: closed_of(door.geometry)}
        return [p for p in candidates if (target := open_of(p.geometry)) is not None and door.joint in blocking_joints(self.asset, p.joint, target, state)]

    def _most_extreme(self, mention: Mention, kept: list[Part]) -> Part | None:
        """Among parts all near the named side, the one strictly furthest that way ("the bottom rack")."""
        side = mention.sides[-1][0]
        axis_of = {Side.TOP: (2, 1.0), Side.BOTTOM: (2, -1.0), Side.LEFT: (1, -1.0), Side.RIGHT: (1, 1.0), Side.FRONT: (0, 1.0), Side.BACK: (0, -1.0)}
        if side not in axis_of:
            return None
        axis, sign = axis_of[side]
        values = sorted(((sign * float(position(p, self.obj)[axis]), p.joint, p) for p in kept), reverse=True)
        if len(values) > 1 and values[0][0] - values[1][0] > EXTREME_GAP_M:
            return values[0][2]
        return None

    def pronoun(self, *, release: bool = False, plural: bool = False, shuts: bool = False) -> list[Part]:
        """What "it" / "them" refers to now ([] when nothing was named yet); "them" after a group was worked one by
        one is the whole group ("open both doors, the left one first, then close them"); ``shuts``: the verb opens or
        closes, so "it" is the latest part that can ("spin the turntable, then close it": the door)."""
        if release and self.last_controls:
            return list(self.last_controls)
        if plural and len(self.last) < len(self.group) and all(p in self.group for p in self.last):
            return list(self.group)
        if plural and len(self.last) == 1 and self.earlier:  # "left drawer out, then the right one, then both back in"
            before = [p for parts in reversed(self.earlier) for p in parts if p.kind is self.last[0].kind and p not in self.last]
            group = next((list(parts) for parts in reversed(self.earlier) if len(parts) > 1), None)  # "... the clasps ...; once the lid
            return list(dict.fromkeys([*before[:1], *self.last])) if before or group is None else group  # is down they snap shut"
        if shuts and self.last and not any(_shuts(p) for p in self.last):
            return next((list(parts) for parts in reversed(self.earlier) if all(_shuts(p) for p in parts)), list(self.last))
        return list(self.last)

    def remember(self, themes: list[Part], controls: list[Part], *, topic: bool = False) -> None:
        if themes or controls:
            self.last_object = False
            self.topic = topic
        if themes:
            if self.last and self.last != list(themes):
                self.earlier.append(self.last)
            self.last = list(themes)
            kinds = [p.kind for p in themes if p.kind is not None]
            self.last_kind = kinds[0] if kinds else self.last_kind
        if controls:
            self.last_controls = list(controls)
        self.referenced.update(p.joint for p in (*themes, *controls))

    def with_kind(self, mention: Mention, kind: PartKind) -> Mention:
        return replace(mention, kind=kind, anaphor=False)


def _shuts(part: Part) -> bool:
    return part.geometry.closed_value is not None and part.geometry.type != "continuous"


def _qualified(mention: Mention) -> bool:
    """The mention says which one (a side, an ordinal, a size, a row, a name, an owner, a place by another part)."""
    return bool(mention.sides or mention.ordinal is not None or mention.size or mention.row is not None or mention.column is not None
                or mention.modifiers or mention.owner is not None or mention.other or mention.relation is not None)
