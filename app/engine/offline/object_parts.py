"""What a clause on the whole object works: "open the microwave" (its door), "turn on the tap" (its
one control), "flush the toilet" (the lever the verb implies), "open the lower oven" (the door on
that side)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.engine.lexicon.kinds import HINGED_KINDS, PartKind
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import OPERATED_OBJECTS
from app.engine.offline import mechanisms as mech
from app.engine.offline.grounding import Part, narrow, openable
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.holders import side_of_object
from app.engine.offline.reading.mentions import Mention
from app.engine.offline.tiebreak import tie_break
from app.engine.offline.units import in_unit, like_units

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder


def object_parts(builder: Builder, frame: Frame, sense: VerbSense) -> list[Part]:
    """What a clause on the whole object ("open the microwave", "turn on the tap", "flush the toilet") works."""
    implied = VERBS[frame.verb].implies if frame.verb is not None and frame.verb in VERBS else ()
    if implied:
        found = [p for kind in implied for p in builder.refs.of_kind(kind)]
        if len(found) > 1:
            return found if _all_said(frame) else [_one_implied(builder, frame, found)]
        if found:
            return found
    if starts(frame):
        return _function_control(builder, frame)
    if sense in (VerbSense.SWITCH_ON, VerbSense.SWITCH_OFF, VerbSense.TURN, VerbSense.OPERATE, VerbSense.TOGGLE) or (
            builder.tracker.obj.category in OPERATED_OBJECTS and sense in (VerbSense.OPEN, VerbSense.CLOSE, VerbSense.MOVE)):
        controls = [p for p in builder.parts if mech.is_control(p)]
        if len(controls) == 1:
            return controls
        if controls and sense in (VerbSense.SWITCH_ON, VerbSense.SWITCH_OFF):
            raise builder.refs.refuse(f"'{frame.text}' could mean {len(controls)} controls", controls)
    if sense in (VerbSense.OPEN, VerbSense.CLOSE, VerbSense.RAISE, VerbSense.LOWER, VerbSense.PULL_OUT, VerbSense.PUSH_IN):
        return _openables(builder, frame)
    return []


_STARTING = frozenset({"run", "start", "heat", "warm", "reheat", "defrost", "nuke", "zap"})


def starts(frame: Frame) -> bool:
    """"Run the dishwasher", "turn on the microwave", "switch it off": the appliance set going or stopped (its control
    worked), not the object moved."""
    return frame.sense in (VerbSense.SWITCH_ON, VerbSense.SWITCH_OFF) or (frame.sense is VerbSense.SPIN and frame.verb in _STARTING)


def _function_control(builder: Builder, frame: Frame) -> list[Part]:
    """The one control that sets the object going (not a button that releases its door); several: a refusal naming
    them; none: a refusal saying so, never the object moved instead."""
    started = [p for kind in VERBS["start"].implies for p in builder.refs.of_kind(kind)]
    if started:  # "turn on the toaster": what starting it works (its lever), as "start the toaster" does
        return started if len(started) == 1 or _all_said(frame) else [_one_implied(builder, frame, started)]
    parts = builder.parts
    controls = [p for p in parts if mech.is_control(p) and not any(mech.drives(p, e, parts, builder.tracker) for e in openable(parts))]
    if len(controls) == 1:
        return controls
    if controls:
        raise builder.refs.refuse(f"'{frame.text}' could mean {len(controls)} controls", controls)
    turning = builder.refs.of_kind(PartKind.TURNTABLE)
    if len(turning) == 1 and turning[0].geometry.type == "continuous":
        builder.notes.append(f"'{frame.text}': {builder.asset.name} has no control that sets it going; its {turning[0].link} turns, as it does when it runs")
        return turning  # "heat up my leftovers in the microwave" on a microwave with only a door and a turntable
    raise builder.refs.refuse(f"'{frame.text}': {builder.asset.name} has no control that sets it going (only a door release, or none)")


def _openables(builder: Builder, frame: Frame) -> list[Part]:
    """"Open the cabinet": its doors (all of one size class), else its lids, drawers, caps."""
    found = openable(builder.parts)
    if frame.sense in (VerbSense.PULL_OUT, VerbSense.PUSH_IN):  # "pull the thing at the top out": what slides, not a door there
        found = [p for p in found if p.geometry.type == "prismatic"] or found
    if not found:
        caps = [p for p in builder.parts if p.kind in (PartKind.CAP, PartKind.LID) and p.geometry.open_value is None]
        return caps[:1]
    ajar = [p for p in found if p.geometry.closed_value is not None and abs(builder.tracker.value(p.joint) - p.geometry.closed_value) > 1e-3]
    if frame.sense is VerbSense.CLOSE and len(ajar) > 1 and not any(m.sides for m in frame.themes) and like_units(ajar, builder.asset) <= 1:
        builder.notes.append(f"'{frame.text}': shut every part that stood open ({', '.join(p.link for p in ajar)})")
        return ajar  # "close this cabinet up properly" with its door and its drawer both open
    first_kind = found[0].kind
    group = [p for p in found if p.kind == first_kind]
    if len(group) > 1 and any(m.plural or m.collective for m in frame.themes):
        return group
    told = side_of_object(frame.text.split())  # "open the left side of the fridge"
    sides = next((m.sides for m in frame.themes if m.is_object and m.sides), ()) or ((told,) if told else ()) or (
        builder.refs.scene if any(m.pronoun for m in frame.themes) or like_units(group, builder.asset) > 1 else ())  # "the casserole is in the bottom oven - open it up"
    placed = group
    if sides and len(group) > 1:  # "open the lower oven": the door on that side (the doors of that one of two ovens stacked)
        placed = in_unit(sides, group, builder.parts, builder.asset, builder.tracker.obj) or narrow(
            Mention(head="part", kind=first_kind, sides=sides), group, builder.asset, builder.tracker.obj, [], set())[0]
        builder.refs.scene = builder.refs.scene or sides  # "open the top oven and get that rack out": that oven's rack
        if len(placed) == 1:
            return placed
    if (units := like_units(group, builder.asset)) > 1 and len(placed) == len(group):
        raise builder.refs.refuse(f"'{frame.text}': {builder.asset.name} is {units} like units side by side or stacked; say which one "
                                  "(the left one, the upper one, ...)", group)
    group = placed or group
    largest = group[0].geometry.size
    same = [p for p in group if p.geometry.size >= largest / 1.5]
    if len(same) == 1:
        return same
    if first_kind in HINGED_KINDS and len(same) == 2:
        builder.notes.append(f"'{frame.text}': worked both {first_kind.value}s")  # "shut the oven" shuts them, "open the fridge" opens them
        return same
    raise builder.refs.refuse(f"'{frame.text}' could mean {len(same)} parts", same)


def _all_said(frame: Frame) -> bool:
    """"start both sides", "flush all of them": every part that does it, not one picked."""
    return any(m.collective for m in frame.themes) or bool({"both", "all"} & set(frame.text.split()))


def _one_implied(builder: Builder, frame: Frame, found: list[Part]) -> Part:
    """"Start the toaster" on a toaster with two levers: the one a geometric tie-break picks, said in a warning; with
    nothing to tell them apart, a refusal naming them (never the URDF's first)."""
    kind = found[0].kind
    words = kind.value if kind is not None else "part"
    if len(unit := in_unit(builder.refs.scene, found, builder.parts, builder.asset, builder.tracker.obj)) == 1:
        return unit[0]  # "flush the toilet on the left" of two toilets side by side: that toilet's button
    picked = tie_break(Mention(head=words, kind=kind), kind, found, builder.tracker.obj, builder.asset)
    if picked is None:
        raise builder.refs.refuse(f"'{frame.text}' could work {len(found)} {words}s", found)
    part, how = picked
    builder.notes.append(f"'{frame.text}' could work {len(found)} {words}s; took {how} ({part.link})")
    return part
