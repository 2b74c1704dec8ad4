"""Classes found by blind round 62 (three writers, the dev pool): each prompt here was answered wrongly — most of them
without a warning — before the fix named beside it."""

from __future__ import annotations

import numpy as np
import pytest

from app.engine.errors import GroundingError
from app.engine.execute.trajectory import Trajectory
from tests.engine.offline.conftest import animate


def _q(trajectory: Trajectory, joint: str) -> np.ndarray:
    return trajectory.q[:, trajectory.joint_names.index(joint)]


def _moved(trajectory: Trajectory) -> set[str]:
    return {j for k, j in enumerate(trajectory.joint_names) if abs(trajectory.q[:, k] - trajectory.q[0, k]).max() > 1e-3}


@pytest.mark.parametrize(("name", "prompt", "joint", "final"), [
    # a habit the user complains of (how_it_is._habit): "it keeps popping open" had opened the lid the user asked to shut
    ("box_100671", "shut the lid on that little box for me, it keeps popping open on its own", "joint_0", -0.3896),
    # "stop there" ends the step before; it had been read as an unknown verb that moved the door again
    ("oven_7138", "oven_7138: door open 45 deg from closed. stop there.", "joint_0", np.pi / 4),
    # a story told of "he" (lexicon.people): "He'd shove ..." had been read as a part named "he'd shove"
    ("faucet_148", "Your grandfather liked his wash water scalding. He'd shove the tap handle all the way over to the left, "
                   "to the hot side. Do it like he did.", "joint_0", np.pi / 2),
    # "it should hit the stop" says the drawer reaches its end (results._at_its_stop); "hit" had pressed it shut
    ("extra/storage_26525", "opne teh drawr all teh way out pls, it shoud hit the stop", "joint_0", 0.512),
    # a latch flipped to lock stays locked (completion._releases): it had sprung back
    ("extra/box_100214", "Close the chest lid, then flip the latch on the left to lock it, and only after that the one on the right, "
                         "as seen from the front.", "joint_1", 0.4363),
    # "no more than that" after an amount (a request's frame): "than that" had been read as a second part
    ("storage_19179", "Pull the lower drawer out 25 cm, no more than that. I want to check the runners.", "joint_0", 0.25),
])
def test_the_part_ends_where_asked(name: str, prompt: str, joint: str, final: float) -> None:
    assert _q(animate(name, prompt).trajectory, joint)[-1] == pytest.approx(final, abs=0.02)


@pytest.mark.parametrize(("name", "prompt", "moved"), [
    # subjects joined before a negation (acts: the verbless "the bottom door" had taken the step's verb and opened)
    ("extra/oven_7179", "Test 7, double wall oven, upper door only: lower it to half open, 45 degrees, and leave it there. "
                        "The bottom door and the racks must not move.", {"joint_4"}),
    # what a part does to a thing that is no part (how_it_is.does_to_a_thing): "the left one hides the dove" opened it
    ("extra/storage_25308", "Standing in front of the desk, pull out the right-hand drawer. The left one hides the dove, so keep it shut.",
     {"joint_0"}),
    # a request run into the clause before ("... you can turn can you spin ..."): it had been refused
    ("extra/safe_101623", "on the safe door there are two things you can turn can you spin the upper one for me a few times", {"joint_2"}),
    # people in the story ("visitors", "he") are no parts: both prompts had been refused
    ("extra/safe_102380", "Visitors often ask how it was secured. Here, I turn the handle on the front of the door.", {"joint_0"}),
    ("toaster_103477", "He twists the round knob on the toaster, then shoves the lever all the way down.", {"joint_0", "joint_1"}),
    # "start sealed" is how the safe starts (starts_as): "start" had run the safe and spun its dial
    ("extra/safe_102380", "the safe has to start sealed, so swing that heavy door shut.", {"joint_2"}),
    # "the entire unit" fits any object (lexicon.objects): it had been refused as naming furniture
    ("dishwasher_12553", "rotate entire unit 90 deg about vertical axis. door and button stay put.", set()),
])
def test_only_the_asked_parts_move(name: str, prompt: str, moved: set[str]) -> None:
    assert _moved(animate(name, prompt).trajectory) == moved


