"""Acts that revise the step before instead of adding one: "..., and lower it 40 degrees" (how far the
previous motion goes), "hold it there for 2 s", "keep it down so the lid swings up to vertical",
"... and let it roll".
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.contracts.steps import Step as ContractStep
from app.engine.errors import GroundingError
from app.engine.lexicon.verbs import VerbSense
from app.engine.offline import mechanisms as mech
from app.engine.offline.goals import goal_for
from app.engine.offline.grounding import Part
from app.engine.offline.moves import Move
from app.engine.offline.reading.acts import Act
from app.engine.offline.reading.frames import Frame
from app.engine.offline.resolve import resolve
from app.engine.offline.tracker import Tracker

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder


def replay(builder: Builder) -> None:
    """Rebuild the tracker's state from the steps (after a step was revised)."""
    builder.tracker = Tracker.of(builder.asset)
    for step in builder.steps:
        builder.tracker.apply(step)


def distance_said(builder: Builder) -> None:
    """The last step's whole-object distance was revised to one the prompt says: replay, restate it in the report and drop
    the note on the default distance it had."""
    replay(builder)
    builder.explanation.restate_base(builder.steps[-1])
    default = next((k for k in range(len(builder.notes) - 1, -1, -1) if builder.notes[k].startswith("no distance given")), None)
    if default is not None:
        del builder.notes[default]


_WAYS = frozenset({VerbSense.RAISE, VerbSense.LOWER, VerbSense.OPEN, VerbSense.CLOSE, VerbSense.PULL_OUT, VerbSense.PUSH_IN})


def restated_means(builder: Builder, act: Act, controls: list[Move], grounded: tuple[list[Part], list[str]]) -> tuple[list[Part], list[str]]:
    """"Spin the dial a full turn to unlock it": a purpose whose parts are all parts its means already moves says
    why the means is done, not a second motion of them; it moves nothing more."""
    parts = grounded[0]
    named = [m for m in act.goal.themes if not m.pronoun]
    if controls and parts and act.means is not None and named and all(m.kind is not None and builder.refs.stands_in(m) for m in named):
        builder.notes.append(f"read '{act.goal.text}' as what working the {controls[0].part.kind} does: {builder.asset.name} has no {named[0].kind}")
        return [], []  # "turn the cross-shaped handle so that the bolts retract": no bolts, not a second knob standing in
    standing_in = [m for m in named if m.kind is not None and builder.refs.stands_in(m)]
    if controls and parts and act.means is not None and standing_in and len(standing_in) < len(named):
        kept = {p.joint for m in named if m not in standing_in for p in builder.refs.resolve(m)[0]}
        builder.notes.append(f"read '{standing_in[0].words}' as what working the {controls[0].part.kind} does: {builder.asset.name} has no "
                             f"{standing_in[0].kind}")  # "turn the wheel to withdraw the bolts, whereupon the door swings open": the door
        pairs = [(p, w) for p, w in zip(parts, grounded[1], strict=True) if p.joint in kept]
        parts, grounded = [p for p, _ in pairs], ([p for p, _ in pairs], [w for _, w in pairs])
    if controls and parts and act.means is not None and _other_controls(act.means, parts, controls):
        moved = " and ".join(dict.fromkeys(m.words or m.part.link for m in controls))
        others = ", ".join(p.link for p in parts)
        builder.notes.append(f"read '{act.goal.text}' as what working {moved} does, the part the prompt named; nothing more moves ("
                             f"'{act.goal.text}' alone could mean {others})")  # "twist the upper knob a quarter turn to set the timer"
        return [], []
    if not controls or not parts or not {p.joint for p in parts} <= {m.part.joint for m in controls}:
        return grounded
    if act.means is None and act.goal.sense in _WAYS and {p.joint for p in parts} == {m.part.joint for m in controls}:
        controls.clear()  # "raise the toast up with the lever": the lever carries the toast, so it goes the way the goal says
        return grounded
    moved = " and ".join(dict.fromkeys(m.words or m.part.link for m in controls))
    builder.notes.append(f"read '{act.goal.text}' as what working {moved} does: nothing more moves")
    return [], []


