"""Objects made of like units (two fridges side by side, three toasters in a row, cabinets stacked): which unit the words
name, then which part of it (rounds 52-53: these were refused, or the wrong unit's part moved, often silently).

The composites are written by :func:`benchmark.stacks.write_stack` from dev assets, as the blind rounds were."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import GroundingError
from app.engine.offline.perceiver import read_prompt
from benchmark.stacks import write_stack
from tests.engine.offline.conftest import animate_model, asset_dir

COMPOSITES = {
    "fridges": ("refrigerator_11178", "stack2y"),  # left fridge: link_3 (left door), link_4; right fridge: link_0, link_1 (right door)
    "toasters": ("toaster_103483", "stack3y"),  # levers: right link_0, middle link_2, left link_4
    "bins": ("trash_can_102181", "stack2y"),  # right bin: pedal link_0, lid link_1; left bin: pedal link_3, lid link_4
    "dishwashers": ("dishwasher_11700", "stack2y"),  # doors: right link_0, left link_2
    "laptops": ("laptop_10697", "stack3y"),  # screens: right link_1, middle link_3, left link_5
    "drawers": ("storage_19179", "stack3z"),  # six drawers, top to bottom: link_7, 6, 4, 3, 1, 0
    "desks": ("extra/storage_25308", "stack2y"),  # four drawers, left to right: link_4, 3, 1, 0
    "microwaves": ("microwave_7304", "stack2z"),  # doors: lower link_1, upper link_3
    "coffee": ("extra/coffee_machine_102145", "stack2y"),  # capsule holders ("rotation_slider"): right link_3, left link_8
}


@pytest.fixture(scope="module")
def composites(tmp_path_factory: pytest.TempPathFactory) -> dict[str, ArticulatedAsset]:
    out = tmp_path_factory.mktemp("composites")
    made = {}
    for name, (source, step) in COMPOSITES.items():
        write_stack(asset_dir(source), Path(out / name), step)
        made[name] = load_asset(out / name)
    return made


def _moved(model: ArticulatedAsset, prompt: str) -> dict[str, float]:
    """{joint: final value} of every joint that moved, and the order they started in."""
    trajectory = animate_model(model, prompt).trajectory
    q = trajectory.q
    return {j: float(q[-1, k]) for k, j in enumerate(trajectory.joint_names) if abs(q[:, k] - q[0, k]).max() > 1e-3}


def _started(model: ArticulatedAsset, prompt: str) -> list[str]:
    trajectory = animate_model(model, prompt).trajectory
    q = trajectory.q
    first = {j: int((abs(q[:, k] - q[0, k]) > 1e-3).argmax()) for k, j in enumerate(trajectory.joint_names) if abs(q[:, k] - q[0, k]).max() > 1e-3}
    return sorted(first, key=lambda j: (first[j], j))


@pytest.mark.parametrize(("name", "prompt", "joints"), [
    ("fridges", "On the left-hand fridge, open the right door.", {"joint_4"}),  # r52g_003: had opened the right fridge's door, silently
    ("fridges", "Left-hand fridge: open the right door.", {"joint_4"}),
    ("toasters", "Push down the lever on the left toaster.", {"joint_4"}),
    ("toasters", "Hold the lever of the right-hand toaster down for two seconds.", {"joint_0"}),
    ("bins", "Step on the pedal of the left-hand trash can.", {"joint_3", "joint_4"}),  # the pedal lifts its own bin's lid
    ("dishwashers", "Of the two dishwashers side by side, fold the left one's door fully down.", {"joint_2"}),
    ("microwaves", "Two microwaves are stacked - get the upper one's door open.", {"joint_3"}),
    ("microwaves", "There are two microwaves here. Open the door of the one on the bottom.", {"joint_1"}),
    ("laptops", "Could you open the laptop that's sitting on the left?", {"joint_5"}),
    ("bins", "There are two bins here. The one on the right is full, so flip its lid open.", {"joint_0", "joint_1"}),  # by its pedal
    ("desks", "Leave the two outermost drawers shut and pull out the remaining drawers.", {"joint_3", "joint_1"}),
    ("desks", "Open all of the drawers apart from the leftmost one.", {"joint_3", "joint_1", "joint_0"}),
    ("drawers", "Open every drawer except the top one.", {"joint_6", "joint_4", "joint_3", "joint_1", "joint_0"}),
    ("coffee", "On the coffee machine on the left, swing up the capsule holder at the front.", {"joint_8"}),  # a name not known, on that unit
])
def test_the_unit_then_its_part(composites: dict[str, ArticulatedAsset], name: str, prompt: str, joints: set[str]) -> None:
    assert set(_moved(composites[name], prompt)) == joints


@pytest.mark.parametrize(("name", "prompt", "order"), [
    ("desks", "Going from left to right, open the four drawers one by one.", ["joint_4", "joint_3", "joint_1", "joint_0"]),
    ("desks", "Open the drawers one after another going from right to left, each one fully out before the next one starts.",
     ["joint_0", "joint_1", "joint_3", "joint_4"]),
    ("drawers", "Open every other drawer, starting with the bottom one.", ["joint_0", "joint_3", "joint_6"]),
    ("drawers", "Open all six drawers one at a time, starting at the top and working down to the bottom.",
     ["joint_7", "joint_6", "joint_4", "joint_3", "joint_1", "joint_0"]),
    ("toasters", "Press the levers one after another, right to left.", ["joint_0", "joint_2", "joint_4"]),
])
def test_order_said_by_place(composites: dict[str, ArticulatedAsset], name: str, prompt: str, order: list[str]) -> None:
    assert _started(composites[name], prompt) == order


@pytest.mark.parametrize(("name", "prompt"), [
    ("dishwashers", "Open the dishwasher."),  # r52g_014: two dishwashers; both doors had opened
    ("laptops", "Open the laptop."),
])
def test_one_of_like_units_unsaid_is_refused(composites: dict[str, ArticulatedAsset], name: str, prompt: str) -> None:
    with pytest.raises(GroundingError, match="like units"):
        read_prompt(prompt, composites[name])


def test_a_single_object_is_still_worked_whole() -> None:
    """One fridge with two doors is one unit: "open the fridge" opens both, as before."""
    model = load_asset(asset_dir("refrigerator_11178"))
    assert set(_moved(model, "open the fridge")) == {"joint_0", "joint_1"}


def test_every_other_keeps_the_state_verb_whole(composites: dict[str, ArticulatedAsset]) -> None:
    """"leave every other drawer shut" is all the others, not every second one."""
    moved = _moved(composites["drawers"], "Pull open the top drawer and the bottom drawer; leave every other drawer shut.")
    assert set(moved) == {"joint_7", "joint_0"}


def test_pause_between_presses() -> None:
    """"pausing a moment between each digit": a wait before each press after the first (had been read as a part)."""
    steps = read_prompt("Enter the code 8 1 6, pausing a moment between each digit.", load_asset(asset_dir("safe_101564"))).extension.steps
    assert [s.wait_before_s for s in steps] == [0.0, 1.0, 1.0]


def test_shape_word_before_a_noun_is_no_end_state() -> None:
    """"the long flat bar under the dials" names the button there; "flat" had been read as the knobs' end state (silent)."""
    moved = _moved(load_asset(asset_dir("extra/microwave_7128")), "Press the long flat bar under the dials, then swing the door wide open.")
    assert set(moved) == {"joint_1", "joint_0"}
    assert math.isclose(moved["joint_0"], math.pi / 2, abs_tol=0.02)


