"""What the agent understood, per clause: words -> link/joint, the goal and what it is measured
from, the order, and why each part moves (asked, or the mechanism). Goes into report.json's
``understanding`` and one line per step on the CLI.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from app.engine.asset.model import ArticulatedAsset
from app.engine.contracts.steps import Goal, JointMove
from app.engine.contracts.steps import Step as ContractStep
from app.engine.offline.geometry import ObjectGeometry
from app.engine.offline.intent import Step
from app.engine.offline.reading.acts import Act


def goal_text(goal: Goal, prismatic: bool) -> str:
    """"open", "45 deg from closed", "half of the way to open", "back to where it was"."""
    if goal.state == "velocity":
        return f"spin at {goal.omega_radps:.3g} rad/s for {goal.duration_s:.3g} s"
    if goal.state == "previous":
        return "back to where it was"
    if goal.state == "value":
        return f"to {goal.value:.4g}"
    if goal.amount is None or goal.unit is None:
        return {"rest": "back to rest", "cw": "clockwise to its limit", "ccw": "counter-clockwise to its limit"}.get(goal.state, goal.state)
    if goal.unit == "fraction":
        return f"{goal.amount:.3g} of the way from {goal.measured_from} to {goal.state}"
    amount = f"{math.degrees(goal.amount):.4g} deg" if goal.unit == "rad" else f"{goal.amount * 100:.4g} cm"
    toward = {"cw": "clockwise", "ccw": "counter-clockwise"}.get(goal.state, f"toward {goal.state}")
    origin = "from closed" if goal.measured_from == "closed" else "from where it is" if goal.measured_from == "current" else "from rest"
    return f"{amount} {toward}, {origin}" if prismatic or goal.unit == "rad" else f"{amount} {toward}"


@dataclass
class Explanation:
    asset: ArticulatedAsset
    obj: ObjectGeometry
    clauses: dict[int, dict[str, Any]] = field(default_factory=dict)
    last: dict[str, Any] | None = None

    def record(self, act: Act, step: ContractStep, resolved: Step, words: list[str]) -> None:
        clause = act.goal.clause
        entry = self.clauses.setdefault(clause, {"clause": clause, "text": act.goal.text, "steps": []})
        if act.means is not None:
            entry["means"] = act.means.text
        moves = []
        said = iter(words)
        for move, goal in zip([*step.controls, *step.effects], [*resolved.controls, *resolved.effects], strict=True):
            moves.append(self._move(move, goal.value, goal.start, next(said, "")))
        record: dict[str, Any] = {"step": step.id, "why": step.why, "start": step.start, "moves": moves}
        if step.base is not None:
            record["base"] = {"axis_world": step.base.axis_world, "distance_m": step.base.distance_m, "yaw_deg": round(math.degrees(step.base.yaw_rad), 3)}
        if step.wait_before_s:
            record["wait_before_s"] = step.wait_before_s
        if step.hold_s:
            record["hold_s"] = step.hold_s
        entry["steps"].append(record)
        self.last = record

    def _move(self, move: JointMove, value: float | None, start: float | None, words: str) -> dict[str, Any]:
        prismatic = self.asset.joints[move.joint].type == "prismatic"
        out: dict[str, Any] = {"words": words, "link": move.link, "joint": move.joint, "role": move.role, "goal": goal_text(move.goal, prismatic),
                               "measured_from": move.goal.measured_from if move.goal.amount is not None else None}
        if value is not None:
            out["value"] = round(value, 6)
        if start is not None:
            out["from_value"] = round(start, 6)
        if move.release != "stays":
            out["then"] = {"self_return": "springs back", "held": "held while its effect lasts"}[move.release]
        return out

    def add_to_last(self, moves: list[JointMove], starts: list[float], words: list[str]) -> None:
        """Effects merged into the step recorded last ("turn the latch, then open the door": one causal step)."""
        if self.last is not None:
            self.last["moves"].extend(self._move(m, m.q, start, said) for m, start, said in zip(moves, starts, words, strict=True))

    def restate_base(self, step: ContractStep) -> None:
        """A step's whole-object motion revised after it was recorded ("pick it up and hold it 1 m off the ground")."""
        for entry in self.clauses.values():
            for record in entry["steps"]:
                if record["step"] == step.id and step.base is not None:
                    record["base"] = {"axis_world": step.base.axis_world, "distance_m": step.base.distance_m,
                                      "yaw_deg": round(math.degrees(step.base.yaw_rad), 3)}

    def because(self, reasons: dict[str, str]) -> None:
        if self.last is None:
            return
        for move in self.last["moves"]:
            if move["joint"] in reasons:
                move["because"] = reasons[move["joint"]]

    def entries(self) -> list[dict[str, Any]]:
        return [self.clauses[k] for k in sorted(self.clauses)]


def lines(understanding: list[dict[str, Any]]) -> list[str]:
    """One line per step for the CLI: "S1 [asked] open the door: door (link_0/joint_0) open -> 1.571"."""
    out = []
    for entry in understanding:
        for step in entry.get("steps", []):
            parts = []
            for move in step.get("moves", []):
                value = f" -> {move['value']:.4g}" if "value" in move else ""
                said = f"'{move['words']}' = " if move.get("words") else ""
                reason = f" ({move['because']})" if "because" in move else ""
                parts.append(f"{said}{move['link']}/{move['joint']} {move['goal']}{value}{reason}")
            if "base" in step:
                base = step["base"]
                parts.append(f"whole object {base['distance_m']:g} m along {base['axis_world']}" if base["distance_m"] else f"whole object yaw {base['yaw_deg']:g} deg")
            timing = " (with the previous step)" if step.get("start") == "with_previous" else ""
            out.append(f"{step['step']} [{step['why']}] '{entry['text']}'{timing}: " + "; ".join(parts))
    return out
