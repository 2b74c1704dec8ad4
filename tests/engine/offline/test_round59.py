"""Classes found this session (round 59 and the leftovers of rounds 56-58, on the dev pool): each prompt here was
answered wrongly without a word of warning before the fix named beside it."""

from __future__ import annotations

import numpy as np
import pytest

from app.engine.errors import GroundingError
from app.engine.offline.perceiver import read_prompt
from tests.engine.offline.conftest import animate, asset


@pytest.mark.parametrize(("name", "prompt", "said"), [
    # a twist, or a turn by an angle, of a part that only slides (motion_fit.check_motion): the lid had been lifted
    ("extra/kitchen_pot_100015", "Twist the pot lid a quarter turn so it locks in place.", "only slides"),
    ("extra/kitchen_pot_100015", "rotate the lid", "only slides"),
    ("extra/kitchen_pot_100015", "turn the lid 90 degrees", "only slides"),
    # a part named as one that slides ("telescopic", "trolley handle") where the only such part swings
    ("extra/suitcase_100550", "pull up the telescopic trolley handle and extend it all the way", "only swings or turns"),
])
def test_a_motion_the_part_cannot_make_is_refused(name: str, prompt: str, said: str) -> None:
    with pytest.raises(GroundingError, match=said):
        animate(name, prompt)


@pytest.mark.parametrize(("name", "prompt", "joint"), [
    ("extra/kitchen_pot_100015", "lift the lid", "joint_0"),
    ("extra/suitcase_100550", "pull up the handle", "joint_1"),
])
def test_the_motion_the_part_makes_still_animates(name: str, prompt: str, joint: str) -> None:
    trajectory = animate(name, prompt).trajectory
    k = trajectory.joint_names.index(joint)
    assert abs(trajectory.q[-1, k] - trajectory.q[0, k]) > 0.01


@pytest.mark.parametrize(("prompt", "joint"), [
    # a count from a side, then the row it is in (mentions._trailing chains "in the top row" after "from the left"):
    # the row had been dropped, and the four keys of that column offered
    ("press the second button from the left in the top row", "joint_1"),
    ("press the second key from the left on the bottom row", "joint_10"),
    # "one" placed in a row, nothing named before: the only kind laid out in rows (one_kind.py); it had been refused
    ("press the second one from the left in the bottom row", "joint_10"),
])
def test_a_key_counted_along_its_row(prompt: str, joint: str) -> None:
    trajectory = animate("safe_101564", prompt).trajectory
    moved = {j for k, j in enumerate(trajectory.joint_names) if abs(trajectory.q[:, k] - trajectory.q[0, k]).max() > 1e-4}
    assert moved == {joint}


@pytest.mark.parametrize(("name", "prompt"), [
    # a part taken off its object, or put somewhere off it (detached.py): the handle had been swung, silently
    ("bucket_100454", "remove the handle from the bucket entirely and lay it on the floor beside it"),
    ("bucket_100454", "detach the handle"),
    ("bucket_100454", "take the handle off and put it on the table"),
    ("bottle_cap_3558", "pull the cap off and set it down next to the bottle"),
])
def test_a_part_cannot_come_off(name: str, prompt: str) -> None:
    with pytest.raises(GroundingError, match=r"fixed to .* by a joint"):
        animate(name, prompt)


def _final(name: str, prompt: str) -> dict[str, float]:
    trajectory = animate(name, prompt).trajectory
    return {j: float(trajectory.q[-1, k]) for k, j in enumerate(trajectory.joint_names)
            if abs(trajectory.q[:, k] - trajectory.q[0, k]).max() > 1e-3}


def test_the_whole_object_is_still_put_down() -> None:
    assert not _final("laptop_10101", "put the laptop on the table")  # a move of the whole object, no joint


@pytest.mark.parametrize("prompt", [
    # a draft, a dog, the steam: the subject of a story, never a part, and no room complaint when a motion follows
    "A draft from the hallway catches the door and pushes it partway open.",
    "A dog catches the door and pushes it partway open.",
])
def test_a_thing_that_moves_a_part_in_a_story(prompt: str) -> None:
    # the door rests fully open (0); "partway open" is a state, half of its travel from shut (it had stayed open or shut)
    final = _final("door_8877", prompt)
    assert set(final) == {"joint_1"} and -1.2 < final["joint_1"] < -0.4


@pytest.mark.parametrize("prompt", [
    # "the whole time" before a clause is "while"; a progressive after "while" is a motion at the same time (it was read as
    # how things are, and refused)
    "Keep the door wide open the whole time the plate is going round.",
    "keep the door open while the plate is spinning",
])
def test_held_while_something_else_moves(prompt: str) -> None:
    assert set(_final("microwave_7119", prompt)) >= {"joint_0"}
    trajectory = animate("microwave_7119", prompt).trajectory
    k = trajectory.joint_names.index("joint_1")
    assert abs(trajectory.q[:, k] - trajectory.q[0, k]).max() > 0.3


