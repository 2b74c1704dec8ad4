"""Acts that become several steps or a whole-object motion: codes typed on a keypad (one press per key),
"both doors, left one first", and moving or turning the whole object.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from app.engine.contracts.steps import Goal
from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import PartKind, info
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.offline.goals import goal_for
from app.engine.offline.keypad import code_keys
from app.engine.offline.moves import Move
from app.engine.offline.reading.acts import Act
from app.engine.offline.reading.codes import place_words
from app.engine.offline.reading.frames import Frame
from app.engine.offline.resolve import resolve
from app.engine.offline.revisions import distance_said
from app.engine.offline.whole_object import object_motion, returning_motion

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.grounding import Part


def with_result_quantities(frame: Frame, results: tuple[Frame, ...]) -> Frame:
    """"Shove the car so it rolls 0.6 m along +X in a second": what the object is said to do afterwards gives
    the motion its amount, direction and time."""
    merged = frame.quantities
    for result in results:
        if result.themes and not all(m.pronoun or m.is_object for m in result.themes):
            continue
        extra = result.quantities
        merged = replace(merged, amount=extra.amount or merged.amount, axis=extra.axis or merged.axis, direction=extra.direction or merged.direction,
                         duration_s=extra.duration_s or merged.duration_s, speed_mps=extra.speed_mps or merged.speed_mps)
    return replace(frame, quantities=merged)


LYING_RAD = 0.785
"""A carry handle this far (45 degrees) or more from upright lies down: it is stood up before the object is held by it."""


def ready_handle(builder: Builder, act: Act) -> bool:
    """"Pick the bucket up by its handle": a carry handle lying down is stood upright first, to hold the object by."""
    for mention in act.goal.instruments:
        try:
            parts, words = builder.ground(act.goal, VerbSense.RAISE, (mention,))
        except GroundingError:
            continue
        for part, said in zip(parts, words, strict=True):
            now = builder.tracker.value(part.joint)
            upright = resolve(Goal(state="vertical"), part.geometry, builder.tracker.obj, builder.asset, now).value
            if part.kind is not PartKind.HANDLE or part.geometry.type != "revolute" or upright is None or abs(upright - now) < LYING_RAD:
                continue
            plain = replace(act, means=None, results=(), goal=replace(act.goal, quantities=replace(act.goal.quantities, amount=None)))
            builder.append(plain, VerbSense.RAISE, [], [Move(part, "direct", Goal(state="vertical"), words=said)], why="prerequisite")
            builder.notes.append(f"stood {part.link} upright first, to hold {builder.asset.name} by it")
            return True
    return False


_AGAIN = frozenset({"again", "more", "further", "higher", "another", "twice"})


def object_motion_act(builder: Builder, act: Act) -> None:
    ready_handle(builder, act)
    goal = act.goal
    previous = builder.steps[-1].base if builder.steps else None
    if goal.quantities.direction == "down" or "down" in goal.text.split():  # "lift it, carry it right and put it back down": the lift, undone
        previous = next((s.base for s in reversed(builder.steps) if s.base is not None and s.base.axis_world and s.base.axis_world[2] > 0.5), previous)
    q = goal.quantities
    if previous is not None and goal.verb in ("move", "go") and goal.themes and goal.themes[0].pronoun and q.amount is None and q.direction is None and (
            q.axis is None and goal.particle is None):
        builder.notes.append(f"read '{goal.text}' as the motion said again")  # "Pick up that bucket! Half a metre up! Move it!"
        return
    motion = returning_motion(goal, previous) if goal.returning or goal.sense in (VerbSense.RETURN,) else None
    if motion is None:
        goal = with_result_quantities(goal, act.results)
        motion = object_motion(goal, builder.tracker.obj, yaw=yaw(builder))
        verbless = goal.text.split()[0] not in VERBS  # "Pick up that bucket! Half a metre straight up!": the lift's distance
        if (act.conjoined or verbless) and previous is not None and builder.last_base_default and goal.themes and (goal.themes[0].pronoun or verbless) and (
                motion.motion.axis_world == previous.axis_world and goal.quantities.amount is not None):
            builder.steps[-1] = builder.steps[-1].model_copy(update={"base": previous.model_copy(update={"distance_m": motion.motion.distance_m})})
            distance_said(builder)
            builder.notes.append(f"read '{goal.text}' as the distance of the previous motion")
            builder.last_base_default = False
            return
    if previous is not None and builder.steps[-1].base is previous and goal.subject_theme and goal.quantities.amount is None and (
            motion.motion.axis_world == previous.axis_world and not motion.motion.yaw_rad and not _AGAIN & set(goal.text.split())):
        builder.notes.append(f"read '{goal.text}' as the motion before, told as it happens")  # "... by its handle! ..., then the bucket lifts!"
        return
    builder.notes.extend(motion.notes)
    builder.last_base_default = any(n.startswith("no distance given") for n in motion.notes)
    builder.append(act, goal.sense or VerbSense.MOVE, [], [], base=motion.motion, why="asked")
    builder.refs.last_object = True


def yaw(builder: Builder) -> float:
    return sum(step.base.yaw_rad for step in builder.steps if step.base is not None)


def is_code(builder: Builder, frame: Frame) -> bool:
    """Keys named by digit or by place only ("press 1, 2, 3", "enter bottom-left then top-right"), on an asset with a keypad."""
    places = [c for c in frame.codes if c[0] == "place"]
    if any(m.kind is PartKind.BUTTON and (m.plural or m.collective) for m in frame.themes) and len(frame.codes) - len(places) < 2:
        return False  # "press the three keys of the top row": keys named as a group ("the keys 1, 2 and 3": a code)
    named = [m for m in frame.themes if not m.is_object and m.kind not in (PartKind.BUTTON, PartKind.CODE) and not place_words(m.words)
             and m.words != "one"]  # "one after another"
    digits = len(frame.codes) > len(places)
    keys = [m for m in frame.themes if m.kind is PartKind.BUTTON and not place_words(m.words)]
    return len(builder.refs.of_kind(PartKind.BUTTON)) > 1 and not named and (digits or len(places) > 1 or (len(places) == 1 and not keys))


def enter_code(builder: Builder, act: Act) -> None:
    """"type 1-2-3-4 on the keypad": one press per key, in order."""
    keys = code_keys(act.goal.codes, builder.refs, builder.notes)
    for index, key in enumerate(keys):
        move = Move(key, "control", goal_for(act.goal, VerbSense.PRESS, key, builder.tracker).goal, words=f"key {index + 1}")
        here = act if index == 0 else replace(act, wait_before_s=0.0, parallel=False)
        if index < len(keys) - 1:
            here = replace(here, results=())
        builder.complete(here, VerbSense.PRESS, [move], [])


def first_then_rest(builder: Builder, act: Act) -> None:
    """"open both doors 90 degrees, left one first": the named one, then the others."""
    goal = act.goal
    assert goal.first is not None
    sense = builder.frame_sense(goal)
    parts, words = builder.ground(goal, sense, goal.themes)
    first_mention = replace(goal.first, kind=parts[0].kind if parts else None, anaphor=False)
    first, _ = builder.refs.resolve(first_mention)
    ordered = [p for p in parts if p in first] + [p for p in parts if p not in first]
    for index, part in enumerate(ordered):
        moves = builder.moves(goal, sense, [part], [words[parts.index(part)]], None)
        builder.complete(act if index == 0 else replace(act, parallel=False, wait_before_s=0.0), sense, [], moves)


_ORDER_KEYS = {"left_to_right": (1, False), "right_to_left": (1, True), "top_to_bottom": (2, True), "bottom_to_top": (2, False)}


def alternating(goal: Frame) -> bool:
    """"open every other drawer": every second one; "leave every other drawer shut": all the others (a verb that keeps)."""
    return any(m.alternate for m in goal.themes) and not goal.stative and not (goal.verb is not None and goal.verb in VERBS and VERBS[goal.verb].stative)


def in_turn(builder: Builder, act: Act) -> None:
    """"press the three keys of the top row, left to right", "open the drawers one by one": one step per part."""
    from app.engine.offline.grounding import position, reading_order

    goal = act.goal
    sense = builder.frame_sense(goal)
    parts, words = builder.ground(goal, sense, goal.themes)
    order = goal.in_turn or ("said" if keys_listed(goal) else "reading")
    if order == "reverse":  # "close them in the reverse order": the last one worked goes first
        ordered = _last_worked_first(builder, parts)
    elif order in _ORDER_KEYS:
        axis, descending = _ORDER_KEYS[order]
        ordered = sorted(parts, key=lambda p: -position(p, builder.tracker.obj)[axis] if descending else position(p, builder.tracker.obj)[axis])
    elif order == "said":
        ordered = parts  # "key in the code: top-left button, the one right under it, then the bottom-right one"
    else:
        ordered = reading_order(parts, builder.tracker.obj)
    if alternating(goal) and len(ordered) > 2:  # "every other drawer, starting with the bottom one"
        builder.notes.append(f"read 'every other' as {', '.join(p.link for p in ordered[::2])}: every second one from the "
                             f"{'first in reading order' if order in ('reading', 'said') else 'end said'}")
        ordered = ordered[::2]
    _one_after_another(builder, act, goal, sense, ordered, [words[parts.index(part)] for part in ordered])


def _worked(builder: Builder) -> list[str]:
    """The joints the steps so far move, in order (a joint once per step that moves it)."""
    return [m.joint for step in builder.steps for m in (*step.controls, *step.effects)]


def _last_worked_first(builder: Builder, parts: list[Part]) -> list[Part]:
    worked = _worked(builder)
    return sorted(parts, key=lambda p: -max((i for i, j in enumerate(worked) if j == p.joint), default=-1))


def _one_after_another(builder: Builder, act: Act, goal: Frame, sense: VerbSense, parts: list[Part], words: list[str]) -> None:
    """One step per part, each after the one before (the act's own timing on the first)."""
    for index, (part, said) in enumerate(zip(parts, words, strict=True)):
        moves = builder.moves(goal, sense, [part], [said], None)
        builder.complete(act if index == 0 else replace(act, parallel=False, wait_before_s=0.0, results=()), sense, [], moves)


def everything(builder: Builder, act: Act) -> bool:
    """"(pull the rack out,) then close everything back up", "put it all back": every part the prompt has moved so far
    (the door opened to reach the rack too), the last moved first — a rack goes back in before its door shuts. True
    when it was added; False when the words are not about everything or nothing has moved yet."""
    goal = act.goal
    said = goal.themes[0] if len(goal.themes) == 1 else None
    words = goal.text.split()
    whole = any(words[k:k + 2] in (["it", "all"], ["them", "all"], ["all", "of"]) and words[k + 2:k + 3] not in (["the"], ["way"])
                for k in range(len(words)))  # "put it all back", not "bring it all the way out"
    if said is None or act.means is not None or not (said.head == "everything" or (said.pronoun and whole)):
        return False
    worked = set(_worked(builder))
    moved = [p for p in builder.parts if p.joint in worked and abs(builder.tracker.value(p.joint) - builder.asset.joints[p.joint].rest) > 1e-6]
    if not moved:
        return False
    sense = VerbSense.CLOSE if builder.frame_sense(goal) is VerbSense.CLOSE and "back" not in words else VerbSense.RETURN
    ordered = _last_worked_first(builder, moved)
    label = "everything" if said.head == "everything" else "it all"
    builder.notes.append(f"read '{label}' as every part moved so far, the last moved first: " + ", ".join(p.link for p in ordered))
    _one_after_another(builder, act, replace(goal, sense=sense), sense, ordered, [label] * len(ordered))
    return True


def lock_object(builder: Builder, act: Act) -> bool:
    """"Lock the box up", "lock up the jewellery box with both clasps", "lock the safe by spinning the dial": what is open
    is shut first, then the object is fastened by what the words say, else by its latches (True when added; False when
    nothing says or has a way to lock it)."""
    from app.engine.offline.completion import shut_open_doors

    goal = act.goal
    named = builder.object_named or builder.refs.last_object or not builder.refs.last  # "shut the safe and lock it ...": "it" is the safe
    if builder.frame_sense(goal) is not VerbSense.LOCK or not goal.themes or not all(m.is_object or (m.pronoun and named) for m in goal.themes):
        return False
    latches = [p for p in builder.parts if p.kind is not None and info(p.kind).latches_host]
    dials = [p for p in builder.parts if p.kind is PartKind.KNOB and p.geometry.type == "continuous"]
    if act.means is None and not goal.instruments and not latches and not dials:
        return False
    shut_open_doors(builder, act, "locks")
    if act.means is None and not goal.instruments and not latches:  # "lock up the safe": shut, then its dial spun (of two, the smaller)
        which = "one" if len(dials) == 1 else "smaller"
        dials = sorted(dials, key=lambda p: (p.geometry.size, p.joint))[:1]
        builder.notes.append(f"read '{goal.text}' as its door shut, then {dials[0].link} (its {which} dial) spun to scramble it")
        builder.complete(replace(act, parallel=False), VerbSense.SPIN, [], builder.moves(goal, VerbSense.SPIN, dials, ["dial"], None))
        return True
    if act.means is not None:
        builder.add(replace(act, goal=act.means, means=None))
        return True
    parts, words = builder.ground(goal, VerbSense.CLOSE, goal.instruments) if goal.instruments else (latches, ["latch"] * len(latches))
    builder.notes.append(f"read '{goal.text}' as its door or lid shut, then {', '.join(p.link for p in parts)} fastened")
    builder.complete(replace(act, parallel=False), VerbSense.CLOSE, [], builder.moves(goal, VerbSense.CLOSE, parts, words, None))
    return True


def object_result(builder: Builder, act: Act) -> bool:
    """"(pull the drawer out,) then keep pulling so the whole cabinet drags 20 cm toward you": a step that names no part,
    whose result moves the whole object, is that motion of the object (True when it was added)."""
    if act.means is not None or (act.goal.themes and act.goal.sense is not VerbSense.HOLD):
        return False  # "keep pulling (it)": the step before, carried on
    moved = next((r for r in act.results if r.themes and r.themes[0].is_object and r.verb is not None), None)
    if moved is None or not builder.is_object_motion(moved):
        return False
    builder.notes.append(f"read '{act.goal.text}' as '{moved.text}': the whole {builder.asset.name} moves")
    object_motion_act(builder, replace(act, goal=moved, results=()))
    return True


def keys_listed(frame: Frame) -> bool:
    """Keys (buttons) named one by one in a list to press: pressed in the order said, one after another (nobody presses
    "the top-left button, the one under it" together unless told to)."""
    keys = [m for m in frame.themes if (m.kind is PartKind.BUTTON or (m.anaphor and m.kind is None)) and not m.plural and not m.collective]
    return frame.sense is VerbSense.PRESS and len(keys) > 1 and len(keys) == len(frame.themes) and keys[0].kind is PartKind.BUTTON and not (
        set(frame.text.split()) & {"together", "simultaneously", "at_once", "at_the_same_time", "both"})