def _other_controls(means: Frame, parts: list[Part], controls: list[Move]) -> bool:
    """A purpose that grounds only to other controls than the ones its means names by place, size or order: the means
    said which control; the purpose says what it is for ("to set the timer"), not a second control to work."""
    named = bool(means.themes) and all(not m.pronoun and bool(m.sides or m.ordinal or m.size or m.relation) for m in means.themes)
    return named and all(mech.is_control(p) for p in parts) and not {p.joint for p in parts} & {m.part.joint for m in controls}


def means_on_goal(builder: Builder, act: Act) -> Act:
    """"Loosen the cap by turning it 90 degrees": a means on "it" before anything was named works the goal's own part,
    so its amount and way are how far and which way the goal's motion goes."""
    means, goal = act.means, act.goal
    if means is not None and means.verb == "use" and goal.themes and goal.themes[0].is_object and builder.is_object_motion(goal):
        builder.notes.append(f"read '{means.text}' as how the whole {builder.asset.name} is held")  # "use it to lift the bucket 30 cm"
        return replace(act, means=None)
    if means is None or builder.refs.last or not goal.themes or not means.themes:
        return act
    whole = all(m.is_object for m in means.themes) and all(m.pronoun for m in goal.themes) and means.quantities.amount is not None and (
        means.sense is VerbSense.TURN and goal.sense in (VerbSense.OPEN, VerbSense.CLOSE))
    if not whole and not all(m.pronoun for m in means.themes):  # "give the bottle a quarter turn to loosen it": the same, said of the object
        return act
    q, how = goal.quantities, means.quantities
    quantities = replace(q, amount=q.amount or how.amount, sense=q.sense or how.sense, direction=q.direction or how.direction)
    builder.notes.append(f"read '{means.text}' as how '{goal.text}' goes")
    return replace(act, goal=replace(goal, quantities=quantities), means=None)


def elaborates(builder: Builder, act: Act, sense: VerbSense, parts: list[Part]) -> bool:
    """"Release the door, and lower it 40 degrees": a conjoined clause on "it" that only says how far the
    previous, unquantified motion of the same parts goes (the same way) replaces that motion's amount."""
    goal = act.goal
    if not act.conjoined or goal.quantities.amount is None or not builder.steps or not goal.themes or not all(m.pronoun for m in goal.themes):
        return False
    last = builder.steps[-1]
    moves = {m.joint: m for m in (*last.controls, *last.effects)}
    joints = {p.joint for p in parts}
    if not parts or any(j not in moves or moves[j].goal.amount is not None for j in joints):
        return False
    before = Tracker.of(builder.asset)
    for step in builder.steps[:-1]:
        before.apply(step)
    updated = {}
    for part in parts:
        old = moves[part.joint]
        start = before.value(part.joint)
        choice = goal_for(goal, sense, part, before).goal
        new_value = resolve(choice, part.geometry, before.obj, builder.asset, start).value
        old_value = resolve(old.goal, part.geometry, before.obj, builder.asset, start).value
        if new_value is None or old_value is None or (new_value - start) * (old_value - start) <= 0:
            return False
        updated[part.joint] = old.model_copy(update={"goal": choice, "q": round(float(new_value), 9)})
    controls = [updated.get(m.joint, m) for m in last.controls]
    effects = [updated.get(m.joint, m) for m in last.effects]
    builder.steps[-1] = last.model_copy(update={"controls": controls, "effects": effects})
    replay(builder)
    builder.notes.append(f"read '{goal.text}' as how far the previous motion goes")
    return True


def coast(builder: Builder, frame: Frame) -> None:
    """"push it forward 1 m and let it roll (0.3 m to a stop)": the motion before coasts."""
    last = builder.steps[-1]
    assert last.base is not None
    update: dict[str, object] = {"coast": True}
    amount = frame.quantities.amount
    if amount is not None and amount.unit == "m":
        update["distance_m"] = amount.value
        update["wheels"] = last.base.wheels
    builder.steps[-1] = last.model_copy(update={"base": last.base.model_copy(update=update)})
    replay(builder)