@pytest.mark.parametrize(("name", "prompt", "joints"), [
    # "from its closed state to fully open": the first state is where it starts (from_state.py); it had swung shut
    ("safe_102387", "Task: actuate the safe door from its closed state to fully open.", {"joint_0": 2.111}),
    ("safe_102387", "swing the door from shut to wide open", {"joint_0": 2.111}),
    # "whichever knob is farthest to the left": the knob that is (which_of.py); the largest knob had been taken
    ("washing_machine_103508", "Twist whichever knob is farthest to the left on the control panel.", {"joint_3": 1.571}),
    # "to the other end" of a slider resting between its ends: the end furthest from it (goals._OTHER_END); refused before
    ("toaster_103477", "There's a small slider round the back near the bottom. Slide it all the way to the other end - don't touch the "
     "lever on the front.", {"joint_2": -0.264}),
    # a half turn said without a way, on a cap that turns one way only: that way (it had been refused)
    ("bottle_cap_3558", "give the cap a half turn to loosen it", {"joint_0": 3.14}),
    # a latch that "clicks closed" stays closed (a brief verb with an end state); it had sprung back
    ("extra/box_100214", "Cutscene: the lid of the case slams shut, then the left latch clicks closed, then the right one.",
     {"joint_0": -1.676, "joint_1": 0.436, "joint_2": 0.436}),
    # "that oven's door" after "a rack in the small top oven": the top oven's door; "its door" after a rack: the door in front
    # of it; "so the rack can come out" is what it makes possible, no motion (the rack had been pushed back in)
    ("extra/oven_7179", "There's a rack in the small top oven. Open that oven's door so you can get at it, then slide the rack out.",
     {"joint_4": 1.571, "joint_0": 0.528}),
    ("extra/oven_7179", "I need the upper rack out of the big bottom oven — drop its door first so the rack can come out.",
     {"joint_3": 1.571, "joint_1": 0.528}),
    # "with the door freed, swing it open": "it" is the door the result names, not the wheel turned
    ("extra/safe_101623", "Turn the spoked wheel to draw the bolts back; with the door freed, swing it open.", {"joint_0": None, "joint_1": 2.13}),
    # a control named by use, then told how ("Set the timer — twist the bottom knob ..."): one knob (use_summary.py)
    ("extra/microwave_7128", "Set the timer — twist the bottom knob a quarter turn clockwise.", {"joint_2": -1.571}),
])
def test_round59_classes(name: str, prompt: str, joints: dict[str, float | None]) -> None:
    final = _final(name, prompt)
    assert set(final) == set(joints)
    for joint, value in joints.items():
        if value is not None:
            assert abs(final[joint] - value) < 0.01, (joint, final[joint])


def test_a_control_left_by_elimination_says_so() -> None:
    reading = read_prompt("set the timer, then turn the bottom knob", asset("extra/microwave_7128"))
    assert any("the timer" in n and "does not name otherwise" in n for n in reading.notes)


def test_held_then_the_other_part_moves() -> None:
    """"keep the door open while the plate goes round": the door opens first, the plate turns after, the door staying."""
    trajectory = animate("microwave_7119", "Keep the door wide open the whole time the plate is going round.").trajectory
    door, plate = (trajectory.joint_names.index(j) for j in ("joint_0", "joint_1"))
    q, t = trajectory.q, trajectory.times
    door_open = t[int(np.argmax(q[:, door] > 0.8 * 1.5708))]
    plate_starts = t[int(np.argmax(np.abs(q[:, plate] - q[0, plate]) > 1e-3))]
    assert plate_starts >= door_open and q[-1, door] > 1.5


def test_a_pocket_the_case_lacks_is_refused() -> None:
    with pytest.raises(GroundingError, match="no such movable part"):
        animate("suitcase_103762", "unzip the front pocket on the suitcase")