def test_five_long_seconds_is_five_seconds() -> None:
    """padded_units: "five long seconds" had lost its count, and the door stayed open for a blink."""
    trajectory = animate("safe_102387", "The safe door is flung wide open, stays open for five long seconds, then slams shut.").trajectory
    q = _q(trajectory, "joint_0")
    top = q.max()
    held = trajectory.times[q >= top - 0.02 * abs(top - q[0])]
    assert held[-1] - held[0] >= 4.9


@pytest.mark.parametrize(("name", "prompt", "joint"), [
    ("trash_can_102155", "Lid on the wheelie bin flips open and then bangs shut again. One loop.", "joint_2"),  # "bang": had been a part
    ("refrigerator_11178", "Open the left door, check the gasket, then close it again.", "joint_0"),  # "gasket" is no typo of "basket"
    ("extra/bucket_100432", "Steps: let the bucket handle fall all the way down against the back of the bucket, then raise it back to its "
                            "starting position. Expected: it ends exactly where it began.", "joint_0"),  # the end, said again
    ("oven_7221", "Grandma would open the oven door just to peek at the roast, and then she'd shut it again straight away so the heat "
                  "stayed in.", "joint_0"),  # "straight away" is at once, not upright
])
def test_the_part_goes_and_comes_back(name: str, prompt: str, joint: str) -> None:
    q = _q(animate(name, prompt).trajectory, joint)
    assert abs(q - q[0]).max() > 0.3
    assert q[-1] == pytest.approx(q[0], abs=0.02)


@pytest.mark.parametrize(("name", "prompt", "first", "second"), [
    # "only once it's off do you lift the jug": the lift had been read as the condition and run first
    ("coffee_machine_103030", "First you take the lid off the jug, and only once it's off do you lift the jug itself up off the base.",
     "joint_2", "joint_1"),
    # "the lower big drawer": the lower one (the larger of two near-equal drawers had been taken)
    ("storage_19179", "Pull out the lower big drawer first, and only after that, the upper one.", "joint_0", "joint_1"),
    # numbered steps are steps: "3) door closed" had run beside step 2 as its effect
    ("microwave_7119", "microwave_7119: 1) door fully open 2) turntable 90 deg 3) door closed.", "joint_1", "joint_0@ret"),
])
def test_steps_run_in_the_order_told(name: str, prompt: str, first: str, second: str) -> None:
    trajectory = animate(name, prompt).trajectory
    joint, returning = second.split("@")[0], second.endswith("@ret")
    a, b = _q(trajectory, first), _q(trajectory, joint)
    first_done = trajectory.times[np.argmax(abs(a - a[0]) >= 0.8 * abs(a - a[0]).max())]
    peak = int(np.argmax(abs(b - b[0])))
    later = b[peak:] if returning else b
    start = trajectory.times[(peak if returning else 0) + int(np.argmax(abs(later - later[0]) > 1e-3))]
    assert first_done <= start


def test_a_missing_part_is_not_stood_in_for_by_one_named_apart() -> None:
    """referents: "the toilet seat" had been read as the lid, though the prompt names "the cover lid" to stay put."""
    with pytest.raises(GroundingError, match="toilet seat"):
        animate("toilet_102622", "Raise the toilet seat on its own and leave the cover lid exactly where it is.")


# --- round 63 (three more writers: a haiku-like voice, a film director, a literal translation from German) ---

@pytest.mark.parametrize(("name", "prompt", "joint", "final"), [
    # lines split by slashes that go on with one step (verse_lines): "half a turn" had been a step of its own (a second turn)
    ("extra/microwave_7128", "upper dial only / half a turn, clockwise / the lower one rests", "joint_3", -np.pi),
    # "as you face it:" ends at the colon (framing._viewpoint): the step after it had been dropped with the aside
    ("refrigerator_11178", "Fridge, the right-hand door as you face it: swing it open ninety degrees. Nothing else moves.", "joint_1", np.pi / 2),
    # "until the half of its way" (learner): half of its way
    ("storage_19179", "Pull the lower drawer out until the half of its way.", "joint_0", 0.5),
    # "click the dial a quarter turn": a turn that stays, not a brief click
    ("coffee_machine_103030", "Click the speed dial on the front of the base a quarter turn and listen to it whirr!", "joint_0", -np.pi / 2),
    # "first make the lid closed": the causative after "first"
    ("washing_machine_103508", "First make the lid closed, then turn the most left knob one quarter.", "joint_0", -0.7917),
])
def test_round63_the_part_ends_where_asked(name: str, prompt: str, joint: str, final: float) -> None:
    q = _q(animate(name, prompt).trajectory, joint)
    assert q[-1] == pytest.approx(final, abs=0.03)