@pytest.mark.parametrize(("name", "prompt", "joints"), [
    ("drawers", "Pull out the third drawer counting up from the floor.", {"joint_3"}),  # r52g_044: had counted from the top (silent)
    ("drawers", "In the column of six drawers, open the second drawer from the top.", {"joint_6"}),  # r52h_056: had opened all six
    ("drawers", "Top drawer first, then the bottom one, and leave the middle ones for last.", {"joint_7", "joint_0", "joint_4", "joint_3"}),
])
def test_counted_and_described(composites: dict[str, ArticulatedAsset], name: str, prompt: str, joints: set[str]) -> None:
    assert set(_moved(composites[name], prompt)) == joints


def test_a_group_of_the_units_is_the_object(composites: dict[str, ArticulatedAsset]) -> None:
    """"Slide the pair of toasters 40 cm to the left": the whole object ("pair" had been read as a part it lacks)."""
    trajectory = animate_model(composites["toasters"], "Turn the entire row of toasters around, 180 degrees.").trajectory
    assert trajectory.base_rotation_xyzw is not None
    assert abs(float(trajectory.base_rotation_xyzw[-1][2])) == pytest.approx(1.0, abs=1e-3)  # a half turn about up


def test_check_on_it_opens_where_it_is() -> None:
    """"Pizza's in the top oven and I'd like to check on it": open the door to look (had been read as starting the oven)."""
    moved = _moved(load_asset(asset_dir("extra/oven_7179")), "The pizza is in the top oven and I'd like to check on it.")
    assert set(moved) == {"joint_4"}


@pytest.mark.parametrize("prompt", ["open a door, either one is fine", "Open a door - any will do."])
def test_a_choice_left_open_is_taken(prompt: str) -> None:
    """The user accepts either door: one is opened, with a note (it had been refused as ambiguous)."""
    reading = read_prompt(prompt, load_asset(asset_dir("refrigerator_11178")))
    assert [m.joint for s in reading.extension.steps for m in s.effects] == ["joint_0"]
    assert any("leaves the choice" in note for note in reading.notes)


def test_without_the_choice_left_open_it_is_refused() -> None:
    with pytest.raises(GroundingError, match="could mean 2 parts"):
        read_prompt("open a door", load_asset(asset_dir("refrigerator_11178")))


@pytest.mark.parametrize(("name", "prompt", "joint"), [
    ("dishwasher_12553", "The dishwasher needs loading.", "joint_0"),  # the button had been pressed ("loading" dropped)
    ("dishwasher_12553", "the dishwasher needs to be loaded", "joint_0"),
    ("trash_can_102155", "gotta chuck this banana peel in the bin", "joint_2"),  # "gotta" had been read as a part
])
def test_everyday_needs(name: str, prompt: str, joint: str) -> None:
    assert set(_moved(load_asset(asset_dir(name)), prompt)) == {joint}


def test_the_unit_a_need_names(composites: dict[str, ArticulatedAsset]) -> None:
    """"The upper microwave needs cleaning" of two stacked: that one's door (it had been refused as one of two units)."""
    assert set(_moved(composites["microwaves"], "The upper microwave needs cleaning.")) == {"joint_3"}
