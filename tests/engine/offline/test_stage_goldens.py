"""Golden tests per stage of the offline front end: a failure names the stage that changed.

normalise (tokens) -> clauses -> frames -> acts -> contract (the ``artimo`` steps). Each stage's
output for each prompt is compared with ``tests/fixtures/stages/<stage>.json``; set
``ARTIMO_UPDATE_GOLDENS=1`` to rewrite them after a deliberate change (and review the diff).
"""

from __future__ import annotations

import dataclasses
import json
import os
from enum import Enum
from pathlib import Path
from typing import Any

import pytest

from app.engine.offline.perceiver import asset_words, read_prompt
from app.engine.offline.reading.acts import build_acts
from app.engine.offline.reading.clauses import split_clauses
from app.engine.offline.reading.frames import read_frames
from app.engine.offline.reading.tokens import tokenize
from tests.engine.offline.conftest import asset

GOLDEN = Path(__file__).resolve().parents[2] / "fixtures" / "stages"
CASES: list[tuple[str, str]] = [
    ("trash_can_102181", "press the pedal to open the lid"),
    ("trash_can_102181", "Step on the pad only a little so the lid opens about 30 degrees."),
    ("trash_can_102181", "step on the pedal, hold the lid open for two seconds, then let go"),
    ("examples/microwave", "opne the microwve door all teh way"),
    ("examples/microwave", "Spin the turntable a half turn counterclockwise while the door is open."),
    ("examples/cabinet", "unlatch the door and open it"),
    ("examples/cabinet", "Open the cupboard door 90 degrees after releasing the latch knob."),
    ("examples/cabinet", "Open the top drawer fully, and after it open the bottom drawer halfway."),
    ("examples/oven", "take the tray out of the oven"),
    ("examples/toy_car", "give the car a push along +x and let it roll 0.3 m to a stop"),
    ("examples/toy_car", "turn the car around"),
    ("examples/toy_car", "Push the car 0.3 m forward and then 0.3 m back to where it started."),
    ("examples/pedal_bin", "lift the lid by hand until it is fully open, without using the pedal"),
    ("examples/pedal_bin", "Lift the pedal bin 10 cm and set it back down."),
    ("safe_101564", "Type the code top-left, top-right, bottom-middle on the keypad"),
    ("safe_101564", "Press the middle key of the keypad's second row."),
    ("safe_101593", "spin the dial one and a half turns counterclockwise, then turn the spoked handle a quarter turn clockwise"),
    ("safe_102387", "Dial the combination, and the safe door opens 90 degrees."),
    ("refrigerator_11178", "Open both fridge doors 90 degrees, left one first."),
    ("refrigerator_11178", "open the left fridge door, the one with the handle, to 90 degrees"),
    ("refrigerator_11178", "open the right door first, then the left one"),
    ("storage_19179", "open the second drawer"),
    ("storage_23472", "The top drawer is sticking out; push it shut."),
    ("laptop_10101", "Close the laptop, then reopen it to its original angle."),
    ("laptop_10697", "fold the screen backwards until it lies flat"),
    ("box_102456", "Open the box lid fully, then let it fall back to 60 degrees."),
    ("bucket_102352", "pick up the bucket by its handle and raise it 50 cm"),
    ("bucket_100454", "Swing the bucket handle down onto the rim on the -X side."),
    ("dishwasher_12553", "Press the door-release button on the control strip; the door drops open to 45 degrees and the button pops back out."),
    ("faucet_991", "turn off the tap"),
    ("kitchen_pot_100038", "lift the whole pot, lid and all, 25 cm"),
    ("coffee_machine_103030", "Once the lid is lifted 20 cm off the jar, lift the jar 4 cm."),
    ("stapler_103099", "snap the stapler's staple magazine shut"),
    ("storage_19179", "Pull out the second drawer counting up from the floor."),
    ("refrigerator_11178", "open a door, either one is fine"),
    ("safe_101564", "Enter the code 8 1 6, pausing a moment between each digit."),
    ("extra/microwave_7128", "Press the long flat bar under the dials, then swing the door wide open."),
    ("extra/storage_25308", "Going from left to right, open the drawers one by one, each one fully out before the next one starts."),
    ("switch_100952", "um turn it on leave it on for two and a half seconds and then turn it back off"),
    ("extra/storage_25308", "Drawer on left open it and then close it again."),
    ("dishwasher_11700", "Please put the dishwasher door down to 70°, hold for 2 sec, after close it back up."),
    ("extra/oven_7179", "Oven have three sliding rack; please pull out the rack of middle."),
    ("laptop_10101", "The screen shall be tilted back to the maximum angle allowed by the hinge."),
    ("safe_101564", "press the 5 key twice"),
    ("faucet_148", "cn u push teh tap handel 40 degres towrds the rihgt"),
    ("microwave_7119", "open the door 30 degrees, then 20 more"),
    ("box_102456", "Drag the toy box 30 cm to my right."),
    ("storage_27044", "pull the drawer out 20 cm, then shove it bak shut"),
    ("washing_machine_103508", "Close the lid, then turn the large cycle dial on the right of the control panel a quarter turn clockwise to start the wash."),
    ("extra/oven_7179", "Step 1: The upper door of the oven is to be opened fully. Step 2: Only after Step 1 has been completed is the highest tray to be extended completely."),
    ("extra/microwave_7128", "Spin the turntable at half a turn per second for two seconds."),
    ("extra/storage_25308", "Slide the left drawer all the way out, then back to the spot it started from."),
    ("extra/storage_25308", "Pull the left drawer fully open, then push it back until it's about halfway."),
    ("toaster_103483", "Push the lever down to start toasting; when the toast is done the lever springs back up."),
    ("toilet_102622", "I need to use the toilet."),
    ("toaster_103483", "Press the toast plunger down and let it pop back up."),  # a name read by elimination
    ("trash_can_102181", "The bin is to be opened in a hands-free manner."),  # a word after what moves is no part
    ("safe_101564", "um the code is two five eight punch it in on the keypad"),  # a code told, then entered
    ("extra/box_100214", "Snap the right-hand catch into place."),  # "into place" is the closed end
]
STAGES = ("tokens", "clauses", "frames", "acts", "contract")