def hold(builder: Builder, act: Act) -> bool:
    """"hold it there for 2 s", "keep the lid open": hold the last step; "hold the button" presses it."""
    frame = act.goal
    duration = frame.quantities.duration_s or 0.0
    pronoun = not frame.themes or all(m.pronoun for m in frame.themes)
    if builder.steps and not pronoun and same_as_last(builder, frame) and _undoes(frame, builder.steps[-1], builder) and _kept_effect(builder, frame):
        return True
    if builder.steps and not pronoun and same_as_last(builder, frame) and _undoes(frame, builder.steps[-1], builder):
        # "lift the toilet seat but keep the lid closed" where seat and lid are one part
        said = " / ".join(m.words or m.head for m in frame.themes)
        raise builder.refs.refuse(f"'{said}' is the part the step before moves ('{builder.steps[-1].op}'): it cannot move and stay "
                                  f"{' '.join(sorted(set(frame.text.split()) & _KEPT_STATES))} at once on {builder.asset.name}")
    if frame.themes and all(m.is_object for m in frame.themes) and not (builder.steps and same_as_last(builder, frame)) and (
            set(frame.text.split()) & {"open", "opened"}):
        builder.add(replace(act, goal=replace(frame, verb="open", sense=VerbSense.OPEN)))  # "keep the bin open for a few seconds"
        return True
    if act.results and (during := _during(builder, act)):  # "keep the door open while the plate goes round": open, then it goes round
        builder.add(replace(act, results=tuple(r for r in act.results if r not in during)))
        for result in during:
            builder.add(Act(goal=replace(result, link=frame.link, subject_theme=False)))
        return True
    amount = frame.quantities.amount
    base = builder.steps[-1].base if builder.steps else None
    if pronoun and base is not None and builder.last_base_default and amount is not None and amount.unit == "m":
        # "pick the laptop up and hold it 30 cm above the desk": the height the lift had no number for
        builder.steps[-1] = builder.steps[-1].model_copy(update={"base": base.model_copy(update={"distance_m": amount.value})})
        builder.last_base_default = False
        distance_said(builder)
        builder.notes.append(f"read '{frame.text}' as the distance of the previous motion")
    if builder.steps and (pronoun or same_as_last(builder, frame)):
        last = builder.steps[-1]
        if not duration and any(c.release == "self_return" for c in last.controls):  # "press the key and keep it pressed": it stays in
            last = last.model_copy(update={"controls": [c.model_copy(update={"release": "stays"}) for c in last.controls]})
        builder.steps[-1] = last.model_copy(update={"hold_s": last.hold_s + duration})
        if act.results:
            refine_last(builder, act)
        return True
    return False


def _during(builder: Builder, act: Act) -> list[Frame]:
    """Results of a hold that move other parts than the one held, each with its own verb ("... while the plate spins"):
    they happen once the held part is there, not at the same moment."""
    held = {p.joint for p in builder.refs.pronoun()} if all(m.pronoun for m in act.goal.themes) else set()
    if not held and act.goal.themes:
        try:
            held = {p.joint for p in builder.ground(act.goal, VerbSense.OPEN, act.goal.themes)[0]}
        except GroundingError:
            return []
    out = []
    for frame in act.results:
        if frame.verb is None or not frame.themes or any(m.pronoun for m in frame.themes):
            continue
        try:
            parts = builder.ground(frame, frame.sense or VerbSense.OPEN, frame.themes)[0]
        except GroundingError:
            continue
        if parts and held and not {p.joint for p in parts} & held:
            out.append(frame)
    return out


