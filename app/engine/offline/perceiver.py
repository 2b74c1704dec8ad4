"""Offline perceiver: prompt + asset -> :class:`Intent` (and from it Causal.json).

Deterministic rules over the parsed prompt and the asset's geometry:
- parts are grounded from every name source with spatial qualifiers;
- targets come from geometry (which limit is open, pressed, up);
- causal knowledge: a pedal opens (and holds) a lid; a release button opens a door or lid;
  a handle, latch or knob on a door is operated before the door opens; wheels roll when the
  whole object moves;
- control return: buttons, pedals, handles self-return unless that would undo the result;
  knobs, levers and switches stay.
A prompt that cannot be grounded raises :class:`GroundingError` listing the movable parts.
"""

from __future__ import annotations

import logging
import re
from dataclasses import replace

import numpy as np

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import GroundingError
from app.engine.offline.base_motion import base_goal
from app.engine.offline.coupling import couple_amounts
from app.engine.offline.geometry import ObjectGeometry, analyse
from app.engine.offline.grounding import Part, ground_mention, movable_parts, openable_parts
from app.engine.offline.intent import BaseGoal, Intent, JointGoal, Step
from app.engine.offline.language import Action, Clause, Mention, ParsedPrompt, parse_prompt
from app.engine.offline.quantities import Quantity
from app.engine.offline.targets import effective_kind, goal_value, spin_omega, target_expression
from app.engine.offline.vocabulary import CONTROL_CATEGORIES, CONTROL_RETURN, HINGED, OBJECT_WORDS, UNLATCH_CATEGORIES

logger = logging.getLogger(__name__)

BASE_KINDS = frozenset({"move", "press", "pull_out", "raise", "lower", "push_in", "spin"})
RELEASE_WORDS = frozenset({"release", "open", "opener", "door", "eject", "unlock"})
RELEASE_BUTTON_OBJECTS = frozenset({"microwave", "kettle", "cooker", "rice", "oven"})
REACHED_TOLERANCE = 1e-6
PRONOUNS = frozenset({"it", "them", "one"})
EVERYTHING = re.compile(r"\b(?:everything|all (?!the way)\w+|all$|every (?:door|drawer|lid|part))")
MANUAL = re.compile(r"\b(?:by hand|manually|with (?:my|your|one|a) hand|without (?:using |pressing |touching )?the)\b")
SWITCHED = re.compile(
    r"\b(?:turn|switch|flip|toggle|twist|put|shut)(?:s|ed|ing)?\s+(on|off)\b"
    r"|\b(?:turn|switch|flip|toggle|twist|put|shut)(?:s|ed|ing)?\s+(?:[a-z'-]+\s+){1,3}?(on|off)\s*(?:$|[,.;]|\b(?:and|then|again|fully|completely|now)\b)"
)
""""turn on the tap", "switch the light off": the object's control to its on / off state."""
SCREW_AXIS_MIN_UP = 0.7
"""|axis . up| above this: a lid turning about a vertical axis is a screw cap."""
DEFAULT_PAUSE_S = 1.0
"""A "wait" without a length."""
DISPLACING_VERBS = frozenset({"push", "hit", "punch", "kick", "shove", "nudge"})
"""Press-type verbs that also move a whole object that is free to move."""
RETURN = re.compile(r"\bback (?:down|to rest)\b")
"""A motion back to where the part (or object) started."""
TO_DISTANCE = re.compile(r"\bto (?:a height of |a point )?\d+(?:\.\d+)?\s*(?:mm|cm|m|millimet|centimet|met|inch|in)\w*\b")
"""A distance that is an end position ("lower it to 10 cm"), not an increment."""
HINGE_VERBS = frozenset({"fold", "swing", "tilt", "unfold"})
"""Verbs of rotation about a hinge."""
SLIDE_VERBS = frozenset({"slide"})
"""Verbs of straight-line motion."""
OBJECT_VERBS = frozenset({"roll", "drag", "carry", "pick", "transport", "drive", "move", "lift", "shove", "wheel", "tow"})


