"""Stages 5-6 — grounded acts -> contract steps, with causal completion.

Each act's themes are grounded (:mod:`.referents`), each part gets a goal (:mod:`.goals`),
and the mechanism rules (:mod:`.mechanisms`) add what the object needs: the pedal under a
pedal bin's lid, the latch holding a door, the door in front of a tray. Every step records
why it is there (asked, mechanism, latch, prerequisite, release), and every clause what was
understood (:mod:`.explain`). The tracker resolves goals as the steps accumulate, so later
clauses see the state earlier ones left.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.steps import BaseMotion, Goal, JointMove, Release, Why
from app.engine.contracts.steps import Step as ContractStep
from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import HINGED_KINDS, PartKind, info
from app.engine.lexicon.verbs import VERBS, VerbSense
from app.engine.lexicon.words import OPERATED_OBJECTS
from app.engine.offline import mechanisms as mech
from app.engine.offline.explain import Explanation
from app.engine.offline.goals import goal_for
from app.engine.offline.grounding import Part, movable_parts, openable
from app.engine.offline.reading.acts import Act
from app.engine.offline.reading.frames import CODE_VERBS, Frame, place_words
from app.engine.offline.reading.mentions import Mention
from app.engine.offline.reading.quantities import Quantities
from app.engine.offline.referents import Referents
from app.engine.offline.resolve import resolve
from app.engine.offline.tracker import Tracker
from app.engine.offline.whole_object import moves_object, object_motion

REACHED = 1e-6


def _with_result_quantities(frame: Frame, results: tuple[Frame, ...]) -> Frame:
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


def _label(part: Part) -> str:
    return part.kind.value if part.kind is not None else "part"
_OPENING = frozenset({VerbSense.OPEN, VerbSense.RAISE, VerbSense.PULL_OUT, VerbSense.RECLINE})
_PRESSING = frozenset({VerbSense.PRESS, VerbSense.OPERATE, VerbSense.PUSH_IN, VerbSense.TOGGLE, VerbSense.SWITCH_ON, VerbSense.HOLD,
                       VerbSense.UNLATCH, VerbSense.TURN, VerbSense.LOWER})


@dataclass
class _Move:
    part: Part
    role: str
    goal: Goal
    release: Release = "stays"
    words: str = ""
    loose: bool = False
    """The amount is a reading of a vague word ("slightly")."""


@dataclass
class Builder:
    asset: ArticulatedAsset
    tracker: Tracker = field(init=False)
    parts: list[Part] = field(init=False)
    refs: Referents = field(init=False)
    steps: list[ContractStep] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    explanation: Explanation = field(init=False)
    mentioned: set[str] = field(default_factory=set)
    excluded: set[str] = field(default_factory=set)
    manual: bool = False
    _last_base_default: bool = False

    def __post_init__(self) -> None:
        self.tracker = Tracker.of(self.asset)
        self.parts = movable_parts(self.asset, self.tracker.obj)
        self.refs = Referents(self.asset, self.tracker.obj, self.parts)
        self.explanation = Explanation(self.asset, self.tracker.obj)

    # --- grounding -----------------------------------------------------------------
    def _object_parts(self, frame: Frame, sense: VerbSense) -> list[Part]:
        """What a clause on the whole object ("open the microwave", "turn on the tap", "flush the toilet") works."""
        implied = VERBS[frame.verb].implies if frame.verb is not None and frame.verb in VERBS else ()
        if implied:
            found = [p for kind in implied for p in self.refs.of_kind(kind)]
            if found:
                return found[:1]
        if sense in (VerbSense.SWITCH_ON, VerbSense.SWITCH_OFF, VerbSense.TURN, VerbSense.OPERATE, VerbSense.TOGGLE) or (
                self.tracker.obj.category in OPERATED_OBJECTS and sense in (VerbSense.OPEN, VerbSense.CLOSE)):
            controls = [p for p in self.parts if mech.is_control(p)]
            if len(controls) == 1:
                return controls
            if controls and sense in (VerbSense.SWITCH_ON, VerbSense.SWITCH_OFF):
                raise self.refs.refuse(f"'{frame.text}' could mean {len(controls)} controls", controls)
        if sense in (VerbSense.OPEN, VerbSense.CLOSE, VerbSense.RAISE, VerbSense.LOWER, VerbSense.PULL_OUT, VerbSense.PUSH_IN):
            return self._openables(frame)
        return []

    def _openables(self, frame: Frame) -> list[Part]:
        """"Open the cabinet": its doors (all of one size class), else its lids, drawers, caps."""
        found = openable(self.parts)
        if not found:
            caps = [p for p in self.parts if p.kind in (PartKind.CAP, PartKind.LID) and p.geometry.open_value is None]
            return caps[:1]
        first_kind = found[0].kind
        group = [p for p in found if p.kind == first_kind]
        if len(group) > 1 and any(m.plural or m.collective for m in frame.themes):
            return group
        largest = group[0].geometry.size
        same = [p for p in group if p.geometry.size >= largest / 1.5]
        if len(same) == 1:
            return same
        if first_kind in HINGED_KINDS and len(same) == 2:
            self.notes.append(f"'{frame.text}': opened both {first_kind.value}s")
            return same
        raise self.refs.refuse(f"'{frame.text}' could mean {len(same)} parts", same)

    def _ground(self, frame: Frame, sense: VerbSense, mentions: tuple[Mention, ...], *, prefer: list[Part] | None = None) -> tuple[list[Part], list[str]]:
        parts: list[Part] = []
        words: list[str] = []
        for mention in mentions:
            if mention.pronoun:
                found = self.refs.pronoun(release=sense is VerbSense.RELEASE)
                if not found and self.parts:
                    found = self._object_parts(frame, sense)
            elif mention.is_object:
                found = self._object_parts(frame, sense)
            else:
                found = self._only_part(frame, mention)
                if not found:
                    found, notes = self.refs.resolve(mention, prefer=prefer)
                    self.notes.extend(notes)
            for part in found:
                if part not in parts:
                    parts.append(part)
                    words.append(mention.words or mention.head)
        return parts, words

    def _only_part(self, frame: Frame, mention: Mention) -> list[Part]:
        """A part name we do not know, tied to the object ("the stapler's magazine") on an object with one
        movable part, with a verb that part can do: that part, with a warning; never a bare guess."""
        if mention.whose is None or len(self.parts) != 1 or self.refs.ground(mention).parts:
            return []
        part = self.parts[0]
        sense = frame.sense
        fits = sense in (VerbSense.OPEN, VerbSense.CLOSE, VerbSense.RAISE, VerbSense.LOWER, VerbSense.RECLINE) and part.geometry.open_value is not None
        if sense in (VerbSense.PULL_OUT, VerbSense.PUSH_IN):
            fits = part.geometry.type == "prismatic"
        if not fits:
            return []
        self.notes.append(f"read '{mention.words}' as {part.describe(self.asset)}, the only movable part")
        return [part]

    # --- goals ---------------------------------------------------------------------
    def _moves(self, frame: Frame, sense: VerbSense, parts: list[Part], words: list[str], role: str | None) -> list[_Move]:
        out = []
        for part, said in zip(parts, words, strict=True):
            own_role = role or ("control" if mech.is_control(part) else "direct")
            choice = goal_for(frame, sense, part, self.tracker)
            self.notes.extend(choice.notes)
            loose = frame.quantities.amount is not None and frame.quantities.amount.loose
            out.append(_Move(part, own_role, choice.goal, words=said, loose=loose))
        return out

    def _frame_sense(self, frame: Frame, *, means: bool = False) -> VerbSense:
        if frame.sense is VerbSense.RELEASE and not means and frame.themes and not frame.let:
            # "release the door (by pressing the button)": a door is released by popping it open
            try:
                parts, _ = self._ground(frame, VerbSense.RELEASE, frame.themes)
            except GroundingError:
                parts = []
            if parts and not any(mech.is_control(p) for p in parts) and not any(p.joint in self.tracker.held for p in parts):
                return VerbSense.OPEN
        if frame.sense is not None:
            return frame.sense
        return VerbSense.OPERATE

    # --- acts ----------------------------------------------------------------------
    def add(self, act: Act) -> None:
        for exclusion in act.exclusions:
            self._exclude(exclusion)
        goal = act.goal
        sense = self._frame_sense(goal)
        if act.condition:
            self._condition(act)
            return
        if goal.verb is None and not goal.themes:
            self.notes.append(f"ignored '{goal.text}' (no action found)")
            return
        if sense is VerbSense.HOLD and self._hold(act):
            return
        if goal.let and goal.verb in ("roll", "coast", "glide", "slide") and self.steps and self.steps[-1].base is not None:
            self._coast(goal)
            return
        if goal.codes and act.means is None and goal.verb in CODE_VERBS and self._is_code(goal):
            self._enter_code(act)
            return
        if act.means is None and self._is_object_motion(goal):
            self._object_motion(act)
            return
        if goal.first is not None and act.means is None:
            self._first_then_rest(act)
            return
        if act.means is not None and self._aimless(goal):
            self.notes.append(f"ignored the purpose '{goal.text}': it names no part of {self.asset.name}")
            self.add(replace(act, goal=act.means, means=None))
            return
        controls: list[_Move] = []
        prefer = self._described(goal)
        if act.means is not None:
            means_sense = self._frame_sense(act.means, means=True)
            parts, words = self._ground(act.means, means_sense, act.means.themes)
            controls = self._moves(act.means, means_sense, parts, words, "control")
        elif goal.instruments:
            controls = self._instrument_controls(goal)
        effects_parts, effect_words = self._ground(goal, sense, goal.themes, prefer=prefer)
        if not effects_parts and not goal.themes and not controls:
            effects_parts = self.refs.pronoun(release=sense is VerbSense.RELEASE)
            effect_words = ["it"] * len(effects_parts)
        if not effects_parts and not controls:
            raise self.refs.refuse(f"nothing in '{goal.text}' names a part to move")
        if sense is VerbSense.RELEASE and effects_parts and all(mech.is_control(p) for p in effects_parts) and not any(
                self._pressed(p) for p in effects_parts):
            sense = VerbSense.OPERATE  # "after releasing the latch knob": nothing held it, so releasing means working it
        self._check_motion(goal, effects_parts)
        if self._elaborates(act, sense, effects_parts):
            return
        self.mentioned.update(p.joint for p in (*effects_parts, *(m.part for m in controls)))
        role = "effect" if controls else None
        effects = self._moves(goal, sense, effects_parts, effect_words, role)
        self._complete(act, sense, controls, effects)

    def _is_object_motion(self, frame: Frame) -> bool:
        targets = list(frame.themes)
        if not targets:
            return (not self.parts and frame.verb is not None) or (self.refs.last_object and frame.verb in VERBS and frame.sense is not None
                                                                   and frame.quantities.amount is not None and not frame.instruments)
        first = targets[0]
        if first.is_object:
            if self.tracker.obj.category in OPERATED_OBJECTS and frame.sense in (VerbSense.TURN, VerbSense.SWITCH_ON, VerbSense.SWITCH_OFF):
                return False
            return moves_object(frame, pronoun=False, after_part=False) and not (
                frame.sense in (VerbSense.OPEN, VerbSense.CLOSE) and openable(self.parts))
        if first.pronoun:
            if self.refs.last_object:
                return moves_object(frame, pronoun=True, after_part=False) or frame.returning
            after_part = bool(self.refs.last)
            return moves_object(frame, pronoun=True, after_part=after_part) and (after_part or not self.parts or frame.verb in ("push", "move"))
        return False

    def _pressed(self, part: Part) -> bool:
        return abs(self.tracker.value(part.joint) - part.geometry.rest) > REACHED

    def _check_motion(self, frame: Frame, parts: list[Part]) -> None:
        """A verb naming a motion the part cannot make is refused, not guessed: "fold down the tray"
        on a part that only slides, "slide the sash 20 cm" on one that only swings."""
        motion = VERBS[frame.verb].motion if frame.verb is not None and frame.verb in VERBS else "any"
        named = [p for p in parts if not mech.is_control(p)]
        if not named or motion == "any":
            return
        if motion == "hinge" and all(p.geometry.type == "prismatic" for p in named):
            raise self.refs.refuse(f"'{frame.verb}' swings a part about a hinge, but the {_label(named[0])} only slides")
        sideways = frame.quantities.direction == "sideways" or (frame.quantities.amount is not None and frame.quantities.amount.unit == "m")
        if motion == "slide" and sideways and all(p.geometry.type != "prismatic" for p in named):
            raise self.refs.refuse(f"'{frame.text}' slides a part in a straight line, but the {_label(named[0])} only rotates")

    def _elaborates(self, act: Act, sense: VerbSense, parts: list[Part]) -> bool:
        """"Release the door, and lower it 40 degrees": a conjoined clause on "it" that only says how far the
        previous, unquantified motion of the same parts goes (the same way) replaces that motion's amount."""
        goal = act.goal
        if not act.conjoined or goal.quantities.amount is None or not self.steps or not goal.themes or not all(m.pronoun for m in goal.themes):
            return False
        last = self.steps[-1]
        moves = {m.joint: m for m in (*last.controls, *last.effects)}
        joints = {p.joint for p in parts}
        if not parts or any(j not in moves or moves[j].goal.amount is not None for j in joints):
            return False
        from app.engine.offline.completion import _replay

        before = Tracker.of(self.asset)
        for step in self.steps[:-1]:
            before.apply(step)
        updated = {}
        for part in parts:
            old = moves[part.joint]
            start = before.value(part.joint)
            choice = goal_for(goal, sense, part, before).goal
            new_value = resolve(choice, part.geometry, before.obj, self.asset, start).value
            old_value = resolve(old.goal, part.geometry, before.obj, self.asset, start).value
            if new_value is None or old_value is None or (new_value - start) * (old_value - start) <= 0:
                return False
            updated[part.joint] = old.model_copy(update={"goal": choice, "q": round(float(new_value), 9)})
        controls = [updated.get(m.joint, m) for m in last.controls]
        effects = [updated.get(m.joint, m) for m in last.effects]
        self.steps[-1] = last.model_copy(update={"controls": controls, "effects": effects})
        _replay(self)
        self.notes.append(f"read '{goal.text}' as how far the previous motion goes")
        return True

    def _object_motion(self, act: Act) -> None:
        from app.engine.offline.whole_object import returning_motion

        goal = act.goal
        previous = self.steps[-1].base if self.steps else None
        motion = returning_motion(goal, previous) if goal.returning or goal.sense in (VerbSense.RETURN,) else None
        if motion is None:
            goal = _with_result_quantities(goal, act.results)
            motion = object_motion(goal, self.tracker.obj, yaw=self._yaw())
            if act.conjoined and previous is not None and self._last_base_default and goal.themes and goal.themes[0].pronoun and (
                    motion.motion.axis_world == previous.axis_world and goal.quantities.amount is not None):
                self.steps[-1] = self.steps[-1].model_copy(update={"base": previous.model_copy(update={"distance_m": motion.motion.distance_m})})
                from app.engine.offline.completion import _replay

                _replay(self)
                self.notes.append(f"read '{goal.text}' as the distance of the previous motion")
                self._last_base_default = False
                return
        self.notes.extend(motion.notes)
        self._last_base_default = any(n.startswith("no distance given") for n in motion.notes)
        self._append(act, goal.sense or VerbSense.MOVE, [], [], base=motion.motion, why="asked")
        self.refs.last_object = True

    def _yaw(self) -> float:
        return sum(step.base.yaw_rad for step in self.steps if step.base is not None)

    def _is_code(self, frame: Frame) -> bool:
        """Keys named by digit or by place only ("press 1, 2, 3", "enter bottom-left then top-right"), on an asset with a keypad."""
        places = [c for c in frame.codes if c[0] == "place"]
        named = [m for m in frame.themes if not m.is_object and m.kind not in (PartKind.BUTTON, PartKind.CODE) and not place_words(m.words)]
        digits = len(frame.codes) > len(places)
        keys = [m for m in frame.themes if m.kind is PartKind.BUTTON and not place_words(m.words)]
        return len(self.refs.of_kind(PartKind.BUTTON)) > 1 and not named and (digits or len(places) > 1 or (len(places) == 1 and not keys))

    def _enter_code(self, act: Act) -> None:
        """"type 1-2-3-4 on the keypad": one press per key, in order."""
        from app.engine.offline.keypad import code_keys

        keys = code_keys(act.goal.codes, self.refs)
        for index, key in enumerate(keys):
            move = _Move(key, "control", goal_for(act.goal, VerbSense.PRESS, key, self.tracker).goal, words=f"key {index + 1}")
            here = act if index == 0 else replace(act, wait_before_s=0.0, parallel=False)
            if index < len(keys) - 1:
                here = replace(here, results=())
            self._complete(here, VerbSense.PRESS, [move], [])

    def _first_then_rest(self, act: Act) -> None:
        """"open both doors 90 degrees, left one first": the named one, then the others."""
        goal = act.goal
        assert goal.first is not None
        sense = self._frame_sense(goal)
        parts, words = self._ground(goal, sense, goal.themes)
        first_mention = replace(goal.first, kind=parts[0].kind if parts else None, anaphor=False)
        first, _ = self.refs.resolve(first_mention)
        ordered = [p for p in parts if p in first] + [p for p in parts if p not in first]
        for index, part in enumerate(ordered):
            moves = self._moves(goal, sense, [part], [words[parts.index(part)]], None)
            self._complete(act if index == 0 else replace(act, parallel=False, wait_before_s=0.0), sense, [], moves)

    def _coast(self, frame: Frame) -> None:
        """"push it forward 1 m and let it roll (0.3 m to a stop)": the motion before coasts."""
        last = self.steps[-1]
        assert last.base is not None
        update: dict[str, object] = {"coast": True}
        amount = frame.quantities.amount
        if amount is not None and amount.unit == "m":
            update["distance_m"] = amount.value
            update["wheels"] = last.base.wheels
        self.steps[-1] = last.model_copy(update={"base": last.base.model_copy(update=update)})
        from app.engine.offline.completion import _replay

        _replay(self)

    def _aimless(self, frame: Frame) -> bool:
        """"... to start the wash", "... to make toast": a purpose that names no part (only what the object does)."""
        themes = [m for m in frame.themes if not m.pronoun and not m.is_object]
        return bool(themes) and all(m.kind is None and not self.refs.ground(m).parts for m in themes)

    def _described(self, frame: Frame) -> list[Part] | None:
        """"the door with the handle", "the one with the knob": parts whose own (mesh) names contain a word of
        an instrument phrase that is not a movable part."""
        words = {m.head for m in frame.instruments if not self.refs.ground(m).parts}
        if not words:
            return None
        from app.engine.offline.naming import link_words

        return [p for p in self.parts if link_words(self.asset, p.link) & words] or None

    def _instrument_controls(self, frame: Frame) -> list[_Move]:
        """"open the microwave with its release button": a control named as the tool is the means."""
        out: list[_Move] = []
        for mention in frame.instruments:
            if mention.kind is None or not info(mention.kind).control:
                continue
            found = self.refs.ground(mention)
            if not found.parts:
                self.notes.append(f"ignored the {mention.head}: not a movable part of {self.asset.name}")
                continue
            plain = replace(frame, quantities=Quantities(speed_factor=frame.quantities.speed_factor))  # the amount is the goal's
            out.extend(self._moves(plain, VerbSense.OPERATE, list(found.parts), [mention.words] * len(found.parts), "control"))
        return out

    def _exclude(self, frame: Frame) -> None:
        """"without touching the knob", "don't use the pedal": keep those parts still."""
        for mention in frame.themes:
            try:
                parts, _ = self._ground(frame, self._frame_sense(frame), (mention,))
            except GroundingError:
                continue
            self.excluded.update(p.joint for p in parts)
            if any(mech.is_control(p) for p in parts):
                self.manual = True

    def _condition(self, act: Act) -> None:
        """A state to reach first ("while the door is open"), or a description that only sets "it"."""
        frame = act.goal
        parts, words = self._ground(frame, VerbSense.OPEN, frame.themes) if frame.themes else ([], [])
        words_in = set(frame.text.split())
        wanted = frame.sense if frame.sense is not None else (
            VerbSense.OPEN if words_in & {"open", "opened"} else VerbSense.CLOSE if words_in & {"closed", "shut"} else None)
        if wanted is None or not parts:
            self.refs.remember(parts, [])
            return
        moves = [m for m in self._moves(frame, wanted, parts, words, None) if not self._reached(m)]
        if moves:
            self._complete(replace(act, goal=replace(frame, sense=wanted)), wanted, [], moves, why="prerequisite")
        self.refs.remember(parts, [])

    def _hold(self, act: Act) -> bool:
        """"hold it there for 2 s", "keep the lid open": hold the last step; "hold the button" presses it."""
        frame = act.goal
        duration = frame.quantities.duration_s or 0.0
        pronoun = not frame.themes or all(m.pronoun for m in frame.themes)
        if self.steps and (pronoun or self._same_as_last(frame)):
            last = self.steps[-1]
            self.steps[-1] = last.model_copy(update={"hold_s": last.hold_s + duration})
            if act.results:
                self._refine_last(act)
            return True
        return False

    def _refine_last(self, act: Act) -> None:
        """"... and keep it down so the lid swings up to vertical": what the hold lets happen refines the last step."""
        from app.engine.offline.completion import _replay

        last = self.steps[-1]
        before = Tracker.of(self.asset)
        for step in self.steps[:-1]:
            before.apply(step)
        updated = {}
        for frame in act.results:
            sense = frame.sense or VerbSense.OPEN
            try:
                parts, _ = self._ground(frame, sense, tuple(m for m in frame.themes if not m.pronoun))
            except GroundingError:
                continue
            for part in parts:
                if any(m.joint == part.joint for m in last.effects):
                    updated[part.joint] = goal_for(frame, sense, part, before).goal
        effects = [m.model_copy(update={"goal": updated[m.joint]}) if m.joint in updated else m for m in last.effects]
        self.steps[-1] = last.model_copy(update={"effects": effects})
        _replay(self)

    def _same_as_last(self, frame: Frame) -> bool:
        try:
            parts, _ = self._ground(frame, VerbSense.HOLD, frame.themes)
        except GroundingError:
            return False
        moved = {m.joint for m in (*self.steps[-1].controls, *self.steps[-1].effects)} if self.steps else set()
        return bool(parts) and all(p.joint in moved for p in parts)

    def _reached(self, move: _Move) -> bool:
        now = self.tracker.value(move.part.joint)
        value = resolve(move.goal, move.part.geometry, self.tracker.obj, self.asset, now, self.tracker.before.get(move.part.joint)).value
        return value is not None and abs(value - now) < REACHED

    # --- completion ----------------------------------------------------------------
    def _complete(self, act: Act, sense: VerbSense, controls: list[_Move], effects: list[_Move], why: Why = "asked") -> None:
        from app.engine.offline.completion import complete

        complete(self, act, sense, controls, effects, why)

    def _append(self, act: Act, sense: VerbSense, controls: list[_Move], effects: list[_Move], *, base: BaseMotion | None = None,
                why: Why = "asked", parallel: bool | None = None) -> None:
        frame = act.goal
        quantities = frame.quantities
        means_speed = act.means.quantities.speed_factor if act.means is not None else 1.0
        speed = quantities.speed_factor if quantities.speed_factor != 1.0 else means_speed
        duration = quantities.duration_s if (base is not None or effects or controls) and quantities.duration_s else None
        if act.means is not None and act.means.quantities.duration_s and not duration:
            duration = None
        hold = act.hold_s + (duration if frame.hold and duration else 0.0)
        if frame.hold and duration:
            duration = None
        step = ContractStep(
            id=f"S{len(self.steps) + 1}", op=sense.value, why=why, clause=frame.clause if why == "asked" else None,
            start="with_previous" if (act.parallel if parallel is None else parallel) and self.steps else "after_previous",
            wait_before_s=act.wait_before_s if why == "asked" else 0.0,
            controls=[self._joint_move(m) for m in controls], effects=[self._joint_move(m) for m in effects], base=base,
            speed_factor=speed, duration_s=duration, hold_s=hold,
        )
        self.steps.append(step)
        resolved = self.tracker.apply(step)
        self.explanation.record(act, step, resolved, [m.words for m in (*controls, *effects)])

    def _joint_move(self, move: _Move) -> JointMove:
        now = self.tracker.value(move.part.joint)
        value = resolve(move.goal, move.part.geometry, self.tracker.obj, self.asset, now, self.tracker.before.get(move.part.joint)).value
        return JointMove(joint=move.part.joint, link=move.part.link, role=move.role, goal=move.goal, release=move.release,  # type: ignore[arg-type]
                         q=None if value is None else round(float(value), 9))
