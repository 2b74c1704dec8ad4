"""The offline agent reads the object, not how its URDF is written: the same asset with every joint's axis and
limits negated, links and joints numbered backwards and its elements in reverse order (``benchmark.metamorphic``)
animates exactly alike — each joint's track is the original's, negated and renamed. Rows are the classes the
metamorphic probe found reading the encoding: amounts measured from a closed end at the lower or the upper limit,
a side said after an amount ("as far left as it will go"), collision samples seeded by link name, the first lever
in file order."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from app.engine.asset.loader import load_asset
from app.engine.errors import GroundingError
from app.engine.execute.trajectory import Trajectory
from benchmark.metamorphic import Mapping, make_variant, mirror_words
from tests.engine.offline.conftest import animate, animate_model, asset_dir

ROWS = [
    ("laptop_10697", "Lower the screen until the laptop is only open about 45 degrees."),
    ("laptop_10101", "open the screen to 100 degrees from closed"),
    ("extra/storage_20279", "Push the drawer most of the way in so it's only open about 5 centimetres."),
    ("extra/faucet_1343", "swing the tap's lever as far left as it will go"),
    ("extra/faucet_1343", "Keep the lever swung fully left for 3 seconds, then return it to the middle."),
    ("extra/faucet_1343", "turn the lever a bit right"),
    ("extra/oven_7179", "drop the upper oven door open"),
    ("extra/toaster_103473", "Start toasting in the front slot."),
    ("safe_101593", "Spin the big dial a full turn clockwise to unlock it, and let the door swing open to 90°."),
    ("trash_can_102181", "press the pedal to raise the lid"),
    ("refrigerator_11178", "open the right door first, then the left one"),
    ("washing_machine_103508", "turn the rightmost knob 45 degrees clockwise"),
    ("box_100671", "close the lid on this box"),
    ("door_8877", "close the door 45 degrees"),
    ("trash_can_102155", "tow the bin 2 m forward by the handle"),
    ("bucket_100454", "let the handle fall forward"),
    ("bottle_cap_3558", "Back the cap off by 90 degrees."),
    ("storage_19179", "1. lower drawer out half its travel\n2. push it back shut\n3. upper drawer out 20 cm"),
    ("extra/oven_7179", "I need the rack out of the top oven."),
    ("door_8877", "Open the door an extra 20 degrees wider."),
]
TRANSFORMS = ("flip", "rename", "reorder")


@pytest.fixture(scope="module")
def variants(tmp_path_factory: pytest.TempPathFactory) -> dict[str, tuple[Path, Mapping]]:
    folder = tmp_path_factory.mktemp("variants")
    out: dict[str, tuple[Path, Mapping]] = {}
    for name in sorted({name for name, _ in ROWS}):
        target = folder / name.replace("/", "_")
        out[name] = (target, make_variant(asset_dir(name), target, TRANSFORMS))
    return out


@pytest.mark.parametrize(("name", "prompt"), ROWS, ids=[f"{n}: {p}" for n, p in ROWS])
def test_same_motion_whatever_the_encoding(name: str, prompt: str, variants: dict[str, tuple[Path, Mapping]]) -> None:
    folder, mapping = variants[name]
    try:
        original = animate(name, prompt).trajectory
    except GroundingError as refused:
        with pytest.raises(GroundingError) as also:
            animate_model(load_asset(folder), prompt)
        assert str(also.value).split(":")[0] == str(refused).split(":")[0]  # refused alike (the part names differ)
        return
    variant = animate_model(load_asset(folder), prompt).trajectory
    assert variant.q.shape == original.q.shape, "a different number of frames"
    moved = False
    for joint in original.joint_names:
        track = original.joint(joint)
        moved |= float(np.ptp(track)) > 1e-3
        assert np.allclose(variant.joint(mapping.name(joint)), mapping.sign(joint) * track, atol=1e-6), (
            f"{joint} (variant {mapping.name(joint)}): {track[-1]:.4f} on the original, {variant.joint(mapping.name(joint))[-1]:.4f} on the variant")
    assert np.allclose(variant.base_translation, original.base_translation, atol=1e-6)
    assert moved or original.has_base_motion(), "the row moves nothing: it tests nothing"


def _on_both(name: str, prompt: str, folder: Path, transforms: tuple[str, ...]) -> tuple[Mapping, Trajectory, Trajectory]:
    """The variant of ``name`` written into ``folder``, and ``prompt`` animated on the original and on it."""
    mapping = make_variant(asset_dir(name), folder / name, transforms)
    return mapping, animate(name, prompt).trajectory, animate_model(load_asset(folder / name), prompt).trajectory


AJAR_ROWS = [
    ("storage_20453", "open the drawer"),
    ("refrigerator_11178", "open the left door"),
    ("microwave_7119", "open the door"),
    ("storage_19179", "pull the top drawer all the way out"),
    ("dishwasher_11700", "open the dishwasher door"),
    ("extra/microwave_7128", "press the button on the control panel"),  # the door ajar sticks out past the button's face
]


@pytest.mark.parametrize(("name", "prompt"), AJAR_ROWS, ids=[f"{n}: {p}" for n, p in AJAR_ROWS])
def test_the_same_end_from_a_part_resting_ajar(name: str, prompt: str, tmp_path: Path) -> None:
    """Doors, lids and drawers resting 30% open instead of at a limit (``ajar``): "open it" / "close it" ends in the same pose."""
    mapping, original, variant = _on_both(name, prompt, tmp_path, ("ajar",))
    assert mapping.offsets, "nothing rests at a limit: the row tests nothing"
    for joint in original.joint_names:
        track = original.joint(joint)
        if float(np.ptp(track)) > 1e-6:  # what the prompt moves ends in the same pose ...
            assert variant.joint(joint)[-1] == pytest.approx(mapping.value(joint, float(track[-1])), abs=1e-6), joint
        else:  # ... and what it does not stays where it rests, ajar or not
            assert float(np.ptp(variant.joint(joint))) < 1e-6, joint


YAW_ROWS = [
    ("refrigerator_11178", "swing the fridge door on the left halfway open"),
    ("washing_machine_103508", "turn the rightmost knob 45 degrees clockwise"),
    ("extra/oven_7179", "open the upper door, then pull the top rack out 20 cm"),
    ("trash_can_102155", "tow the bin 2 m forward by the handle"),
    ("microwave_7304", "Scoot the microwave 20 cm to the left."),
]


@pytest.mark.parametrize(("name", "prompt"), YAW_ROWS, ids=[f"{n}: {p}" for n, p in YAW_ROWS])
def test_an_object_with_a_front_turned_on_the_table_moves_alike(name: str, prompt: str, tmp_path: Path) -> None:
    """Turned 90 degrees (``yaw``), an object whose doors, drawers or named parts show its front is read alike: the same
    joints move the same way, and a whole-object motion turns with it."""
    _, original, variant = _on_both(name, prompt, tmp_path, ("yaw",))
    assert np.allclose(variant.q, original.q, atol=1e-6)
    turn = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    assert np.allclose(variant.base_translation, original.base_translation @ turn.T, atol=1e-6)


MIRROR_ROWS = [
    ("coffee_machine_103030", "Turn the speed dial a quarter turn counterclockwise, and then another 45 degrees the same way."),
    ("coffee_machine_103030", "Turn the speed dial a quarter turn counterclockwise, then do the same again."),
    ("extra/box_100214", "Close the lid. Once it's down, fasten the left-hand latch - only that one, the other stays open."),
    ("refrigerator_11178", "open the left door halfway, then the right one all the way"),
    ("extra/faucet_1343", "swing the lever 30 degrees to the right"),
    ("washing_machine_103508", "turn the rightmost knob 45 degrees clockwise"),
    ("microwave_7304", "Scoot the microwave 20 cm to the left."),
]


@pytest.mark.parametrize(("name", "prompt"), MIRROR_ROWS, ids=[f"{n}: {p}" for n, p in MIRROR_ROWS])
def test_the_mirror_image_said_with_its_sides_swapped_moves_alike(name: str, prompt: str, tmp_path: Path) -> None:
    """The object's mirror image (``mirror``), asked with left/right and clockwise/counterclockwise swapped, moves the
    same joints to the same values (a reflection keeps each joint's values), and a whole-object motion is mirrored."""
    make_variant(asset_dir(name), tmp_path / name, ("mirror",))
    original = animate(name, prompt).trajectory
    variant = animate_model(load_asset(tmp_path / name), mirror_words(prompt)).trajectory
    assert np.allclose(variant.q, original.q, atol=1e-6)
    assert np.allclose(variant.base_translation, original.base_translation * [1.0, -1.0, 1.0], atol=1e-6)
    assert float(np.ptp(original.q)) > 1e-3 or original.has_base_motion(), "the row moves nothing: it tests nothing"


def test_a_distance_raised_is_from_where_the_part_rests(tmp_path: Path) -> None:
    """"raise the lid 20 cm" on a pot whose lid rests ajar (15 cm up): 20 cm higher than it rests, not 20 cm off the rim."""
    mapping = make_variant(asset_dir("kitchen_pot_100038"), tmp_path / "kitchen_pot_100038", ("ajar",))
    assert mapping.offsets, "the lid does not rest ajar: the test tests nothing"
    track = animate_model(load_asset(tmp_path / "kitchen_pot_100038"), "raise the lid 20 cm").trajectory.joint("joint_0")
    assert track[-1] - track[0] == pytest.approx(0.2, abs=1e-6)


BACK_HOME_ROWS = [
    ("storage_20453", "slide the drawer back in", "close the drawer"),
    ("storage_20453", "slide that drawer back in till its shut", "close the drawer"),
    ("kitchen_pot_100038", "Put the lid back down on the pot.", "close the lid"),
]


@pytest.mark.parametrize(("name", "prompt", "plain"), BACK_HOME_ROWS, ids=[f"{n}: {p}" for n, p, _ in BACK_HOME_ROWS])
def test_back_in_on_a_part_resting_open_is_shut(name: str, prompt: str, plain: str, tmp_path: Path) -> None:
    """"slide the drawer back in" on a drawer resting open (nothing moved it yet): back where it belongs, shut — not "back to
    where it rests", which moves nothing."""
    mapping = make_variant(asset_dir(name), tmp_path / name, ("ajar",))
    assert mapping.offsets, "nothing rests ajar: the row tests nothing"
    asset = load_asset(tmp_path / name)
    said, shut = animate_model(asset, prompt).trajectory, animate_model(asset, plain).trajectory
    moved = [j for j in shut.joint_names if float(np.ptp(shut.joint(j))) > 1e-6]
    assert moved, "the plain prompt moves nothing: the row tests nothing"
    for joint in said.joint_names:
        assert said.joint(joint)[-1] == pytest.approx(shut.joint(joint)[-1], abs=1e-6), joint