class _Builder:
    def __init__(self, asset: ArticulatedAsset, parsed: ParsedPrompt) -> None:
        self.asset = asset
        self.parsed = parsed
        self.obj: ObjectGeometry = analyse(asset)
        self.parts = movable_parts(asset, self.obj)
        self.words = set(re.findall(r"[a-z]+", parsed.text))
        self.steps: list[Step] = []
        self.notes: list[str] = []
        self.mentioned: set[str] = set()
        self.sustained: dict[str, JointGoal] = {}
        self.last_parts: list[Part] = []
        self.last_controls: list[Part] = []
        self.head_of: dict[str, str] = {}
        self.clause_text = ""
        self.implicit_effects_at: dict[str, int] = {}
        self.implicit_from: dict[str, float | None] = {}
        """Where each implied effect started: a later clause stating that effect measures its amount from there."""
        self.state: dict[str, float] = {}
        self.unlatched: list[Part] = []
        self.last_base_quantified = True
        self.pauses: dict[int, float] = {}
        self.index = 0

    # --- grounding -----------------------------------------------------------------
    def refuse(self, why: str) -> GroundingError:
        movable = [p.describe(self.asset) for p in self.parts]
        listing = "; ".join(movable) if movable else "none"
        return GroundingError(f"{why}. Movable parts of {self.asset.name}: {listing}", movable_parts=movable)

    def ground(self, mention: Mention, kind: str | None) -> list[Part]:
        """Parts a mention refers to ([] when it names nothing movable)."""
        if mention.category == "object" and mention.head in PRONOUNS and self.last_parts:
            if kind == "release" and self.last_controls:
                return list(self.last_controls)
            return list(self.last_parts)
        if mention.category == "object":
            openable = openable_parts(self.parts)
            if kind in ("open", "close") and openable:
                return openable if mention.plural or EVERYTHING.search(self.clause_text) else openable[:1]
            if kind in ("open", "close"):
                caps = [p for p in self.parts if self._is_screw_cap(p)]
                if caps:  # "open the bottle": its cap unscrews
                    return caps if mention.plural or EVERYTHING.search(self.clause_text) else caps[:1]
            if self._switched(self.clause_text) is not None:
                controls = [p for p in self.parts if p.category in CONTROL_CATEGORIES]
                if len(controls) == 1:  # "turn on the tap": the object's only control
                    return controls
            return []
        if mention.size is None and mention.head.startswith("dial") and "handle" in self.words:
            mention = replace(mention, size="small")  # a dial named beside a handle is the smaller of the two
        found = ground_mention(mention, self.asset, self.obj, self.parts, self.words)
        if len(found) > 1 and not mention.plural:
            return found
        others = [p for p in ground_mention(replace(mention, plural=True), self.asset, self.obj, self.parts, self.words)
                  if self.head_of.get(p.joint, mention.head) == mention.head]
        if found and others and found[0].joint in self.head_of and self.head_of[found[0].joint] != mention.head:
            found = others[:1]  # "the dial ... the handle": different words name different parts
        for part in found:
            self.head_of.setdefault(part.joint, mention.head)
        return found

    # --- goals ---------------------------------------------------------------------
    @staticmethod
    def _switched(text: str) -> str | None:
        """``on`` / ``off`` when the clause switches something on or off."""
        match = SWITCHED.search(text)
        return None if match is None else (match.group(1) or match.group(2))

    def _is_screw_cap(self, part: Part) -> bool:
        """A lid with no open side that turns about the vertical: opening it means unscrewing it."""
        geometry = part.geometry
        return (part.category == "lid" and geometry.open_value is None and geometry.type in ("revolute", "continuous")
                and abs(float(geometry.axis_world @ self.obj.up)) > SCREW_AXIS_MIN_UP)

    def goal(self, part: Part, clause: Clause, role: str, quantity: Quantity) -> JointGoal:
        kind = clause.kind or "operate"
        effective = effective_kind(kind, clause.particle)
        if effective in ("open", "close") and quantity.sense is None and self._is_screw_cap(part):
            # a screw cap opens by unscrewing (counter-clockwise from above) and closes by screwing it on
            kind, quantity = "turn", replace(quantity, sense="ccw" if effective == "open" else "cw")
        switched = self._switched(clause.text) if part.category in CONTROL_CATEGORIES else None
        if switched == "off":
            # "turn off the tap": the control goes back to its rest (off) state
            now = self.state.get(part.joint, part.geometry.rest)
            if abs(now - part.geometry.rest) < REACHED_TOLERANCE:
                self.notes.append(f"{part.joint} is already off (at rest)")
            return JointGoal(part.joint, part.link, part.category, role, value=part.geometry.rest,  # type: ignore[arg-type]
                             expr=target_expression(part.geometry, part.geometry.rest), returns="stays")
        current = self.state.get(part.joint)
        if self.implicit_effects_at.get(part.joint) == len(self.steps) - 1:
            # "depress the pedal halfway; the lid lifts about 40 degrees": the stated effect replaces the implied one
            current = self.implicit_from.get(part.joint)
        value = goal_value(kind, clause.particle, part, quantity, self.obj, self.asset, current)
        if (value is not None and quantity.distance_m is not None and part.geometry.type == "prismatic" and TO_DISTANCE.search(clause.text)
                and part.geometry.lower is not None and part.geometry.upper is not None):
            # "lower it to 10 cm": a distance after "to" is where the part ends, measured from where it rests
            far = part.geometry.upper if abs(part.geometry.upper - part.geometry.rest) >= abs(part.geometry.lower - part.geometry.rest) else part.geometry.lower
            value = float(np.clip(part.geometry.rest + np.sign(far - part.geometry.rest) * quantity.distance_m, part.geometry.lower, part.geometry.upper))
        if RETURN.search(clause.text) and not _has_amount(quantity) and part.joint in self.state:
            value = part.geometry.rest  # "lower it back down", "reopen it back to rest": to where it started
        returns = CONTROL_RETURN.get(part.category or "", "stays") if role == "control" else "stays"
        if returns == "self_return" and (quantity.orientation is not None or (part.category == "handle" and not self._on_hinged(part))):
            returns = "stays"  # a requested end state, or a carry handle (a bucket's), is kept
        if value is None:
            omega, _ = spin_omega(part, quantity, self.obj)
            return JointGoal(part.joint, part.link, part.category, role, omega=omega, returns="stays")  # type: ignore[arg-type]
        if part.geometry.type != "continuous" and abs(value - part.geometry.rest) < 1e-9 and kind not in ("close", "release", "push_in", "lower"):
            self.notes.append(f"{part.joint} is already at the requested state")
        return JointGoal(part.joint, part.link, part.category, role, value=value, expr=target_expression(part.geometry, value), returns=returns)  # type: ignore[arg-type]

    def _names_the_only_part(self, clause: Clause) -> bool:
        """An unknown part name is read as the asset's only movable part only when the prompt ties it
        to the object ("the stapler's staple magazine") and the verb fits that part; never a bare guess."""
        part = self.parts[0]
        kind = effective_kind(clause.kind, clause.particle)
        possessed = bool(re.search(r"\b(?:" + "|".join(sorted(OBJECT_WORDS)) + r")(?:'s\b|\s+\w+\s+of\b)", clause.text)) or bool(
            re.search(r"\b(?:of|on) (?:the|this) (?:" + "|".join(sorted(OBJECT_WORDS)) + r")\b", clause.text))
        fits = kind in ("open", "close", "raise", "lower", "pull_out", "push_in") and part.geometry.open_value is not None
        if kind in ("pull_out", "push_in") and part.geometry.type != "prismatic":
            fits = False  # "eject the laptop's battery": pulling something out is not swinging a hinged part
        return possessed and fits

    def _on_hinged(self, part: Part) -> bool:
        joint = self.asset.joints[part.joint]
        parent = next((p for p in self.parts if p.link == joint.parent), None)
        return parent is not None and parent.category in HINGED

    def goals(self, clause: Clause, role: str | None, quantity: Quantity, *, required: bool = True) -> list[JointGoal]:
        """Goals of the parts a clause names; names that match nothing are ignored when others match."""
        parts: list[Part] = []
        missing: list[str] = []
        for mention in clause.mentions:
            if mention.instrument:
                continue
            found = self.ground(mention, clause.kind)
            if not found and mention.category != "object":
                missing.append(mention.head)
            parts.extend(p for p in found if p not in parts)
        if not parts and required and not missing:  # "unlatch the cupboard with the knob": the tool is what moves
            for mention in clause.mentions:
                if mention.instrument and mention.category != "object":
                    parts.extend(p for p in self.ground(mention, clause.kind) if p not in parts)
        if clause.kind == "unlatch" and clause.particle == "open" and any(p.category in HINGED for p in parts):
            clause = replace(clause, kind="open")  # "unlock the door, which swings open 60 degrees": the door opens too
        if clause.kind == "unlatch" or (clause.kind == "release" and re.search(r"\b(?:latch|lock|catch|bolts?)\b", clause.text)):
            hinged = [p for p in parts if p.category in HINGED]
            parts = [p for p in parts if p.category not in HINGED]  # "unlatch the door" does not move the door itself
            if hinged:
                self.unlatched = hinged  # "unlatch the door, then open it": "it" is the door
                if not parts and required:  # ... but its latch does
                    parts = [q for h in hinged for q in self.parts
                             if q.category in UNLATCH_CATEGORIES and q.joint != h.joint and q.link in self.asset.descendants(h.link)][:1]
        if not parts:
            if not required:
                return []
            if missing:
                raise self.refuse(f"the prompt mentions a {missing[0]}, but the asset has no such movable part")
            if len(self.parts) == 1 and self._names_the_only_part(clause):
                parts = list(self.parts)  # a name we do not know, on an object with one movable part
                self.notes.append(f"read '{clause.text}' as acting on {self.parts[0].describe(self.asset)}, the only movable part")
            elif clause.unknown_object:
                raise self.refuse(f"cannot find '{clause.unknown_object}' on the asset")
        elif missing:
            self.notes.append(f"ignored '{', '.join(missing)}': no such movable part")
        self.check_motion(clause, parts)
        out = []
        for part in parts:
            self.mentioned.add(part.joint)
            own_role = role or ("control" if part.category in CONTROL_CATEGORIES else "direct")
            out.append(self.goal(part, clause, own_role, quantity))
        return out

    def check_motion(self, clause: Clause, parts: list[Part]) -> None:
        """A verb that names a kind of motion the grounded part cannot make is not a guess to animate:
        "fold down the tray" on a part that only slides, "slide the sash 20 cm" on a part that only swings."""
        named = [p for p in parts if p.category not in CONTROL_CATEGORIES and p not in self.last_parts]
        if not named:
            return
        if clause.verb in HINGE_VERBS and all(p.geometry.type == "prismatic" for p in named):
            raise self.refuse(f"'{clause.verb}' swings a part about a hinge, but the {named[0].category or 'part'} found only slides")
        sliding = clause.verb in SLIDE_VERBS or re.search(r"\bsideways\b", clause.text)
        if sliding and clause.quantity.distance_m is not None and all(p.geometry.type != "prismatic" for p in named):
            raise self.refuse(f"'{clause.text}' slides a part in a straight line, but the {named[0].category or 'part'} found only rotates")

    def is_base(self, clause: Clause) -> bool:
        """Whole-object motion: the first thing the verb acts on is the object itself."""
        targets = [m for m in clause.mentions if not m.instrument]
        if not targets or targets[0].category != "object":
            return False
        pronoun = targets[0].head in PRONOUNS and bool(self.last_parts)
        quantity = clause.quantity
        directional = quantity.direction in ("forward", "backward", "left", "right") and clause.particle not in ("in", "out", "open", "shut")
        if pronoun and directional and self.steps and self.steps[-1].base is None and quantity.direction == "backward" and not re.search(r"\bbackwards?\b", clause.text):
            directional = False  # "slide it back halfway" after moving a part: the part goes back, not the object
        if pronoun and not (quantity.axis is not None or clause.verb in OBJECT_VERBS or directional):
            return False
        if clause.kind == "press" and clause.verb not in DISPLACING_VERBS and not (
                quantity.axis is not None or quantity.distance_m is not None or quantity.direction is not None):
            return False  # "squeeze the bottle", "tap the box": pressing in place does not carry the object away
        return clause.kind in BASE_KINDS or (clause.kind in ("open", "close") and not openable_parts(self.parts) and clause.particle in ("up", "down"))

    # --- causal knowledge ----------------------------------------------------------
    def implicit_controls(self, effects: list[JointGoal], kind: str | None, text: str = "") -> list[JointGoal]:
        if kind not in ("open", "raise") or not effects or MANUAL.search(text):
            return []
        lids = [g for g in effects if g.category in HINGED]
        if not lids:
            return []
        pedals = [p for p in self.parts if p.category == "pedal" and p.joint not in self.mentioned]
        if pedals and any(g.category == "lid" for g in lids):
            press = Clause(text="press", verb="press", kind="press", particle=None, mentions=(), quantity=Quantity())
            goal = self.goal(pedals[0], press, "control", Quantity())
            return [replace(goal, sustains=True, returns="stays")]
        buttons = [p for p in self.parts if p.category == "button" and p.joint not in self.mentioned and self._is_release(p)]
        if buttons:
            press = Clause(text="press", verb="press", kind="press", particle=None, mentions=(), quantity=Quantity())
            return [self.goal(buttons[0], press, "control", Quantity())]
        return []

    def _is_release(self, part: Part) -> bool:
        from app.engine.offline.naming import link_words

        return bool(link_words(self.asset, part.link, visuals=False) & RELEASE_WORDS)

    def implicit_effects(self, controls: list[JointGoal]) -> list[JointGoal]:
        """What a control causes on its own: pedal -> lid, release button -> door/lid."""
        effects: list[JointGoal] = []
        openable = [p for p in openable_parts(self.parts) if p.joint not in self.mentioned]
        for control in controls:
            part = next(p for p in self.parts if p.joint == control.joint)
            wanted: tuple[str, ...] = ()
            if control.category == "pedal":
                wanted = ("lid",)
            elif control.category == "button" and (self._is_release(part) or (self.obj.category in RELEASE_BUTTON_OBJECTS and len(openable) == 1)):
                wanted = HINGED
            targets = [p for p in openable if p.category in wanted]
            if targets:
                opening = Clause(text="open", verb="open", kind="open", particle=None, mentions=(), quantity=Quantity())
                effects.append(self.goal(targets[0], opening, "effect", Quantity()))
                self.mentioned.add(targets[0].joint)
        return effects

    def unlatch_controls(self, effects: list[JointGoal], kind: str | None) -> list[JointGoal]:
        """Handles, latches and knobs on a door or lid that must be operated before it opens."""
        if kind != "open":
            return []
        controls = []
        for goal in effects:
            if goal.category not in HINGED:
                continue
            door = self.obj.joints[goal.joint]
            now = self.state.get(goal.joint, door.rest)
            if door.closed_value is not None and abs(now - door.closed_value) > REACHED_TOLERANCE:
                continue  # already ajar: nothing holds it shut
            if any(p.joint in self.mentioned and p.category in UNLATCH_CATEGORIES and p.link in self.asset.descendants(goal.link) for p in self.parts):
                continue  # its latch was already worked ("unlock it with the handle, then open the door")
            for part in self.parts:
                below = part.link in self.asset.descendants(goal.link) and part.joint != goal.joint
                if below and part.category in UNLATCH_CATEGORIES and part.joint not in self.mentioned:
                    turn = Clause(text="unlatch", verb="unlatch", kind="unlatch", particle=None, mentions=(), quantity=Quantity())
                    controls.append(self.goal(part, turn, "control", Quantity()))
                    self.mentioned.add(part.joint)
        return controls

    # --- steps ---------------------------------------------------------------------
    def add(self, action: Action) -> None:
        clause = action.clause
        self.clause_text = clause.text
        quantity = replace(clause.quantity, speed_factor=clause.quantity.speed_factor if clause.quantity.speed_factor != 1.0 else self.parsed.quantity.speed_factor)
        if clause.kind is None and action.means is None and re.match(r"pause\b", clause.text):
            # "..., wait (2 seconds), then ...": the next step starts that much later
            self.pauses[len(self.steps)] = self.pauses.get(len(self.steps), 0.0) + (quantity.duration_s or DEFAULT_PAUSE_S)
            return
        if clause.kind is None and action.means is None:
            self.notes.append(f"ignored '{clause.text}' (no action found)")
            named = [p for m in clause.mentions if m.category != "object" for p in ground_mention(m, self.asset, self.obj, self.parts, self.words)]
            if named:  # "The top drawer is sticking out; push it shut."
                self.last_parts = named
            return
        if self.is_base(clause) and action.means is None:
            motion = base_goal(clause.verb, clause.particle, quantity, self.parsed.text, self.parts, self.obj)
            previous = self.steps[-1].base if self.steps else None
            if RETURN.search(clause.text) and quantity.distance_m is None and previous is not None:
                motion = replace(motion, distance_m=previous.distance_m)  # "lift it 10 cm and set it back down": the same way back
            quantified = quantity.distance_m is not None or quantity.duration_s is not None
            if self.elaborates(action, clause, motion, quantified):
                return
            self.last_base_quantified = quantified
            self.steps.append(Step(primitive=clause.verb or "move", base=motion, parallel=action.parallel, speed_factor=quantity.speed_factor, duration_s=quantity.duration_s))
            return
        means = action.means
        if means is not None and means.mentions and all(m.head in PRONOUNS for m in means.mentions):
            # "take the lid off by lifting it 15 cm": the means says how far the goal's part moves
            clause = replace(clause, quantity=means.quantity.merged(clause.quantity), particle=clause.particle or means.particle)
            quantity = replace(clause.quantity, speed_factor=quantity.speed_factor)
            means = None
        if means is None:
            means = self.instrument_means(clause)
        if means is not None and clause.kind == "release" and not re.search(r"\b(?:latch|lock|catch|bolts?)\b", clause.text):
            if self._opens_next():
                clause = replace(clause, kind="unlatch", verb="unlatch")  # "... to release it, then the door opens to 120 degrees"
            else:
                clause = replace(clause, kind="open", verb="open")  # "release the door by pressing the button": it pops open
        if means is not None and means.quantity.sense is None and clause.quantity.sense is not None:
            means = replace(means, quantity=replace(means.quantity, sense=clause.quantity.sense))  # "twist the cap to loosen it"
        kind = effective_kind(clause.kind, clause.particle)
        controls = self.goals(means, "control", means.quantity) if means else []
        effects = self.goals(clause, "effect" if controls else None, quantity, required=not controls)
        if clause.kind == "release":
            effects = self.release(self.hold_until_released(effects))
        if not controls and self.refine_implicit(effects):
            self.hold_for(clause, quantity)
            return
        implied: list[JointGoal] = []
        control_amount, effect_amount = _has_amount(means.quantity) if means else False, _has_amount(quantity)
        if controls and not effects:
            effects = implied = self.implicit_effects(controls)
            effect_amount = False
        if not controls:
            direct_controls = [g for g in effects if g.role == "control"]
            effects = [g for g in effects if g.role != "control"]
            implicit = self.implicit_controls(effects, kind, clause.text)
            if implicit:
                effects = [replace(g, role="effect") for g in effects]
            controls = direct_controls + implicit
            if direct_controls and not effects:
                effects = implied = self.implicit_effects(direct_controls)
                control_amount, effect_amount = effect_amount, False
        if not controls and not effects and self._unlocked_by_previous_control(clause):
            self.notes.append(f"read '{clause.text}' as the effect of the control operated before")
            self.last_parts, self.unlatched = list(self.unlatched), []
            return
        if not controls and not effects:
            raise self.refuse(f"nothing in '{clause.text}' names a part to move")
        controls, effects = self.drop_reached(controls), self.drop_reached(effects)
        if not controls and not effects:
            self.hold_for(clause, quantity)
            return
        for prerequisite in self.prerequisites(effects):
            self.steps.append(prerequisite)
        if not controls and not MANUAL.search(clause.text):
            controls = self.unlatch_controls(effects, kind)
            effects = [replace(g, role="effect") for g in effects] if controls else effects
        controls = self.sustain(controls, effects)
        controls, effects, coupled = couple_amounts(controls, effects, control_amount, effect_amount, self.parts, self.obj, self.asset)
        if coupled:
            self.notes.append(coupled)
        coupling = tuple(f"{c.category or c.link} ({c.joint}) drives {e.category or e.link} ({e.joint})" for c in controls for e in effects)
        if controls and effects and not implied and not effect_amount and kind not in ("open", "close", "raise", "lower", "pull_out", "push_in"):
            # "push the key so the door unlocks and swings open 30 degrees": the effect's end was not stated, a later amount refines it
            implied = list(effects)
        primitive = (means.verb if means else clause.verb) or clause.kind or "move"
        moved = effects or controls
        self.last_parts = [p for p in self.parts if any(g.joint == p.joint for g in moved)]
        if self.unlatched and not effects:
            self.last_parts = list(self.unlatched)
        self.unlatched = []
        self.last_controls = [p for p in self.parts if any(g.joint == p.joint for g in controls)]
        self.implicit_from.update({g.joint: self.state.get(g.joint) for g in implied})
        self.state.update({g.joint: g.value for g in moved if g.value is not None})
        for control in controls:  # a control that springs back ends at rest
            if control.returns == "self_return" and not control.sustains:
                self.state[control.joint] = self.asset.joints[control.joint].rest
        for implied_goal in implied:
            self.implicit_effects_at[implied_goal.joint] = len(self.steps)
        self.steps.append(
            Step(primitive=primitive, controls=tuple(controls), effects=tuple(effects), parallel=action.parallel,
                 speed_factor=quantity.speed_factor, duration_s=quantity.duration_s, coupling=coupling)
        )

    def _unlocked_by_previous_control(self, clause: Clause) -> bool:
        """ "Press the button; the door then unlocks and opens": a latch-less door unlocking right
        after a control was operated says what that control did, not a motion of its own."""
        named = [m for m in clause.mentions if not m.instrument]
        return (clause.kind == "unlatch" and bool(named) and all(m.category in HINGED for m in named)
                and bool(self.steps) and bool(self.steps[-1].controls))

    def _opens_next(self) -> bool:
        """The next action opens a part itself ("..., then the door opens to 120 degrees")."""
        actions = self.parsed.actions
        following = actions[self.index + 1] if self.index + 1 < len(actions) else None
        return following is not None and effective_kind(following.clause.kind, following.clause.particle) == "open"

    def hold_for(self, clause: Clause, quantity: Quantity) -> None:
        """"hold the lid open for two seconds": what it names is already there; the next step waits that long."""
        if clause.verb in ("hold", "keep", "leave") and quantity.duration_s:
            self.pauses[len(self.steps)] = self.pauses.get(len(self.steps), 0.0) + quantity.duration_s

    def elaborates(self, action: Action, clause: Clause, motion: BaseGoal, quantified: bool) -> bool:
        """ "Pick up the bucket and raise it 50 cm": a conjoined motion of the same object ("it") the
        same way only gives the distance of the previous, unquantified motion; it replaces it."""
        previous = self.steps[-1] if self.steps else None
        targets = [m for m in clause.mentions if not m.instrument]
        if (not action.conjoined or previous is None or previous.base is None or self.last_base_quantified or not quantified
                or not targets or targets[0].head not in PRONOUNS):
            return False
        if float(np.asarray(previous.base.axis) @ np.asarray(motion.axis)) < 1.0 - 1e-6:
            return False
        self.steps[-1] = replace(previous, base=replace(motion, coast=motion.coast or previous.base.coast))
        self.last_base_quantified = True
        self.notes.append(f"read '{clause.text}' as the distance of the previous motion")
        return True

    def instrument_means(self, clause: Clause) -> Clause | None:
        """ "Open the microwave with its release button": a control named as the tool is the means."""
        tools = [m for m in clause.mentions if m.instrument and m.category in CONTROL_CATEGORIES
                 and ground_mention(m, self.asset, self.obj, self.parts, self.words)]
        for mention in clause.mentions:  # "open the door with the handle": a tool the asset lacks only describes how
            if mention.instrument and mention.category in CONTROL_CATEGORIES and mention not in tools:
                self.notes.append(f"ignored the {mention.head}: not a movable part of the asset")
        targets = [m for m in clause.mentions if not m.instrument]
        if not tools or not targets:
            return None
        return Clause(text=clause.text, verb="operate", kind="operate", particle=None,
                      mentions=tuple(replace(m, instrument=False) for m in tools), quantity=Quantity())

    def drop_reached(self, goals: list[JointGoal]) -> list[JointGoal]:
        """Goals already met by the state the earlier steps left (an elaboration repeating them)."""
        kept = []
        for goal in goals:
            current = self.state.get(goal.joint)
            if goal.value is not None and current is not None and abs(goal.value - current) < REACHED_TOLERANCE:
                self.notes.append(f"{goal.joint} is already at {goal.value:.4g}")
                continue
            kept.append(goal)
        return kept

    def hold_until_released(self, goals: list[JointGoal]) -> list[JointGoal]:
        """ "... and only then let the knob turn back": a control released explicitly later is held
        until then instead of springing back on its own."""
        for goal in goals:
            for index, step in enumerate(self.steps):
                held = [replace(c, returns="stays") if c.joint == goal.joint and c.returns == "self_return" else c for c in step.controls]
                if held != list(step.controls):
                    self.steps[index] = replace(step, controls=tuple(held))
                    self.state[goal.joint] = next(c.value for c in held if c.joint == goal.joint and c.value is not None)
        return goals

    def refine_implicit(self, effects: list[JointGoal]) -> bool:
        """"Press the pedal: the lid opens to vertical" - the second clause states the effect the
        previous step already implied; update its target instead of adding a motion."""
        last = len(self.steps) - 1
        if not effects or any(self.implicit_effects_at.get(g.joint) != last for g in effects):
            return False
        step = self.steps[last]
        updated = {g.joint: g for g in effects}
        self.steps[last] = replace(step, effects=tuple(replace(updated[e.joint], role="effect") if e.joint in updated else e for e in step.effects))
        self.state.update({g.joint: g.value for g in effects if g.value is not None})
        for joint in updated:
            del self.implicit_effects_at[joint]
        return True

    def prerequisites(self, effects: list[JointGoal]) -> list[Step]:
        """State-dependent motion: open what stands in the way first (the door before the tray)."""
        from app.engine.offline.collisions import blocking_joints

        steps = []
        for goal in effects:
            if goal.value is None or goal.joint in self.state:
                continue
            for blocker in blocking_joints(self.asset, goal.joint, goal.value, self.state):
                part = next((p for p in self.parts if p.joint == blocker), None)
                if part is None or part.geometry.open_value is None or blocker in self.mentioned:
                    continue
                opening = Clause(text="open", verb="open", kind="open", particle=None, mentions=(), quantity=Quantity())
                first = self.goal(part, opening, "direct", Quantity())
                self.mentioned.add(blocker)
                self.state[blocker] = part.geometry.open_value
                latches = self.unlatch_controls([first], "open")
                effect = replace(first, role="effect") if latches else first
                steps.append(Step(primitive="open", controls=tuple(latches), effects=(effect,), coupling=(f"{blocker} must be open before {goal.joint} can move",)))
                self.notes.append(f"opened {part.link} first: it blocks {goal.link}")
        return steps

    def sustain(self, controls: list[JointGoal], effects: list[JointGoal]) -> list[JointGoal]:
        out = []
        for control in controls:
            if control.category == "pedal" and any(e.category in HINGED for e in effects):
                control = replace(control, sustains=True, returns="stays")
                for effect in effects:
                    self.sustained[effect.joint] = control
            out.append(control)
        return out

    def release(self, goals: list[JointGoal]) -> list[JointGoal]:
        """Releasing a sustaining control also lets what it holds fall back (a pedal's lid)."""
        extra = []
        for goal in goals:
            for effect_joint, control in list(self.sustained.items()):
                if control.joint == goal.joint:
                    part = next(p for p in self.parts if p.joint == effect_joint)
                    closing = Clause(text="close", verb="close", kind="close", particle=None, mentions=(), quantity=Quantity())
                    extra.append(self.goal(part, closing, "effect", Quantity()))
                    del self.sustained[effect_joint]
        return [replace(g, role="control") for g in goals] + extra