@pytest.mark.parametrize(("name", "prompt", "moved"), [
    # a key pressed and kept pressed (revisions.hold): it had sprung back
    ("safe_101564", "On the safe press the key in the middle of the lowest row and let it stay pressed.", {"joint_10"}),
    ("safe_101564", "press the top-left key and keep it pressed", {"joint_0"}),
    # "the pedal thing" is the pedal (mentions): it had been refused
    ("trash_can_102181", "step on the pedal thing so the lid pops open", {"joint_0", "joint_1"}),
    # "Lid only" says which part moves (acts): the pedal had been worked, against "leave the pedal alone"
    ("trash_can_102181", "Pedal bin: lid goes all the way open, as far as it will go. Lid only, leave the pedal alone.", {"joint_1"}),
    # a motion said as a noun applied to the object (light_verbs._applied): it had been refused
    ("stapler_103099", "Apply a pure yaw of 90° to the stapler about the vertical axis, no tilt, articulation left at rest.", set()),
    # cues, apologies and "about to" beside the request (said_aside), and "could I", "if you can": each had been refused
    ("box_102456", "Slide the whole box half a metre to my right. I'm the one standing at the front of it. Go!", set()),
    ("kitchen_pot_100038", "Raise the lid on that pot ten centimetres and leave it hovering there, it's about to boil over.", {"joint_0"}),
    ("kitchen_pot_100038", "Could I just peek under the pot lid, and then put it back down where it was? Sorry if that's a silly request.",
     {"joint_0"}),
    ("laptop_10248", "um could u cloes the laptp lid? sory", {"joint_1"}),
    # a heading that is the step, with how it goes after the colon ("in and straight back out": briefly)
    ("safe_101564", "Tap the top-left key on the safe's keypad: in and straight back out.", {"joint_0"}),
])
def test_round63_only_the_asked_parts_move(name: str, prompt: str, moved: set[str]) -> None:
    assert _moved(animate(name, prompt).trajectory) == moved


def test_a_key_kept_pressed_stays_in() -> None:
    q = _q(animate("safe_101564", "press the top-left key and keep it pressed").trajectory, "joint_0")
    assert q[-1] > 0.5 * q.max() > 0


@pytest.mark.parametrize(("name", "prompt", "said"), [
    # a fold past flat on a hinge that stops at flat (motion_fit): it had opened to the stop, silently
    ("laptop_10101", "Bend the screen backwards past flat until it folds all the way round and lies against the underside of the keyboard, "
                     "like a tablet.", "past flat"),
    # "move" by an angle on a part resting part open, no way said (goals): it had closed the screen to 30 degrees from shut
    ("laptop_10697", "laptop_10697: move screen 30 deg.", "either way"),
])
def test_round63_refusals(name: str, prompt: str, said: str) -> None:
    with pytest.raises(GroundingError, match=said):
        animate(name, prompt)


# --- later round-63 and round-64 classes ---

@pytest.mark.parametrize(("name", "prompt", "moved"), [
    # "once it's shut you can spin the wheel": a step told to "you" after a condition (clauses, verb_cues): the wheel had not turned
    ("extra/safe_101623", "Swing the safe door closed first; once it's shut you can spin the spoked wheel on it to lock it.", {"joint_0", "joint_1"}),
    # "give the kids at the back a look" is for them (holders.looked_inside): the cap had been twisted open
    ("bottle_cap_3558", "Let's give the kids at the back a look - turn the whole bottle around, half a turn, so the other side faces them.", set()),
    # "I need to get behind it": where the user goes (said_aside): the dishwasher door had been opened
    ("dishwasher_12553", "Drag the whole dishwasher half a metre out toward me, I need to get behind it.", set()),
    # "Expected: ..." tells what should be seen (said_aside): the dial had been turned a second time
    ("extra/safe_101623", "Repro: turn the round combination dial a quarter turn clockwise, as seen when facing the safe door. "
                          "Expected: only the dial rotates.", {"joint_2"}),
    # a paddle is a lever (lexicon.kinds), and "it" after "the trigger is the little paddle on top": it had been refused
    ("extra/coffee_machine_102145", "The puzzle trigger is the little paddle on top of the coffee machine's head, above the spout. Tip it over "
                                    "to the left, as far as it will go.", {"joint_0"}),
])
def test_round64_only_the_asked_parts_move(name: str, prompt: str, moved: set[str]) -> None:
    assert _moved(animate(name, prompt).trajectory) == moved


