"""Where an object with no door, drawer or lid faces comes from its shape: a tap's spout, the side its controls sit on.
The cue turns with the object; without any cue the front is PartNet-Mobility's convention, and said to be."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from app.cli.main import main
from app.engine.asset.loader import load_asset
from app.engine.offline.front import FrontCue
from app.engine.offline.geometry import analyse
from benchmark.variants import make_variant
from tests.engine.offline.conftest import asset, asset_dir

MINUS_X = np.array([-1.0, 0.0, 0.0])
MINUS_Y = np.array([0.0, -1.0, 0.0])
"""-X turned 90 degrees about up (the ``yaw`` variant)."""

SHOWN = {"faucet_148": FrontCue.SPOUT, "faucet_991": FrontCue.SPOUT, "extra/faucet_1343": FrontCue.SPOUT,  # it reaches toward the user
         "toaster_103477": FrontCue.CONTROLS, "toaster_103483": FrontCue.CONTROLS, "coffee_machine_103030": FrontCue.CONTROLS,
         "extra/coffee_machine_102145": FrontCue.CONTROLS, "switch_100952": FrontCue.CONTROLS, "extra/safe_101612": FrontCue.CONTROLS,
         "microwave_7119": FrontCue.PARTS}
UNSHOWN = ["bucket_100454", "kitchen_pot_100038", "extra/toaster_103473"]  # round, or levers on two opposite ends


@pytest.mark.parametrize(("name", "cue"), SHOWN.items())
def test_a_front_shown_by_a_spout_or_controls(name: str, cue: FrontCue) -> None:
    geometry = analyse(asset(name))
    assert not geometry.front_by_convention
    assert geometry.front_cue is cue
    np.testing.assert_allclose(geometry.front, MINUS_X, atol=1e-9)


def test_inspect_says_what_showed_the_front(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["inspect", str(asset_dir("faucet_148"))]) == 0
    assert "front faces -X, shown by its spout" in capsys.readouterr().out
    assert main(["inspect", str(asset_dir("bucket_100454"))]) == 0
    assert "front faces -X by convention: nothing on it shows where it faces" in capsys.readouterr().out


@pytest.mark.parametrize("name", ["faucet_148", "toaster_103477", "extra/safe_101612"])
def test_the_front_turns_with_the_object(name: str, tmp_path: Path) -> None:
    turned = tmp_path / name.rsplit("/", 1)[-1]  # the folder's name gives the object's kind (a tap)
    make_variant(asset_dir(name), turned, ("yaw",))
    geometry = analyse(load_asset(turned))
    assert not geometry.front_by_convention
    np.testing.assert_allclose(geometry.front, MINUS_Y, atol=1e-9)


@pytest.mark.parametrize("name", UNSHOWN)
def test_no_cue_is_the_convention_and_said(name: str) -> None:
    geometry = analyse(asset(name))
    assert geometry.front_by_convention and geometry.front_cue is FrontCue.CONVENTION
    np.testing.assert_allclose(geometry.front, MINUS_X, atol=1e-9)


SHOWN_FIXED = ["extra/laptop_11395", "toaster_103498"]  # a laptop whose screen, a toaster whose lever, the URDF fixed


@pytest.mark.parametrize("name", SHOWN_FIXED)
def test_a_front_shown_by_a_fixed_screen_or_control_turns_with_the_object(name: str, tmp_path: Path) -> None:
    """The base lies in front of a fixed screen; a fixed control sits on the front. Turned 90 degrees, the front turns too."""
    assert analyse(asset(name)).front_cue is FrontCue.SCREEN
    np.testing.assert_allclose(analyse(asset(name)).front, MINUS_X, atol=1e-9)
    make_variant(asset_dir(name), tmp_path / name.split("/")[-1], ("yaw",))
    turned = analyse(load_asset(tmp_path / name.split("/")[-1]))
    assert turned.front_cue is FrontCue.SCREEN
    np.testing.assert_allclose(turned.front, MINUS_Y, atol=1e-9)


def test_two_doors_resting_ajar_still_show_the_front(tmp_path: Path) -> None:
    """A fridge whose two doors rest half open: each door's face is read with the other shut, so the front stays the front
    (it was lost to the convention when each open door turned the other's nearest face sideways)."""
    make_variant(asset_dir("refrigerator_11178"), tmp_path / "refrigerator_11178", ("mirror", "yaw", "ajar"))
    found = analyse(load_asset(tmp_path / "refrigerator_11178"))
    assert found.front_cue is FrontCue.PARTS
    np.testing.assert_allclose(found.front, MINUS_Y, atol=1e-9)
