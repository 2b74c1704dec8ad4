"""Classes found by blind round 66 (three writers, the dev pool, half of the prompts naming parts in the writers' own
words) and by the misses rounds 62-65 left: each prompt here was answered wrongly — several without a warning — before the
fix named beside it."""

from __future__ import annotations

import numpy as np
import pytest

from app.engine.execute.trajectory import Trajectory
from app.engine.offline.perceiver import read_prompt
from tests.engine.offline.conftest import animate, asset


def _q(trajectory: Trajectory, joint: str) -> np.ndarray:
    return trajectory.q[:, trajectory.joint_names.index(joint)]


def _moved(trajectory: Trajectory) -> set[str]:
    return {j for k, j in enumerate(trajectory.joint_names) if abs(trajectory.q[:, k] - trajectory.q[0, k]).max() > 1e-3}


@pytest.mark.parametrize(("name", "prompt", "joint", "final"), [
    # "a turn to loosen, then back" (ellipsis: "back" after a verb with no "back" of its own returns): refused as going further
    ("bottle_cap_3558", "Half a turn to loosen the cap, then half a turn back to snug it down again.", "joint_0", 0.0),
    # "where it sits when shut" is the closed end (from_state.where_in_state): 90 degrees had been counted from the zero pose
    ("box_102456", "Raise the cover to a right angle: ninety degrees measured from where it sits when shut.", "joint_0", 0.7854),
    # where a step stops, said after it (left_short): "but leave it ... short of shut" had been dropped, the drawer pushed shut
    ("storage_23472", "The top drawer is sticking out. Push it in, but leave it open a crack - about two centimetres short of shut.",
     "joint_1", -0.244),
    ("storage_23472", "Push the top drawer in, but leave it open a crack.", "joint_1", -0.2376),
    # "let it flip back up" after a fold is a release (frames: "let" + "back"): it had flipped over to the other end
    ("extra/suitcase_100550", "fold the carrying grip on top down toward the front, keep it down there for three seconds, then let it "
                              "flip back up", "joint_1", 0.0),
    # "a five count" is five seconds (told_order._counted); "flick it straight back" is back at once, not upright (everyday)
    ("switch_100952", "Flick the light switch and flick it straight back - the classic 'anyone in here?' move.", "joint_0", 0.0),
    # "just enough that ..." says why (everyday): the clause had made the drawer ambiguous
    ("storage_19179", "Slide the bottom drawer out about a quarter of its travel, just enough that I can reach past it to the trap.",
     "joint_0", 0.25),
    # "through its full closing range" (casual_pieces): "range" had been read as a part
    ("laptop_10248", "Take the lid through its full closing range, all the way down.", "joint_1", -1.71),
])
def test_the_part_ends_where_asked(name: str, prompt: str, joint: str, final: float) -> None:
    assert _q(animate(name, prompt).trajectory, joint)[-1] == pytest.approx(final, abs=0.02)


