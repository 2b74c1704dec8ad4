"""Robustness: prompts garbled the way users garble them (a word dropped, doubled, swapped or
replaced by another prompt's word) never crash the offline agent. Each one either animates or
is refused with an EngineError that says why; nothing else escapes (a KeyError or TypeError
here was a real crash a user could hit)."""

from __future__ import annotations

import random

import pytest

from app.engine.errors import EngineError
from tests.engine.offline.conftest import animate
from tests.engine.offline.test_prompt_table import ROWS

SEEDS = range(120)
_WORDS = sorted({word for row in ROWS for word in row.prompt.split()})


def _mutated(seed: int) -> tuple[str, str]:
    rng = random.Random(seed)
    row = rng.choice(ROWS)
    words = row.prompt.split()
    for _ in range(rng.randint(1, 3)):
        i = rng.randrange(len(words))
        roll = rng.random()
        if roll < 0.3 and len(words) > 2:
            del words[i]
        elif roll < 0.6:
            words.insert(i, rng.choice(_WORDS))
        elif roll < 0.8:
            j = rng.randrange(len(words))
            words[i], words[j] = words[j], words[i]
        else:
            words[i] = rng.choice(_WORDS)
    return row.asset, " ".join(words)


@pytest.mark.parametrize("seed", SEEDS)
def test_a_garbled_prompt_animates_or_is_refused(seed: int) -> None:
    name, prompt = _mutated(seed)
    try:
        animate(name, prompt)
    except EngineError as exc:
        assert str(exc), f"{name}: {prompt!r}: an empty error"


@pytest.mark.parametrize(("name", "prompt"), [
    ("laptop_10248", "Close the laptop, wait 2 seconds, third open it was. to where it again"),
    ("dishwasher_12553", "Task: the dishes Step 1: press button on the top strip to pause it. Step 2: lower the door to 30°."),
    ("dishwasher_12553", "pause the door"),
    ("microwave_7119", "open the turntable"),
    ("extra/safe_101623", "Open the safe door about 45 second, degrees."),  # a step longer than the contract allows: clamped, said
    ("storage_23472", "Swing open the cupboard door under the drawer halfway; keep your hands box off 15 the drawer."),
])
def test_prompts_that_once_crashed(name: str, prompt: str) -> None:
    try:
        animate(name, prompt)
    except EngineError as exc:
        assert str(exc)