def _plain(value: Any) -> Any:
    """JSON-able form of a stage's output, leaving out empty defaults."""
    if isinstance(value, Enum):
        return value.value
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        out = {}
        for item in dataclasses.fields(value):
            field_value = getattr(value, item.name)
            if (field_value in (None, (), [], frozenset(), False, "", 0) and not isinstance(field_value, float)) or item.name in ("start", "end", "used"):
                continue
            out[item.name] = _plain(field_value)
        return out
    if isinstance(value, tuple | list):
        return [_plain(v) for v in value]
    if isinstance(value, float):
        return round(value, 9)
    return value


def stage_output(asset_name: str, prompt: str, stage: str) -> Any:
    model = asset(asset_name)
    tokens = tokenize(prompt, asset_words(model))
    if stage == "tokens":
        return [t.text if t.lemma == t.text and not t.corrected_from else {"text": t.text, "lemma": t.lemma, "typed": t.corrected_from} for t in tokens]
    clauses = split_clauses(tokens)
    if stage == "clauses":
        return [{"link": c.link.value, "text": c.text, "first": c.goes_first} for c in clauses]
    frames = read_frames(clauses)
    if stage == "frames":
        return _plain(frames)
    if stage == "acts":
        return [{"goal": a.goal.text, "means": a.means.text if a.means else None, "results": [r.text for r in a.results], "condition": a.condition,
                 "parallel": a.parallel, "wait": a.wait_before_s, "hold": a.hold_s} for a in build_acts(frames)]
    return json.loads(read_prompt(prompt, model).extension.model_dump_json(exclude_defaults=True))


def _golden(stage: str) -> dict[str, Any]:
    path = GOLDEN / f"{stage}.json"
    return json.loads(path.read_text()) if path.is_file() else {}


@pytest.mark.parametrize("stage", STAGES)
def test_stage_matches_golden(stage: str) -> None:
    produced = {f"{a}: {p}": stage_output(a, p, stage) for a, p in CASES}
    if os.environ.get("ARTIMO_UPDATE_GOLDENS"):
        (GOLDEN / f"{stage}.json").write_text(json.dumps(produced, indent=1, sort_keys=True) + "\n")
    golden = _golden(stage)
    changed = [key for key in produced if golden.get(key) != produced[key]]
    assert not changed, f"stage '{stage}' changed for: " + "; ".join(changed[:5])
