"""Causal knowledge, asked of the part-kind registry: which control drives which part, which
latch holds which door, what must be opened first.

- A control's ``operates`` kinds are what it moves when worked (a pedal lifts a lid; a
  release button pops a door) — for a button only when its name says so or the object is a
  kind whose only door such a button releases.
- A part whose kind ``latches_host`` holds the hinged part it sits on shut.
- A part is blocked when sweeping it to its target passes through another part (an oven
  tray behind a closed door).
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, Literal

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.steps import Goal
from app.engine.lexicon.kinds import HINGED_KINDS, PartKind, info
from app.engine.lexicon.verbs import VerbSense
from app.engine.lexicon.words import BUTTON_RELEASED_OBJECTS, FUNCTION_NAME_WORDS, RELEASE_NAME_WORDS
from app.engine.offline.grounding import Part, openable
from app.engine.offline.naming import link_words
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.tracker import ANY_HOST, Tracker

if TYPE_CHECKING:
    from app.engine.offline.moves import Move

REACHED = 1e-6


def _named_release(part: Part, asset: ArticulatedAsset) -> bool:
    return bool(link_words(asset, part.link, visuals=False) & RELEASE_NAME_WORDS)


def release_by_guess(control: Part, words: str, asset: ArticulatedAsset) -> bool:
    """Working ``control`` releases something only because of what the object is (any button on a microwave): neither its
    name in the asset nor the user's words call it a release."""
    named = _named_release(control, asset) or bool(set(words.lower().replace("-", " ").split()) & RELEASE_NAME_WORDS)
    return control.kind is not None and info(control.kind).operates_needs_name and not named


def named_for_another_job(words: str) -> bool:
    """What the user called a control gives it a job other than releasing ("the start button", "the timer knob"); only the
    words before its noun count ("the button on the microwave" names no job)."""
    said = words.lower().split()
    head = next((k for k, word in enumerate(said) if kind_of_word(word) is not None), len(said))
    name = set(said[:head])
    return bool(name & FUNCTION_NAME_WORDS) and not name & RELEASE_NAME_WORDS


def drives(control: Part, effect: Part, parts: list[Part], tracker: Tracker) -> bool:
    """Whether working ``control`` moves ``effect`` through the object's mechanism."""
    if control.kind is None or effect.kind is None:
        return False
    entry = info(control.kind)
    if effect.kind not in entry.operates:
        return False
    if not entry.operates_needs_name:
        return True
    if _named_release(control, tracker.asset):
        return True
    hinged = [p for p in openable(parts) if p.kind in HINGED_KINDS]
    return tracker.obj.category in BUTTON_RELEASED_OBJECTS and len(hinged) == 1


def controls_for(effect: Part, parts: list[Part], tracker: Tracker, excluded: set[str], *, popped: bool = False) -> list[Part]:
    """The control a user works to open ``effect`` (a pedal for a pedal bin's lid), if any: only a control whose effect
    it holds (a release button or handle is one way among others to open a door, not implied), or, when the words say
    it pops open (``popped``: "pop the microwave open") and it is shut, the one control that releases it."""
    shut = effect.geometry.closed_value is not None and abs(tracker.value(effect.joint) - effect.geometry.closed_value) < 1e-3
    found = [p for p in parts if p.joint not in excluded and p.joint != effect.joint and (holds(p) or (popped and shut)) and drives(p, effect, parts, tracker)]
    if popped and shut and len(found) > 1:
        return []
    return _same_body_first(effect, found, tracker.asset)[:1]


def effects_of(control: Part, parts: list[Part], tracker: Tracker, excluded: set[str]) -> list[Part]:
    """What working ``control`` opens on its own (the lid a pedal lifts)."""
    candidates = [p for p in openable(parts) if p.joint not in excluded and drives(control, p, parts, tracker)]
    return _same_body_first(control, candidates, tracker.asset)[:1]


def _same_body_first(part: Part, others: list[Part], asset: ArticulatedAsset) -> list[Part]:
    """``others`` with those hung from the same body as ``part`` first: of two pedal bins side by side, a pedal lifts
    its own bin's lid."""
    body = asset.joints[part.joint].parent
    return sorted(others, key=lambda p: asset.joints[p.joint].parent != body)


