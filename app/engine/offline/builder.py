"""Stages 5-6 — grounded acts -> contract steps, with causal completion.

Each act's themes are grounded (:mod:`.referents`), each part gets a goal (:mod:`.goals`), and the mechanism rules
(:mod:`.mechanisms`) add what the object needs: the pedal under a pedal bin's lid, the latch holding a door, the door in
front of a tray. Every step records why it is there (asked, mechanism, latch, prerequisite, release), and every clause
what was understood (:mod:`.explain`). The tracker resolves goals as the steps accumulate (later clauses see the state).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.steps import MAX_STEP_S, BaseMotion, JointMove, Why
from app.engine.contracts.steps import Step as ContractStep
from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import PartKind, info
from app.engine.lexicon.objects import names_other_object
from app.engine.lexicon.verbs import VERBLESS_SENSES, VERBS, VerbSense
from app.engine.lexicon.words import OPERATED_OBJECTS, WHOLE_WORDS
from app.engine.offline import mechanisms as mech
from app.engine.offline import sequences as seq
from app.engine.offline.conditions import condition, exclude
from app.engine.offline.detached import check_detached
from app.engine.offline.explain import Explanation
from app.engine.offline.goals import goal_for
from app.engine.offline.grounding import Part, movable_parts, openable
from app.engine.offline.motion_fit import check_motion, check_press
from app.engine.offline.moves import Move
from app.engine.offline.object_parts import object_parts, starts
from app.engine.offline.only_part import only_part, sole_fit
from app.engine.offline.reading.acts import Act
from app.engine.offline.reading.codes import CODE_VERBS
from app.engine.offline.reading.frames import Frame
from app.engine.offline.reading.mentions import Mention
from app.engine.offline.reading.quantities import Quantities
from app.engine.offline.referents import Referents
from app.engine.offline.resolve import resolve
from app.engine.offline.revisions import coast, elaborates, hold, means_on_goal, restated_means, take_hold
from app.engine.offline.side_apart import side_apart
from app.engine.offline.strays import stray
from app.engine.offline.tracker import Tracker
from app.engine.offline.travel import beyond_limit, impossible, shown, travel_left
from app.engine.offline.whole_object import moves_object

REACHED = 1e-6

def _label(part: Part) -> str:
    return part.kind.value if part.kind is not None else "part"


_OPENING = frozenset({VerbSense.OPEN, VerbSense.RAISE, VerbSense.PULL_OUT, VerbSense.RECLINE})
_PRESSING = frozenset({VerbSense.PRESS, VerbSense.OPERATE, VerbSense.PUSH_IN, VerbSense.TOGGLE, VerbSense.SWITCH_ON, VerbSense.HOLD,
                       VerbSense.UNLATCH, VerbSense.TURN, VerbSense.LOWER})


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
    excluded_as: dict[str, PartKind | None] = field(default_factory=dict)
    """By what kind each excluded joint was named ("leave the cover lid where it is": a lid)."""
    turned: set[int] = field(default_factory=set)  # clauses whose told state was put the other way (a complaint)
    manual: bool = False
    last_base_default: bool = False
    object_named: bool = False  # the last part worked was named as the whole object ("close the laptop": its screen)

    def __post_init__(self) -> None:
        self.tracker = Tracker.of(self.asset)
        self.parts = movable_parts(self.asset, self.tracker.obj)
        self.refs = Referents(self.asset, self.tracker.obj, self.parts)
        self.explanation = Explanation(self.asset, self.tracker.obj)

    # --- grounding -----------------------------------------------------------------
    def _object_parts(self, frame: Frame, sense: VerbSense) -> list[Part]:
        return object_parts(self, frame, sense)

    def ground(self, frame: Frame, sense: VerbSense, mentions: tuple[Mention, ...], *, prefer: list[Part] | None = None) -> tuple[list[Part], list[str]]:
        parts: list[Part] = []
        words: list[str] = []
        for mention in mentions:
            if mention.pronoun and starts(frame) and self.parts:
                found = self._object_parts(frame, sense)  # "put my leftovers in, shut it and heat them up": the microwave runs
            elif mention.pronoun:
                found = self.refs.pronoun(release=sense is VerbSense.RELEASE, plural=mention.plural, shuts=sense in (VerbSense.OPEN, VerbSense.CLOSE)) or (
                    self._object_parts(frame, sense) if self.parts else [])
                self.notes.extend([f"read 'it' in '{frame.text}' as all of {', '.join(p.link for p in found)}: say which one if not"] if mention.head == "it" and len(found) > 1 else [])
            elif mention.is_object:
                self._same_object(mention)
                found, self.object_named = self._object_parts(frame, sense), True
            else:
                self.object_named = False
                if mention.relation is not None and mention.relation[1].pronoun and parts:
                    self.refs.last, self.refs.last_kind = [parts[-1]], parts[-1].kind  # "top-left key, the one right under it"
                found = only_part(self, frame, mention)
                if not found:
                    try:
                        found, notes = self.refs.resolve(mention, prefer=prefer)
                    except GroundingError as exc:
                        if (apart := side_apart(self.refs, frame, mention, exc)) is None and not stray(mention, exc, mentions, "" if frame.guessed_verb else frame.text):
                            raise
                        found, notes = apart or ([], [f"ignored the word '{mention.head}': it names no part of {self.asset.name}"])
                    self.notes.extend(notes)
                if (mention.plural or mention.collective) and len(found) > 1:
                    found = [p for p in found if p.joint not in self.excluded] or found  # "open every drawer except the top one"
                    self.refs.group = list(found)
            for part in mech.opened_through(found, VERBS[frame.verb].sense if frame.verb is not None and frame.verb in VERBS else sense,
                                            self.parts, self.asset):
                if part not in parts:
                    parts.append(part)
                    words.append(mention.words or mention.head)
        return parts, words

    # --- goals ---------------------------------------------------------------------
    def moves(self, frame: Frame, sense: VerbSense, parts: list[Part], words: list[str], role: str | None) -> list[Move]:
        out = []
        for part, said in zip(parts, words, strict=True):
            own_role = role or ("control" if mech.is_control(part) else "direct")
            choice = goal_for(frame, sense, part, self.tracker)
            self.notes.extend(choice.notes)
            amount = frame.quantities.amount
            loose = amount is not None and amount.loose
            if loose and amount is not None and choice.goal.amount is not None:
                self.notes.append(f"read '{amount.words}' as {amount.value:.0%} of the way for {part.link}")
            limit = beyond_limit(choice.goal, part, self.tracker)
            value, low, high = choice.goal.value, part.geometry.lower, part.geometry.upper
            if choice.goal.state == "value" and value is not None and low is not None and high is not None and not low - 1e-9 <= value <= high + 1e-9:
                limit = min(max(value, low), high)
            if limit is not None and choice.goal.state in ("cw", "ccw") and frame.quantities.sense is None:
                flipped = choice.goal.model_copy(update={"state": "ccw" if choice.goal.state == "cw" else "cw"})
                if abs(limit - self.tracker.value(part.joint)) <= 1e-6 and beyond_limit(flipped, part, self.tracker) is None:
                    self.notes.append(f"turned {part.link} ({part.joint}) {flipped.state}: it cannot turn {choice.goal.state} from where it is")
                    choice, limit = replace(choice, goal=flipped), None
            if limit is not None and impossible(choice.goal, part, self.tracker, limit):
                raise self.refs.refuse(f"'{frame.text}': {part.link} ({part.joint}) can move only "
                                       f"{shown(travel_left(choice.goal, part, self.tracker, limit), choice.goal.unit)} that way "
                                       f"(it stops at {limit:.4g}), not {shown(choice.goal.amount or 0.0, choice.goal.unit)}; say 'all the way' to take it to its stop")
            if limit is not None:
                self.notes.append(f"{part.link} ({part.joint}) cannot go that far: it stops at its limit {limit:.4g}")
            out.append(Move(part, own_role, choice.goal, words=said, loose=loose))
        return out

    def frame_sense(self, frame: Frame, *, means: bool = False) -> VerbSense:
        if frame.particle == "back" and frame.sense in (VerbSense.OPEN, VerbSense.RECLINE, VerbSense.RAISE) and frame.themes:
            try:
                parts, _ = self.ground(frame, VerbSense.RETURN, frame.themes)
            except GroundingError:
                parts = []
            moved = any(abs(self.tracker.value(p.joint) - p.geometry.rest) > 1e-6 or self.worked_before(p) for p in parts)
            if parts and all(mech.is_control(p) for p in parts) and moved:
                return VerbSense.RETURN  # "flip the switch back": a control goes back, a lid flips open
        if frame.sense is VerbSense.RELEASE and not means and frame.themes and not frame.let:
            # "release the door (by pressing the button)": a door is released by popping it open
            try:
                parts, _ = self.ground(frame, VerbSense.RELEASE, frame.themes)
            except GroundingError:
                parts = []
            if parts and not any(mech.is_control(p) for p in parts) and not any(p.joint in self.tracker.held for p in parts):
                return VerbSense.OPEN
        if frame.sense is not None:
            return frame.sense
        if frame.verb is None and not frame.returning:  # "screen down until it's shut", "drawer out 40 cm": the word says which way
            said = next((VERBLESS_SENSES[w] for w in frame.text.split() if w in VERBLESS_SENSES), None)
            if said is not None:
                return said
        return VerbSense.OPERATE

    # --- acts ----------------------------------------------------------------------
    def add(self, act: Act) -> None:
        self.notes.extend([act.note] if act.note else [])
        for exclusion in act.exclusions:
            exclude(self, exclusion)
        act = means_on_goal(self, act)
        goal = act.goal
        sense = self.frame_sense(goal)
        if goal.guessed_verb:
            self.notes.append(f"read the verb '{goal.guessed_verb}' as '{sense.value}' (not a verb the agent knows)")
        if act.condition:
            condition(self, act)
            return
        if goal.verb is None and not goal.wish and (not goal.themes or self._nothing_known(goal)):
            self.notes.append(f"ignored '{goal.text}' (no action found)")
            return
        if sense is VerbSense.GRASP and act.means is not None and act.means.verb is not None:
            self.notes.append(f"ignored the purpose '{goal.text}': choosing moves nothing by itself")  # "twist the dial to choose a program"
            return self.add(replace(act, goal=act.means, means=None))
        if seq.object_result(self, act) or take_hold(self, goal, sense) or seq.everything(self, act) or seq.lock_object(self, act):
            return
        if sense is VerbSense.HOLD and hold(self, act):
            return
        if goal.let and goal.verb in ("roll", "coast", "glide", "slide") and self.steps and self.steps[-1].base is not None:
            coast(self, goal)
            return
        if goal.codes and act.means is None and goal.verb in CODE_VERBS and seq.is_code(self, goal):
            seq.enter_code(self, act)
            return
        if act.means is None and self.is_object_motion(goal):
            seq.object_motion_act(self, act)
            return
        if goal.first is not None and act.means is None:
            seq.first_then_rest(self, act)
            return
        if act.means is None and ((goal.in_turn is not None and (any(m.plural or m.collective for m in goal.themes) or len(goal.themes) > 1)) or seq.keys_listed(goal) or seq.alternating(goal)):
            seq.in_turn(self, act)
            return
        if act.means is not None and self._aimless(goal):
            self.notes.append(f"ignored the purpose '{goal.text}': it names no part of {self.asset.name}")
            self.add(replace(act, goal=act.means, means=None))
            return
        controls: list[Move] = []
        prefer = self._described(goal)
        if act.means is not None:
            means_sense = self.frame_sense(act.means, means=True)
            parts, words = self.ground(act.means, means_sense, act.means.themes)
            controls = self.moves(act.means, means_sense, parts, words, "control")
        elif goal.instruments:
            controls = self._instrument_controls(goal)
        effects_parts, effect_words = restated_means(self, act, controls, self.ground(goal, sense, goal.themes, prefer=prefer))
        if not effects_parts and not goal.themes and not controls:
            implied = self._object_parts(goal, sense) if goal.verb is not None and goal.verb in VERBS and VERBS[goal.verb].implies else []  # "flush!"
            effects_parts = implied or self.refs.pronoun(release=sense is VerbSense.RELEASE)
            effect_words = ["it"] * len(effects_parts)
        effects_parts, effect_words = (effects_parts, effect_words) if effects_parts or controls or goal.themes else sole_fit(self, goal)
        if not effects_parts and not controls:
            raise self.refs.refuse(f"nothing in '{goal.text}' names a part to move")
        if sense is VerbSense.RELEASE and effects_parts and all(mech.is_control(p) for p in effects_parts) and not any(
                self.pressed(p) or self.worked_before(p) for p in effects_parts):
            sense = VerbSense.OPERATE  # "after releasing the latch knob": nothing held it, so releasing means working it
        check_motion(self.refs, goal, effects_parts, " ".join(r.text for r in act.results))
        if (kept := [p for p in effects_parts if p.joint in self.excluded and self.excluded_as.get(p.joint) is p.kind]) and len(effects_parts) == 1 and (
                len(goal.themes) == 1 and goal.themes[0].kind not in (None, kept[0].kind)):  # "raise the toilet seat, leave the lid": the seat would be the lid
            raise self.refs.refuse(f"'{goal.text}' would move {kept[0].link} ({kept[0].joint}), the part the prompt keeps still")
        check_detached(self.refs, goal, effects_parts)
        check_press(self.refs, self.tracker, goal, sense, effects_parts, self.notes)
        if elaborates(self, act, sense, effects_parts):
            return
        self.mentioned.update(p.joint for p in (*effects_parts, *(m.part for m in controls)))
        role = "effect" if controls else None
        effects = self.moves(goal, sense, effects_parts, effect_words, role)
        self.complete(act, sense, controls, effects)

    def is_object_motion(self, frame: Frame) -> bool:
        targets = list(frame.themes)
        if not targets:
            return (not self.parts and frame.verb is not None) or (self.refs.last_object and frame.verb in VERBS and frame.sense is not None
                                                                   and frame.quantities.amount is not None and not frame.instruments)
        first = targets[0]
        if first.is_object and first.sides and openable(self.parts):
            return False  # "lower the front half of the suitcase": the part on that side
        implied = VERBS[frame.verb].implies if frame.verb is not None and frame.verb in VERBS else ()
        if first.is_object and (any(self.refs.of_kind(kind) for kind in implied) or starts(frame)):
            return False  # "start the toaster", "flush the toilet", "run the dishwasher": the part the verb works
        if first.is_object:
            self._same_object(first)
            amount = frame.quantities.amount
            if self.tracker.obj.category in OPERATED_OBJECTS and (frame.sense in (VerbSense.TURN, VerbSense.SWITCH_ON, VerbSense.SWITCH_OFF) or (
                    amount is not None and amount.unit == "fraction")) and not WHOLE_WORDS & set(first.words.split()):
                return False  # "turn on the tap", "Tap: fully to the left": its lever
            return moves_object(frame, pronoun=False, after_part=False) and not (
                frame.sense in (VerbSense.OPEN, VerbSense.CLOSE) and openable(self.parts))
        if first.pronoun and starts(frame):
            return False  # "the dishwasher is loaded - get it running": it runs, it does not move
        if first.pronoun:
            amount = frame.quantities.amount  # "close the laptop, then push it back 20 cm": the laptop, not its screen
            if self.refs.last_object or (self.object_named and amount is not None and amount.unit == "m" and frame.particle in ("back", "forward", "away")):
                return moves_object(frame, pronoun=True, after_part=False) or frame.returning
            if frame.sense in (VerbSense.YAW, VerbSense.SPIN) and frame.particle in ("around", "round") and frame.quantities.amount is None and (
                    frame.verb is not None and frame.verb in VERBS and VERBS[frame.verb].object_sense is VerbSense.YAW) and not any(
                    p.geometry.type == "continuous" or mech.is_control(p) for p in self.refs.last):
                return True  # "spin it round so the other side faces me": only the object turns around (a knob would be "it")
            if self.refs.topic:
                return False  # "Bucket handle: let it fall toward the front": the part the heading named
            after_part = bool(self.refs.last)
            return moves_object(frame, pronoun=True, after_part=after_part) and (after_part or not self.parts or frame.verb in ("push", "move", "yaw"))
        return False

    def _same_object(self, mention: Mention) -> None:
        """"open the trunk" on a microwave names some other object: refuse rather than guess."""
        category = self.tracker.obj.category
        if names_other_object(mention.head, category, " ".join(mention.modifiers)):
            raise self.refs.refuse(f"'{mention.words or mention.head}' does not name {self.asset.name} (a {category}): "
                                   f"say 'the {category}' or name one of its parts")

    def worked_before(self, part: Part) -> bool:
        """An earlier step pressed or turned this control (it may have sprung back since)."""
        return any(m.joint == part.joint and m.goal.state != "rest" for step in self.steps for m in step.controls)

    def pressed(self, part: Part) -> bool:
        return abs(self.tracker.value(part.joint) - part.geometry.rest) > REACHED

    def _nothing_known(self, frame: Frame) -> bool:
        """"It's getting drafty", "check on the roast": no verb we know, and no part or object named."""
        return all(m.kind is None and not m.is_object and not m.pronoun and not m.anaphor and not self.refs.ground(m).parts
                   for m in frame.themes)

    def _aimless(self, frame: Frame) -> bool:
        """"... to start the wash", "... to make toast": a purpose that names no part (only what the object does), or
        only a control standing in for a kind the asset lacks ("crank the handle to pull the bolts": a safe has no latch)."""
        themes = [(m, self.refs.ground(m)) for m in frame.themes if not m.pronoun and not m.is_object]
        return bool(themes) and all(not f.parts if m.kind is None else f.how == "related" and all(
            p.kind is not None and info(p.kind).control for p in f.parts) for m, f in themes)

    def _described(self, frame: Frame) -> list[Part] | None:
        """"the door with the handle", "the one with the knob": parts whose own (mesh) names contain a word of
        an instrument phrase that is not a movable part."""
        words = {m.head for m in frame.instruments if not self.refs.ground(m).parts}
        if not words:
            return None
        from app.engine.offline.naming import link_words

        return [p for p in self.parts if link_words(self.asset, p.link) & words] or None

    def _instrument_controls(self, frame: Frame) -> list[Move]:
        """"open the microwave with its release button": a control named as the tool is the means."""
        out: list[Move] = []
        for mention in frame.instruments:
            if mention.kind is None or not info(mention.kind).control:
                if frame.sense in (VerbSense.LOCK, VerbSense.UNLATCH) and mention.kind is None and not self.refs.ground(mention).parts and not (
                        self._described(frame)):
                    raise self.refs.refuse(f"'{frame.text}': {self.asset.name} has no movable {mention.head} to do it with")
                continue
            found = self.refs.ground(mention)
            if not found.parts:
                if frame.sense in (VerbSense.LOCK, VerbSense.UNLATCH):
                    raise self.refs.refuse(f"'{frame.text}': {self.asset.name} has no movable {mention.head} to do it with")
                self.notes.append(f"ignored the {mention.head}: not a movable part of {self.asset.name}")
                continue
            plain = replace(frame, quantities=Quantities(speed_factor=frame.quantities.speed_factor))  # the amount is the goal's
            out.extend(self.moves(plain, VerbSense.OPERATE, list(found.parts), [mention.words] * len(found.parts), "control"))
        return out

    def reached(self, move: Move) -> bool:
        now = self.tracker.value(move.part.joint)
        value = resolve(move.goal, move.part.geometry, self.tracker.obj, self.asset, now, self.tracker.before.get(move.part.joint)).value
        return value is not None and abs(value - now) < REACHED

    # --- completion ----------------------------------------------------------------
    def complete(self, act: Act, sense: VerbSense, controls: list[Move], effects: list[Move], why: Why = "asked") -> None:
        from app.engine.offline.completion import complete

        complete(self, act, sense, controls, effects, why)

    def append(self, act: Act, sense: VerbSense, controls: list[Move], effects: list[Move], *, base: BaseMotion | None = None,
                why: Why = "asked", parallel: bool | None = None) -> None:
        frame = act.goal
        quantities = frame.quantities
        means_speed = act.means.quantities.speed_factor if act.means is not None else 1.0
        speed = quantities.speed_factor if quantities.speed_factor != 1.0 else means_speed
        duration = quantities.duration_s if (base is not None or effects or controls) and quantities.duration_s else None
        if act.means is not None and act.means.quantities.duration_s and not duration:
            duration = None
        hold = act.hold_s + (duration if frame.hold and duration else 0.0)
        if act.means is not None and act.means.hold and act.means.quantities.duration_s and controls and not frame.hold:
            hold += act.means.quantities.duration_s  # "press and hold the button for 3 seconds to reset it": the control is held
        if frame.hold and duration:
            duration = None
        if duration is not None and duration > MAX_STEP_S:
            self.notes.append(f"'{frame.text}': a step lasts at most {MAX_STEP_S:g} s; took {MAX_STEP_S:g} s, not {duration:g} s")
            duration = MAX_STEP_S
        step = ContractStep(
            id=f"S{len(self.steps) + 1}", op=sense.value, why=why, clause=frame.clause if why == "asked" else None,
            start="with_previous" if (act.parallel if parallel is None else parallel) and self.steps else "after_previous",
            wait_before_s=act.wait_before_s if why == "asked" else 0.0,
            controls=[self.joint_move(m) for m in controls], effects=[self.joint_move(m) for m in effects], base=base,
            speed_factor=speed, duration_s=duration, hold_s=hold,
        )
        self.steps.append(step)
        try:
            resolved = self.tracker.apply(step)
        except GroundingError as exc:  # a goal the part cannot reach ("open the turntable")
            raise self.refs.refuse(f"'{frame.text}': {exc}") from None
        self.explanation.record(act, step, resolved, [m.words for m in (*controls, *effects)])

    def joint_move(self, move: Move) -> JointMove:
        now = self.tracker.value(move.part.joint)
        value = resolve(move.goal, move.part.geometry, self.tracker.obj, self.asset, now, self.tracker.before.get(move.part.joint)).value
        return JointMove(joint=move.part.joint, link=move.part.link, role=move.role, goal=move.goal, release=move.release,  # type: ignore[arg-type]
                         q=None if value is None else round(float(value), 9))
