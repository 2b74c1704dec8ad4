"""Causal completion of one act: what the object's mechanism adds to what the user said.

Small rules, each asking the registry through :mod:`.mechanisms`:

- stated results ("so the door pops open", "the lid lifts 40 degrees") refine or add effects;
- "unlatch the door" works its latch, not the door;
- a part opened without its control gets the control its mechanism needs (a pedal bin's pedal);
- a control worked alone gets the effect it drives (the lid a pedal lifts);
- a closed hinged part opens after its latch;
- a part blocked by a closed one opens it first (the oven door before the tray);
- controls spring back, stay, or stay held while their effect lasts; releasing a holding
  control lets what it held fall back; releasing a control pressed earlier holds it until then.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.contracts.steps import Goal, Why
from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import HINGED_KINDS, PartKind, info
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import POPPING_VERBS
from app.engine.offline import mechanisms as mech
from app.engine.offline.goals import goal_for
from app.engine.offline.moves import Move
from app.engine.offline.reading.acts import Act
from app.engine.offline.reading.frames import Frame
from app.engine.offline.revisions import replay

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.grounding import Part

_OPENING_STATES = frozenset({"open", "up", "vertical"})
_NOTHING = Frame(clause=-1, text="", verb=None, sense=None)


def complete(builder: Builder, act: Act, sense: VerbSense, controls: list[Move], effects: list[Move], why: Why) -> None:
    unlatched: list[Move] = []
    if sense is VerbSense.UNLATCH:
        unlatched = [m for m in effects if m.part.kind in HINGED_KINDS]
        controls, effects = _unlatch(builder, act, controls, effects)
        if not controls and not effects and not act.results:
            return
    effects, freed = _results(builder, act, controls, effects, [m.part for m in unlatched])
    direct_controls = [m for m in effects if m.role == "control"]
    if not controls and direct_controls:
        controls = direct_controls
        effects = [m for m in effects if m.role != "control"]
    opening = [m for m in effects if m.goal.state in _OPENING_STATES]
    notes: dict[str, str] = {}
    manual = builder.manual or act.goal.manual or (act.means is not None and act.means.manual)
    if not controls and opening and not manual and sense is not VerbSense.RECLINE:
        for move in opening:
            popped = act.goal.verb in POPPING_VERBS or move.part.joint in builder.excluded  # "pop the microwave open", "... without touching the door": by its release
            for control in mech.controls_for(move.part, builder.parts, builder.tracker, builder.excluded | builder.mentioned, popped=popped):
                controls.append(Move(control, "control", goal_for(_NOTHING, VerbSense.PRESS, control, builder.tracker).goal, words=""))
                notes[control.joint] = f"{_kind(control)} ({control.joint}) opens the {_kind(move.part)}"
                builder.mentioned.add(control.joint)
    if controls and not effects and sense in (VerbSense.PRESS, VerbSense.OPERATE, VerbSense.HOLD, VerbSense.PUSH_IN, VerbSense.TOGGLE):
        for worked in list(controls):
            if mech.named_for_another_job(worked.words):
                continue  # "hit the start button": it starts the oven, it releases nothing
            for effect in mech.effects_of(worked.part, builder.parts, builder.tracker, builder.excluded | builder.mentioned):
                if mech.release_by_guess(worked.part, worked.words, builder.asset):
                    builder.notes.append(f"pressed the {_kind(worked.part)} ({worked.part.joint}) only: it may release the {_kind(effect)} "
                                         f"({effect.joint}); say 'so the {_kind(effect)} opens' to open it too")
                    continue  # "press the microwave's button": the door opening is not asked, and the button may start it
                effects.append(Move(effect, "effect", goal_for(_NOTHING, VerbSense.OPEN, effect, builder.tracker).goal, words=""))
                notes[effect.joint] = f"the {_kind(worked.part)} ({worked.part.joint}) drives it"
                builder.mentioned.add(effect.joint)
    effects = [replace(m, role="effect") if controls else m for m in effects]
    if sense in _OPEN_SENSES and not manual:
        latches = _latches(builder, effects)
        for latch in latches:
            notes[latch.part.joint] = f"the {_kind(latch.part)} ({latch.part.joint}) holds it shut"
        controls = latches + controls
        if latches:
            effects = [replace(m, role="effect") for m in effects]
    controls, effects, coupled = mech.couple(controls, effects, builder.tracker)
    if coupled:
        builder.notes.append(coupled)
    if sense is VerbSense.LOCK:
        _shut_before_fastening(builder, act, controls + effects)
    if sense in (VerbSense.CLOSE, VerbSense.LOWER) and not controls:
        controls = _let_go_first(builder, effects)
    _prerequisites(builder, act, effects + [m for m in controls if m.role == "direct"])
    controls = _releases(builder, act, sense, controls, effects)
    if sense is VerbSense.RELEASE:
        effects = effects + _let_fall(builder, controls)
    original_controls = list(controls)
    for move in controls:
        if builder.reached(move) and move.release != "held" and why == "asked" and (move.goal.state not in ("previous", "rest") or (
                move.part.joint not in builder.tracker.before and sense is not VerbSense.RELEASE)) and sense is not VerbSense.HOLD:
            builder.notes.append(f"{move.part.link} ({move.part.joint}) is already {_as_far(move.goal.state)}: it did not move")
    controls = [m for m in controls if not builder.reached(m) or m.release == "held"]
    kept = []
    for move in effects:
        if builder.reached(move):
            builder.notes.append(f"{move.part.link} ({move.part.joint}) is already {_as_far(move.goal.state)}")
            continue
        kept.append(move)
    if not controls and not kept and (effects or original_controls):
        kept, controls = effects, original_controls  # nothing left to do: a still step keeps the contract honest (the note says why)
    if not controls and not kept:
        return
    if not controls and why == "asked" and _joins_unlatch(builder, act, kept):
        _merge_into_last(builder, kept)
        builder.refs.remember([m.part for m in kept], [])
        return
    builder.append(act, sense, controls, kept, why=why)
    builder.explanation.because(notes)
    verb = VERBS.get(act.goal.verb or "")
    if VerbSense.LOCK in (sense, verb.sense if verb is not None else None) and not controls:
        _fasten(builder, act, kept)  # "latch the toolbox shut": its verb locks, its result closes
    _brief_fall(builder, act, controls, kept)
    builder.refs.remember([m.part for m in kept] or [m.part for m in unlatched] or freed or [m.part for m in controls], [m.part for m in controls])


_OPEN_SENSES = frozenset({VerbSense.OPEN, VerbSense.PULL_OUT, VerbSense.RAISE, VerbSense.OPERATE, VerbSense.MOVE})


def _kind(part: object) -> str:
    kind = getattr(part, "kind", None)
    return kind.value if kind is not None else "part"


def _joins_unlatch(builder: Builder, act: Act, effects: list[Move]) -> bool:
    """"Turn the latch, then open the door": the door's opening is the latch's effect, one causal step
    (the latch springs back while the door swings)."""
    if not builder.steps or act.parallel or act.wait_before_s:
        return False
    last = builder.steps[-1]
    if last.effects or last.base is not None or not last.controls or last.hold_s:
        return False
    asset = builder.asset
    controls = [next(p for p in builder.parts if p.joint == m.joint) for m in last.controls]
    if not all(p.kind is not None and (info(p.kind).latches_host or info(p.kind).press == "turn" or p.kind is PartKind.HANDLE) for p in controls):
        return False
    return all(m.part.kind in HINGED_KINDS and m.goal.state in _OPENING_STATES for m in effects) and all(
        any(c.link in asset.descendants(m.part.link) for m in effects) for c in controls)


def _merge_into_last(builder: Builder, effects: list[Move]) -> None:
    last = builder.steps[-1]
    moves = [builder.joint_move(replace(m, role="effect")) for m in effects]
    starts = [builder.tracker.value(m.joint) for m in moves]
    builder.steps[-1] = last.model_copy(update={"effects": [*last.effects, *moves]})
    replay(builder)
    builder.explanation.add_to_last(moves, starts, [m.words for m in effects])  # the understanding shows the door it freed


def _results(builder: Builder, act: Act, controls: list[Move], effects: list[Move], implicit: list[Part]) -> tuple[list[Move], list[Part]]:
    """Stated results refine the amount of an effect already there, or add the effect (``implicit``: what
    a subjectless result is about, e.g. the door an unlatching freed); and the parts a result said were freed ("turn the
    wheel; with the door freed, swing it open": "it" is the door)."""
    out = list(effects)
    freed: list[Part] = []
    for frame in act.results:
        if frame.quantities.direction is None and act.goal.quantities.direction is not None and all(m.pronoun for m in frame.themes):
            # "fold the handle forward until it lies flat": flat, reached moving forward
            frame = replace(frame, quantities=replace(frame.quantities, direction=act.goal.quantities.direction))
        if {"can", "could", "may"} & set(told := frame.text.split()) and (frame.verb is None or frame.verb not in told):
            continue  # "drop its door so the rack can come out": what it makes possible, no motion of the rack
        sense = frame.sense or act.goal.sense or VerbSense.OPEN
        if sense is VerbSense.UNLATCH:
            named = tuple(m for m in frame.themes if not m.pronoun)  # "...; that unlatches the door and it falls open": it is the door
            try:
                freed = builder.ground(frame, VerbSense.OPEN, named)[0] if named else []
            except GroundingError:
                freed = []
            continue  # "... so the door unlocks": no motion of its own
        themes = tuple(m for m in frame.themes if not m.pronoun)
        if themes and all(m.kind is not None and builder.refs.stands_in(m) for m in themes):
            builder.notes.append(f"read '{frame.text}' as what the step does: {builder.asset.name} has no {themes[0].kind}")
            continue  # "turn the handle so that the bolts retract": no bolts to move, not another control standing in for them
        current = freed or [m.part for m in out] or implicit or [m.part for m in controls]
        try:
            parts, words = builder.ground(frame, sense, themes, prefer=current) if themes else (current or builder.refs.pronoun(), [])
        except GroundingError as exc:
            if not themes:
                raise
            builder.notes.append(f"left out '{frame.text}': {str(exc).split('. Movable parts')[0]}")
            parts, words = [], []
        if not parts and not themes and not out:
            continue
        for index, part in enumerate(parts):
            if sense in (VerbSense.RELEASE, VerbSense.RETURN) and mech.is_control(part):
                continue  # "... and the button pops back out": it springs back anyway
            goal = goal_for(frame, sense, part, builder.tracker).goal
            existing = next((i for i, m in enumerate(out) if m.part.joint == part.joint), None)
            loose = frame.quantities.amount is not None and frame.quantities.amount.loose
            if existing is not None:
                out[existing] = replace(out[existing], goal=goal, loose=loose)
            elif part.joint not in {m.part.joint for m in controls}:
                said = words[index] if index < len(words) else part.link
                out.append(Move(part, "effect" if controls else "direct", goal, words=said, loose=loose))
                builder.mentioned.add(part.joint)
    return out, freed


def _unlatch(builder: Builder, act: Act, controls: list[Move], effects: list[Move]) -> tuple[list[Move], list[Move]]:
    """"unlatch the door": the door's latch (or handle) moves, the door does not."""
    hinged = [m for m in effects if m.part.kind in HINGED_KINDS]
    others = [m for m in effects if m.part.kind not in HINGED_KINDS]
    if not hinged or controls:
        return controls, others if controls else effects
    found: list[Move] = []
    for move in hinged:
        latches = mech.latches_of(move.part, builder.parts, builder.tracker, builder.excluded) or [
            p for p in builder.parts if mech.is_control(p) and p.link in builder.asset.descendants(move.part.link)]
        for latch in latches[:1]:
            found.append(Move(latch, "control", goal_for(act.goal, VerbSense.UNLATCH, latch, builder.tracker).goal, words=move.words))
            builder.mentioned.add(latch.joint)
    if not found and builder.steps and builder.steps[-1].controls:
        builder.notes.append(f"read '{act.goal.text}' as the effect of the control worked before")
        builder.refs.remember([m.part for m in hinged], [])
        return [], []
    if not found and any({"open", "opens", "opened"} & set(r.text.split()) for r in act.results):
        builder.notes.append(f"nothing on the {_kind(hinged[0].part)} holds it shut: read '{act.goal.text}' as letting it go, and it opens as said")
        return [], []  # "unlatch it and it just drops open under its own weight": the opening is what is asked
    if not found:
        raise builder.refs.refuse(f"'{act.goal.text}': nothing on the {_kind(hinged[0].part)} holds it shut")
    builder.refs.remember([m.part for m in hinged], [m.part for m in found])
    return found, others


def _latches(builder: Builder, effects: list[Move]) -> list[Move]:
    out: list[Move] = []
    for move in effects:
        if move.goal.state not in _OPENING_STATES:
            continue
        for latch in mech.latches_of(move.part, builder.parts, builder.tracker, builder.excluded | builder.mentioned):
            out.append(Move(latch, "control", goal_for(_NOTHING, VerbSense.UNLATCH, latch, builder.tracker).goal, words=""))
            builder.mentioned.add(latch.joint)
    return out


def _fasten(builder: Builder, act: Act, closed: list[Move]) -> None:
    """"Latch the toolbox shut": once its lid is closed, the latches that hold it shut are worked too."""
    for move in closed:
        latches = [] if move.part.kind not in HINGED_KINDS else mech.latches_of(move.part, builder.parts, builder.tracker, builder.excluded | builder.mentioned)
        if not latches:
            continue
        locking = [Move(latch, "control", goal_for(_NOTHING, VerbSense.LOCK, latch, builder.tracker).goal, words="") for latch in latches]
        builder.mentioned.update(latch.joint for latch in latches)
        builder.append(replace(act, means=None, hold_s=0.0, wait_before_s=0.0, parallel=False), VerbSense.LOCK, locking, [], why="latch", parallel=False)
        builder.explanation.because({latch.joint: f"the {_kind(latch)} ({latch.joint}) holds the {_kind(move.part)} shut" for latch in latches})


def _shut_to_run(builder: Builder, act: Act) -> None:
    """"Run the dishwasher" with its door ajar: the door is shut first (an appliance runs shut)."""
    from app.engine.offline.object_parts import starts

    if not act.runs and (act.goal.sense is VerbSense.SWITCH_OFF or not starts(act.goal) or not act.goal.themes or not (
            act.goal.themes[0].is_object or act.goal.themes[0].pronoun)):
        return
    shut_open_doors(builder, act, "runs")


def shut_open_doors(builder: Builder, act: Act, why: str) -> None:
    """Every door or lid of the object not shut is shut, each a step of its own ("shut link_0 first: it runs with it shut")."""
    from app.engine.offline.grounding import openable

    for part in (p for p in openable(builder.parts) if p.kind in HINGED_KINDS and p.joint not in builder.excluded):
        g = part.geometry
        if g.closed_value is None or g.open_value is None or abs(builder.tracker.value(part.joint) - g.closed_value) < 0.05 * abs(
                g.open_value - g.closed_value):
            continue
        builder.mentioned.add(part.joint)
        shut = Move(part, "direct", goal_for(_NOTHING, VerbSense.CLOSE, part, builder.tracker).goal, words="")
        builder.append(replace(act, means=None, hold_s=0.0), VerbSense.CLOSE, [], [shut], why="prerequisite", parallel=False)
        builder.notes.append(f"shut {part.link} first: {builder.asset.name} {why} with it shut")


def _shut_before_fastening(builder: Builder, act: Act, moves: list[Move]) -> None:
    """"Fasten both clasps on the box" with its lid standing open: the lid they hold shut is shut first."""
    for host in dict.fromkeys(h for m in moves if (h := mech.latched_host(m.part, builder.parts, builder.tracker)) is not None):
        g = host.geometry
        if host.joint in builder.mentioned | builder.excluded or g.closed_value is None or abs(builder.tracker.value(host.joint) - g.closed_value) < mech.REACHED:
            continue
        builder.mentioned.add(host.joint)
        shut = Move(host, "direct", goal_for(_NOTHING, VerbSense.CLOSE, host, builder.tracker).goal, words="")
        builder.append(replace(act, means=None, hold_s=0.0), VerbSense.CLOSE, [], [shut], why="prerequisite", parallel=False)
        holding = ", ".join(m.part.link for m in moves if mech.latched_host(m.part, builder.parts, builder.tracker) is host)
        builder.notes.append(f"shut {host.link} first: {holding} fasten it shut")


def _prerequisites(builder: Builder, act: Act, moves: list[Move]) -> None:
    """Open what stands in the way first (the door before the tray)."""
    from app.engine.offline.resolve import resolve

    _shut_to_run(builder, act)
    for move in moves:
        if move.part.joint in builder.tracker.before:
            continue
        target = resolve(move.goal, move.part.geometry, builder.tracker.obj, builder.asset, builder.tracker.value(move.part.joint)).value
        if target is None and not act.goal.manual:
            continue  # a spin (a speed, no end) meets nothing; "spin the plate half a turn by hand" still reaches in
        reached = [d for d in mech.enclosing(move.part, builder.parts, builder.tracker) if d.joint not in builder.mentioned | builder.excluded] if (
            act.goal.manual) else []  # "turn the glass plate by hand": the door is opened to reach in
        blocking = mech.blockers(move.part, target, builder.parts, builder.tracker, builder.mentioned | builder.excluded) if target is not None else []
        for blocker in blocking or reached:
            builder.mentioned.add(blocker.joint)
            opening = Move(blocker, "direct", goal_for(_NOTHING, VerbSense.OPEN, blocker, builder.tracker).goal, words="")
            latches = _latches(builder, [opening])
            if latches:
                opening = replace(opening, role="effect")
            latches = _releases(builder, act, VerbSense.OPEN, latches, [opening])
            builder.append(replace(act, means=None, hold_s=0.0, wait_before_s=act.wait_before_s), VerbSense.OPEN, latches, [opening],
                            why="prerequisite", parallel=False)
            builder.explanation.because({blocker.joint: f"{blocker.link} must be open before {move.part.link} can move"})
            builder.notes.append(f"opened {blocker.link} first: it blocks {move.part.link}")


_KEPT_END = frozenset({"lies", "lie", "sits", "sit", "rests", "rest", "stays", "stay", "remains", "flat", "flush", "locked", "latched", "in_place"})


def _releases(builder: Builder, act: Act, sense: VerbSense, controls: list[Move], effects: list[Move]) -> list[Move]:
    """What each control does after its actuation."""
    held = (act.goal.hold or sense is VerbSense.HOLD) and not act.goal.quantities.duration_s  # a timed hold ends with a release
    brief = act.goal.brief or (act.means is not None and act.means.brief)
    out = []
    for move in controls:
        if sense is VerbSense.RELEASE:
            _hold_until_now(builder, move.part.joint)
            out.append(replace(move, release="stays"))
            continue
        toggles = move.part.kind is not None and "toggle" in info(move.part.kind).affordances  # a rocker stays where a click puts it
        if brief and move.goal.state != "rest" and not toggles:
            out.append(replace(move, release="self_return"))  # "tap the lever (down) briefly": pressed and let go
        elif mech.holds(move.part) and any(e.goal.state in _OPENING_STATES for e in effects):
            out.append(replace(move, release="held"))
        elif (move.goal.state == "closed" and (sense in (VerbSense.LOCK, VerbSense.CLOSE) or act.goal.quantities.onto_body)) or (
                sense in (VerbSense.TOGGLE, VerbSense.LOCK, VerbSense.RAISE, VerbSense.LOWER) and move.part.kind is not None and info(move.part.kind).latches_host):
            out.append(replace(move, release="stays"))  # "lock the latch": it stays locked; "flip the catch over": it stays over
        elif mech.springs_back(move.part, builder.tracker, builder.parts) and not held and move.goal.state not in ("vertical", "flat") and not (
                any(set(r.text.split()) & _KEPT_END for r in act.results)):  # "swing the catch up so it lies flat against the box": it stays
            out.append(replace(move, release="self_return"))
        else:
            out.append(replace(move, release="stays"))
    return out


def _let_go_first(builder: Builder, effects: list[Move]) -> list[Move]:
    """"(pedal held) ... then let the lid close": the control holding it open is let go, and the lid falls with it."""
    out: list[Move] = []
    for move in effects:
        holder = builder.tracker.held.get(move.part.joint)
        part = next((p for p in builder.parts if p.joint == holder), None)
        if part is not None and all(m.part.joint != holder for m in out):
            out.append(Move(part, "control", Goal(state="rest"), words=""))
            builder.notes.append(f"let go of {part.link} ({part.joint}): it held {move.part.link} open")
    return out


def _hold_until_now(builder: Builder, joint: str) -> None:
    """"Press the button, then release it": the earlier press is held until this release."""
    part = next(p for p in builder.parts if p.joint == joint)
    for index, step in enumerate(builder.steps):
        holding = mech.holds(part) and any(e.goal.state in _OPENING_STATES for e in step.effects)
        release = "held" if holding else "stays"
        moves = [m.model_copy(update={"release": release}) if m.joint == joint and m.release == "self_return" else m for m in step.controls]
        if moves != list(step.controls):
            builder.steps[index] = step.model_copy(update={"controls": moves})
            replay(builder)


def _brief_fall(builder: Builder, act: Act, controls: list[Move], effects: list[Move]) -> None:
    """A tap on a holding control (a pedal): what it lifted falls back once it is let go."""
    if not (act.goal.brief or (act.means is not None and act.means.brief)):
        return
    if not any(mech.holds(m.part) and m.release == "self_return" for m in controls):
        return
    falling = [Move(m.part, "effect", Goal(state="previous"), words="") for m in effects if m.goal.state in _OPENING_STATES]
    if falling:
        builder.append(replace(act, means=None, results=(), wait_before_s=0.0, hold_s=0.0, parallel=False), VerbSense.RELEASE, [], falling, why="release")
        builder.explanation.because({m.part.joint: "it falls back when the control is let go" for m in falling})


def _let_fall(builder: Builder, controls: list[Move]) -> list[Move]:
    """Letting go of a holding control lets what it held return (a pedal's lid falls shut)."""
    out = []
    for effect_joint, control_joint in list(builder.tracker.held.items()):
        if any(m.part.joint == control_joint for m in controls):
            part = next(p for p in builder.parts if p.joint == effect_joint)
            out.append(Move(part, "effect", Goal(state="previous"), words=""))
    return out


def _as_far(state: str) -> str:
    """"already closed", "already as far left as it goes"."""
    directions = {"left": "left", "right": "right", "forward": "forward", "backward": "back", "up": "up", "down": "down", "toward": "that way",
                  "cw": "clockwise", "ccw": "counter-clockwise"}
    if state in directions:
        return f"as far {directions[state]} as it goes"
    return {"rest": "where it rests", "previous": "where it was"}.get(state, state)