def holds(control: Part) -> bool:
    """Its effect lasts only while it is held (a pedal)."""
    return control.kind is not None and info(control.kind).holds_effect


def latched_host(latch: Part, parts: list[Part], tracker: Tracker) -> Part | None:
    """The door or lid a latch holds shut ("fasten both clasps" on a box whose lid stands open: that lid), else None."""
    if latch.kind is None or not info(latch.kind).latches_host:
        return None
    asset = tracker.asset
    hinged = [p for p in parts if p.kind in HINGED_KINDS and p.geometry.closed_value is not None and p.joint != latch.joint]
    on = [h for h in hinged if latch.link in asset.descendants(h.link)]
    if len(on) == 1:
        return on[0]
    return hinged[0] if len(hinged) == 1 and not any(latch.link in asset.descendants(p.link) for p in parts if p.joint != latch.joint) else None


def latches_of(host: Part, parts: list[Part], tracker: Tracker, excluded: set[str]) -> list[Part]:
    """Latches holding ``host`` shut that must be worked before it opens (none when it is already open)."""
    if host.kind not in HINGED_KINDS or host.geometry.closed_value is None:
        return []
    if abs(tracker.value(host.joint) - host.geometry.closed_value) > REACHED:
        return []  # already ajar: nothing holds it
    stated = tracker.releases.get(host.joint) or tracker.releases.get(ANY_HOST)
    if stated is not None:
        return [stated] if stated.joint not in excluded and stated.joint != host.joint else []  # the prompt said what releases it
    asset = tracker.asset
    below = set(asset.descendants(host.link))
    hinged = [p for p in parts if p.kind in HINGED_KINDS]
    out = []
    for part in parts:
        if part.kind is None or not info(part.kind).latches_host or part.joint in excluded:
            continue
        on_host = part.link in below and part.joint != host.joint
        lone_host = len(hinged) == 1 and not any(part.link in asset.descendants(p.link) for p in parts if p.joint != part.joint)
        if on_host or lone_host:
            out.append(part)
    return out


def blockers(effect: Part, target: float, parts: list[Part], tracker: Tracker, mentioned: set[str]) -> list[Part]:
    """Closed parts in the way of moving ``effect`` to ``target`` that the user did not name."""
    from app.engine.offline.collisions import blocking_joints

    found = []
    for joint in blocking_joints(tracker.asset, effect.joint, target, dict(tracker.now)):
        part = next((p for p in parts if p.joint == joint), None)
        if part is None or part.geometry.open_value is None or joint in mentioned:
            continue
        found.append(part)
    return found


def enclosing(part: Part, parts: list[Part], tracker: Tracker) -> list[Part]:
    """Front doors, not open, that a hand must pass to reach ``part`` inside ("turn the glass plate by hand": the
    microwave's door): in front of it by a margin and across from it."""
    obj = tracker.obj
    here = obj.local(part.geometry.home_centroid)
    found = []
    for door in parts:
        g = door.geometry
        if door is part or door.kind is None or not info(door.kind).hinged or g.open_value is None or g.closed_value is None:
            continue
        if part.link in g.moving_links or abs(tracker.value(door.joint) - g.open_value) <= 0.25 * abs(g.open_value - g.closed_value):
            continue  # it rides on the door, or the door is open
        there = obj.local(g.home_centroid)
        if float(g.home_face @ obj.front) > 0.7 and there[0] - here[0] > 0.05 * obj.diag and max(abs(there[1:] - here[1:])) < 0.5 * g.size:
            found.append(door)
    return found


def opened_through(found: list[Part], sense: VerbSense, parts: list[Part], asset: ArticulatedAsset) -> list[Part]:
    """``found``, each part that opens through another riding on it ("open the jug": its lid) replaced by that part."""
    if sense not in (VerbSense.OPEN, VerbSense.CLOSE):
        return found
    out = []
    for part in found:
        kinds = info(part.kind).opened_by if part.kind is not None else ()
        carried = asset.moving_links(part.joint) if kinds else ()
        riding = [p for p in parts if p.kind in kinds and p.link in carried and p is not part]
        out.append(riding[0] if len(riding) == 1 else part)
    return out