def _has_amount(quantity: Quantity) -> bool:
    """The clause says how far (a fraction, an angle, a distance or an end orientation)."""
    return any(v is not None for v in (quantity.fraction, quantity.angle_rad, quantity.distance_m, quantity.orientation))


def _merge_unlatch(steps: list[Step], asset: ArticulatedAsset) -> list[Step]:
    """"Turn the latch, then open the door": one causal step, so the latch returns while the door opens."""
    merged: list[Step] = []
    for step in steps:
        previous = merged[-1] if merged else None
        if (
            previous is not None and previous.controls and not previous.effects and previous.base is None
            and not step.controls and step.effects and step.base is None
            and all(c.category in UNLATCH_CATEGORIES for c in previous.controls)
            and all(any(c.link in asset.descendants(e.link) for e in step.effects) for c in previous.controls)
        ):
            effects = tuple(replace(e, role="effect") for e in step.effects)
            merged[-1] = replace(previous, effects=effects, coupling=previous.coupling + step.coupling, primitive=step.primitive)
            continue
        merged.append(step)
    return merged


def read_intent(prompt: str, asset: ArticulatedAsset) -> Intent:
    """Deterministic reading of ``prompt`` on ``asset``.

    Raises
    ------
    GroundingError
        Nothing in the prompt maps to a movable part (the message lists them).
    """
    parsed = parse_prompt(prompt)
    builder = _Builder(asset, parsed)
    if not builder.parts and not any(builder.is_base(action.clause) and action.means is None for action in parsed.actions):
        raise GroundingError(f"{asset.name} has no movable parts to animate", movable_parts=[])
    for index, action in enumerate(parsed.actions):
        builder.index = index
        builder.add(action)
    if not builder.steps:
        raise builder.refuse(f"could not find an action in '{prompt}'")
    steps = [replace(step, pause_before_s=builder.pauses[index]) if index in builder.pauses else step for index, step in enumerate(builder.steps)]
    return Intent(prompt=prompt, steps=tuple(_merge_unlatch(steps, asset)), notes=tuple(builder.notes))
