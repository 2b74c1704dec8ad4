"""A joint move while the perceiver builds a step: the part, its role and goal, what it does after."""

from __future__ import annotations

from dataclasses import dataclass

from app.engine.contracts.steps import Goal, Release
from app.engine.offline.grounding import Part


@dataclass
class Move:
    part: Part
    role: str
    goal: Goal
    release: Release = "stays"
    words: str = ""
    loose: bool = False
    """The amount is a reading of a vague word ("slightly")."""
