"""The audit stage: a reading that drops a measured amount, or moves a part toward the end opposite to the one
the clause names, carries a warning naming the words; a faithful reading carries none.

The warned prompts are readings the agent once got wrong silently (blind dev probes); they stay here as
the audit's own cases whether or not the front end later reads them right (then the audit is quiet, and
the test checks only that nothing wrong is silent)."""

from __future__ import annotations

import pytest

from app.engine.offline.audit import said_amounts
from app.engine.offline.perceiver import read_prompt
from app.engine.offline.reading.clauses import split_clauses
from app.engine.offline.reading.tokens import tokenize
from tests.engine.offline.conftest import asset

AUDIT = "check the result"

QUIET = [
    ("storage_27044", "pull the drawer out 25 cm"),
    ("microwave_7119", "open the door 30 degrees, then 20 more"),
    ("window_103135", "Push the window out to 40 degrees from shut, then put it back."),
    ("box_102456", "Set the toy box lid to 30 degrees open."),
    ("laptop_10697", "Open the laptop screen to a right angle with the keyboard."),
    ("faucet_148", "Set joint_0 of the faucet to -pi/4 rad."),
    ("trash_can_102155", "Spin the left wheel one full revolution."),
    ("microwave_7119", "Open the microwave door 90 degrees, hold it for 3 s, then close it."),
    ("storage_19179", "open the top drawer, then close it again"),
]


@pytest.mark.parametrize(("name", "prompt"), QUIET, ids=[p for _, p in QUIET])
def test_faithful_readings_carry_no_audit_warning(name: str, prompt: str) -> None:
    reading = read_prompt(prompt, asset(name))
    assert not [n for n in reading.notes if AUDIT in n]


def _understood(name: str, prompt: str) -> list[tuple[str, float, float]]:
    reading = read_prompt(prompt, asset(name))
    return [(m["joint"], m["from_value"], m["value"]) for e in reading.understanding for s in e["steps"] for m in s["moves"] if "value" in m]


CAUGHT = [
    # (asset, prompt, a word the warning must quote, joint, True if the part must end nearer its closed end than it started)
    ("extra/storage_20279", "Shove the writing desk's drawer shut.", "shut", "joint_0", True),
    ("microwave_7304", "Scoot the microwave 20 cm forward, toward the front edge of the counter. Door stays shut.", "shut", "joint_1", True),
    ("extra/storage_24644", "Something rolled to the very back of the drawer - open it as far as it'll go so I can reach it.", "open", "joint_0", False),
]


@pytest.mark.parametrize(("name", "prompt", "word", "joint", "closing"), CAUGHT, ids=[c[1] for c in CAUGHT])
def test_a_part_moving_against_the_named_state_is_warned(name: str, prompt: str, word: str, joint: str, closing: bool) -> None:
    reading = read_prompt(prompt, asset(name))
    warned = [n for n in reading.notes if AUDIT in n and f"'{word}'" in n]
    moves = [(a, b) for j, a, b in _understood(name, prompt) if j == joint]
    geometry_closed = {"extra/storage_20279": -0.188, "microwave_7304": 0.0, "extra/storage_24644": 0.0}[name]
    wrong = any((abs(b - geometry_closed) > abs(a - geometry_closed) + 1e-6) == closing for a, b in moves)
    assert warned or not wrong, f"{prompt!r} moved {joint} the wrong way without a warning: {moves}"


def test_dropped_amounts_are_named() -> None:
    reading = read_prompt("Open the microwave door 30 degrees... actually make it 20 more than that.", asset("microwave_7119"))
    values = [v for _, _, v in _understood("microwave_7119", "Open the microwave door 30 degrees... actually make it 20 more than that.")]
    if abs(values[-1] - 0.8727) > 0.02:
        assert any("'20 more'" in n and AUDIT in n for n in reading.notes), reading.notes


def test_amounts_said_take_units_and_carry_them_to_a_bare_more() -> None:
    clauses = split_clauses(tokenize("turn the dial one and a half turns, wait 3 s, then 20 more; lift it 35 cm and 40% of the way"))
    said = [(kind, round(value, 4)) for found in said_amounts(clauses).values() for kind, value, _ in found]
    assert ("rad", round(3 * 3.141592653589793, 4)) in said
    assert ("s", 3.0) in said
    assert ("rad", round(20 * 2 * 3.141592653589793, 4)) in said  # "20 more" after turns: 20 turns
    assert ("m", 0.35) in said
    assert ("fraction", 0.4) in said