@pytest.mark.parametrize(("name", "prompt", "moved"), [
    # a purpose said with a verb of its own before a gerund ("to simulate setting the timer": clauses._other_verb): both
    # knobs had turned, silently
    ("extra/microwave_7128", "Twist the upper of the two control knobs a quarter turn clockwise (front view), to simulate setting the timer.",
     {"joint_3"}),
    # a counted shape word ("the two round dials": part_words.shape_adjective): "round" had been the particle, both dials turned
    ("extra/microwave_7128", "Turn the upper of the two round dials on the panel by a quarter turn.", {"joint_3"}),
    # a part ruled out before it is named (not_that_one): "that one" had been the button, "it" the whole faucet
    ("dishwasher_12553", "Um, not the little button up at the top, sorry, the big panel underneath it. Could you open that one all the way?",
     {"joint_0"}),
    ("faucet_991", "Not the spout - the lever sitting on top! Push it all the way round to the right.", {"joint_0"}),
    # the object called "her" (object_her): refused as a part named "her round", the spring-back ignored
    ("stapler_103099", "Bring the stapler about: turn her round a full hundred and eighty degrees where she sits.", set()),
    # "the top bit", "clean off" (casual_pieces): refused as naming no part
    ("coffee_machine_103030", "Lift the very top bit clean off.", {"joint_2"}),
    # greetings and "be so kind as to" (a request's frame); "drop-front" is a door (the part lexicon)
    ("extra/oven_7179", "Good evening — would you be so kind as to let down the big drop-front at the bottom of the oven for our guest?",
     {"joint_3"}),
    # a part ruled out in note form (telegraphic_not): "Handle not touched." had lifted the handle
    ("extra/bucket_100432", "Bucket: lift 0.5 m straight up. Handle not touched.", set()),
    # "leave the drawer be" is leaving it alone (everyday): it had been opened; "swing the whole desk" turns the desk
    ("storage_20453", "swing the whole desk a quarter turn on the spot. Leave the drawer be.", set()),
    # "door opens, turntable does one full revolution, door closes" (word_forms: "does" stays finite): the door had closed
    # while the plate turned, or the list had been refused
    ("microwave_7119", "Sequence on the microwave: door opens, turntable does one full revolution, door closes.", {"joint_0", "joint_1"}),
    # "the door" after "the rack behind the top door" is that door (referents._named_before, an apposition's relation kept)
    ("extra/oven_7179", "Pull the upper rack — the one behind the small door on top — out halfway. The door you may open if it stands in "
                        "the way.", {"joint_0", "joint_4"}),
    # "it's got commitment issues" describes (everyday: "it has"): refused as a part named "commitment issues"
    ("washing_machine_103508", "Bring the lid halfway down from where it is now. Not shut - it's got commitment issues.", {"joint_0"}),
])
def test_only_the_asked_parts_move(name: str, prompt: str, moved: set[str]) -> None:
    assert _moved(animate(name, prompt).trajectory) == moved


def test_a_story_told_way_first() -> None:
    """"Round and round went the glass plate ... it spun exactly two whole times" (inverted; padded_units: "two whole
    times" is two turns): refused as opening the plate, or one turn for "2 whole" seconds."""
    q = _q(animate("extra/microwave_7128", "Round and round went the glass plate inside the microwave, it spun exactly two whole times, "
                                           "and then it stopped to rest.").trajectory, "joint_4")
    assert abs(q[-1] - q[0]) == pytest.approx(4 * np.pi, abs=0.1)


def test_a_story_told_way_first_comes_back_down() -> None:
    """"Up came the lid, then down it went again": the lid is back down (it had opened again)."""
    q = _q(animate("extra/kitchen_pot_100015", "Up came the lid, then down it went again.").trajectory, "joint_0")
    assert q.max() > 0.04 and q[-1] == pytest.approx(q[0], abs=1e-3)


def test_a_five_count_holds_five_seconds() -> None:
    outcome = animate("microwave_7236", "Hold the microwave door wide open for a five count, then let it swing shut.")
    q, t = _q(outcome.trajectory, "joint_0"), outcome.trajectory.times
    assert float(t[q > 0.95 * q.max()][-1] - t[q > 0.95 * q.max()][0]) >= 4.5 and q[-1] == pytest.approx(q[0], abs=1e-3)


def test_the_report_states_the_distance_said_later() -> None:
    """"lift the suitcase and hold it 1 metre off the ground": the report's step says 1 m (it had said the default 0.44 m)
    and no note of a default distance is left."""
    prompt = "lift the suitcase and hold it 1 metre off the ground"
    assert animate("extra/suitcase_100550", prompt).trajectory.base_translation[-1][2] == pytest.approx(1.0, abs=1e-3)
    reading = read_prompt(prompt, asset("extra/suitcase_100550"))
    assert [s["base"]["distance_m"] for e in reading.understanding for s in e["steps"]] == [1.0]
    assert not any(n.startswith("no distance given") for n in reading.notes)


