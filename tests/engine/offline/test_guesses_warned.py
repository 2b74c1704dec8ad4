"""Choices the URDF's encoding used to make silently now come from the shape, or carry a warning naming the guess:
a lever that goes as far either way with no side said, a verb that implies a control ("start the toaster") on an
object with two of them."""

from __future__ import annotations

import pytest

from app.engine.errors import GroundingError
from app.engine.offline.perceiver import read_prompt
from tests.engine.offline.conftest import asset

EITHER_WAY = "goes about as far either way"


def _notes(name: str, prompt: str) -> list[str]:
    return list(read_prompt(prompt, asset(name)).notes)


@pytest.mark.parametrize("prompt", ["swing the lever", "push the lever all the way"])
def test_a_lever_with_no_side_said_is_a_named_guess(prompt: str) -> None:
    assert any(EITHER_WAY in n for n in _notes("extra/faucet_1343", prompt))


@pytest.mark.parametrize("prompt", ["swing the lever to the left", "push the lever as far right as possible", "turn the lever hard left",
                                    "swing the lever all the way left"])
def test_a_side_said_is_no_guess(prompt: str) -> None:
    assert not any(EITHER_WAY in n for n in _notes("extra/faucet_1343", prompt))


def test_a_door_with_a_closed_end_is_no_guess() -> None:
    assert not any(EITHER_WAY in n for n in _notes("refrigerator_11178", "open the left door"))


@pytest.mark.parametrize("prompt", ["Start the toaster.", "Start toasting in the front slot."])
def test_an_implied_control_among_two_is_chosen_by_shape_and_said(prompt: str) -> None:
    notes = _notes("extra/toaster_103473", prompt)
    assert any("could work 2 levers; took the one on the front (link_0)" in n for n in notes), notes


CONVENTION = "the PartNet-Mobility convention: nothing on it shows where it faces"


@pytest.mark.parametrize(("name", "prompt"), [("bucket_100454", "fold the handle down toward the front"),
                                              ("extra/toaster_103473", "press the lever nearest me down"),
                                              ("extra/toaster_103473", "push down the back lever")])
def test_sides_read_from_a_conventional_front_are_said(name: str, prompt: str) -> None:
    assert any(CONVENTION in n for n in _notes(name, prompt))


@pytest.mark.parametrize(("name", "prompt"), [("extra/faucet_1343", "swing the lever all the way"),  # no side word
                                              ("refrigerator_11178", "open the left door"),  # its doors show its front
                                              ("extra/faucet_1343", "swing the lever to the left")])  # its spout shows its front
def test_no_convention_warning_without_a_side_or_with_a_shown_front(name: str, prompt: str) -> None:
    assert not any(CONVENTION in n for n in _notes(name, prompt))


@pytest.mark.parametrize(("prompt", "note"), [("pull the top drawer out a few centimetres", "read 'a few' as '3'"),
                                              ("pull the top drawer out a couple of inches", "read 'a couple of' as '2'"),
                                              ("pull the top drawer out several centimetres", "read 'several' as '4'")])
def test_a_vague_count_of_a_unit_says_the_number_taken(prompt: str, note: str) -> None:
    assert note in _notes("storage_19179", prompt)


def test_a_plain_count_of_a_unit_is_no_guess() -> None:
    assert not any("as '1'" in n for n in _notes("storage_19179", "pull the top drawer out an inch"))


def test_a_part_named_by_place_that_another_carries_is_a_named_guess() -> None:
    """"the top half of the machine" on a coffee maker whose jug carries its lid: either could be meant."""
    notes = _notes("coffee_machine_103030", "Twist the knob on the front to make the top half of the machine rise up.")
    assert any("which carries it" in n for n in notes), notes


@pytest.mark.parametrize(("name", "prompt"), [("extra/suitcase_100550", "put the handle back"), ("extra/bucket_100432", "put the handle back")])
def test_a_part_asked_back_where_it_already_rests_is_said(name: str, prompt: str) -> None:
    """Nothing moved the part yet and it rests there: the animation is still, and the note says why (never a silent no-op)."""
    assert any("is already where it rests: it did not move" in n for n in _notes(name, prompt)), _notes(name, prompt)


def test_a_purpose_naming_a_kind_the_asset_lacks_moves_nothing_else() -> None:
    """"crank the handle to pull the bolts": a safe has no latch, and its other knob is no stand-in for one."""
    notes = _notes("safe_101593", "crank the big spoked handle a quarter turn clockwise to pull the bolts")
    assert any("ignored the purpose 'pull the bolts'" in n for n in notes), notes


def test_a_tilt_of_the_whole_object_among_other_steps_is_said() -> None:
    notes = _notes("trash_can_102155", "tilt the bin back and wheel it backwards 40 cm")
    assert any("tilting the whole trash_can_102155 is not animated" in n for n in notes), notes


@pytest.mark.parametrize(("name", "prompt"), [("extra/box_100214", "someone left the box lid open again"),
                                              ("extra/box_100214", "the lid is open and I keep banging my elbow on it"),
                                              ("storage_19179", "My keys are in the top drawer."),
                                              ("switch_100952", "It's way too dark in here.")])
def test_an_action_read_from_a_complaint_or_a_place_is_said(name: str, prompt: str) -> None:
    """Nothing was asked: what the agent did instead (shut the part complained of, opened the one a thing is in, turned
    the light on) is a guess, and the note says so."""
    assert any(n.startswith("no action was asked") for n in _notes(name, prompt)), _notes(name, prompt)


def test_a_person_running_into_a_part_is_no_step() -> None:
    notes = _notes("extra/box_100214", "the lid is open and I keep banging my elbow on it")
    assert any("it is about what happens to a person" in n for n in notes), notes


UNKNOWN_NAME = "(a name the agent does not know)"


@pytest.mark.parametrize(("name", "prompt"), [("trash_can_102181", "Flip up the shutter."), ("extra/oven_7179", "Pull out the top grate."),
                                              ("microwave_7119", "Swing open the porthole.")])
def test_a_name_read_by_elimination_is_said(name: str, prompt: str) -> None:
    notes = _notes(name, prompt)
    assert any(UNKNOWN_NAME in n and "the only movable part that can" in n for n in notes), notes


@pytest.mark.parametrize(("name", "prompt"), [("trash_can_102181", "Open the lid."), ("microwave_7119", "Open the door.")])
def test_a_known_name_is_no_elimination(name: str, prompt: str) -> None:
    assert not any(UNKNOWN_NAME in n for n in _notes(name, prompt))


def test_a_generic_name_read_by_elimination_is_said() -> None:
    notes = _notes("microwave_7119", "Open the panel.")
    assert any("read 'the panel' as door (link_0)" in n and "the only movable part that can open" in n for n in notes), notes


@pytest.mark.parametrize("prompt", ["Open the porthole.", "open the flux capacitor"])
def test_a_bare_unknown_name_is_refused_not_guessed(prompt: str) -> None:
    with pytest.raises(GroundingError, match="no such movable part"):
        _notes("microwave_7119", prompt)
