"""What the critic checks an execution against: the expected motion of each joint, typed.

The critic (geometric or model) never reads the perceiver's internals. It gets an
:class:`Expectations` record built by **one adapter**, :func:`expectations_of`, from the
perceiver's output. Today that output's steps are the offline ``Intent`` (decoded from
Causal.json for model perceivers); when the perceiver contract changes, only
:func:`expectations_of` changes. The critic harness builds the same record from a
benchmark annotation (``benchmark.critic_injection``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

if TYPE_CHECKING:
    from app.engine.agents.roles import Perception
    from app.engine.offline.intent import Intent

MotionRole = Literal["control", "direct", "effect"]


@dataclass(frozen=True)
class ExpectedMotion:
    """One intended motion of one joint, in the order the request asks for it.

    ``target`` is the joint value (radians or metres) the motion must reach by the end of
    the segment that drives it; ``omega`` a constant speed (rad/s or m/s) instead. With
    ``returns_to_rest`` the joint must be back at rest when the animation ends (a button
    that springs back).
    """

    joint: str
    link: str
    step: int
    role: MotionRole
    target: float | None = None
    omega: float | None = None
    returns_to_rest: bool = False
    expr: str | None = None
    label: str | None = None

    def describe(self) -> str:
        """One line for the critic prompt ("move to 1.5708 (upper_limit; effect), then return to rest")."""
        if self.omega is not None:
            return f"spin at {self.omega:.4g} rad/s ({self.role})"
        returns = ", then return to rest" if self.returns_to_rest else ""
        return f"move to {self.target:.5g} ({self.expr or 'value'}; {self.role}){returns}"


@dataclass(frozen=True)
class Expectations:
    """Every intended motion of a request; joints not named here must stay still."""

    motions: tuple[ExpectedMotion, ...]
    rolling: tuple[str, ...] = ()
    """Wheel joints that roll with a whole-object motion (any amount is fine)."""
    base_motion: bool = False

    @property
    def joints(self) -> set[str]:
        return {m.joint for m in self.motions} | set(self.rolling)

    def describe(self, joint: str) -> str:
        """What ``joint`` should do, for the critic prompt."""
        for motion in self.motions:
            if motion.joint == joint:
                return motion.describe()
        return "roll with the object without slipping" if joint in self.rolling else "stay still"

    def links(self) -> list[str]:
        """Links of the expected motions, in order, each once."""
        return list(dict.fromkeys(m.link for m in self.motions))


def expectations_from_intent(intent: Intent) -> Expectations:
    """The expectations encoded by the offline agent's ``Intent`` steps."""
    motions: list[ExpectedMotion] = []
    rolling: list[str] = []
    base = False
    for index, step in enumerate(intent.steps):
        if step.base is not None:
            base = True
            rolling.extend(j for j, _ in step.base.wheels if j not in rolling)
        for goal in step.goals:
            returns = goal.role == "control" and goal.returns == "self_return" and not goal.sustains and goal.value is not None
            motions.append(ExpectedMotion(joint=goal.joint, link=goal.link, step=index, role=goal.role, target=goal.value, omega=goal.omega,
                                          returns_to_rest=returns, expr=goal.expr, label=goal.category))
    return Expectations(motions=tuple(motions), rolling=tuple(rolling), base_motion=base)


def expectations_of(perception: Perception) -> Expectations:
    """THE adapter from the perceiver's output to what the critic checks (swap here when the contract changes)."""
    return expectations_from_intent(perception.intent)