@pytest.mark.parametrize(("name", "prompt", "joint", "final"), [
    # round 67 (amounts and ends in the writers' own words): "just short of flat" is almost flat (left_short); it had gone
    # flat, silently
    ("extra/oven_7179", "Kindly lower the large bottom door of the oven to just short of flat.", "joint_3", 1.414),
    ("suitcase_103762", "Swing the lid up until it's nearly shut.", "joint_0", -0.9425),
    # "After step 1 completes" with the labels read before (step_labels): it had been a step that shut the jug, silently
    ("coffee_machine_103030", "1) Raise the jug 3 cm off the motor base. 2) After step 1 completes, lift the lid 20 cm off the jug.",
     "joint_1", 0.03),
    # "Step 2: left drawer halfway": the label's "step" is no verb to carry (ellipsis); it had pushed the drawer shut
    ("extra/storage_25308", "Step 1: right drawer all the way out. Step 2: left drawer halfway.", "joint_1", 0.22),
    # "press the button that releases the door so it drops open": "it" is the door (whose_side.row_first); nothing had opened
    ("dishwasher_12553", "press the button that releases the door so it drops open", "joint_0", 1.571),
])
def test_round67_the_part_ends_where_asked(name: str, prompt: str, joint: str, final: float) -> None:
    assert _q(animate(name, prompt).trajectory, joint)[-1] == pytest.approx(final, abs=0.02)


@pytest.mark.parametrize(("name", "prompt", "moved"), [
    # "the oven does not tip" (a subject before "does not": clauses): "the oven" had turned the oven a second quarter turn
    ("oven_7138", "Rotate the entire oven a quarter turn about the vertical axis. The door stays closed and the oven does not tip.", set()),
    # "spin that half a turn" after a part named alone ("that" before an amount is "it": mentions)
    ("microwave_7119", "not the door, the round plate on the floor inside. spin that half a turn", {"joint_1"}),
    # a wish that names no part after a step ("I need the counter space"); "Can someone ..." (a request's frame)
    ("microwave_7236", "can you shove the whole microwave about 40 cm to the left, I need the counter space", set()),
    ("dishwasher_11700", "Can someone open the dishwasher please. I just need to get the clean plates out.", {"joint_0"}),
    # what people keep doing is a reason (how_it_is): "the kids keep mashing the keys" had been refused
    ("laptop_10697", "close the laptop and then turn the whole thing round so it faces the other way, the kids keep mashing the keys",
     {"joint_1"}),
    # "ease" moves the object; "keeping it square to the room" asks nothing more (kept_steady): both had been refused
    ("extra/oven_7179", "Ease the entire oven back toward the wall behind it by about twenty centimetres, keeping it square to the room.",
     set()),
    # "once it's home" is once it is shut (everyday): the cupboard door had been shut first
    ("storage_23472", "Push that top drawer back in first, and once it's home shut the cupboard door below it.", {"joint_0", "joint_1"}),
    # "- that's what sets the turntable going -" says how it works (said_aside); "come round once" spins the plate
    ("extra/microwave_7128", "Twist the top knob a quarter turn to set the timer - that's what sets the turntable going - and let the plate "
                             "come round once.", {"joint_3", "joint_4"}),
])
def test_round67_only_the_asked_parts_move(name: str, prompt: str, moved: set[str]) -> None:
    assert _moved(animate(name, prompt).trajectory) == moved


def test_not_at_the_same_time_is_in_turn() -> None:
    """"..., not at the same time" (telegraphic_not): the second drawer had started with the first, silently."""
    trajectory = animate("extra/storage_25308", "Right drawer all the way out, left drawer halfway, not at the same time.").trajectory
    first, second = _q(trajectory, "joint_0"), _q(trajectory, "joint_1")
    assert trajectory.times[np.argmax(second > second[0] + 1e-3)] >= trajectory.times[np.argmax(first >= first[-1] - 1e-3)]


@pytest.mark.parametrize("prompt", [
    "Can you lift the bucket straight up, maybe 30 centimetres? Just up, no tipping it.",  # kept_steady: "no tipping it"
    "Pick up that bucket! Half a metre straight up! Move it!",  # the lift's distance, then the motion said again
])
def test_a_lift_said_again_is_one_lift(prompt: str) -> None:
    height = 0.3 if "30" in prompt else 0.5
    base = animate("extra/bucket_100432", prompt).trajectory.base_translation[-1]
    assert base == pytest.approx([0.0, 0.0, height], abs=1e-3)