@pytest.mark.parametrize(("name", "prompt", "joint"), [
    # a clause before a colon inside a sentence is no heading: "..., then slams shut again: that's the jump scare"
    ("extra/microwave_7128", "The microwave door swings wide open, then slams shut again: that's the jump scare.", "joint_0"),
    # telegraphic steps joined by a comma: "door shut" had been lost
    ("oven_7138", "Door open, door shut. Go.", "joint_0"),
    # "keep the lid down flat" after opening a lid that opens flat: a hold, not a contradiction (it had been refused)
    ("extra/suitcase_100550", "Open the suitcase fully and keep the lid down flat for five seconds while I photograph the hinge, then close "
                              "it again.", "joint_0"),
    # "Beat one, ..., Beat two, ...": step labels
    ("microwave_7119", "Beat one, the microwave door swings open. Beat two, the door swings shut again.", "joint_0"),
])
def test_round64_the_part_goes_and_comes_back(name: str, prompt: str, joint: str) -> None:
    q = _q(animate(name, prompt).trajectory, joint)
    assert abs(q - q[0]).max() > 0.3
    assert q[-1] == pytest.approx(q[0], abs=0.02)


def test_a_clasp_flipped_up_goes_up_and_stays() -> None:
    """frames._sense: "flip up" on a latch is where it goes (it had been read as unlatched, already so)."""
    trajectory = animate("extra/box_100214", "Flip up the clasp on the right-hand side of the box front (right as you face it). "
                                             "The left clasp must not be touched.").trajectory
    assert _q(trajectory, "joint_2")[-1] == pytest.approx(0.4363, abs=0.02)
    assert _moved(trajectory) == {"joint_2"}


@pytest.mark.parametrize(("name", "prompt", "joint"), [
    # a row said first, the key after a comma (row_apposed); "the left corner one" is the left one: both had been refused
    ("safe_101564", "On the keypad, the key in the bottom row, the left corner one, press it.", "joint_11"),
    ("safe_101564", "Keypad cue: top row, the middle key. One crisp press.", "joint_1"),
])
def test_a_key_told_by_its_row_first(name: str, prompt: str, joint: str) -> None:
    assert _moved(animate(name, prompt).trajectory) == {joint}


@pytest.mark.parametrize(("name", "prompt", "translation"), [
    # "0.5 m straight up": the way it goes (word_forms); it had gone away from the front
    ("bucket_100454", "Translate the entire bucket 0.5 m straight up along the vertical axis, with no rotation.", (0.0, 0.0, 0.5)),
    # "displace" moves the object; ", no rotation, no change in height" is said aside: it had been refused
    ("oven_7138", "Displace the oven 300 mm rearward, toward the wall behind it; no rotation, no change in height.", (0.3, 0.0, 0.0)),
    # the way and amount told first, the verb after with "it" (told_first_verb): the bin had rolled twice
    ("trash_can_102155", "Forward half a metre the wheelie bin, roll it please.", (-0.5, 0.0, 0.0)),
])
def test_the_whole_object_moves_as_told(name: str, prompt: str, translation: tuple[float, float, float]) -> None:
    trajectory = animate(name, prompt).trajectory
    moved = trajectory.base_translation[-1] - trajectory.base_translation[0]
    assert np.allclose(moved, translation, atol=0.05)
    assert _moved(trajectory) <= ({"joint_0", "joint_1"} if name == "trash_can_102155" else set())  # the bin's wheels roll


def test_a_time_said_with_when_moves_nothing() -> None:
    """perceiver: "... where it was when the scene loaded" had swung the door open again."""
    q = _q(animate("safe_102387", "Steps: 1) swing the safe door open to its limit. 2) return it to exactly where it was when the scene "
                                  "loaded.").trajectory, "joint_0")
    assert q[-1] == pytest.approx(q[0], abs=0.02) and q.max() > 2.0


# --- round 65 (a bedtime story, a commentator, an apologiser, a tour guide, a retired sailor, ...) ---