# round 60 (three more blind writers; tests/engine/offline/test_round59.py holds both rounds)
@pytest.mark.parametrize(("name", "prompt", "joints"), [
    # a hint of how many keys, then "start with ... finish on ..." (object_wants.py, start_with.py): every key had been
    # pressed, silently, then the keys refused; "the middle one of the top row" is placed in that row
    ("safe_101564", "Hint: the safe wants three keys. Start with the middle one of the top row, then the key right under it, and finish on "
     "the bottom-left key.", {"joint_1": None, "joint_4": None, "joint_11": None}),
    # "the little knob up and to the right of the spoked wheel": the relation across (it had taken both knobs, silently);
    # "spoked" in the reference does not make the knob meant the large one
    ("extra/safe_101623", "Give the little knob up and to the right of the spoked wheel a turn.", {"joint_2": None}),
    # "so that the bolts retract" on a safe with no bolts: what turning does, no second knob standing in for them
    ("safe_101593", "Turn the cross-shaped handle so that the bolts retract, and then open the door of the safe.", {"joint_1": None, "joint_0": None}),
    # "there's a small slider ..." after "on the end opposite the browning dial": "it" is the slider, not the dial too
    ("toaster_103477", "On the end opposite the browning dial there's a small slider down near the bottom. Push it all the way over to one side.",
     {"joint_2": None}),
    # "leave the other one hanging": as it is (the other clasp had been closed)
    ("extra/box_100214", "Animator note for shot 14: only the left-hand clasp on the front of the chest. Swing it up so it lies flat against the "
     "box, leave the other one hanging.", {"joint_1": 0.436}),
    # "..., which means that little door up there has to come down first": a clause of its own, ordered first
    ("extra/oven_7179", "I need to get the tray out of the top compartment, which means that little door up there has to come down first.",
     {"joint_4": 1.571, "joint_0": 0.528}),
    # a word on its own after a full stop takes no verb from the sentence before ("Cold only!" had been refused)
    ("faucet_991", "Push the mixer handle to the right as far as it goes. Cold only!", {"joint_0": -1.571}),
    # "let it lie against the rim" keeps it where it was put (it had been let go, back upright)
    ("bucket_100454", "Put the pail's handle down, would you? Just let it lie against the rim.", {"joint_0": 1.571}),
    # "a gust of wind catches the door and blows it shut"; "the cat jumps onto the back of the open screen and shoves it ..."
    ("door_8877", "A gust of wind catches the door and blows it shut.", {"joint_1": -1.571}),
    ("laptop_10697", "The cat jumps onto the back of the open screen and shoves it all the way back until it's lying flat.", {"joint_1": 1.074}),
    # "the panel that forms the top - tip it back": "it" is the part the description names
    ("box_102456", "on the wooden crate, the panel that forms the top - tip it back, as far back as it goes", {"joint_0": 2.094}),
])
def test_round60_classes(name: str, prompt: str, joints: dict[str, float | None]) -> None:
    test_round59_classes(name, prompt, joints)


@pytest.mark.parametrize(("name", "prompt", "joints"), [
    # what these fixes must not take: a place said with the description keeps "that one" the part placed
    ("coffee_machine_103030", "There's a piece sitting on the very top of the coffee maker - raise that one up.", {"joint_2": 0.5}),
    # "the top rack" read as a tray (no shelf here) is still moved by a result, not taken for a stand-in
    ("extra/oven_7179", "Drop the upper door open; as it opens it drags the top rack out with it, about 15 cm.", {"joint_4": 1.571, "joint_0": 0.15}),
    # "let some steam out": the steam is no subject here, and no part
    ("kitchen_pot_100038", "Let some steam out - lift the lid about 10 cm off the pot and leave it there", {"joint_0": None}),
])
def test_round60_fixes_keep(name: str, prompt: str, joints: dict[str, float | None]) -> None:
    test_round59_classes(name, prompt, joints)


@pytest.mark.parametrize(("name", "prompt", "joints"), [
    # a plural subject acting ("the android's fingers turn the dial") and "only after that does it lift ...": both had no verb
    ("coffee_machine_103030", "The android's fingers turn the dial on the blender's base; only after that does it lift the little lid off the jug.",
     {"joint_0": None, "joint_2": 0.5}),
    # a heading whose one grounded mention is what carries "the food": "it" is the turntable (refused before)
    ("microwave_7119", "Inside the microwave, the round thing the food sits on: give it a quarter turn.", {"joint_1": -1.571}),
    # "the spring in the oven door's shot" ("'s" before "shot" is "has"): "it" is the door; "unlatch it and it drops open" on a
    # door with no latch lets it go and it opens, as said (it had been refused)
    ("oven_7138", "The spring in the oven door's shot. Unlatch it and it just drops open under its own weight, all the way.", {"joint_0": 1.571}),
])
def test_round60_stories_and_headings(name: str, prompt: str, joints: dict[str, float | None]) -> None:
    test_round59_classes(name, prompt, joints)


@pytest.mark.parametrize(("name", "prompt", "joints"), [
    # round 61: parts told by what can be done with them (things_you_can.py); "the bigger one" given a spin keeps its "one"
    ("extra/safe_101623", "There are two things you can turn on that door. Turn the lower one.", {"joint_0": None}),
    ("safe_101593", "There are two things you can turn on the front of this safe. Give the bigger one a spin.", {"joint_1": None}),
])
def test_round61_classes(name: str, prompt: str, joints: dict[str, float | None]) -> None:
    test_round59_classes(name, prompt, joints)