def is_control(part: Part) -> bool:
    return part.kind is not None and info(part.kind).control


def springs_back(part: Part, tracker: Tracker, parts: list[Part]) -> bool:
    """Let go, it returns to rest (buttons, pedals, latches; a handle only on a door or lid)."""
    if part.kind is None:
        return False
    entry = info(part.kind)
    if entry.returns != "self_return":
        return False
    if entry.returns_only_on_hinged:
        joint = tracker.asset.joints[part.joint]
        parent = next((p for p in parts if p.link == joint.parent), None)
        return parent is not None and parent.kind in HINGED_KINDS
    return True


def kind_of(part: Part) -> PartKind | None:
    return part.kind


def held_span(part: Part, tracker: Tracker) -> tuple[float, float]:
    """(closed value, signed opening) a fully worked holding control gives its part: to upright, or its open
    limit when that comes first (a pedal bin's lid can flip 180 degrees, a pedal lifts it upright)."""
    from app.engine.offline.orientation import orientation_value

    geometry = part.geometry
    closed = geometry.closed_value if geometry.closed_value is not None else geometry.rest
    opened = geometry.open_value if geometry.open_value is not None else closed
    upright = orientation_value(tracker.asset, geometry, "vertical", opening=True)
    if upright is not None and REACHED < abs(upright - closed) < abs(opened - closed):
        return closed, upright - closed
    return closed, opened - closed


def _value(move: Move, tracker: Tracker) -> float | None:
    from app.engine.offline.resolve import resolve

    return resolve(move.goal, move.part.geometry, tracker.obj, tracker.asset, tracker.value(move.part.joint)).value


def couple(controls: list[Move], effects: list[Move], tracker: Tracker) -> tuple[list[Move], list[Move], str | None]:
    """A holding control and what it holds move in proportion: the fraction of the pedal's travel is the
    fraction of the lid's opening (see :func:`held_span`). When only one side says how far, the other follows;
    a vague amount ("slightly") on the effect does not override a stated one on the control."""
    holding = [m for m in controls if holds(m.part)]
    held = [m for m in effects if m.goal.state in ("open", "up") and m.part.kind in HINGED_KINDS]
    if len(holding) != 1 or not held:
        return controls, effects, None
    control = holding[0]
    geometry = control.part.geometry
    rest = geometry.rest
    full = _value(replace(control, goal=Goal(state=control.goal.state, direction_world=control.goal.direction_world)), tracker)
    if full is None or abs(full - rest) < REACHED:
        return controls, effects, None
    effect_amount = held[0].goal.amount is not None and not held[0].loose
    if control.goal.amount is not None and not effect_amount:
        depth = _value(control, tracker)
        if depth is None:
            return controls, effects, None
        fraction = min(max((depth - rest) / (full - rest), 0.0), 1.0)
        coupled = []
        for move in effects:
            if move in held:
                closed, span = held_span(move.part, tracker)
                unit: Literal["m", "rad"] = "m" if move.part.geometry.type == "prismatic" else "rad"
                move = replace(move, goal=Goal(state=move.goal.state, amount=round(abs(fraction * span), 9), unit=unit, measured_from="closed"))
            coupled.append(move)
        return controls, coupled, f"the {held[0].part.link} opens the fraction {fraction:.3g} its {control.part.link} is pressed"
    if effect_amount and control.goal.amount is None:
        closed, span = held_span(held[0].part, tracker)
        target = _value(held[0], tracker)
        if target is None or abs(span) < REACHED:
            return controls, effects, None
        fraction = min(max((target - closed) / span, 0.0), 1.0)
        pressed = replace(control, goal=Goal(state=control.goal.state, amount=round(fraction, 9), unit="fraction", measured_from="rest"))
        return [pressed if m is control else m for m in controls], effects, f"the {control.part.link} is pressed the fraction {fraction:.3g} its {held[0].part.link} opens"
    return controls, effects, None