@pytest.mark.parametrize(("name", "prompt", "moved"), [
    # round 68 (whole voices): a likeness said after a step (similes): "the laptop like" and "a wine" had been read as parts
    ("laptop_10697", "Close the laptop like the evening forecast wrapping up, then pop it back open to exactly where it was.", {"joint_1"}),
    # "a sliver of light" is no amount (only "just a sliver" is): the door opens a crack, as "just a crack" says
    ("microwave_7236", "Open the microwave door just a crack, a sliver of light spilling out, nothing more.", {"joint_0"}),
    # "withdraw" is a verb (it had been split into "with draw" and the rack left shut)
    ("extra/oven_7179", "First lower the main oven door, the bottom one, completely; only thereafter withdraw the lowest rack from behind it.",
     {"joint_3", "joint_2"}),
    # bolts the asset lacks, named beside a door in the purpose (revisions.restated_means): the second knob had turned too
    ("extra/safe_101623", "Turn the spoked wheel to withdraw the locking bolts, whereupon the door is swung to its fully open position.",
     {"joint_0", "joint_1"}),
    # "chuck the bag in": a thing put in, though "bag" names an object elsewhere (it had been refused)
    ("trash_can_102155", "Flip the lid up, chuck the bag in, and let it drop shut again.", {"joint_2"}),
    # the step described after a dash ("— a quiet, almost tentative first move": said_aside)
    ("safe_101564", "She taps the top-left key on the keypad — a quiet, almost tentative first move.", {"joint_0"}),
    # "I'd like to nose what's simmering" (a wish naming no part); "heave" lifts; ", lid and all," (kept_steady)
    ("extra/kitchen_pot_100015", "Lift the lid off the stockpot, please, I'd like to nose what's simmering.", {"joint_0"}),
    ("extra/kitchen_pot_100015", "Heave the whole pot, lid and all, straight up about half a metre.", set()),
])
def test_round68_only_the_asked_parts_move(name: str, prompt: str, moved: set[str]) -> None:
    assert _moved(animate(name, prompt).trajectory) == moved


@pytest.mark.parametrize(("name", "prompt", "joint", "final"), [
    # "just a sliver" is a crack (the amount lexicon), the simile after it dropped: the door had opened all the way
    ("oven_7221", "Crack the door open, just a sliver, the way you'd ease a door to see if anyone's home.", "joint_0", 0.1571),
    # "flat on the floor" is flat (casual_pieces), "like a little bed" no amount: refused, or opened a fifth of the way
    ("extra/suitcase_100550", "Lay the case's front shell open, flat on the floor, and let it rest there five seconds, as you'd let a "
                              "wine breathe.", "joint_0", 1.571),
    ("suitcase_103762", "Now let's open our suitcase right down until the lid is lying flat on the floor, like a little bed!", "joint_0", 0.5236),
])
def test_round68_the_part_ends_where_asked(name: str, prompt: str, joint: str, final: float) -> None:
    assert _q(animate(name, prompt).trajectory, joint)[-1] == pytest.approx(final, abs=0.02)


@pytest.mark.parametrize(("prompt", "degrees"), [
    ("Let's turn the toaster a quarter of the way round, so its side is looking at us!", 90.0),  # it had turned half a turn, silently
    ("And he spins the toaster right round, it's facing the other way now, what a turn!", 180.0),  # "right round" stays a half turn
])
def test_a_fraction_of_the_way_round(prompt: str, degrees: float) -> None:
    """"a quarter of the way round" is a quarter of a full circle (whole_object); "right round" is still a half turn."""
    rotation = animate("toaster_103483", prompt).trajectory.base_rotation_xyzw[-1]
    assert abs(2 * np.degrees(np.arctan2(rotation[2], rotation[3]))) == pytest.approx(degrees, abs=0.5)