def refine_last(builder: Builder, act: Act) -> None:
    """"... and keep it down so the lid swings up to vertical": what the hold lets happen refines the last step."""
    last = builder.steps[-1]
    before = Tracker.of(builder.asset)
    for step in builder.steps[:-1]:
        before.apply(step)
    updated = {}
    for frame in act.results:
        sense = frame.sense or VerbSense.OPEN
        try:
            parts, _ = builder.ground(frame, sense, tuple(m for m in frame.themes if not m.pronoun))
        except GroundingError:
            continue
        for part in parts:
            if any(m.joint == part.joint for m in last.effects):
                updated[part.joint] = goal_for(frame, sense, part, before).goal
    effects = [m.model_copy(update={"goal": updated[m.joint]}) if m.joint in updated else m for m in last.effects]
    builder.steps[-1] = last.model_copy(update={"effects": effects})
    replay(builder)


_KEPT_STATES = frozenset({"closed", "shut", "down", "open", "up"})
_OPENING = frozenset({"open", "up", "upper", "pressed"})


def _kept_effect(builder: Builder, frame: Frame) -> bool:
    """"Press the release button, but keep the door closed": the door the press would free stays; the press stays."""
    last = builder.steps[-1]
    parts, _ = builder.ground(frame, VerbSense.HOLD, frame.themes)
    joints = {p.joint for p in parts}
    if not last.controls or not joints or not all(m.joint in joints for m in last.effects if m.joint in joints) or not any(
            m.joint in joints for m in last.effects):
        return False
    builder.steps[-1] = last.model_copy(update={"effects": [m for m in last.effects if m.joint not in joints]})
    replay(builder)
    builder.notes.append(f"kept {', '.join(sorted(joints))} where it is: '{frame.text}'")
    return True


def _undoes(frame: Frame, step: ContractStep, builder: Builder | None = None) -> bool:
    """The hold keeps a state the step before leaves ("... keep the cover closed" after opening it); "down" is no undoing
    of an opening that ends down ("open the suitcase fully and keep the lid down flat": a lid that opens flat)."""
    words = set(frame.text.split())
    opens_down = builder is not None and any(p.geometry.open_value is not None and p.geometry.down_value == p.geometry.open_value
                                             for p in builder.parts if any(m.joint == p.joint for m in step.effects))
    words = words - {"down"} if opens_down else words
    opened = any(m.goal.state in _OPENING for m in step.effects)
    closed = any(m.goal.state in ("closed", "down", "lower") for m in step.effects)
    return (opened and bool(words & {"closed", "shut", "down"})) or (closed and bool(words & {"open", "up"}))


def same_as_last(builder: Builder, frame: Frame) -> bool:
    try:
        parts, _ = builder.ground(frame, VerbSense.HOLD, frame.themes)
    except GroundingError:
        return False
    moved = {m.joint for m in (*builder.steps[-1].controls, *builder.steps[-1].effects)} if builder.steps else set()
    return bool(parts) and all(p.joint in moved for p in parts)


def take_hold(builder: Builder, goal: Frame, sense: VerbSense) -> bool:
    """"grab the bucket by its handle", "take hold of the lid": nothing moves; what is held becomes what "it" means next
    (the whole object when the object is named). False when ``goal`` is no taking hold."""
    kept = bool(set(goal.text.split()) & _KEPT_STATES)  # "keep the bin open with the pedal": a state held, no grasp
    if (sense is VerbSense.GRASP or (sense is VerbSense.HOLD and goal.instruments and not kept)) and goal.themes and goal.themes[0].is_object:
        from app.engine.offline.sequences import ready_handle  # sequences builds on this module

        readied = ready_handle(builder, Act(goal=goal))
        builder.refs.last_object = True  # "grab the bucket by its handle and lift it": "it" is the bucket
        if readied:
            return True
    elif sense is VerbSense.GRASP:
        try:
            parts, _ = builder.ground(goal, sense, goal.themes) if goal.themes else ([], [])
        except GroundingError:
            builder.notes.append(f"ignored '{goal.text}': it names no part of {builder.asset.name}")  # "while grabbing the milk"
            return True
        builder.refs.remember(parts, [])
    else:
        return False
    builder.notes.append(f"'{goal.text}': taking hold moves nothing by itself")
    return True