@pytest.mark.parametrize(("name", "prompt", "moved"), [
    # who acts in a story, before a verb that names the part it acts on (frames): each had been refused as a missing part
    ("extra/box_100214", "Then the sleepy dragon pushed the lid of his treasure chest shut, so nobody could peek at his gold.", {"joint_0"}),
    ("extra/oven_7179", "Grandma's little oven had three racks inside, and the bunny pulled the very bottom one all the way out to fetch "
                        "the carrot cake.", {"joint_2", "joint_3"}),
    # an interjection or a form of address is no part ("matey", "haha"): refused before
    ("toilet_102622", "Hoist that toilet lid up, matey, same as you'd raise a hatch cover.", {"joint_0"}),
    # "Neither door should open while it moves": no door opens, and "it moves" is the fridge already moving
    ("refrigerator_11178", "Push the entire fridge 20 cm straight back toward the wall behind it. Neither door should open while it moves.", set()),
    # "Let's give the dial ... a quarter turn": "let's" frames the request (it had been read as a part)
    ("safe_102387", "Let's give the dial on the safe's door a quarter turn.", {"joint_1"}),
    # "no other part moves", "Got a tray of ... going in", "I just want a warm rinse", "like halfway": said beside the step
    ("microwave_7304", "test_open_door: the microwave door swings to fully open and no other part moves.", {"joint_1"}),
    ("oven_7138", "Drop the oven door down for me, would you? Got a tray of croissants going in.", {"joint_0"}),
    ("faucet_991", "Nudge that tap lever about 45 degrees to the left, I just want a warm rinse for the milk jug.", {"joint_0"}),
    ("storage_27044", "opne teh drawr like halfwy pls", {"joint_0"}),
])
def test_round65_only_the_asked_parts_move(name: str, prompt: str, moved: set[str]) -> None:
    assert _moved(animate(name, prompt).trajectory) == moved


def test_a_fold_to_tablet_style_is_refused() -> None:
    """motion_fit: "lies flat against the underside, tablet style" in the result: the screen cannot fold that far."""
    with pytest.raises(GroundingError, match="past flat"):
        animate("laptop_10101", "Fold the laptop screen all the way back round until it lies flat against the underside, tablet style.")


@pytest.mark.parametrize(("name", "prompt", "moved"), [
    # "leave the other clasp as found": kept still (the other clasp had been closed too, silently)
    ("extra/box_100214", "Close the clasp on the right-hand side of the chest as you face its front; leave the other clasp as found.", {"joint_2"}),
])
def test_round65_a_part_left_as_found(name: str, prompt: str, moved: set[str]) -> None:
    assert _moved(animate(name, prompt).trajectory) == moved


def test_a_turn_said_again_is_one_turn() -> None:
    """perceiver: "... Just spin it around where it sits" after "turn the toaster round" had turned it a second time, back
    to where it was, silently."""
    trajectory = animate("toaster_103477", "Could you turn the toaster round so it faces the other way? Just spin it around where it sits on "
                                           "the counter.").trajectory
    z, w = trajectory.base_rotation_xyzw[-1][2:]
    assert abs(abs(np.degrees(2 * np.arctan2(z, w))) - 180.0) < 5.0


@pytest.mark.parametrize(("name", "prompt", "joint", "final"), [
    # "Right back where it started!" after the door shut says it again (it had swung the door open again, silently)
    ("microwave_7119", "The door swings open... and SLAMS shut again! Right back where it started!", "joint_0", 0.0),
    # the way said inside "that's flopped forward" is how the lid is, not where it goes (how_it_is.told_way)
    ("suitcase_103762", "Swing the big flat slab that's flopped forward back up against the rest of the upright case, so it's shut.",
     "joint_0", -1.0472),
])
def test_round65_the_part_ends_where_asked(name: str, prompt: str, joint: str, final: float) -> None:
    assert _q(animate(name, prompt).trajectory, joint)[-1] == pytest.approx(final, abs=0.03)


def test_a_part_and_its_end_state_after_another_kind_of_step() -> None:
    """ellipsis.carry: "..., the plate gets one full turn, door shut": the door shuts (it had taken "turn" and been ignored)."""
    q = _q(animate("microwave_7119", "Door open, the plate gets one full turn, door shut. Textbook sequence from the microwave!").trajectory,
           "joint_0")
    assert q.max() > 1.2 and q[-1] == pytest.approx(0.0, abs=0.02)
