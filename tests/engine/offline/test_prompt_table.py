"""Table-driven behaviour of the offline agent: prompt -> which joints move, which way, how far.

Expectations are written from each asset's geometry (which limit is open, pressed, up)
and the prompt's meaning. ``upper``/``lower`` name the joint's limits; numbers are joint
values (radians or metres). Refusals must raise a GroundingError listing the movable parts.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pytest

from app.engine.errors import GroundingError
from tests.engine.offline.conftest import animate, asset

PI = math.pi
TOLERANCE = 0.02
BOX_100671_CLOSED = -0.3896
BOX_102456_CLOSED = -0.7854
SAFE_102387_CLOSED = -0.7854
WINDOW_103135_CLOSED = -0.276460154
LAPTOP_10101_CLOSED = -2.092300707
"""Closed ends (lower limits) of boxes that rest open: angles in prompts are measured from closed."""


@dataclass(frozen=True)
class E:
    """Expectation on one joint: final value, peak then return, unchanged, or any motion."""

    end: float | str | None = None
    peak: float | str | None = None
    still: bool = False
    moves: bool = False
    abs_end: float | None = None
    sign: int | None = None


@dataclass(frozen=True)
class Row:
    asset: str
    prompt: str
    joints: dict[str, E] = field(default_factory=dict)
    base: tuple[float, float, float] | None = None
    order: tuple[tuple[str, str], ...] = ()
    refuse: bool = False
    yaw_deg: float | None = None
    """The whole object ends turned this much about the vertical (counter-clockwise seen from above is positive)."""

    @property
    def id(self) -> str:
        return f"{self.asset}: {self.prompt}"


def R(asset_name: str, prompt: str, **kwargs: object) -> Row:
    return Row(asset_name, prompt, **kwargs)  # type: ignore[arg-type]


ROWS: list[Row] = [
    # --- paraphrase rounds 46-47 (dev prompts said again by other writers: chatty, terse, reordered, typed on a phone) ---
    R("extra/storage_26525", "About halfway - that's how far I want the drawer slid open.", joints={"joint_0": E(end=0.256)}),  # r46c_023
    R("toaster_103477", "Half a turn on the browning dial, please - twist it.", joints={"joint_0": E(end=-3.1416), "joint_1": E(still=True), "joint_2": E(still=True)}),  # r46c_039
    R("extra/microwave_7128", "180 degrees on the lower knob (there are two), please - turn it.", joints={"joint_2": E(end=-3.1416), "joint_0": E(still=True), "joint_1": E(still=True), "joint_3": E(still=True), "joint_4": E(still=True)}),  # r46c_054
    R("window_103135", "45 degrees - tilt the window open to that.", joints={"joint_0": E(end=0.5089)}),  # r46c_071
    R("box_100671", "Roughly 90 degrees - lift the chest's lid up to about that.", joints={"joint_0": E(end=1.1812)}),  # r46c_147
    R("extra/kitchen_pot_100015", "30 cm - a foot - off the rim: that's how high I want the pot lid raised.", refuse=True),  # r46c_021
    R("dishwasher_12553", "To make the dishwasher door drop open, hit the release button.", joints={"joint_1": E(moves=True), "joint_0": E(end=1.5708)}, order=(("joint_1", "joint_0"),)),  # r46c_113
    R("dishwasher_12553", "I want the dishwasher's door to drop open - press the release button so that it does.", joints={"joint_1": E(moves=True), "joint_0": E(end=1.5708)}, order=(("joint_1", "joint_0"),)),  # r46c_114
    R("extra/microwave_7128", "I'd like the microwave door to swing open - can you press the door-release button underneath the knobs to make that happen?", joints={"joint_1": E(moves=True), "joint_0": E(end=1.5708), "joint_2": E(still=True), "joint_3": E(still=True), "joint_4": E(still=True)}, order=(("joint_1", "joint_0"),)),  # r46a_010
    R("toaster_103483", "Let the toaster lever go back up after holding it all the way down for 2 seconds.", joints={"joint_0": E(peak=0.3)}),  # r46c_154
    R("toaster_103483", "Robot test - release the toaster lever so it springs back up, but only after you've depressed it fully and held it down for 3 s.", joints={"joint_0": E(peak=0.3)}),  # r46c_074
    R("extra/safe_101612", "Hold the safe's handle there for two seconds once you've turned it as far as it will go.", joints={"joint_2": E(moves=True), "joint_1": E(still=True)}),  # r46c_151
    R("window_103135", "Shut window, it's chilly.", joints={"joint_0": E(end=-0.2765)}),  # r46b_142
    R("suitcase_103762", "Shut the suitcase, needs to be travel-ready.", joints={"joint_0": E(end=-1.0472), "joint_1": E(still=True)}),  # r46b_036
    R("extra/box_100214", "Shut the right-hand clasp, meaning the one on my right when I'm facing the front; just flip it closed.", joints={"joint_2": E(end=0.4363), "joint_0": E(still=True), "joint_1": E(still=True)}),  # r46c_018
    R("extra/coffee_machine_102145", "could you lift the small lid on top of the coffee machine right up to the top, going as slow as possible", joints={"joint_1": E(end=0.036), "joint_0": E(still=True), "joint_2": E(still=True), "joint_3": E(still=True)}),  # r46c_084
    R("window_103135", "I'd like the casement swung open by 0.52 radians, counting from where it's completely shut.", joints={"joint_0": E(end=0.2435)}),  # r46a_018
    R("storage_23472", "I'd like the drawer up top on this door-and-drawer cabinet extended to its maximum, please.", joints={"joint_1": E(end=0.4), "joint_0": E(still=True)}),  # r46a_136
    R("extra/box_100214", "I'd like only the catch on the right put into its locked position, please - leave everything else as it is.", joints={"joint_2": E(end=0.4363), "joint_0": E(still=True), "joint_1": E(still=True)}),  # r46a_092
    R("extra/kitchen_pot_100015", "I want the lid seated back on the pot at the end, but first raise it by the entire 6 cm of its travel.", joints={"joint_0": E(peak=0.06)}),  # r46c_014
    R("extra/kitchen_pot_100015", "Could you raise the pot's lid all the way up for just a sec so I can look inside, then set it back down?", joints={"joint_0": E(peak=0.06)}),  # r46a_144
    R("trash_can_102155", "Turn the trash can's left-side wheel through half a revolution.", joints={"joint_1": E(end=3.1416), "joint_0": E(still=True), "joint_2": E(still=True)}),  # r46c_116
    R("trash_can_102155", "Could you turn the wheel on the bin's right side through one full revolution?", joints={"joint_0": E(end=6.2832), "joint_1": E(still=True), "joint_2": E(still=True)}),  # r46a_037
    R("refrigerator_11178", "Could you open the right-hand one of the two fridge doors?", joints={"joint_1": E(end=3.1416), "joint_0": E(still=True)}),  # r46a_077
    R("extra/box_100214", "The lid gets closed first; then lock the left latch, and the right one after that.", joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}, order=(("joint_0", "joint_1"), ("joint_1", "joint_2"),)),  # r46c_158
    R("bucket_102352", "Bucket handle: move from front side over to rest against the back side.", joints={"joint_0": E(end=4.7187)}),  # r46b_034
    R("extra/coffee_machine_102145", "Little lever on top of coffee machine -> shove all the way left. Left = my left when facing the machine from front.", joints={"joint_0": E(end=-0.6095), "joint_1": E(still=True), "joint_2": E(still=True), "joint_3": E(still=True)}),  # r46b_084
    R("extra/coffee_machine_102145", "Espresso lever: after swinging it 20 degrees over to the left and keeping it there for three seconds, let go so it springs back.", joints={"joint_0": E(peak=-0.3491), "joint_1": E(still=True), "joint_2": E(still=True), "joint_3": E(still=True)}),  # r46c_127
    R("storage_19179", "ok so bottom drawer, open it 40 cm thx", joints={"joint_0": E(end=0.4), "joint_1": E(still=True)}),  # r47d_002
    R("stapler_103099", "ok so whole stapler, 0.2 m to my left pls", joints={"joint_0": E(still=True)}, base=(0.0, 0.2, 0.0)),  # r47d_052
    R("switch_100952", "ok so toggle needs to go to the opposite end of its throw, snap it over thx", joints={"joint_0": E(end=0.3142)}),  # r47d_060
    R("kitchen_pot_100038", "pot needs lifting 15 cm off the stove pls", joints={"joint_0": E(still=True)}, base=(0.0, 0.0, 0.15)),  # r47d_053
    R("storage_19179", "ok so pull out the lower drawer of the table, i need somthing out of it", joints={"joint_0": E(end=1.0), "joint_1": E(still=True)}),  # r47d_098
    R("faucet_991", "Tap handle -> ~45deg left.", joints={"joint_0": E(end=0.7854)}),  # r47b_073
    R("suitcase_103762", "Zip up suitcase -> drive lid to completely closed.", joints={"joint_0": E(end=-1.0472), "joint_1": E(still=True)}),  # r47b_008
    R("extra/safe_102380", "Safe - drive door to closed pls.", joints={"joint_2": E(end=-1.3195), "joint_0": E(still=True)}),  # r47b_094
    R("extra/storage_25308", "Extend right drawer first; once open, extend left drawer.", joints={"joint_0": E(end=0.524), "joint_1": E(end=0.44)}, order=(("joint_0", "joint_1"),)),  # r47b_084
    R("box_100671", "Prop box open to 90deg relative to closed.", joints={"joint_0": E(end=1.1812)}),  # r47b_090
    R("trash_can_102181", "Don't use pedal - raise bin lid manually until it's open.", joints={"joint_1": E(end=3.1542), "joint_0": E(still=True)}),  # r47b_106
    R("extra/storage_25308", "Open right drawer first, left drawer after.", joints={"joint_0": E(end=0.524), "joint_1": E(end=0.44)}, order=(("joint_0", "joint_1"),)),  # r47b_080
    R("washing_machine_103508", "Turn the knob furthest left on washer one full revolution counterclockwise.", joints={"joint_3": E(end=-6.2832), "joint_0": E(still=True), "joint_1": E(still=True), "joint_2": E(still=True)}),  # r47b_044
    R("washing_machine_103508", "on the washing machine rotate the knob furthest left a quarter turn clockwise", joints={"joint_3": E(end=1.5708), "joint_0": E(still=True), "joint_1": E(still=True), "joint_2": E(still=True)}),  # r47d_084
    R("extra/safe_102380", "can u swing the safe door closed, the safe's standing open", joints={"joint_2": E(end=-1.3195), "joint_0": E(still=True)}),  # r47d_105
    R("dishwasher_12553", "Can you bring the front flap of the dishwasher down so it lies flat, leaving the buttons alone?", joints={"joint_0": E(end=1.5708), "joint_1": E(still=True)}),  # r47a_118
    R("toaster_103477", "basically i want some toast, make it happen thx", joints={"joint_1": E(end=0.428), "joint_0": E(still=True), "joint_2": E(still=True)}),  # r47d_012
    R("bottle_cap_3558", "Rotate cap half turn in unscrewing direction.", joints={"joint_0": E(end=3.14)}),  # r47b_108
    R("safe_101564", "Keys: press bottom row middle key -> then top-right key.", joints={"joint_10": E(peak=0.004), "joint_2": E(peak=0.004), "joint_0": E(still=True), "joint_1": E(still=True), "joint_11": E(still=True), "joint_13": E(still=True), "joint_3": E(still=True), "joint_4": E(still=True), "joint_5": E(still=True), "joint_6": E(still=True), "joint_7": E(still=True), "joint_8": E(still=True), "joint_9": E(still=True)}, order=(("joint_10", "joint_2"),)),  # r47b_053
    R("coffee_machine_103030", "Blender: topmost piece (small cap sitting right on top of jug) -> lift straight up, fully clear off.", joints={"joint_2": E(end=0.5), "joint_0": E(still=True), "joint_1": E(still=True)}),  # r47b_017
    R("kitchen_pot_100038", "saucepan cover, lift it as high as it can go pls", joints={"joint_0": E(end=0.5)}),  # r47d_055
    R("kitchen_pot_100038", "theres steam building up inside so can u get the lid off the pot", joints={"joint_0": E(end=0.5)}),  # r47d_047
    R("extra/microwave_7128", "one full revolution exactly on the microwave turntable pls, just spin it", joints={"joint_4": E(end=-6.2832), "joint_0": E(still=True), "joint_1": E(still=True), "joint_2": E(still=True), "joint_3": E(still=True)}),  # r47d_081
    R("microwave_7236", "Open the microwave door wide, and after holding it wide open for 4 s, close it.", joints={"joint_0": E(peak=1.5708)}),  # r47c_015
    R("refrigerator_11178", "I'd like the right-hand door swung to 90\u00b0 first, please, and after that the left-hand door opened as far as it goes.", joints={"joint_1": E(end=1.5708), "joint_0": E(end=3.1416)}, order=(("joint_1", "joint_0"),)),  # r47a_058
    R("dishwasher_12553", "door needs to unlatch and swing down open, so press the release button pls", joints={"joint_1": E(moves=True), "joint_0": E(end=1.5708)}, order=(("joint_1", "joint_0"),)),  # r47d_061
    R("dishwasher_12553", "ok so hit the release button, door should unlatch and swing down open", joints={"joint_1": E(moves=True), "joint_0": E(end=1.5708)}, order=(("joint_1", "joint_0"),)),  # r47d_062
    R("extra/box_100214", "Toolbox -> shut and latched.", joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}, order=(("joint_0", "joint_1"),)),  # r47b_117
    R("faucet_148", "Flick faucet lever to left limit, then return to centre.", joints={"joint_0": E(peak=1.5708)}),  # r47b_088
    R("trash_can_102181", "Press foot pedal with foot so lid opens up (pops open).", joints={"joint_0": E(moves=True), "joint_1": E(end=3.1542)}, order=(("joint_0", "joint_1"),)),  # r47b_026
    R("bucket_102352", "Rotate pail handle joint to far end of its range so handle rests across the back rim.", joints={"joint_0": E(end=4.7187)}),  # r47b_064
    R("faucet_991", "turn the faucet handle joint +1.0 rad toward the hot side pls, hot is the viewer's left", joints={"joint_0": E(end=1.0)}),  # r47d_091
    R("extra/microwave_7128", "I'd like the knob that's second from the top rotated 45° counterclockwise, please.", joints={"joint_2": E(end=0.7854), "joint_0": E(still=True), "joint_1": E(still=True), "joint_3": E(still=True), "joint_4": E(still=True)}),  # r47a_098
    R("extra/microwave_7128", "I'd like the uppermost knob on the microwave turned clockwise three-quarters of a full turn, please.", joints={"joint_3": E(end=-4.7124), "joint_0": E(still=True), "joint_1": E(still=True), "joint_2": E(still=True), "joint_4": E(still=True)}),  # r47a_034
    R("extra/toaster_103473", "ok so two slot toaster, sink the front lever first, after thats done sink the back lever too", joints={"joint_0": E(end=0.404), "joint_1": E(end=0.404)}, order=(("joint_0", "joint_1"),)),  # r47d_076
    R("dishwasher_12553", "Could you press the button that releases the latch, and then let the door fall all the way open?", joints={"joint_1": E(moves=True), "joint_0": E(end=1.5708)}, order=(("joint_1", "joint_0"),)),  # r46a_013
    R("safe_101564", "I'd like you to tap the centre button of the keypad's third row, counting from the top, please.", joints={"joint_7": E(peak=0.004), "joint_0": E(still=True), "joint_1": E(still=True), "joint_10": E(still=True), "joint_11": E(still=True), "joint_13": E(still=True), "joint_2": E(still=True), "joint_3": E(still=True), "joint_4": E(still=True), "joint_5": E(still=True), "joint_6": E(still=True), "joint_8": E(still=True), "joint_9": E(still=True)}),  # r46a_028
    R("dishwasher_11700", "Lower door until flat, pause 2s, raise back up.", joints={"joint_0": E(peak=1.5708)}),  # r46b_159
    R("extra/safe_102380", "Turn safe prop's combo dial clockwise by 60 degrees, leave door as is.", joints={"joint_0": E(end=-1.0472), "joint_2": E(still=True)}),  # r46b_114
    R("extra/suitcase_100550", "For four seconds I want the suitcase open, so open it up and keep it that way.", joints={"joint_0": E(end=1.5708), "joint_1": E(still=True)}),  # r46c_093
    # --- blind round 45 (the held-out mix again, written after rounds 43 and 44 were fixed) ---
    R("extra/microwave_7128", "This microwave door has no handle. Get it open for me, all the way.",  # no handle: its release
      joints={"joint_0": E(end="upper"), "joint_1": E(moves=True)}, order=(("joint_1", "joint_0"),)),
    R("extra/oven_7179", "I want to give the lower oven a proper clean, so I need both of its racks pulled out.",
      joints={"joint_3": E(end="upper"), "joint_1": E(end="upper"), "joint_2": E(end="upper"), "joint_0": E(still=True), "joint_4": E(still=True)}),
    R("extra/oven_7179", "I need to baste the chicken on the rack in the top oven.", joints={"joint_4": E(end="upper"), "joint_0": E(end="upper")},
      order=(("joint_4", "joint_0"),)),
    R("oven_7138", "I need to baste the roast in the oven.", joints={"joint_0": E(end="upper")}),
    R("safe_102387", "Leave the safe door open just a crack.", joints={"joint_0": E(end=SAFE_102387_CLOSED + 0.2896)}),  # a crack from closed
    R("storage_20453", "This cabinet is sticking out into the walkway; it should sit 40 cm further back, against the wall.", base=(0.4, 0.0, 0.0)),
    R("trash_can_102155", "The wheelie bin is too far away for me to reach, I need it half a metre closer.", base=(-0.5, 0.0, 0.0)),
    R("extra/suitcase_100550", "I'd rather have the lid side of the suitcase facing the wall instead of facing me.", yaw_deg=180.0),
    R("extra/suitcase_100550", "I want to see the back of the suitcase.", yaw_deg=180.0),
    R("kitchen_pot_100038", "I want to check whether the soup is boiling yet.", joints={"joint_0": E(sign=1)}),
    R("extra/storage_20279", "the drawr is stickin out, i keep bumpin into it", joints={"joint_0": E(end=-0.188)}),  # the g dropped
    R("storage_20453", "Shove the whole desk back about 40 cm, closer to the wall behind it.", base=(0.4, 0.0, 0.0)),  # closer to the wall: back
    R("extra/faucet_1343", "I need to rinse my hands.", joints={"joint_0": E(moves=True)}),  # "rinse" said as the verb is still the wish
    # --- blind round 44 (state-dependent and coupled cases; spatial, sequenced, control and hold prompts, a third indirect) ---
    R("extra/oven_7179", "The baking tray is sitting on the rack nearest the floor; slide that rack out for me.",  # a thing on the rack
      joints={"joint_3": E(end="upper"), "joint_2": E(end="upper"), "joint_0": E(still=True), "joint_1": E(still=True)}),
    R("extra/oven_7179", "I need to get at the bottom rack in the oven.", joints={"joint_3": E(end="upper"), "joint_2": E(end="upper")}),
    R("extra/oven_7179", "The chicken on the top shelf needs basting, bring it out where I can reach it.",
      joints={"joint_4": E(end="upper"), "joint_0": E(end="upper"), "joint_3": E(still=True)}),
    R("refrigerator_11178", "The milk is behind the fridge door on the left.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("refrigerator_11178", "Grab me a drink from the left side of the fridge, and don't leave the door hanging open.",
      joints={"joint_0": E(peak="upper", end=0.0), "joint_1": E(still=True)}),
    R("kitchen_pot_100038", "I just want to peek at the soup, then keep the heat in.", joints={"joint_0": E(peak=0.5, end=0.0)}),
    R("oven_7138", "I need to check on the roast.", joints={"joint_0": E(end="upper")}),
    R("extra/kitchen_pot_100015", "Let a bit of steam out of the pot.", joints={"joint_0": E(moves=True)}),
    R("toilet_102622", "Somebody forgot to flush.", joints={"joint_1": E(peak=-0.012, end=0.0), "joint_0": E(still=True)}),
    R("extra/safe_101623", "Open the safe door, but turn the little knob before you do.", joints={"joint_1": E(end="upper"), "joint_2": E(moves=True)},
      order=(("joint_2", "joint_1"),)),
    R("window_103135", "Close the window, but before that, open it all the way.", joints={"joint_0": E(end=WINDOW_103135_CLOSED)}),
    R("extra/box_100214", "I'm about to carry this box down the stairs, make sure it can't pop open on the way.",
      joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}),
    R("safe_102387", "Lock up the safe.", joints={"joint_0": E(end=SAFE_102387_CLOSED), "joint_1": E(moves=True)}, order=(("joint_0", "joint_1"),)),
    R("extra/suitcase_100550", "Pack a sweater into the suitcase and zip it back up.", joints={"joint_0": E(peak="upper", end=0.0)}),
    R("extra/microwave_7128", "The microwave door is latched and won't pull open. Get it open.",  # held shut: its release is worked
      joints={"joint_0": E(end="upper"), "joint_1": E(moves=True)}, order=(("joint_1", "joint_0"),)),
    R("extra/box_100214", "latch it up", joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}),  # not lifted
    R("extra/box_100214", "Make sure this chest can't flop open - latch it up.",
      joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}),
    R("laptop_10101", "Done with work for today, don't leave the screen sticking up.", joints={"joint_1": E(end=LAPTOP_10101_CLOSED)}),
    R("storage_23472", "Where did I put the cleaning stuff? Have a look in the cupboard at the bottom.",
      joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("extra/safe_102380", "teh safe is wide opne anyone can see my stuff", joints={"joint_2": E(end="lower")}),
    R("suitcase_103762", "All packed - the case shouldn't be gaping open like that.", joints={"joint_0": E(end="lower"), "joint_1": E(still=True)}),
    R("bucket_100454", "I can't stack buckets with that handle sticking straight up.", joints={"joint_0": E(moves=True)}),
    R("safe_101593", "The combination is already dialled in. Get the safe open using the spoked wheel.",
      joints={"joint_0": E(end="upper"), "joint_1": E(moves=True), "joint_2": E(still=True)}, order=(("joint_1", "joint_0"),)),
    R("microwave_7304", "Peek inside the microwave, then leave the door the way you found it.", joints={"joint_1": E(peak="upper", end=0.0)}),
    R("safe_102387", "Swing the safe door all the way open, then leave it as it was.", joints={"joint_0": E(peak="upper", end=0.0)}),
    R("faucet_991", "Run the hot water for a moment, then turn it off.", joints={"joint_0": E(peak=PI / 2, end=0.0)}),
    R("refrigerator_11178", "I need to look in the left side of the fridge for about five seconds, then it should be shut again.",
      joints={"joint_0": E(peak="upper", end=0.0), "joint_1": E(still=True)}),
    R("extra/safe_101612", "The handle on the safe is hanging straight down - turn it up so it points to the right.",
      joints={"joint_2": E(moves=True)}),  # the handle turns; the safe does not move
    R("safe_102387", "Push the door shut, and only once it's closed give the knob a twist to lock it.",
      joints={"joint_0": E(end=SAFE_102387_CLOSED), "joint_1": E(moves=True)}, order=(("joint_0", "joint_1"),)),
    # --- blind round 43 (indirect prompts: complaints about the room, things kept, "too far"; spatial and sequenced) ---
    R("toilet_102622", "I need to use the toilet and the lid is in the way.", joints={"joint_0": E(end="upper")}),  # shut: in the way
    R("toaster_103477", "I'd like some toast.", joints={"joint_1": E(end=0.428)}),  # what it makes: the lever down, not up
    R("toaster_103477", "The toast is sitting too low to grab, raise it up with the lever.", joints={"joint_1": E(end=-0.092)}),
    R("extra/storage_20279", "I keep banging my knee on that drawer sticking out.", joints={"joint_0": E(end=-0.188)}),
    R("laptop_10101", "I'm done working for today.", joints={"joint_1": E(end=LAPTOP_10101_CLOSED)}),
    R("laptop_10101", "I'm done working for today, put my laptop away.", joints={"joint_1": E(end=LAPTOP_10101_CLOSED)}),  # no base motion
    R("laptop_10101", "The screen is tilted too far toward me, I can't see it properly.", joints={"joint_1": E(sign=1)}),  # back a little
    R("window_103135", "There's a cold draft coming through the window.", joints={"joint_0": E(end=WINDOW_103135_CLOSED)}),
    R("window_103135", "It's getting stuffy in here.", joints={"joint_0": E(end="upper")}),
    R("box_102456", "I don't want dust getting into this box.", joints={"joint_0": E(end=BOX_102456_CLOSED)}),
    R("extra/storage_25308", "I keep my socks in the left drawer and I need a pair.", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("storage_19179", "The spare towels live in the drawer nearest the floor.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("storage_19179", "Pull out the top drawer after you've pulled out the bottom one.", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")},
      order=(("joint_0", "joint_1"),)),
    R("refrigerator_11178", "Grab me the milk, it's on the right-hand side of the fridge.", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("extra/oven_7179", "The casserole is in the bottom oven and I want to see how it's doing.",
      joints={"joint_3": E(end="upper"), "joint_4": E(still=True)}),
    R("extra/oven_7179", "Take the pizza out of the top oven.", joints={"joint_4": E(end="upper"), "joint_0": E(end="upper")},
      order=(("joint_4", "joint_0"),)),  # the one rack behind that door comes out with it
    R("extra/oven_7179", "The lasagna on the very bottom rack should be done by now, I want to get it out.",
      joints={"joint_3": E(end="upper"), "joint_2": E(end="upper"), "joint_4": E(still=True)}),
    R("kitchen_pot_100038", "Let me see how the soup is doing.", joints={"joint_0": E(sign=1)}),
    R("oven_7138", "Open the oven all the way, and when it's fully open bring it back up to halfway.", joints={"joint_0": E(end=PI / 4)}),
    R("faucet_991", "My hands are all soapy.", joints={"joint_0": E(moves=True)}),
    R("faucet_991", "turn on the water", joints={"joint_0": E(moves=True)}),
    R("washing_machine_103508", "See the dial sitting off on its own to the right? Give it a half turn.",
      joints={"joint_1": E(abs_end=PI), "joint_2": E(still=True), "joint_3": E(still=True)}),
    R("storage_20453", "This cabinet sticks out ten centimetres too far from the wall.", base=(0.1, 0.0, 0.0)),
    R("trash_can_102181", "I want to toss this wrapper in without touching the lid with my hands.",
      joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_0", "joint_1"),)),
    R("dishwasher_12553", "Dishes are all loaded, get the dishwasher going.", joints={"joint_1": E(peak=0.052, end=0.0)}),
    R("microwave_7119", "The mug in the microwave has its handle facing the back - I'd like it turned around to face me.",
      joints={"joint_1": E(abs_end=PI)}),  # the turntable carries the mug; the microwave itself does not turn
    # --- blind round 42 (the same mix, written after round 41's fixes) ---
    R("storage_19179", "My socks are in the lower drawer, pull it out for me.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("refrigerator_11178", "The milk is on the left side of the fridge, get that door open for me.",
      joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("washing_machine_103508", "Start a wash - turn the big dial a quarter turn clockwise.",  # the dial is how; the lid shut first
      joints={"joint_0": E(end="lower"), "joint_1": E(abs_end=PI / 2)}, order=(("joint_0", "joint_1"),)),
    R("safe_102387", "Lock up the safe, give the dial a spin.", joints={"joint_0": E(end=SAFE_102387_CLOSED), "joint_1": E(moves=True)},
      order=(("joint_0", "joint_1"),)),
    R("safe_101593", "turn the big wheel a quarter turn clockwise", joints={"joint_1": E(abs_end=PI / 2), "joint_2": E(still=True)}),
    R("safe_101593", "spin the wheels", refuse=True),  # "wheels": the safe has none (one wheel said is its wheel handle)
    R("dishwasher_12553", "The dishwasher is loaded and shut, start it.", joints={"joint_1": E(peak=0.052, end=0.0)}),
    R("trash_can_102181", "Keep the bin open with the pedal for a few seconds while I scrape my plate.",
      joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("oven_7138", "Peek at the roast in the oven, then close it up again.", joints={"joint_0": E(peak="upper", end=0.0)}),
    R("window_103135", "It's stuffy in here, let some fresh air in through the window.", joints={"joint_0": E(end="upper")}),
    R("refrigerator_11178", "The sodas are behind the left-hand fridge door — get one out for me.",
      joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("storage_23472", "Open the top one.", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("kitchen_pot_100038", "lift the lid off, then pop it back on", joints={"joint_0": E(peak="upper", end=0.0)}),
    R("laptop_10101", "Shut the laptop, leave it closed for a second, then open it back up halfway.",
      joints={"joint_1": E(end=(LAPTOP_10101_CLOSED + 1.0367) / 2)}),
    R("kitchen_pot_100038", "the pot needs to be covered", joints={"joint_0": E(end="lower")}),
    R("refrigerator_11178", "Get the milk out - it's on the shelf inside the right door.", joints={"joint_1": E(end="upper"),
                                                                                                  "joint_0": E(still=True)}),
    R("extra/storage_20279", "That drawer is poking out a few inches; shove it back in until it's flush with the cabinet.",
      joints={"joint_0": E(end=-0.188)}),  # "until ... the cabinet" names no holder
    # --- blind round 41 (state-dependent and coupled cases, prompts half indirect, on variant dev assets) ---
    R("extra/box_100214", "someone left the box lid open again", joints={"joint_0": E(end=-1.6755)}),  # a complaint: shut it
    R("extra/box_100214", "the lid is open and I keep banging my elbow on it", joints={"joint_0": E(end=-1.6755)}),
    R("storage_19179", "My keys are in the top drawer.", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("microwave_7119", "Heat up my leftovers in the microwave.",  # in, shut, run (no control: its turntable turns)
      joints={"joint_0": E(peak="upper", end=0.0), "joint_1": E(moves=True)}, order=(("joint_0", "joint_1"),)),
    R("washing_machine_103508", "Load my laundry, then turn the big dial a quarter turn clockwise to start the wash.",
      joints={"joint_0": E(end="lower"), "joint_1": E(abs_end=PI / 2)}, order=(("joint_0", "joint_1"),)),
    R("dishwasher_11700", "I've got a stack of dirty plates that need to go in the dishwasher.", joints={"joint_0": E(end="upper")}),
    R("laptop_10248", "I'm heading out and the laptop has to go in my bag.", joints={"joint_1": E(end="lower")}),
    R("extra/box_100214", "Fasten both clasps on the box.", joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363),
                                                                     "joint_2": E(end=0.4363)}, order=(("joint_0", "joint_1"),)),
    R("trash_can_102181", "Open the bin without using my hands, drop the banana peel in, then let the lid fall shut.",
      joints={"joint_0": E(peak="upper", end=0.0), "joint_1": E(peak="upper", end=0.0)}),  # the pedal is let go too
    R("kitchen_pot_100038", "I want to give the soup a stir, then cover it again.", joints={"joint_0": E(peak="upper", end=0.0)}),
    R("switch_100952", "It's way too dark in here.", joints={"joint_0": E(moves=True)}),
    R("dishwasher_12553", "The dishwasher is loaded — get it running.", joints={"joint_1": E(peak=0.052, end=0.0)}),  # not moved
    R("trash_can_102181", "Keep the bin open for a few seconds while I scrape my plate into it.",
      joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("storage_23472", "I need the napkins from the drawer and then the plates behind the cabinet door — drawer first.",
      joints={"joint_1": E(end="upper"), "joint_0": E(end="upper")}, order=(("joint_1", "joint_0"),)),
    R("extra/microwave_7128", "Pop the microwave open so I can put my mug in.",  # its release, then the door
      joints={"joint_1": E(peak=0.012), "joint_0": E(end="upper")}),
    R("safe_101593", "Turn the wheel handle and pull the safe door open.", joints={"joint_1": E(moves=True), "joint_2": E(still=True),
                                                                                  "joint_0": E(end="upper")}),
    R("safe_101564", "open the safe, the code is 1-5-9.", joints={"joint_0": E(peak=0.004), "joint_4": E(peak=0.004),
                                                                  "joint_8": E(peak=0.004), "joint_13": E(end="upper")},
      order=(("joint_8", "joint_13"),)),
    R("extra/oven_7179", "The casserole is in the bottom oven — open it up.", joints={"joint_3": E(end="upper"), "joint_4": E(still=True)}),
    R("extra/oven_7179", "Open the top oven door, then slide out the rack inside it.", joints={"joint_4": E(end="upper"),
                                                                                              "joint_0": E(end=0.528)}),
    R("toaster_103477", "Turn the toaster's browning knob a quarter turn clockwise.", joints={"joint_0": E(abs_end=PI / 2)}, base=None),
    # --- blind round 40 (cases and prompts, a third of the prompts indirect, on variant dev assets) ---
    R("extra/box_100214", "lock up the jewelry box with both clasps", joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363),
                                                                            "joint_2": E(end=0.4363)}, order=(("joint_0", "joint_1"),)),
    R("extra/box_100214", "Lock the box up so the kids can't get into it.",  # locked by its latches, the lid shut first
      joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}, order=(("joint_0", "joint_2"),)),
    R("safe_102387", "lock the safe by spinning the dial a quarter turn clockwise",
      joints={"joint_0": E(end=SAFE_102387_CLOSED), "joint_1": E(abs_end=PI / 2)}, order=(("joint_0", "joint_1"),)),
    R("extra/suitcase_100550", "The suitcase is facing the wrong way, spin it round so the other side faces me.", yaw_deg=180.0),
    R("microwave_7236", "I want the microwave's door facing the wall - turn it around.", joints={"joint_0": E(still=True)}, yaw_deg=180.0),
    R("microwave_7236", "Some soup exploded in there and I need to wipe out the inside of the microwave.", joints={"joint_0": E(end="upper")}),
    R("dishwasher_11700", "Time to load the dishes.", joints={"joint_0": E(end="upper")}),
    R("extra/box_100214", "lift the box off the table", joints={"joint_0": E(still=True)}, base=(0.0, 0.0, 0.36)),  # a place, no holder
    R("refrigerator_11178", "The ketchup is in the left-hand door of the fridge, open that one for me.",
      joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),  # where the thing is: what "that one" means
    R("extra/oven_7179", "I need to get the top tray out of the oven", joints={"joint_4": E(end="upper"), "joint_0": E(end=0.528)}),
    R("extra/oven_7179", "I want to check on the roast in the bottom oven", joints={"joint_3": E(end="upper"), "joint_4": E(still=True)}),
    # --- blind round 39 (cases and prompts on dev assets mirrored, flipped, shifted, moved, turned or resting ajar) ---
    R("extra/oven_7179", "i need to get the pizza stone off the very bottom rack",  # a thing on a rack: the rack out, its door first
      joints={"joint_3": E(end="upper"), "joint_2": E(end=0.528), "joint_1": E(still=True), "joint_4": E(still=True)}),
    R("dishwasher_12553", "run the dishwasher", joints={"joint_1": E(peak=0.052, end=0.0), "joint_0": E(still=True)}),  # not moved 1 m
    R("dishwasher_12553", "turn on the dishwasher", joints={"joint_1": E(peak=0.052, end=0.0), "joint_0": E(still=True)}),
    R("dishwasher_12553", "open the door, then run the dishwasher", joints={"joint_0": E(peak="upper", end=0.0),
                                                                            "joint_1": E(peak=0.052, end=0.0)}),  # it runs shut
    R("extra/microwave_7128", "start the microwave", refuse=True),  # two knobs, the button a door release: which one?
    R("washing_machine_103508", "start the washing machine", refuse=True),  # three knobs
    R("coffee_machine_103030", "Lift the jug off the base.", joints={"joint_1": E(end="upper"), "joint_2": E(still=True)}),
    R("toaster_103477", "Drop the bread in — lever down.", joints={"joint_1": E(end="upper")}),
    # --- blind round 38 (cases and prompts on dev assets re-encoded, mirrored, moved, flipped, turned or resting ajar) ---
    R("laptop_10697", "Fold the screen down flat shut, then flip it back up to where it was.", joints={"joint_1": E(peak=-1.9541, end=0.0)}),
    R("dishwasher_12553", "use the release button to unlatch the dishwasher door and only lower it a third of the way",
      joints={"joint_0": E(end=PI / 6), "joint_1": E(peak=0.052, end=0.0)}),  # "and only lower it": a step of its own
    R("extra/oven_7179", "I need to get the tray out of the top oven.", joints={"joint_4": E(end="upper"), "joint_0": E(end=0.528),
                                                                               "joint_3": E(still=True)}),
    R("extra/oven_7179", "pull the middle rack out, then close everything back up",  # the door opened for the rack shuts last
      joints={"joint_1": E(peak=0.528, end=0.0), "joint_3": E(peak="upper", end=0.0)}),
    R("safe_102387", "Twist the right-hand dial all the way round once, then pull the door open.",
      joints={"joint_1": E(abs_end=2 * PI), "joint_0": E(end="upper")}),
    R("extra/microwave_7128", "I spilled soup in the nuker, rotate the turntable half way round", joints={"joint_4": E(abs_end=PI),
                                                                                                       "joint_0": E(still=True)}),
    R("extra/microwave_7128", "I spilled soup in the nuker, rotate the turntable half way round so I can reach the mess at the back",
      joints={"joint_0": E(end="upper"), "joint_4": E(abs_end=PI)}, order=(("joint_0", "joint_4"),)),  # reaching in: the door first
    R("microwave_7119", "The glass plate in the microwave is sitting crooked, can you turn it a quarter turn by hand?",
      joints={"joint_0": E(end="upper"), "joint_1": E(abs_end=PI / 2)}, order=(("joint_0", "joint_1"),)),  # by hand: reach in
    R("microwave_7119", "turn the glass plate a quarter turn", joints={"joint_0": E(still=True), "joint_1": E(abs_end=PI / 2)}),
    R("coffee_machine_103030", "I want to drop some ice cubes into the blender jug, then cover it again",
      joints={"joint_2": E(peak="upper", end=0.0), "joint_1": E(still=True)}),  # the jug opens by its lid
    R("extra/suitcase_100550", "pack my jacket in the suitcase and shut it", joints={"joint_0": E(peak="upper", end=0.0)}),
    R("extra/safe_101623", "I need to grab the jewellery box out of the safe.", joints={"joint_1": E(end="upper")}),
    R("extra/safe_101623", "Turn the small knob up top on the door by a quarter turn.", joints={"joint_2": E(abs_end=PI / 2),
                                                                                                 "joint_0": E(still=True)}),
    R("extra/box_100214", "lock up the toolbox - shut the lid and snap both clasps closed",
      joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}),
    R("extra/box_100214", "Shut the lid and then do up both clasps.", joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363),
                                                                              "joint_2": E(end=0.4363)}),
    R("bucket_102352", "pick the bucket up by it's handle and lift it about 30 cm", joints={"joint_0": E(end=2.3593)},
      base=(0.0, 0.0, 0.3)),  # a handle lying down is stood up first
    R("storage_27044", "Push the cabinet back 10 cm so it sits flush against the wall.", base=(0.1, 0.0, 0.0)),
    R("safe_101564", "Tap in top-left, top-right, then bottom-left on the keypad, and after that open the door.",
      joints={"joint_0": E(peak=0.004), "joint_2": E(peak=0.004), "joint_11": E(peak=0.004), "joint_13": E(end="upper")},
      order=(("joint_0", "joint_2"), ("joint_2", "joint_11"))),
    # --- blind round 37 (cases, mostly state dependent, on dev assets negated, mirrored, turned or resting ajar) ---
    R("extra/oven_7179", "I need the very bottom rack pulled out about half way - drop the bottom door first obviously.",
      joints={"joint_3": E(end="upper"), "joint_2": E(end=0.264), "joint_1": E(still=True), "joint_4": E(still=True)}),
    R("extra/box_100214", "Shut the box lid, then flip both front latches up so it's locked.",
      joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}),
    # --- blind round 36 (cases on dev assets re-encoded, mirrored, or turned and resting ajar) ---
    R("dishwasher_12553", "Press the release button on the top right of the panel; that unlatches the door and it falls all the way open.",
      joints={"joint_1": E(peak=0.052), "joint_0": E(end="upper")}),  # "it" falls: the door the unlatching freed
    R("safe_102387", "Give the combination dial a quarter turn counter-clockwise - that trips the latch and the door swings open as far as "
      "it'll go.", joints={"joint_1": E(end=PI / 2), "joint_0": E(end="upper")}),
    R("laptop_10697", "Close the laptop, then push it back about 20 cm, away from where you sit.", joints={"joint_1": E(end=-1.9541)},
      base=(0.2, 0.0, 0.0)),
    R("extra/oven_7179", "Drop the bottom oven door fully open, then slide the higher of the two racks in there all the way out.",
      joints={"joint_3": E(end="upper"), "joint_1": E(end=0.528), "joint_0": E(still=True), "joint_2": E(still=True)}),
    R("extra/bucket_100432", "Pull the bucket handle up straight and use it to lift the bucket about 30 cm off the floor.",
      joints={"joint_0": E(end=0.4778)}, base=(0.0, 0.0, 0.3)),
    R("oven_7221", "Let me check on the roast in there.", joints={"joint_0": E(end="upper")}),
    R("extra/box_100214", "Close the lid of the box and then flip both front latches up so it's locked shut.",
      joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}),  # "locked" is a state, no lock
    R("safe_101564", "Punch in the code on the keypad - top left key, then top right, then the middle key on the bottom row - and then "
      "swing the safe door open.", joints={"joint_0": E(peak=0.004), "joint_2": E(peak=0.004), "joint_10": E(peak=0.004), "joint_13": E(end="upper")},
      order=(("joint_0", "joint_2"), ("joint_2", "joint_10"))),
    # --- blind round 35 (cases and prompts on dev assets mirrored, turned, flipped and resting ajar) ---
    R("extra/oven_7179", "Pull the tray in the small top compartment out about halfway.",
      joints={"joint_4": E(end="upper"), "joint_0": E(end=0.264), "joint_1": E(still=True), "joint_3": E(still=True)}),
    R("extra/oven_7179", "take both racks out of the oven", refuse=True),  # "both" among three racks: which two?
    R("switch_100952", "Press the lower half of the rocker switch to flip it, then pull the whole switch module about 10 cm straight out "
      "from the wall toward you.", joints={"joint_0": E(end=0.3142)}, base=(-0.1, 0.0, 0.0)),
    R("safe_101593", "Spin the spoked handle wheel a quarter turn clockwise to pull the bolts back, then swing the door open as wide as it'll "
      "go.", joints={"joint_1": E(end=-PI / 2), "joint_0": E(end="upper"), "joint_2": E(still=True)}),
    R("extra/safe_102380", "Close the safe door and then lock it by giving the T-handle a quarter turn clockwise.",
      joints={"joint_0": E(end=-PI / 2)}),
    R("box_102456", "Close the lid, then flip it back up to exactly where it is now.", joints={"joint_0": E(peak=BOX_102456_CLOSED)}),
    R("dishwasher_11700", "I've got a stack of dirty plates to load into the dishwasher.", joints={"joint_0": E(end="upper")}),
    R("toaster_103498", "Push the toaster back roughly 15 cm, away from the side with the lever.", base=(0.15, 0.0, 0.0)),
    R("microwave_7236", "I'm going to open the door", joints={"joint_0": E(end="upper")}),
    # --- blind round 34 (cases and prompts on dev assets flipped, mirrored, turned, moved or resting ajar) ---
    R("extra/microwave_7128", "Press the microwave's button in and hold it there for about two seconds before letting go.",
      joints={"joint_1": E(peak=0.012), "joint_0": E(still=True)}),  # a button that may release the door, said only as a button
    R("extra/microwave_7128", "press the door-release button", joints={"joint_1": E(peak=0.012), "joint_0": E(end="upper")}),
    R("extra/microwave_7128", "press the button so the door pops open", joints={"joint_1": E(peak=0.012), "joint_0": E(end="upper")}),
    R("extra/box_100214", "Close the box lid first, then do up the left clasp, and after that the right one.",
      joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}),
    R("extra/kitchen_pot_100015", "The soup's about to boil over, let a bit of steam escape from the pot.", joints={"joint_0": E(end=0.06)}),
    R("washing_machine_103508", "The little knob on the far right is the lid release. Give it a quarter turn clockwise so the lid pops all the "
      "way open, then let the knob spring back.", joints={"joint_0": E(end="upper"), "joint_1": E(peak=PI / 2), "joint_2": E(still=True)}),
    R("safe_101564", "Close the safe, then key in the lock code: top-left button, the one right under it, then the bottom-right one.",
      joints={"joint_0": E(peak=0.004), "joint_5": E(peak=0.004), "joint_9": E(peak=0.004), "joint_1": E(still=True)},
      order=(("joint_0", "joint_5"), ("joint_5", "joint_9"))),
    R("suitcase_103762", "Grab the suitcase by its top handle, lift it a few inches (10 cm or so), carry it half a metre to the right and put "
      "it back down.", base=(0.0, -0.5, 0.0)),
    R("storage_27044", "Pull the drawer out till it stops, then keep pulling so the whole little cabinet drags about 20 cm toward you.",
      joints={"joint_0": E(end="upper")}, base=(-0.2, 0.0, 0.0)),
    R("stapler_103099", "Close up the stapler - tuck the staple magazine back up into the top cover.", joints={"joint_0": E(end="lower")}),
    R("stapler_103099", "open the staple magazine", joints={"joint_0": E(end="upper")}),
    R("extra/laptop_11395", "Slide the laptop 30 cm to the left.", base=(0.0, 0.3, 0.0)),  # its screen is fixed: the base lies in front of it
    # --- blind round 33 (cases and prompts on dev assets turned, moved, mirrored, flipped or resting ajar) ---
    R("safe_101593", "crank the big spoked handle a quarter turn clockwise to pull the bolts, then swing the door all the way open",
      joints={"joint_1": E(end=-PI / 2), "joint_0": E(end="upper"), "joint_2": E(still=True)}),  # "the bolts" are no knob
    R("coffee_machine_103030", "lift the jug up as far as it goes — the lid's sitting on it, so it just rides along",
      joints={"joint_1": E(end=0.05), "joint_2": E(still=True)}),
    R("coffee_machine_103030", "lift the jug up as far as it goes; the lid rides along", joints={"joint_1": E(end=0.05), "joint_2": E(still=True)}),
    R("extra/oven_7179", "open the bottom oven door fully, then pull the upper rack in that compartment out halfway",
      joints={"joint_3": E(end="upper"), "joint_1": E(end=0.264), "joint_0": E(still=True), "joint_4": E(still=True)}),
    R("extra/oven_7179", "open the bottom oven door, then pull the upper rack in the bottom compartment out halfway",
      joints={"joint_3": E(end="upper"), "joint_1": E(end=0.264), "joint_0": E(still=True), "joint_4": E(still=True)}),
    R("extra/oven_7179", "Open the top oven door and slide the rack inside all the way out.",
      joints={"joint_4": E(end="upper"), "joint_0": E(end=0.528), "joint_1": E(still=True), "joint_3": E(still=True)}),
    R("extra/oven_7179", "Open the bottom oven door and slide the rack inside all the way out.", refuse=True),  # two racks behind it
    R("extra/oven_7179", "I need to check what's on the very bottom rack of the lower oven. Drop that door open and pull the rack out about "
      "halfway.", joints={"joint_3": E(end="upper"), "joint_2": E(end=0.264), "joint_1": E(still=True), "joint_4": E(still=True)}),
    R("extra/bucket_100432", "Grab the bucket by its handle and lift it about half a metre off the floor.", base=(0.0, 0.0, 0.5)),
    R("extra/bucket_100432", "Hold the bucket by the handle, then raise it 50 cm", base=(0.0, 0.0, 0.5)),
    R("extra/suitcase_100550", "Fold the carry handle on top back away from the lid first, otherwise it's in the way, then flop the lid open all "
      "the way.", joints={"joint_1": E(end=1.2217), "joint_0": E(end="upper")}, order=(("joint_1", "joint_0"),)),
    R("extra/suitcase_100550", "fold the handle toward the lid", joints={"joint_1": E(end=-1.2217)}),
    R("trash_can_102155", "flip the lid all the way open, then tilt the bin back and wheel it backwards about 40cm",
      joints={"joint_2": E(end="upper"), "joint_0": E(end=-3.6355), "joint_1": E(end=-3.6355)}, base=(0.4, 0.0, 0.0)),
    R("trash_can_102155", "tilt the bin back", refuse=True),  # tilting the whole object is not animated: said, not guessed
    R("extra/box_100214", "Press the lid down until it closes. The clasps on this box are spring-loaded, so both of them snap shut by themselves "
      "once the lid is down.", joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}),
    R("laptop_10697", "Tilt the screen so it sits at a right angle to the keyboard, like 90°.", joints={"joint_1": E(end=-0.3833)}),
    R("switch_100952", "Press the lower half of the rocker switch in.", joints={"joint_0": E(end=0.3142)}),
    R("microwave_7236", "I need to put a bowl of soup in there, get the door out of the way.", joints={"joint_0": E(end="upper")}),
    R("microwave_7236", "swing the door out of the way", joints={"joint_0": E(end="upper")}),
    R("trash_can_102181", "Give the foot pedal a quick tap and let it spring back.", joints={"joint_0": E(peak=0.5718)}),
    R("window_103135", "Crack the window open, something like 45 degrees.", joints={"joint_0": E(end=WINDOW_103135_CLOSED + PI / 4)}),
    # --- blind round 30 (mirrored and turned dev assets): a side before an amount, wheels the object rolled on ---
    R("trash_can_102155", "Give the wheel on the right a full spin.", joints={"joint_0": E(end=2 * PI)}),
    R("trash_can_102155", "give the wheel on the left a full turn", joints={"joint_1": E(end=2 * PI)}),
    R("trash_can_102155", "Roll the bin 1 metre forward - the wheels should turn as it goes.",
      joints={"joint_0": E(end=9.0888), "joint_1": E(end=9.0888)}, base=(-1.0, 0.0, 0.0)),
    R("trash_can_102155", "roll the bin 1 m forward, then turn the left wheel a full turn",
      joints={"joint_0": E(end=9.0888), "joint_1": E(end=9.0888 + 2 * PI)}, base=(-1.0, 0.0, 0.0)),
    R("trash_can_102155", "turn the left wheel a full turn forward, then another full turn forward", joints={"joint_1": E(end=4 * PI)}),
    R("extra/box_100214", "flip the left-hand latch up flat against the box", joints={"joint_1": E(end=0.4363)}),
    R("extra/safe_101623", "Open the safe door about 45 degrees.", joints={"joint_1": E(end=-0.3958)}),  # it rests 75 degrees open
    # --- blind round 32 (dev assets resting ajar, flipped, mirrored or turned) ---
    R("refrigerator_11178", "open both doors, then shut the right one first, then the left one",
      joints={"joint_0": E(peak="upper"), "joint_1": E(peak="upper")}),  # "the right one first" is no list's first: it is read
    R("safe_101564", "tap the three keys across the top row of the keypad, left to right",
      joints={"joint_0": E(peak=0.004), "joint_1": E(peak=0.004), "joint_2": E(peak=0.004), "joint_3": E(still=True), "joint_11": E(still=True)}),
    R("door_8877", "raise the whole door, frame and all, 5 cm straight up", base=(0.0, 0.0, 0.05)),
    R("suitcase_103762", "Fold the carry handle down flat toward the lid side.", joints={"joint_1": E(end=PI / 2)}),
    R("suitcase_103762", "Close the suitcase, then fold the handle down on the side away from the lid.",
      joints={"joint_0": E(end=-1.0472), "joint_1": E(end=-PI / 2)}),
    R("laptop_10101", "Open the laptop screen until it's 270 degrees from closed, like folding it all the way around.", refuse=True),
    R("laptop_10101", "Open the laptop screen until it's 100 degrees from closed.", joints={"joint_1": E(end=LAPTOP_10101_CLOSED + math.radians(100))}),
    R("microwave_7119", "I need just the microwave door closing.", joints={"joint_0": E(still=True)}),
    R("laptop_10697", "Fold the screen down to 45 degrees, then back to where it was.", joints={"joint_1": E(peak=-1.1687)}),
    R("coffee_machine_103030", "Two steps, one after the other: first the lid comes up off the jug, then - once the lid is up - the whole jug lifts "
      "out of the base.", joints={"joint_2": E(end=0.5), "joint_1": E(end=0.05)}),
    R("microwave_7119", "Shut the microwave door — once it's shut the turntable starts going round. Show about half a turn of the plate after the door closes.",
      joints={"joint_1": E(abs_end=PI)}),
    R("box_102456", "Lift the toy box lid 20 degrees higher than it is now, then let it settle back where it was.", joints={"joint_0": E(peak=0.3491)}),
    R("bucket_100454", "Let the bucket's handle fall flat on the side that faces me.", joints={"joint_0": E(end=-PI / 2)}),
    R("door_8877", "Somebody left this door sticking straight out. Swing it back so it sits flush in its frame.", joints={"joint_1": E(end=-PI / 2)}),
    R("storage_23472", "Close the cabinet door — don't touch the drawer, it stays out like it is.",
      joints={"joint_0": E(end=-0.3267), "joint_1": E(still=True)}),
    # --- blind round 31 (dev assets resting ajar, turned, flipped, mirrored) ---
    R("laptop_10697", "push the screen back as far as it'll go, then bring it back to its original angle", joints={"joint_1": E(peak=1.0744)}),
    R("extra/storage_25308", "Shift the whole cabinet half a metre to its left.", base=(0.0, 0.5, 0.0)),
    R("extra/safe_102380", "turn the combination dial a couple of turns to unlock it, and then the door swings open",
      joints={"joint_0": E(end=-4 * PI), "joint_2": E(end="upper")}),
    R("extra/safe_101623", "Open the safe door 45 degrees more.", joints={"joint_1": E(end=PI / 4)}),
    R("extra/box_100214", "Open the lid all the way back, close it again, then flip both latches up so they sit flat against the front.",
      joints={"joint_0": E(end=-1.6755), "joint_1": E(end=0.4363), "joint_2": E(end=0.4363)}),
    R("safe_101593", "Turning the big knob a quarter turn clockwise releases the bolt, and that lets the door swing open about 90 degrees.",
      joints={"joint_1": E(end=-PI / 2), "joint_0": E(end=PI / 2)}),
    R("safe_101593", "Dial it like a combination lock: turn the big dial right one full turn, then back left half a turn.",
      joints={"joint_1": E(end=-PI)}),
    # --- a bare "tilt" rocks a rocker over (it names no way of its own); "a (full) <unit>" is one unit ---
    R("switch_100952", "Tilt the wall switch 10 degrees.", joints={"joint_0": E(end=0.1745)}),
    R("switch_100952", "tilt the rocker a full degree", joints={"joint_0": E(end=PI / 180)}),
    R("switch_100952", "Tilt the rocker a full radian.", refuse=True),
    R("storage_19179", "pull the top drawer out an inch", joints={"joint_1": E(end=0.0254), "joint_0": E(still=True)}),
    R("storage_19179", "pull the top drawer out an inch and a half", joints={"joint_1": E(end=0.0381)}),
    R("storage_19179", "pull the top drawer out a half inch", joints={"joint_1": E(end=0.0127)}),
    R("storage_19179", "pull the top drawer out a couple of inches", joints={"joint_1": E(end=0.0508)}),
    R("storage_19179", "slide the top drawer out a few centimetres", joints={"joint_1": E(end=0.03)}),
    R("storage_19179", "pull the top drawer out several centimetres", joints={"joint_1": E(end=0.04)}),
    R("bucket_102352", "Hoist the bucket half a metre into the air.", base=(0.0, 0.0, 0.5)),
    R("storage_19179", "pull the top drawer a quarter of an inch out", joints={"joint_1": E(end=0.00635)}),
    R("storage_19179", "pull the top drawer out 2 and a half inches", joints={"joint_1": E(end=0.0635)}),
    R("storage_19179", "pull the top drawer out two inches and a half", joints={"joint_1": E(end=0.0635)}),
    R("storage_19179", "pull the top drawer out 5 cm, then 2 more centimetres", joints={"joint_1": E(end=0.07)}),
    R("storage_19179", "pull the top drawer out 5 cm, then a couple more centimetres", joints={"joint_1": E(end=0.07)}),
    R("microwave_7119", "open the door a dozen degrees", joints={"joint_0": E(end=PI / 15)}),
    R("storage_27044", "could u open teh drawer by a quarter metre (25 cm)?", joints={"joint_0": E(end=0.25)}),
    R("storage_27044", "open the drawer three quarters inch", joints={"joint_0": E(end=0.01905)}),
    R("storage_27044", "open the drawer an eighth inch", joints={"joint_0": E(end=0.003175)}),
    R("storage_27044", "open the drawer a quarter", joints={"joint_0": E(end=0.25 * 0.684)}),
    R("storage_27044", 'pull the drawer out 4"', joints={"joint_0": E(end=0.1016)}),
    R("storage_27044", 'pull the drawer out "4" inches', joints={"joint_0": E(end=0.1016)}),
    R("storage_27044", "pull the drawer out a decimetre", joints={"joint_0": E(end=0.1)}),
    R("storage_27044", "pull the drawer out 2 dm", joints={"joint_0": E(end=0.2)}),
    R("extra/faucet_1343", "swing the lever a single degree to the left", joints={"joint_0": E(end=PI / 180)}),
    # --- found by the metamorphic probe (benchmark/metamorphic.py; 2026-11-29): a side said after an amount, an
    # amount measured from a closed end that is the limit the state named ---
    R("extra/faucet_1343", "swing the tap's lever as far left as it will go", joints={"joint_0": E(end="upper")}),
    R("extra/faucet_1343", "push the lever as far right as possible", joints={"joint_0": E(end="lower")}),
    R("extra/faucet_1343", "swing the lever all the way left", joints={"joint_0": E(end="upper")}),
    R("extra/faucet_1343", "turn the lever hard right", joints={"joint_0": E(end="lower")}),
    R("extra/faucet_1343", "set the lever to full left", joints={"joint_0": E(end="upper")}),
    R("extra/faucet_1343", "turn the lever a bit right", joints={"joint_0": E(sign=-1)}),
    R("extra/faucet_1343", "Keep the lever swung fully left for 3 seconds, then return it to the middle.", joints={"joint_0": E(peak="upper")}),
    R("laptop_10697", "Lower the screen until it is open 45 degrees.", joints={"joint_1": E(end=-1.954 + PI / 4)}),
    R("bottle_cap_3558", "Back the cap off by 90 degrees.", joints={"joint_0": E(end=PI / 2)}),
    R("storage_19179", "1. lower drawer out half its travel\n2. push it back shut\n3. upper drawer out 20 cm",
      joints={"joint_0": E(peak=0.5), "joint_1": E(end=0.2)}),
    # --- generalisation probes (all pass with /tmp/probe/offline_generalisation.patch) ---
    R("storage_27044", "pull the nightstand drawer three quarters of the way out", joints={"joint_0": E(end=0.75 * 0.684)}),
    R("refrigerator_11178", "swing the fridge door on the left halfway open", joints={"joint_0": E(end=PI / 2), "joint_1": E(still=True)}),
    R("refrigerator_11178", "open the right door first, then the left one", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_1", "joint_0"),)),
    R("laptop_10697", "close the laptop halfway", joints={"joint_1": E(end=-1.954 / 2)}),
    R("door_8877", "close the door 45 degrees", joints={"joint_1": E(end=-PI / 4)}),
    R("bucket_100454", "tip the bucket handle over to the +X side", joints={"joint_0": E(end="upper")}),
    R("trash_can_102181", "press the pedal to raise the lid", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("trash_can_102181", "step on the pedal to lift the lid, then take your foot off", joints={"joint_0": E(peak="upper"), "joint_1": E(peak="upper")}),
    R("examples/microwave", "release the door by pushing the button", joints={"release_button_slide": E(peak="upper"), "door_hinge": E(end="upper")}),
    R("examples/cabinet", "unlatch the door and open it", joints={"latch_knob_turn": E(peak="lower"), "door_hinge": E(end="lower")}),
    R("examples/cabinet", "turn the knob to unlatch the door, then open it", joints={"door_hinge": E(end="lower")}),
    R("safe_101593", "unlock the safe by turning the handle, then open the door", joints={"joint_1": E(moves=True), "joint_2": E(still=True), "joint_0": E(end="upper")}),
    R("safe_102387", "open the safe door fully", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),  # door is ajar at rest
    R("washing_machine_103508", "turn the rightmost knob 45 degrees clockwise", joints={"joint_1": E(end=PI / 4), "joint_2": E(still=True)}),
    R("washing_machine_103508", "Shut the washer lid first, then rotate the leftmost small knob 90 degrees counterclockwise", joints={"joint_3": E(end=-PI / 2), "joint_2": E(still=True)}),
    R("microwave_7119", "make the glass tray rotate twice", joints={"joint_1": E(abs_end=4 * PI)}),
    R("trash_can_102155", "tow the bin 2 m forward by the handle", base=(-2.0, 0.0, 0.0), joints={"joint_0": E(moves=True)}),
    R("toaster_103483", "turn the toaster knob", refuse=True),
    R("storage_27044", "open the second drawer", refuse=True),
    # --- pedal bin (PartNet): pedal -> lid, the pedal holds the lid open ---
    R("trash_can_102181", "press the pedal to open the lid", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_0", "joint_1"),)),
    R("trash_can_102181", "Step on the foot pedal", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_0", "joint_1"),)),
    R("trash_can_102181", "open the bin", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_0", "joint_1"),)),
    R("trash_can_102181", "open the lid by pressing the pedal", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("trash_can_102181", "press the pedal, then release it", joints={"joint_0": E(peak="upper"), "joint_1": E(peak="upper")}),
    # the lid opens in proportion to the pedal, up to upright: half of its 180-degree range is upright, a full press
    R("trash_can_102181", "use the pedal to open the lid halfway", joints={"joint_0": E(end="upper"), "joint_1": E(end=3.15416 / 2)}),
    # --- wheeled bin: lid, rolling ---
    R("trash_can_102155", "open the lid", joints={"joint_2": E(end="upper"), "joint_0": E(still=True), "joint_1": E(still=True)}),
    R("trash_can_102155", "push the trash can 1 m along -X", base=(-1.0, 0.0, 0.0), joints={"joint_0": E(sign=1), "joint_1": E(sign=1), "joint_2": E(still=True)}),
    R("trash_can_102155", "roll the bin 0.5 m in the +x direction", base=(0.5, 0.0, 0.0), joints={"joint_0": E(sign=-1), "joint_1": E(sign=-1)}),
    R("trash_can_102155", "lift the bin 20 cm", base=(0.0, 0.0, 0.2), joints={"joint_0": E(still=True), "joint_2": E(still=True)}),
    R("trash_can_102155", "push the bin forward 1 m and let it roll", base=(-1.0, 0.0, 0.0), joints={"joint_0": E(sign=1)}),
    R("trash_can_102155", "drag the trash can 30 cm to the left", base=(0.0, 0.3, 0.0)),
    # --- safes: door, knobs ---
    R("safe_101593", "open the safe door", joints={"joint_0": E(end="upper")}),
    # a door does not need its knobs turned because it has knobs (issue 10 §3: only latches hold a door shut)
    R("safe_101593", "open the safe", joints={"joint_0": E(end="upper"), "joint_1": E(still=True), "joint_2": E(still=True)}),
    R("safe_101593", "rotate the left knob 90 degrees clockwise", joints={"joint_1": E(end=-PI / 2), "joint_2": E(still=True), "joint_0": E(still=True)}),
    R("safe_101593", "turn the right dial a quarter turn counterclockwise", joints={"joint_2": E(end=PI / 2), "joint_1": E(still=True)}),
    R("safe_101593", "spin the right knob two full turns", joints={"joint_2": E(abs_end=4 * PI), "joint_1": E(still=True)}),
    R("safe_101593", "swing the door open halfway", joints={"joint_0": E(end=2.96706 / 2)}),
    R("safe_101593", "close the safe door", joints={"joint_0": E(still=True)}),
    R("safe_102387", "close the safe", joints={"joint_0": E(end="lower")}),
    R("safe_102387", "open the safe door fully", joints={"joint_0": E(end="upper")}),
    R("safe_101564", "press the top left button", joints={"joint_0": E(peak="upper"), "joint_1": E(still=True), "joint_13": E(still=True)}),
    R("safe_101564", "open the safe", joints={"joint_13": E(end="upper"), "joint_0": E(still=True)}),
    # --- storage: drawers, door ---
    R("storage_19179", "pull out the top drawer", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("storage_19179", "open the bottom drawer halfway", joints={"joint_0": E(end=0.5), "joint_1": E(still=True)}),
    R("storage_19179", "open both drawers", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("storage_19179", "slide the upper drawer out by 30 cm", joints={"joint_1": E(end=0.3), "joint_0": E(still=True)}),
    R("storage_19179", "open the second drawer", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("storage_19179", "open the top drawer, then open the bottom drawer", joints={"joint_1": E(end="upper"), "joint_0": E(end="upper")}, order=(("joint_1", "joint_0"),)),
    R("storage_19179", "pull the top drawer out, then push it back in", joints={"joint_1": E(peak="upper"), "joint_0": E(still=True)}),
    R("storage_27044", "open the drawer slightly", joints={"joint_0": E(end=0.2 * 0.684)}),
    R("storage_20453", "pull the drawer all the way out", joints={"joint_0": E(end="upper")}),
    R("storage_23472", "open the cabinet door", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("storage_23472", "pull the drawer all the way out", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("storage_23472", "close the drawer", joints={"joint_1": E(end="lower")}),
    R("storage_23472", "open the door and pull out the drawer", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_0", "joint_1"),)),
    R("storage_23472", "after opening the door, slide the drawer out", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_0", "joint_1"),)),
    R("storage_23472", "pull out the drawer before opening the door", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_1", "joint_0"),)),
    # --- microwaves ---
    R("microwave_7119", "open the microwave", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("microwave_7119", "open the microwave door halfway", joints={"joint_0": E(end=PI / 4)}),
    R("microwave_7119", "open the door 45 degrees", joints={"joint_0": E(end=PI / 4)}),
    R("microwave_7119", "spin the turntable", joints={"joint_1": E(moves=True), "joint_0": E(still=True)}),
    R("microwave_7119", "rotate the glass plate one full turn", joints={"joint_1": E(abs_end=2 * PI), "joint_0": E(still=True)}),
    R("microwave_7119", "open the door, then spin the turntable at 2 rad/s for 3 seconds", joints={"joint_0": E(end="upper"), "joint_1": E(abs_end=6.0)}, order=(("joint_0", "joint_1"),)),
    R("microwave_7236", "swing open the microwave door", joints={"joint_0": E(end="upper")}),
    R("microwave_7304", "open the microwave door slowly", joints={"joint_1": E(end="upper")}),
    # --- ovens, dishwashers, fridge ---
    R("oven_7138", "open the oven", joints={"joint_0": E(end="upper")}),
    R("oven_7138", "open the oven door, then close it", joints={"joint_0": E(peak="upper")}),
    R("oven_7221", "open the oven door slightly", joints={"joint_0": E(end=0.2 * PI / 2)}),
    R("dishwasher_11700", "open the dishwasher", joints={"joint_0": E(end="upper")}),
    R("dishwasher_12553", "press the button", joints={"joint_1": E(peak="upper"), "joint_0": E(still=True)}),
    R("dishwasher_12553", "pull the dishwasher door open", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("refrigerator_11178", "open the left door of the fridge", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("refrigerator_11178", "open the right door", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("refrigerator_11178", "open both doors", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("refrigerator_11178", "open the left door, then the right door", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_0", "joint_1"),)),
    # --- laptops, lids, boxes ---
    R("laptop_10101", "close the laptop", joints={"joint_1": E(end="lower")}),
    R("laptop_10101", "open the laptop all the way", joints={"joint_1": E(end="upper")}),
    R("laptop_10248", "shut the laptop lid", joints={"joint_1": E(end="lower")}),
    R("laptop_10697", "fold the screen down", joints={"joint_1": E(end="lower")}),
    R("box_102456", "close the box", joints={"joint_0": E(end="lower")}),
    R("box_100671", "open the box lid", joints={"joint_0": E(end="upper")}),
    R("kitchen_pot_100038", "lift the lid off the pot", joints={"joint_0": E(end="upper")}),
    R("kitchen_pot_100038", "raise the pot lid by 10 cm", joints={"joint_0": E(end=0.1)}),
    R("coffee_machine_103030", "lift the coffee machine lid", joints={"joint_2": E(end="upper"), "joint_1": E(still=True)}),
    R("coffee_machine_103030", "turn the knob", joints={"joint_0": E(abs_end=PI / 2), "joint_2": E(still=True)}),
    R("toilet_102622", "lift the toilet lid", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    # the flush button rests at the deep end of its travel (its only travel leads outward): a press moves it along that
    # travel, with a note saying so (a blind round expected the motion; a refusal animated nothing)
    R("toilet_102622", "press the flush button", joints={"joint_1": E(peak="lower"), "joint_0": E(still=True)}),
    R("window_103135", "open the window", joints={"joint_0": E(end="upper")}),
    R("window_103135", "close the window", joints={"joint_0": E(end="lower")}),
    R("stapler_103099", "open the stapler", joints={"joint_0": E(end="upper")}),
    R("suitcase_103762", "open the suitcase", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("washing_machine_103508", "open the washing machine door", joints={"joint_0": E(end="upper")}),
    R("washing_machine_103508", "turn the middle knob 90 degrees", joints={"joint_2": E(abs_end=PI / 2), "joint_1": E(still=True), "joint_3": E(still=True)}),
    # --- controls: toaster, switch, faucet, cap ---
    R("toaster_103477", "push the toaster lever down", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("toaster_103477", "turn the toaster knob a quarter turn", joints={"joint_0": E(abs_end=PI / 2), "joint_1": E(still=True)}),
    R("toaster_103483", "press down the lever", joints={"joint_0": E(end="upper")}),
    R("switch_100952", "flip the switch", joints={"joint_0": E(end="upper")}),
    R("faucet_148", "rotate the faucet handle 45 degrees", joints={"joint_0": E(abs_end=PI / 4)}),
    R("bottle_cap_3558", "twist the bottle cap", joints={"joint_0": E(moves=True)}),
    # --- the project's examples (signs vary on purpose: see examples/README.md) ---
    R("examples/pedal_bin", "press the pedal to open the bin", joints={"pedal_pivot": E(end="upper"), "lid_hinge": E(end="lower")}, order=(("pedal_pivot", "lid_hinge"),)),
    R("examples/pedal_bin", "open the lid", joints={"pedal_pivot": E(end="upper"), "lid_hinge": E(end="lower")}, order=(("pedal_pivot", "lid_hinge"),)),
    R("examples/pedal_bin", "open the lid halfway", joints={"lid_hinge": E(end=-0.7)}),
    R("examples/pedal_bin", "step on the pedal, then let go of it", joints={"pedal_pivot": E(peak="upper"), "lid_hinge": E(peak="lower")}),
    R("examples/microwave", "press the door release button", joints={"release_button_slide": E(peak="upper"), "door_hinge": E(end="upper")}, order=(("release_button_slide", "door_hinge"),)),
    R("examples/microwave", "open the microwave", joints={"door_hinge": E(end="upper"), "release_button_slide": E(peak="upper"), "turntable_spin": E(still=True)}),
    R("examples/microwave", "spin the turntable counterclockwise", joints={"turntable_spin": E(sign=1), "door_hinge": E(still=True)}),
    R("examples/microwave", "rotate the turntable a half turn clockwise", joints={"turntable_spin": E(end=-PI)}),
    R("examples/cabinet", "pull out the top drawer", joints={"drawer_top_slide": E(end="upper"), "drawer_bottom_slide": E(still=True), "door_hinge": E(still=True)}),
    R("examples/cabinet", "open the bottom drawer halfway", joints={"drawer_bottom_slide": E(end=-0.175), "drawer_top_slide": E(still=True)}),
    R("examples/cabinet", "open the door", joints={"latch_knob_turn": E(peak="lower"), "door_hinge": E(end="lower")}, order=(("latch_knob_turn", "door_hinge"),)),
    R("examples/cabinet", "turn the latch knob, then open the door", joints={"latch_knob_turn": E(peak="lower"), "door_hinge": E(end="lower")}, order=(("latch_knob_turn", "door_hinge"),)),
    R("examples/cabinet", "open both drawers", joints={"drawer_top_slide": E(end="upper"), "drawer_bottom_slide": E(end="lower")}),
    R("examples/oven", "open the oven door, then slide the tray out", joints={"door_hinge": E(end="upper"), "tray_slide": E(end="lower")}, order=(("door_hinge", "tray_slide"),)),
    R("examples/oven", "pull out the tray", joints={"door_hinge": E(end="upper"), "tray_slide": E(end="lower")}, order=(("door_hinge", "tray_slide"),)),
    R("examples/oven", "drop the oven door open", joints={"door_hinge": E(end="upper"), "tray_slide": E(still=True)}),
    R("examples/toy_car", "push the car 0.5 m along +X", base=(0.5, 0.0, 0.0),
      joints={"wheel_front_left_axle": E(end=0.5 / 0.03), "wheel_front_right_axle": E(end=-0.5 / 0.03), "wheel_rear_left_axle": E(end=0.5 / 0.03)}),
    R("examples/toy_car", "push the toy car forward 40 cm", base=(0.4, 0.0, 0.0), joints={"wheel_rear_right_axle": E(end=-0.4 / 0.03)}),
    R("examples/toy_car", "roll the car backwards 20 cm", base=(-0.2, 0.0, 0.0), joints={"wheel_front_left_axle": E(end=-0.2 / 0.03)}),
    R("examples/toy_car", "give the car a push along +x and let it roll 0.3 m to a stop", base=(0.3, 0.0, 0.0), joints={"wheel_front_left_axle": E(end=0.3 / 0.03)}),
    R("examples/toy_car", "lift the car 10 cm", base=(0.0, 0.0, 0.1), joints={"wheel_front_left_axle": E(still=True)}),
    R("examples/toy_car", "open the trunk", refuse=True),
    # --- phrasing: keypads, orientation, direction, instruments, negation, ellipsis, elaboration ---
    R("safe_101564", "Type the code top-left, top-right, bottom-middle on the keypad", joints={"joint_0": E(peak="upper"), "joint_2": E(peak="upper"), "joint_10": E(peak="upper"), "joint_4": E(still=True)},
      order=(("joint_0", "joint_2"), ("joint_2", "joint_10"))),
    R("safe_101564", "press the middle key of the second row", joints={"joint_4": E(peak="upper"), "joint_1": E(still=True), "joint_7": E(still=True)}),
    R("safe_101564", "press the left button in the bottom row", joints={"joint_11": E(peak="upper"), "joint_9": E(still=True)}),
    R("trash_can_102181", "step on the pedal so the lid swings up to vertical", joints={"joint_1": E(end=PI / 2), "joint_0": E(end="upper")}),
    R("laptop_10697", "fold the screen backwards until it lies flat", joints={"joint_1": E(end="upper")}),
    R("bucket_102352", "raise the handle until it stands upright", joints={"joint_0": E(end=4.71867216569187 / 2)}),
    R("faucet_991", "turn the faucet handle halfway to the right", joints={"joint_0": E(end=-PI / 4)}),
    R("faucet_991", "swing the lever 90 degrees to the left", joints={"joint_0": E(end=PI / 2)}),
    R("bucket_100454", "lift the bucket 30 cm straight up by its handle", base=(0.0, 0.0, 0.3), joints={"joint_0": E(still=True)}),
    R("trash_can_102155", "roll the wheelie bin 1 m along -X on its wheels", base=(-1.0, 0.0, 0.0), joints={"joint_0": E(sign=1), "joint_2": E(still=True)}),
    R("kitchen_pot_100038", "lift the whole pot, lid and all, 25 cm", base=(0.0, 0.0, 0.25), joints={"joint_0": E(still=True)}),
    R("laptop_10248", "close the laptop, then slide it 0.3 m along +Y", base=(0.0, 0.3, 0.0), joints={"joint_1": E(end="lower")}),
    R("storage_27044", "push the nightstand 0.4 m back along +X", base=(0.4, 0.0, 0.0)),
    R("refrigerator_11178", "open the left fridge door, the one with the handle, to 90 degrees", joints={"joint_0": E(end=PI / 2), "joint_1": E(still=True)}),
    R("storage_23472", "swing the cupboard door below the drawer wide open", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("storage_23472", "The top drawer is sticking out; push it shut.", joints={"joint_1": E(end="lower"), "joint_0": E(still=True)}),
    R("laptop_10248", "tilt the laptop screen back by another 10 degrees", joints={"joint_1": E(end=math.radians(10))}),
    R("bottle_cap_3558", "unscrew the bottle cap by half a turn", joints={"joint_0": E(end=PI)}),
    R("safe_102387", "swing the safe door shut and then give the dial half a turn counterclockwise", joints={"joint_0": E(end="lower"), "joint_1": E(abs_end=PI)}),
    R("safe_101593", "spin the dial one and a half turns counterclockwise, then turn the spoked handle a quarter turn clockwise",
      joints={"joint_2": E(abs_end=3 * PI), "joint_1": E(end=-PI / 2)}, order=(("joint_2", "joint_1"),)),
    R("coffee_machine_103030", "take the lid off by lifting it 15 cm", joints={"joint_2": E(end=0.15)}),
    R("stapler_103099", "snap the stapler's staple magazine shut", joints={"joint_0": E(end="lower")}),
    R("examples/pedal_bin", "lift the lid by hand until it is fully open, without using the pedal", joints={"lid_hinge": E(end="lower"), "pedal_pivot": E(still=True)}),
    R("examples/pedal_bin", "slide the closed pedal bin 0.3 m along +Y", base=(0.0, 0.3, 0.0), joints={"lid_hinge": E(still=True)}),
    R("examples/microwave", "open the microwave with its release button, then push the door closed again by hand",
      joints={"release_button_slide": E(peak="upper"), "door_hinge": E(peak="upper")}),
    R("examples/oven", "take the tray out of the oven", joints={"door_hinge": E(end="upper"), "tray_slide": E(end="lower")}, order=(("door_hinge", "tray_slide"),)),
    R("examples/oven", "open the oven and take the tray out: drop the door fully open, then pull the tray all the way out",
      joints={"door_hinge": E(end="upper"), "tray_slide": E(end="lower")}, order=(("door_hinge", "tray_slide"),)),
    R("examples/cabinet", "unlatch the cupboard with the knob, open the door to 90 degrees, and only then let the knob turn back",
      joints={"door_hinge": E(end=-PI / 2), "latch_knob_turn": E(peak="lower")}, order=(("latch_knob_turn", "door_hinge"),)),
    R("examples/toy_car", "turn the front left wheel a quarter turn in the forward-rolling direction", joints={"wheel_front_left_axle": E(end=PI / 2), "wheel_front_right_axle": E(still=True)}),
    R("examples/toy_car", "spin the rear right wheel", joints={"wheel_rear_right_axle": E(moves=True), "wheel_front_right_axle": E(still=True)}),
    # --- elaboration of a whole-object motion, screw caps, on/off of an object's control, wheel rolling sense ---
    R("bucket_102352", "pick up the bucket by its handle and raise it 50 cm", base=(0.0, 0.0, 0.5),
      joints={"joint_0": E(end=2.3593)}),  # its handle rests lying on the rim: stood up first to lift it by (blind round 38)
    R("bucket_102352", "lift the bucket 20 cm and raise it 50 cm", base=(0.0, 0.0, 0.7)),
    R("bottle_cap_3558", "open the bottle", joints={"joint_0": E(end="upper")}),
    R("bottle_cap_3558", "open the bottle, then close it", joints={"joint_0": E(peak="upper")}),
    R("bottle_cap_3558", "close the bottle", joints={"joint_0": E(still=True)}),
    R("faucet_991", "turn on the tap", joints={"joint_0": E(end="upper")}),
    R("faucet_991", "turn on the faucet", joints={"joint_0": E(end="upper")}),
    R("faucet_991", "turn off the tap", joints={"joint_0": E(still=True)}),
    R("faucet_991", "turn the tap on, then turn it off", joints={"joint_0": E(peak="upper")}),
    R("faucet_148", "turn on the faucet", joints={"joint_0": E(end="upper")}),
    R("faucet_148", "turn off the tap", joints={"joint_0": E(still=True)}),
    R("examples/toy_car", "spin all four wheels", joints={"wheel_front_left_axle": E(sign=1), "wheel_rear_left_axle": E(sign=1),
                                                          "wheel_front_right_axle": E(sign=-1), "wheel_rear_right_axle": E(sign=-1)}),
    R("examples/toy_car", "turn all the wheels a quarter turn", joints={"wheel_front_left_axle": E(end=PI / 2), "wheel_rear_right_axle": E(end=-PI / 2)}),
    # --- probe 5: unknown part kinds, effect-clause amounts, relative "push it back", world sides ---
    R("examples/cabinet", "Lift the cabinet's top lid.", refuse=True),  # a side-hinged door is not a lid
    R("refrigerator_11178", "Open the ice dispenser flap.", refuse=True),
    R("kitchen_pot_100038", "Rotate the knob on the pot lid.", refuse=True),  # no knob: the lid is not moved instead
    R("examples/pedal_bin", "Depress the pedal halfway; the lid lifts about 40 degrees.",
      joints={"pedal_pivot": E(end=0.175), "lid_hinge": E(end=-math.radians(40))}, order=(("pedal_pivot", "lid_hinge"),)),
    R("safe_101593", "Turn the spoked handle a quarter turn clockwise to unlock the door, which swings open 60 degrees.",
      joints={"joint_1": E(end=-PI / 2), "joint_0": E(end=math.radians(60))}, order=(("joint_1", "joint_0"),)),
    R("safe_101564", "Push the bottom-middle key so the safe door unlocks and swings open 30 degrees.",
      joints={"joint_10": E(moves=True), "joint_13": E(end=math.radians(30))}),
    R("storage_19179", "Pull the top drawer out 30 cm, then push it back 10 cm.", joints={"joint_1": E(end=0.20)}),
    R("bucket_100454", "Swing the bucket handle down onto the rim on the +X side.", joints={"joint_0": E(end="upper")}),
    R("bucket_100454", "Swing the bucket handle down onto the rim on the -X side.", joints={"joint_0": E(end="lower")}),
    # --- refusals ---
    R("microwave_7119", "open the flux capacitor", refuse=True),
    R("storage_19179", "open the door", refuse=True),
    R("laptop_10101", "press the power button", refuse=True),
    R("toaster_103498", "push the lever down", refuse=True),
    R("safe_101593", "spin the wheels", refuse=True),
    R("oven_7138", "pull out the tray", refuse=True),
    R("refrigerator_11178", "open the drawer", refuse=True),
    R("bucket_100454", "xyzzy plugh", refuse=True),
    R("stapler_103099", "spin the propeller", refuse=True),
    R("laptop_10101", "open the flux capacitor", refuse=True),
    # --- blind probe 2: coupled amounts, release clauses, object names, carried amounts, preconditions ---
    R("trash_can_102181", "Push the pedal a quarter of the way down so the lid cracks open.",
      joints={"joint_0": E(end=0.25 * 0.57177), "joint_1": E(end=0.25 * PI / 2)}, order=(("joint_0", "joint_1"),)),
    R("examples/pedal_bin", "Press the pedal a third of the way down.", joints={"pedal_pivot": E(end=0.35 / 3), "lid_hinge": E(end=-1.4 / 3)}),
    R("trash_can_102181", "Open the bin lid with the foot pedal to 45 degrees and keep it there.",
      joints={"joint_0": E(end=0.285885), "joint_1": E(end=PI / 4)}, order=(("joint_0", "joint_1"),)),
    R("examples/pedal_bin", "Stomp on the pedal so the lid opens, then release it so the lid shuts.",
      joints={"pedal_pivot": E(peak="upper"), "lid_hinge": E(peak="lower")}),
    R("storage_19179", "Slide the chest of drawers 0.5 m along +X.", base=(0.5, 0.0, 0.0), joints={"joint_0": E(still=True), "joint_1": E(still=True)}),
    R("storage_19179", "push the bank of drawers 20 cm along -Y", base=(0.0, -0.2, 0.0), joints={"joint_0": E(still=True), "joint_1": E(still=True)}),
    R("examples/toy_car", "Push the car 0.3 m forward and then 0.3 m back to where it started.", base=(0.0, 0.0, 0.0)),
    R("examples/toy_car", "Spin the rear right wheel a half turn backward by hand.",
      joints={"wheel_rear_right_axle": E(end=PI), "wheel_rear_left_axle": E(still=True)}),
    R("examples/toy_car", "spin the front left wheel a half turn forward", joints={"wheel_front_left_axle": E(end=PI)}),
    R("bottle_cap_3558", "Squeeze the bottle.", refuse=True),
    R("examples/microwave", "Spin the turntable a half turn counterclockwise while the door is open.",
      joints={"door_hinge": E(end="upper"), "turntable_spin": E(end=PI)}, order=(("door_hinge", "turntable_spin"),)),
    R("microwave_7304", "Open the microwave door 90 degrees, wait, then shut it.", joints={"joint_1": E(peak=PI / 2)}),
    # --- probe 3: amounts in effect clauses, "back" on a part, angles from closed, let-verbs, vocabulary ---
    R("examples/cabinet", "Rotate the latch knob to free the door and let it swing open 20 degrees.",
      joints={"latch_knob_turn": E(peak="lower"), "door_hinge": E(end=-PI / 9)}),
    R("safe_101593", "Twist the small dial on the safe door to release it, then the door opens to 120 degrees.",
      joints={"joint_2": E(moves=True), "joint_0": E(end=2 * PI / 3)}),
    R("examples/pedal_bin", "Press the pedal down a quarter of its travel and watch the lid lift slightly.",
      joints={"pedal_pivot": E(end=0.25 * 0.35), "lid_hinge": E(end=-0.35)}),
    R("storage_27044", "Pull the drawer all the way out, then slide it back halfway.", joints={"joint_0": E(end=0.5 * 0.684)}),
    R("dishwasher_11700", "Open the dishwasher door fully, then raise it back to 45 degrees.", joints={"joint_0": E(end=PI / 4)}),
    R("microwave_7304", "Open the door to 90 degrees and then close it back to 30 degrees.", joints={"joint_1": E(end=PI / 6)}),
    # angles are measured from closed (the lid rests 45 degrees open; closed is the lower limit)
    R("box_102456", "Open the box lid fully, then let it fall back to 60 degrees.", joints={"joint_0": E(end=BOX_102456_CLOSED + PI / 3)}),
    R("laptop_10101", "Push the laptop lid down until it is about 45 degrees from closed.", joints={"joint_1": E(end=-2.0923007 + PI / 4)}),
    R("dishwasher_11700", "Let the dishwasher door drop most of the way, to about 70 degrees.", joints={"joint_0": E(end=math.radians(70))}),
    R("oven_7138", "Let the oven door down all the way.", joints={"joint_0": E(end="upper")}),
    R("laptop_10248", "Lean the laptop display back as far as its hinge allows.", joints={"joint_1": E(end="upper")}),
    R("examples/toy_car", "Let the toy car coast 70 cm forward over 2 seconds, slowing to a stop.", base=(0.7, 0.0, 0.0),
      joints={"wheel_front_left_axle": E(moves=True), "wheel_rear_right_axle": E(moves=True)}),
    R("bucket_102352", "Hoist the bucket half a metre into the air.", base=(0.0, 0.0, 0.5)),
    R("bottle_cap_3558", "Give the bottle cap a quarter twist to loosen it.", joints={"joint_0": E(end=PI / 2)}),
    R("toaster_103498", "Push the toaster 20 cm along -Y.", base=(0.0, -0.2, 0.0)),
    R("toaster_103498", "Open the toaster.", refuse=True),
    R("box_100671", "Lift the storage chest's lid until it stands about 110 degrees open.", joints={"joint_0": E(end=BOX_100671_CLOSED + math.radians(110))}),
    R("washing_machine_103508", "Turn the big dial 90 degrees, then each small knob 45 degrees.",
      joints={"joint_1": E(abs_end=PI / 2), "joint_2": E(abs_end=PI / 4), "joint_3": E(abs_end=PI / 4)}, order=(("joint_1", "joint_2"),)),
    R("washing_machine_103508", "Turn both small knobs 45 degrees.", joints={"joint_1": E(still=True), "joint_2": E(abs_end=PI / 4), "joint_3": E(abs_end=PI / 4)}),
    # --- speeds and durations of whole-object motion, pronouns, comparatives, codes, subjectless effects ---
    R("examples/toy_car", "push the toy car forward for 2 seconds", base=(0.8, 0.0, 0.0)),  # no distance: default 0.4 m/s x 2 s
    R("examples/toy_car", "push the toy car forward at 0.1 m/s for 3 seconds", base=(0.3, 0.0, 0.0)),
    R("refrigerator_11178", "Open both fridge doors fully, then close them back to 30 degrees.", joints={"joint_0": E(end=PI / 6), "joint_1": E(end=PI / 6)}),
    R("refrigerator_11178", "Swing the narrower fridge door open 100 degrees.", joints={"joint_0": E(end=math.radians(100)), "joint_1": E(still=True)}),
    R("refrigerator_11178", "Open the wider fridge door 90 degrees.", joints={"joint_1": E(end=PI / 2), "joint_0": E(still=True)}),
    R("safe_102387", "Dial the combination, and the safe door opens 90 degrees.", joints={"joint_1": E(moves=True), "joint_0": E(end=SAFE_102387_CLOSED + PI / 2)},
      order=(("joint_1", "joint_0"),)),
    R("safe_101564", "Key in the top-middle button; the door then unlocks and opens 45 degrees.", joints={"joint_13": E(end=PI / 4)}, order=(("joint_1", "joint_13"),)),
    R("trash_can_102181", "Step on the pad only a little so the lid opens about 30 degrees.", joints={"joint_0": E(end=0.2 * 0.5718), "joint_1": E(end=PI / 6)}),
    # --- a named part that is not there, or cannot move as asked, is refused ---
    R("storage_20453", "Fold down the desk's keyboard tray.", refuse=True),
    R("laptop_10101", "Eject the laptop's battery.", refuse=True),
    R("window_103135", "Slide the window sash sideways 20 cm.", refuse=True),
    # --- descriptions and references are not the target ---
    # "with the handle" tells the two doors apart: only link_0's mesh has a handle
    R("refrigerator_11178", "Open the fridge door with the handle a third of the way.", joints={"joint_0": E(end=PI / 3), "joint_1": E(still=True)}),
    R("coffee_machine_103030", "Lift the blender jar 3 cm out of its base.", joints={"joint_1": E(end=0.03), "joint_2": E(still=True)}),
    R("coffee_machine_103030", "Once the lid is lifted 20 cm off the jar, lift the jar 4 cm.", joints={"joint_2": E(end=0.2), "joint_1": E(end=0.04)},
      order=(("joint_2", "joint_1"),)),
    R("switch_100952", "Rock the wall switch fully to its other position.", joints={"joint_0": E(end="upper")}),
    # --- returns and lowering ---
    R("toilet_102622", "Lift the lid all the way up, then lower it back down.", joints={"joint_0": E(peak="upper")}),
    R("laptop_10101", "Close the laptop, then reopen it to its original angle.", joints={"joint_1": E(peak="lower")}),
    R("kitchen_pot_100038", "Raise the lid 30 cm, hold it there, then lower it to 10 cm.", joints={"joint_0": E(end=0.1)}),
    R("kitchen_pot_100038", "Raise the lid 30 cm, then lower it 20 cm.", joints={"joint_0": E(end=0.1)}),
    R("examples/pedal_bin", "Lift the pedal bin 10 cm and set it back down.", base=(0.0, 0.0, 0.0)),
    R("examples/pedal_bin", "Lift the pedal bin 10 cm, then lower it 10 cm.", base=(0.0, 0.0, 0.0)),
    # --- which way a verb moves the part ---
    R("box_100671", "Raise the chest lid 50 degrees.", joints={"joint_0": E(end=BOX_100671_CLOSED + math.radians(50))}),
    R("stapler_103099", "Fold the stapler's top arm fully back.", joints={"joint_0": E(end="upper")}),
    R("bucket_102352", "Raise the bucket handle halfway to upright.", joints={"joint_0": E(end=4.71867216569187 / 4)}),
    # --- probe6 fixes ---
    R("microwave_7304", "Press the microwave's door release button.", refuse=True),
    R("examples/toy_car", "Raise the toy car's spoiler.", refuse=True),
    R("safe_101564", "Press the middle key in the bottom row to pop the door fully open.",
      joints={"joint_10": E(peak="upper"), "joint_13": E(end="upper"), "joint_9": E(still=True), "joint_11": E(still=True)}, order=(("joint_10", "joint_13"),)),
    R("examples/microwave", "Press the door release button to open the door 80 degrees.",
      joints={"release_button_slide": E(peak="upper"), "door_hinge": E(end=math.radians(80))}, order=(("release_button_slide", "door_hinge"),)),
    R("dishwasher_12553", "Press the button to release the door, and lower it 40 degrees.",
      joints={"joint_1": E(peak="upper"), "joint_0": E(end=math.radians(40))}, order=(("joint_1", "joint_0"),)),
    R("examples/cabinet", "Open the cupboard door 90 degrees after releasing the latch knob.",
      joints={"latch_knob_turn": E(peak="lower"), "door_hinge": E(end=-PI / 2)}, order=(("latch_knob_turn", "door_hinge"),)),
    R("refrigerator_11178", "Open both fridge doors 90 degrees, left one first.",
      joints={"joint_0": E(end=PI / 2), "joint_1": E(end=PI / 2)}, order=(("joint_0", "joint_1"),)),
    # --- agent v2: whole-object turning, reclining, spelling, ambiguity, holds, brief presses, codes, the other one ---
    R("examples/toy_car", "turn the car around", yaw_deg=180.0),
    R("examples/toy_car", "rotate the toy car 90 degrees clockwise on the table", yaw_deg=-90.0),
    R("examples/pedal_bin", "spin the bin a quarter turn on the spot", yaw_deg=90.0),
    R("laptop_10101", "recline the screen as far as it goes", joints={"joint_1": E(end="upper")}),
    R("laptop_10101", "tilt the screen back 20 degrees", joints={"joint_1": E(end=math.radians(20))}),
    R("laptop_10101", "open the laptop to 90 degrees", joints={"joint_1": E(end=-2.092 + PI / 2)}),
    R("examples/microwave", "opne the microwve door all teh way", joints={"door_hinge": E(end="upper")}),
    R("examples/oven", "pull the trey out", joints={"tray_slide": E(end="lower"), "door_hinge": E(moves=True)}, order=(("door_hinge", "tray_slide"),)),
    R("refrigerator_11178", "open the fridge door", refuse=True),
    R("storage_19179", "open a drawer", refuse=True),
    R("storage_19179", "open the third drawer", refuse=True),
    R("storage_19179", "open the top drawer, then the other one", joints={"joint_1": E(end="upper"), "joint_0": E(end="upper")}, order=(("joint_1", "joint_0"),)),
    R("storage_19179", "open both drawers halfway", joints={"joint_0": E(end=0.5), "joint_1": E(end=0.5)}),
    R("storage_19179", "pull the bottom drawer out 30 cm, then push it back to where it was", joints={"joint_0": E(peak=0.3)}),
    R("trash_can_102181", "tap the pedal", joints={"joint_0": E(peak="upper"), "joint_1": E(peak="upper")}),
    R("trash_can_102181", "keep your foot on the pedal for 2 seconds, then let go", joints={"joint_0": E(peak="upper"), "joint_1": E(peak="upper")}),
    R("safe_101564", "press 1, 2, 3 on the keypad", joints={"joint_0": E(peak="upper"), "joint_1": E(peak="upper"), "joint_2": E(peak="upper"), "joint_13": E(still=True)},
      order=(("joint_0", "joint_1"), ("joint_1", "joint_2"))),
    R("examples/cabinet", "open the cupboard door without touching the knob", joints={"door_hinge": E(end="lower"), "latch_knob_turn": E(still=True)}),
    R("toilet_102622", "flush the toilet", joints={"joint_1": E(peak="lower"), "joint_0": E(still=True)}),  # its button, along its only travel
    R("examples/toy_car", "push the car forward 20 cm, then turn it around", base=None, yaw_deg=180.0),
    # --- blind dev probe, round 2 (benchmark/probes/dev_prompts.jsonl; dev assets from partnet-extra) ---
    R("examples/microwave", "open the trunk", refuse=True),
    R("extra/oven_7179", "I need the rack out of the top oven.", joints={"joint_4": E(end="upper"), "joint_0": E(end="upper"), "joint_1": E(still=True)},
      order=(("joint_4", "joint_0"),)),
    R("extra/oven_7179", "Open the lower oven, then shut the door.", joints={"joint_3": E(end=0.0), "joint_4": E(still=True)}),
    R("extra/oven_7179", "Open the upper oven door; its rack is hooked to the door and slides out 15 cm as the door comes down.",
      joints={"joint_4": E(end="upper"), "joint_0": E(end=0.15)}),
    R("extra/oven_7179", "Pull out the rack of the lower oven.", refuse=True),
    R("extra/box_100214", "clsoe the lid and lock both latchs", joints={"joint_0": E(end="lower"), "joint_1": E(end="upper"), "joint_2": E(end="upper")}),
    R("extra/box_100214", "Lower the lid until it is open only about 45 degrees.", joints={"joint_0": E(end=-1.6755 + PI / 4)}),
    R("extra/coffee_machine_102145", "Raise the lid.", joints={"joint_1": E(end="upper"), "joint_2": E(still=True)}),
    R("extra/coffee_machine_102145", "Flick the stubby lever on top of the brewing head to the right and let it go.", joints={"joint_0": E(peak="upper")}),
    R("extra/toaster_103473", "Hold the back lever down for a second and a half, then release it.", joints={"joint_1": E(end=0.0), "joint_0": E(still=True)}),
    R("extra/toaster_103473", "Press the front lever down; the two carriages are linked, so the back lever follows it down.",
      joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("extra/safe_101623", "Lock up the safe: swing the door shut and give the spoked wheel a quarter turn clockwise.", joints={"joint_2": E(still=True)}),
    R("extra/storage_20279", "Open the second drawer of the desk.", refuse=True),
    R("extra/storage_24644", "Turn the side table around so the drawer faces the wall.", joints={"joint_0": E(still=True)}, yaw_deg=180.0),
    R("extra/suitcase_100550", "Flip the handle back, then swing the front half of the case open.", joints={"joint_0": E(end="upper")}),
    R("refrigerator_11178", "Open the left door 90 degrees and close it, then open the other one the same amount.", joints={"joint_1": E(end=PI / 2)}),
    # --- blind dev probe, round 3 (benchmark/probes/dev_round3_prompts.jsonl) ---
    R("laptop_10697", "Set joint_1 to -1.0 rad.", joints={"joint_1": E(end=-1.0)}),
    R("microwave_7304", "Get the microwave door open for me, please.", joints={"joint_1": E(end="upper")}),
    R("microwave_7236", "Pop the microwave open so I can put my plate in, then close the door on it.", joints={"joint_0": E(peak="upper", end=0.0)}),
    R("extra/microwave_7128", "Turn both knobs at the same time: the top one a quarter turn clockwise, the bottom one half a turn clockwise.",
      joints={"joint_3": E(end=-PI / 2), "joint_2": E(end=-PI)}),
    R("washing_machine_103508", "Twist the knob nearest the lid's hinge half a turn counterclockwise.", joints={"joint_3": E(abs_end=PI), "joint_1": E(still=True)}),
    R("safe_102387", "Turn the dial on the safe door three quarters of a turn counterclockwise.", joints={"joint_1": E(abs_end=1.5 * PI)}),
    R("toaster_103477", "Set the browning knob a third of a turn clockwise and then start the toaster.", joints={"joint_0": E(abs_end=2 * PI / 3), "joint_1": E(end="upper")}, base=(0.0, 0.0, 0.0)),
    R("oven_7138", "Drop the oven door all the way, then lift it halfway back up.", joints={"joint_0": E(end=PI / 4)}, base=(0.0, 0.0, 0.0)),
    R("box_102456", "Jiggle the lid open.", joints={"joint_0": E(end="upper")}),
    R("safe_101564", "Press any key in the second row of the keypad.", joints={"joint_5": E(peak="upper", end=0.0)}),
    R("kitchen_pot_100038", "Lift the pot lid 20 cm, hold it there for 1.5 seconds to check the food, then put it back on.", joints={"joint_0": E(peak=0.2, end=0.0)}),
    R("faucet_148", "Standing at the sink facing the faucet, swing its lever 90 degrees to the left.", joints={"joint_0": E(end=PI / 2)},
      base=(0.0, 0.0, 0.0)),
    # --- blind dev probe, round 4 (benchmark/probes/dev_round4_prompts.jsonl), rephrased ---
    R("extra/box_100214", "Fasten the left catch; the lid stays put.", joints={"joint_1": E(end=0.4363), "joint_0": E(still=True)}),
    R("extra/box_100214", "Close the left catch. Leave the lid alone.", joints={"joint_1": E(end=0.4363), "joint_0": E(still=True)}),
    R("safe_101593", "Turn the smaller of the two knobs 45 degrees clockwise.", joints={"joint_2": E(end=-PI / 4), "joint_1": E(still=True)}),
    R("safe_101593", "Turn the bigger of the knobs a quarter turn anticlockwise.", joints={"joint_1": E(end=PI / 2), "joint_2": E(still=True)}),
    R("door_8877", "Push the door nearly closed, leaving it 20 degrees ajar.", joints={"joint_1": E(end=-PI / 2 + PI / 9)}),
    R("door_8877", "Push the door almost shut.", joints={"joint_1": E(end=-0.9 * PI / 2)}),
    R("toaster_103477", "Turn the browning knob from 12 o'clock to 3 o'clock.", joints={"joint_0": E(end=-PI / 2)}),
    R("oven_7221", "Open the upper door.", refuse=True),
    R("bucket_100454", "Fold the handle down on the back edge, then pull the bucket a quarter of a metre towards me.",
      joints={"joint_0": E(end=PI / 2)}, base=(-0.25, 0.0, 0.0)),
    R("window_103135", "shut the window its snowing", joints={"joint_0": E(end=-0.2765)}),
    R("extra/safe_101623", "Goal: lock the safe. First close the door. Then turn the small dial near the top of the door a quarter turn clockwise.",
      joints={"joint_1": E(end=-1.1812), "joint_2": E(end=PI / 2)}, order=(("joint_1", "joint_2"),)),
    R("trash_can_102155", "Push the bin 30 cm forward and 20 cm to the right", base=(-0.3, -0.2, 0.0)),
    R("oven_7138", "Lower the oven door flat", joints={"joint_0": E(end=PI / 2)}),
    R("box_102456", "Raise the lid 30 degrees from where it is, then let it settle back.", joints={"joint_0": E(peak=PI / 6, end=0.0)}),
    R("storage_20453", "angle the cabinet 45 degrees", yaw_deg=45.0),
    # --- blind dev probe, round 5 (benchmark/probes/dev_round5_prompts.jsonl), rephrased ---
    R("suitcase_103762", "Fold the carrying handle back until it lies flat.", joints={"joint_1": E(end=-PI / 2)}),
    R("suitcase_103762", "Fold the carrying handle forward till it lies flat.", joints={"joint_1": E(end=PI / 2)}),
    R("bucket_100454", "Let the handle fall forward until it rests on the rim.", joints={"joint_0": E(end=-PI / 2)}),
    R("refrigerator_11178", "Swing the right door open by π/4.", joints={"joint_1": E(end=PI / 4), "joint_0": E(still=True)}),
    R("extra/box_100214", "a) close the lid. b) once it is shut, fasten the right latch.", joints={"joint_0": E(end=-1.676), "joint_2": E(end=0.4363)}),
    R("microwave_7304", "door -> open it 45 degrees", joints={"joint_1": E(end=PI / 4)}),
    R("extra/box_100214", "Close the right-hand latch. Leave the left latch and the lid as they are.",
      joints={"joint_2": E(end=0.4363), "joint_1": E(still=True), "joint_0": E(still=True)}),
    R("box_100671", "Raise the lid to 60 degrees, i.e. measured from fully closed.", joints={"joint_0": E(end=BOX_100671_CLOSED + PI / 3)}),
    R("safe_101593", "Give the small dial one full turn clockwise.", joints={"joint_2": E(end=-2 * PI), "joint_1": E(still=True)}),
    R("laptop_10101", "The screen is leaning back too far. Tilt it forward until it forms a right angle with the base.", joints={"joint_1": E(end=-0.5215)}),
    R("dishwasher_11700", "Lower the door all the way and keep it there 2 seconds so the steam clears, then shut it.", joints={"joint_0": E(peak=PI / 2, end=0.0)}),
    R("microwave_7119", "The door swings open, then the turntable makes a quarter revolution.", joints={"joint_0": E(end="upper"), "joint_1": E(abs_end=PI / 2)}),
    R("microwave_7119", "Open the turntable.", refuse=True),
    R("oven_7221", "The door is hinged at the bottom. Open it forty degrees.", joints={"joint_0": E(end=math.radians(40))}),
    R("safe_102387", "The door is ajar. Push it toward closed until only a 10 degree gap is left.", joints={"joint_0": E(end=SAFE_102387_CLOSED + math.radians(10))}),
    R("storage_19179", "Pull the top drawer out until it hits the end, then push it back in.", joints={"joint_1": E(peak="upper", end=0.0)}),
    R("coffee_machine_103030", "Lift the container itself 2 cm.", joints={"joint_1": E(end=0.02)}),
    R("laptop_10248", "fold the screen down, shut onto the base", joints={"joint_1": E(end=-1.71)}),
    R("toilet_102622", "Lift the seat but keep the lid closed.", refuse=True),
    R("switch_100952", "Turn the switch through two full turns.", refuse=True),
    R("door_8877", "Open the door another 30 degrees.", refuse=True),
    R("refrigerator_11178", "open the left door 200 degrees", joints={"joint_0": E(end="upper")}),
    R("extra/laptop_11395", "Lift the laptop up and hold it 25 cm above the table.", base=(0.0, 0.0, 0.25)),
    R("trash_can_102155", "Bin lid: raise it to vertical, 3 s pause, then let it drop shut.", joints={"joint_2": E(peak=PI / 2, end=0.0)}),
    # --- blind dev probe, round 6 (benchmark/probes/dev_round6_prompts.jsonl), rephrased ---
    R("washing_machine_103508", "Of the three knobs, turn the middle one 90 degrees clockwise.", joints={"joint_2": E(end=PI / 2), "joint_1": E(still=True), "joint_3": E(still=True)}),
    R("extra/toaster_103473", "Push the rear lever down halfway and leave the front one up.", joints={"joint_1": E(end=0.202), "joint_0": E(still=True)}),
    R("toaster_103483", "Move the toaster 15 cm toward me and 0.1 m to the right.", base=(-0.15, -0.1, 0.0)),
    R("toaster_103483", "Slide the toaster 20 cm away from me.", base=(0.2, 0.0, 0.0)),
    R("safe_101593", "Robot task: (a) turn the big left-hand knob half a turn clockwise; (b) then open the door 90 degrees.",
      joints={"joint_1": E(end=-PI), "joint_0": E(end=PI / 2)}),
    R("extra/microwave_7128", "Press the door release button but keep the door shut.", joints={"joint_1": E(moves=True), "joint_0": E(still=True)}),
    R("extra/safe_102380", "Turn the safe 90 degrees as seen from above; the door stays as it is.", joints={"joint_2": E(still=True)}, yaw_deg=90.0),
    R("dishwasher_11700", "Open the dishwasher 20 degrees to look at the plates, then close it.", joints={"joint_0": E(peak=PI / 9, end=0.0)}),
    R("microwave_7119", "Open the door 90 degrees, leave it like that for 2 s so the smell escapes, then shut it.", joints={"joint_0": E(peak=PI / 2, end=0.0)}),
    R("extra/microwave_7128", "Upper knob: give it a 90 degree clockwise turn.", joints={"joint_3": E(end=-PI / 2), "joint_2": E(still=True)}),
    R("storage_27044", "pull the drawer al the way out", joints={"joint_0": E(end="upper")}),
    R("refrigerator_11178", "swing the left hand fridge door open 45 degrees", joints={"joint_0": E(end=PI / 4), "joint_1": E(still=True)}),
    R("refrigerator_11178", "Open the right door while grabbing a snack, then close it.", joints={"joint_1": E(moves=True), "joint_0": E(still=True)}),
    R("microwave_7119", "Open the door. Then turn the turntable a quarter turn. Finally close it.", joints={"joint_0": E(peak="upper", end=0.0), "joint_1": E(abs_end=PI / 2)}),
    R("box_102456", "Fling the lid open as far as the hinge allows, then put it back the way it was.", joints={"joint_0": E(peak="upper", end=0.0)}),
    R("faucet_148", "Push the lever right as far as it goes, then back to the middle.", joints={"joint_0": E(peak=-PI / 2, end=0.0)}),
    R("extra/faucet_1343", "Swing the lever fully to the left, let it run for 3 seconds, then return it to the centre.", joints={"joint_0": E(moves=True, end=0.0)}),
    R("laptop_10248", "The lid comes down fully shut, rests there for a second, then lifts back up to where it started.", joints={"joint_1": E(peak=-1.71, end=0.0)}),
    R("extra/bucket_100432", "Let the handle tip 20 degrees further toward the front from where it's resting now.", joints={"joint_0": E(end=-PI / 9)}),
    # --- blind dev probes, rounds 7 and 8 (benchmark/probes/dev_round7_prompts.jsonl, dev_round8_prompts.jsonl), rephrased ---
    R("microwave_7236", "Open the door 40 degrees, then 25 more.", joints={"joint_0": E(end=65 * PI / 180)}),
    R("microwave_7236", "Open the door 70 degrees... no wait, make it 50.", joints={"joint_0": E(end=50 * PI / 180)}),
    R("kitchen_pot_100038", "Raise the lid 30 cm - actually no, 15 cm is plenty.", joints={"joint_0": E(end=0.15)}),
    R("extra/storage_20279", "Nudge the desk drawer shut.", joints={"joint_0": E(end=-0.188)}),
    R("extra/storage_24644", "pul the drawr out 10cm then shove it bak in", joints={"joint_0": E(peak=0.1, end=0.0)}),
    R("faucet_148", "cn u turn teh tap lever 30 degs to the rihgt", joints={"joint_0": E(end=-PI / 6)}),
    R("microwave_7119", "Turn the glass plate 3/8 of a turn counterclockwise.", joints={"joint_1": E(abs_end=3 * PI / 4)}),
    R("bottle_cap_3558", "Loosen the cap by an eighth of a turn.", joints={"joint_0": E(end=PI / 4)}),
    R("microwave_7304", "Slide the microwave 15 cm to my right. The door stays shut.", base=(0.0, -0.15, 0.0), joints={"joint_1": E(still=True)}),
    R("microwave_7304", "Rotate the microwave so its door faces the wall.", yaw_deg=180.0, joints={"joint_1": E(still=True)}),
    R("toaster_103498", "Slide the toaster 10 cm to the left and then 5 cm further back.", base=(0.05, 0.1, 0.0)),
    R("window_103135", "Push the window open 30 degrees from closed, hold it 2 seconds, then back to where it started.", joints={"joint_0": E(peak=0.2471, end=0.0)}),
    R("box_100671", "Swing the lid to 60 degrees from closed, then undo that.", joints={"joint_0": E(peak=BOX_100671_CLOSED + PI / 3, end=0.0)}),
    R("faucet_991", "Swing the lever 40 degrees to the left, then centre it.", joints={"joint_0": E(peak=40 * PI / 180, end=0.0)}),
    R("safe_101593", "Turn the knob further from the hinge a quarter turn clockwise; the door stays exactly where it is.",
      joints={"joint_1": E(end=-PI / 2), "joint_2": E(still=True), "joint_0": E(still=True)}),
    R("washing_machine_103508", "Turn the knob third from the right 45 degrees clockwise.", joints={"joint_3": E(moves=True), "joint_1": E(still=True), "joint_2": E(still=True)}),
    R("storage_19179", "Task list: 1) upper drawer out 0.3 m 2) lower drawer out the same distance 3) upper drawer back in.",
      joints={"joint_1": E(peak=0.3, end=0.0), "joint_0": E(end=0.3)}),
    R("extra/microwave_7128", "Lower knob - turn it 60 degrees anticlockwise.", joints={"joint_2": E(end=PI / 3), "joint_3": E(still=True)}),
    R("extra/storage_25308", "Pull the far-left drawer out 20 cm.", joints={"joint_1": E(end=0.2), "joint_0": E(still=True)}),
    R("extra/storage_25308", "Open the left drawer 15 cm, then the right one.", joints={"joint_1": E(end=0.15), "joint_0": E(end=0.15)}),
    R("switch_100952", "Click the switch over to its other position.", joints={"joint_0": E(end=0.3142)}),
    R("switch_100952", "Flip the switch on, then off again.", joints={"joint_0": E(peak=0.3142, end=0.0)}),
    R("extra/box_100214", "Turn the toolbox 90 degrees on the bench; lid and latches untouched.", yaw_deg=90.0,
      joints={"joint_0": E(still=True), "joint_1": E(still=True), "joint_2": E(still=True)}),
    R("toilet_102622", "Put the toilet lid up.", joints={"joint_0": E(end="upper")}),
    R("extra/coffee_machine_102145", "Flip the front flap up as far as it goes.", joints={"joint_3": E(end="upper"), "joint_1": E(still=True), "joint_2": E(still=True)}),
    R("oven_7138", "Swing the oven door right round to 160 degrees.", refuse=True),
    R("extra/oven_7179", "The oven door: open it, please.", refuse=True),
    # --- blind dev probe, round 9 (benchmark/probes/dev_round9_prompts.jsonl): classes fixed, rephrased ---
    R("extra/storage_25308", "Pull the right drawer out 15 cm and then do the same for the other one.",
      joints={"joint_0": E(end=0.15), "joint_1": E(end=0.15)}, order=(("joint_0", "joint_1"),)),
    R("extra/storage_25308", "Slide the left drawer out 10 cm, then give the other one the same.",
      joints={"joint_1": E(end=0.10), "joint_0": E(end=0.10)}),
    R("storage_19179", "Steps:\n* top drawer out 30 cm\n* top drawer back in", joints={"joint_1": E(peak=0.30, end=0.0), "joint_0": E(still=True)}),
    R("extra/oven_7179", "Slide the second rack from the bottom all the way out.",
      joints={"joint_3": E(end="upper"), "joint_1": E(end="upper"), "joint_0": E(still=True), "joint_2": E(still=True)}),
    R("extra/oven_7179", "The chicken is on the lowest shelf - bring it out.",
      joints={"joint_3": E(end="upper"), "joint_2": E(end="upper"), "joint_0": E(still=True), "joint_1": E(still=True)}),
    R("extra/oven_7179", "Take 2, upper oven: door goes down; its rack slides out a bit, then back in.",
      joints={"joint_4": E(end="upper"), "joint_0": E(moves=True, end=0.0), "joint_3": E(still=True)}),
    R("extra/oven_7179", "To get at the top rack, pull it out 20 cm.", joints={"joint_4": E(end="upper"), "joint_0": E(end=0.20)}),
    R("extra/storage_24644", "I want its drawer to come out 10 cm.", joints={"joint_0": E(end=0.10)}),
    R("window_103135", "Swing the sash outwards all the way.", joints={"joint_0": E(end="upper")}),
    R("toaster_103483", "Sink the lever all the way down.", joints={"joint_0": E(end="upper")}),
    R("faucet_148", "Animator here - turn the whole faucet model 90 degrees, lever untouched.", yaw_deg=90.0),
    R("oven_7138", "The oven door drops open, and that's it.", joints={"joint_0": E(end="upper")}),
    R("extra/microwave_7128", "The knob nearest the floor: a quarter turn.", joints={"joint_2": E(moves=True), "joint_3": E(still=True)}),
    R("extra/coffee_machine_102145", "Move the lever on top of the coffee machine all the way left.", joints={"joint_0": E(end="lower")}),
    R("washing_machine_103508", "Third knob from the left on the washer: a quarter turn.", joints={"joint_1": E(moves=True), "joint_2": E(still=True)}),
    R("extra/safe_102380", "Spin the dial one and a half turns, door left alone.", joints={"joint_0": E(moves=True), "joint_2": E(still=True)}),
    R("toilet_102622", "Somebody needs to use the bathroom; raise the lid.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("safe_101564", "Tap the 5 key.", joints={"joint_4": E(moves=True, end=0.0), "joint_3": E(still=True), "joint_5": E(still=True)}),
    R("extra/storage_25308", "Open the left drawer 20 cm, then the right one 20 cm, then push both back in.",
      joints={"joint_1": E(peak=0.20, end=0.0), "joint_0": E(peak=0.20, end=0.0)}),
    R("storage_19179", "top drawer out 10 cm and bottom drawer out 30 cm at the same time", joints={"joint_1": E(end=0.10), "joint_0": E(end=0.30)}),
    R("refrigerator_11178", "opne both fridge dors", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("extra/storage_20279", "pul the drawr out 10 cm thnx", joints={"joint_0": E(end=-0.088)}),  # 10 cm out from closed (it rests 18.8 cm out)
    R("oven_7138", "Door down to 30 degrees, stays there for 2 s while the music plays, then shuts.", joints={"joint_0": E(peak=0.5236, end=0.0)}),
    R("trash_can_102181", "Tread on the pedal, keep your foot down for 2 s, then step off.", joints={"joint_0": E(moves=True, end=0.0), "joint_1": E(moves=True, end=0.0)}),
    R("laptop_10697", "Shut the laptop, then put it back how it was.", joints={"joint_1": E(peak="lower", end=0.0)}),
    R("extra/microwave_7128", "The door opens, and while it is opening the turntable starts to turn half a turn.",
      joints={"joint_0": E(end="upper"), "joint_4": E(moves=True)}),  # the plate turns while the door opens (no order)
    R("extra/oven_7179", "I want to look at the bread on the middle rack - pull it out.", joints={"joint_3": E(end="upper"), "joint_1": E(end="upper")}),
    R("bottle_cap_3558", "I'd like a drink, so unscrew the cap a quarter turn.", joints={"joint_0": E(moves=True)}),
    R("kitchen_pot_100038", "Let the steam escape - lift the lid 2 cm.", joints={"joint_0": E(end=0.02)}),
    # --- blind dev probe, round 10 (benchmark/probes/dev_round10_prompts.jsonl): classes fixed, rephrased ---
    R("storage_27044", "animator here, I need the drawer all the way out", joints={"joint_0": E(end="upper")}),
    R("door_8877", "Door: shut it, wait 1 s, then back to the start pose.", joints={"joint_1": E(peak="lower", end=0.0)}),
    R("box_102456", "Levitate the chest 10 cm.", base=(0.0, 0.0, 0.10)),
    R("stapler_103099", "yaw the stapler 90 degrees", yaw_deg=90.0, joints={"joint_0": E(still=True)}),
    R("bucket_100454", "Bucket: yaw it 90 degrees on the spot.", yaw_deg=90.0),
    R("toilet_102622", "toilet - lift the lid", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("safe_101593", "Make the door to open, please.", joints={"joint_0": E(end="upper")}),
    R("coffee_machine_103030", "Nudge the reservoir up 2 cm.", joints={"joint_1": E(end=0.02)}),
    R("toilet_102622", "Flush.", joints={"joint_1": E(peak="lower"), "joint_0": E(still=True)}),
    R("coffee_machine_103030", "Dial on the front: half a rotation.", joints={"joint_0": E(moves=True), "joint_1": E(still=True)}),
    R("extra/safe_102380", "Combination dial -> half a revolution.", joints={"joint_0": E(abs_end=3.1416), "joint_2": E(still=True)}),
    R("toaster_103477", "turn the browning control 90 degrees", joints={"joint_0": E(moves=True)}),
    R("extra/safe_101612", "Spin the combination wheel a quarter rotation.", joints={"joint_1": E(moves=True)}),
    R("microwave_7304", "open the microwave real quick, then close it", joints={"joint_1": E(peak="upper", end=0.0)}),
    R("microwave_7236", "opn teh dore all the way", joints={"joint_0": E(end="upper")}),
    # --- blind dev probe, round 11 (benchmark/probes/dev_round11_prompts.jsonl): classes fixed, rephrased ---
    R("laptop_10248", "I want the screen at 60 degrees, counted from fully closed.", joints={"joint_1": E(end=-0.6632)}),
    R("microwave_7236", "need the microwave flipped round, facing away", yaw_deg=180.0, joints={"joint_0": E(still=True)}),
    R("extra/kitchen_pot_100015", "Lift the lid the whole 6 cm it can travel.", joints={"joint_0": E(end=0.06)}),
    R("trash_can_102155", "Spin the left-side wheel a quarter turn.", joints={"joint_1": E(moves=True), "joint_0": E(still=True)}),
    # a part hinged about the normal of its nearest face (a stapler's arm) says nothing of the front: -X, the dataset's
    R("stapler_103099", "Push the stapler 5 cm to the left.", base=(0.0, 0.05, 0.0), joints={"joint_0": E(still=True)}),
    R("extra/storage_20279", "I'm about to sit down at the desk, so shut the drawer.", joints={"joint_0": E(end="lower")}),
    R("extra/coffee_machine_102145", "Push the lever on top all the way to the left so the machine starts heating.",
      joints={"joint_0": E(end="lower"), "joint_1": E(still=True), "joint_2": E(still=True)}),
    # --- blind dev probe, round 12 (benchmark/probes/dev_round12_prompts.jsonl): classes fixed, rephrased ---
    # "no" and chat interjections are no part names
    R("dishwasher_11700", "Lower the dishwasher door 30 degrees, no more.", joints={"joint_0": E(end=0.5236)}),
    R("microwave_7304", "hey, could u open the microwave door", joints={"joint_1": E(end="upper")}),
    R("toilet_102622", "Raise the seat cover 30 degrees - no flushing please.", joints={"joint_0": E(end=0.5236), "joint_1": E(still=True)}),
    R("safe_102387", "Open the door - there's no need to turn the dial.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    # "the drawer's sticking out" is "is"; "home" is in as far as it goes
    R("extra/storage_20279", "The drawer's hanging out; push it home.", joints={"joint_0": E(end="lower")}),
    # a heading that names a part makes it "it", also with a direction ("toward the front", "to the left")
    R("bucket_100454", "Handle: tip it toward the front until it lies flat.", joints={"joint_0": E(end=-1.5708)}),
    R("extra/coffee_machine_102145", "Lever: nudge it 20 degrees toward the left.", joints={"joint_0": E(end=-0.3491), "joint_3": E(still=True)}),
    R("washing_machine_103508", "On the washer, the knob furthest to the left: a quarter twist clockwise.",
      joints={"joint_3": E(moves=True), "joint_1": E(still=True), "joint_2": E(still=True)}),
    # a wanted state with "needs to / has to / should be"
    R("oven_7138", "The oven door has to be fully open.", joints={"joint_0": E(end="upper")}),
    # a negation told first, and "using the pedal" as what not to touch
    R("trash_can_102181", "Without using the pedal, lift the lid by hand to 90 degrees.", joints={"joint_0": E(still=True), "joint_1": E(end=1.5708)}),
    R("trash_can_102181", "Stand on the pedal and keep it down so the lid stays up.", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    # "into its locked position": the latch's shut end
    R("extra/box_100214", "Flip the left catch into its locked position.", joints={"joint_1": E(end=0.4363), "joint_2": E(still=True)}),
    # a correction that names the other part
    R("extra/storage_25308", "Pull the left drawer out 15 cm - no wait, I meant the other one.", joints={"joint_0": E(end=0.15), "joint_1": E(still=True)}),
    # a side word before a part noun is no verb ("bottom door down")
    R("extra/oven_7179", "Top door down flat.", joints={"joint_4": E(moves=True), "joint_3": E(still=True)}),
    # "N full <sense> turns", "..., turning clockwise"
    R("safe_102387", "Give the dial two full clockwise turns.", joints={"joint_1": E(abs_end=12.5664), "joint_0": E(still=True)}),
    R("safe_101593", "Big dial: one and a half revolutions, turning clockwise.", joints={"joint_1": E(end=-9.4248)}),
    # a height "above the pot" is measured from closed; "measured from where it sits shut"
    R("kitchen_pot_100038", "Lift the lid so it floats 20 cm above the pot.", joints={"joint_0": E(end=0.2)}),
    R("box_102456", "Open the lid 60 degrees, measured from where it sits closed.", joints={"joint_0": E(end=BOX_102456_CLOSED + 1.0472)}),
    # what a part carries or holds: the toaster's bread, a thing kept in a door
    R("toaster_103483", "Sink the slices down.", joints={"joint_0": E(moves=True)}),
    R("refrigerator_11178", "I need the mustard, which sits in the right-hand door.", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("refrigerator_11178", "Get the milk out - it's on the shelf in the left door.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("washing_machine_103508", "Open the top-loader.", joints={"joint_0": E(end="upper")}),
    # steps split by " / "; a return after a hold
    R("storage_27044", "drawer out 30cm / wait 1s / back in", joints={"joint_0": E(peak=0.3, end="lower")}),
    R("laptop_10697", "Shut the laptop, leave it for a second, then back up to the angle it started at.", joints={"joint_1": E(peak="lower", end=0.0)}),
    # a lid on a side face opens downward; "full right"; a flush after a lid works the flush button
    R("extra/suitcase_100550", "The case is upright. Fold its front lid down all the way.", joints={"joint_0": E(end="upper")}),
    R("faucet_148", "Tap lever: full right.", joints={"joint_0": E(end="lower")}),
    R("toilet_102622", "Lid up, then flush.", joints={"joint_0": E(end="upper"), "joint_1": E(moves=True)}, order=(("joint_0", "joint_1"),)),
    # --- blind dev probes, rounds 11 and 13 (benchmark/probes/dev_round1{1,3}_prompts.jsonl): classes fixed, rephrased ---
    # a result on "it" says where the part ends ("so it lies ... toward the back", "so it sits flush"); the scene names "it"
    R("bucket_100454", "Let the handle drop so it rests flat against the back.", joints={"joint_0": E(end="upper")}),
    R("door_8877", "Someone left the door standing open. Push it back so it sits flush.", joints={"joint_1": E(end="lower")}),
    # hot is the viewer's left on a mixer tap, cold the right
    R("faucet_148", "Lever to full hot.", joints={"joint_0": E(end="upper")}),
    R("faucet_148", "Give the tap 20 degrees toward cold.", joints={"joint_0": E(end=-0.3491)}),
    # "at an angle of", ", where zero means ...": from closed
    R("laptop_10697", "Put the screen at an angle of 90 degrees, where 0 means fully shut.", joints={"joint_1": E(end=-1.954 + 1.5708)}),
    # "needs to <verb>", "the midpoint of its travel", "of right side", "the one at the back"
    R("storage_19179", "The top drawer needs to come out 30 cm.", joints={"joint_1": E(end=0.3), "joint_0": E(still=True)}),
    R("storage_27044", "Slide the drawer to the midpoint of its travel.", joints={"joint_0": E(end=0.342)}),
    R("refrigerator_11178", "Open the door of left side to 60 degree.", joints={"joint_0": E(end=1.0472), "joint_1": E(still=True)}),
    R("extra/toaster_103473", "It has two levers. Press the one at the back all the way down.", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    # a latch flipped over stays; "once it's open" with the comma left out; "when it gets there, do ..."
    R("extra/box_100214", "Flip the left catch over.", joints={"joint_1": E(end=0.4363), "joint_2": E(still=True)}),
    R("microwave_7119", "Open the door and once it's open spin the plate a quarter turn.", joints={"joint_0": E(end="upper"), "joint_1": E(moves=True)},
      order=(("joint_0", "joint_1"),)),
    # holds said as "N s hold", "stay N seconds", "give it N seconds"; verbless steps by their particle
    R("oven_7138", "door fully open, 2 s hold, shut", joints={"joint_0": E(peak="upper", end="lower")}),
    R("toilet_102622", "lid up, stay 2 seconds, back down", joints={"joint_0": E(peak="upper", end="lower")}),
    R("switch_100952", "Flip the switch on, give it a couple of seconds, then back off.", joints={"joint_0": E(peak="upper", end="lower")}),
    R("laptop_10697", "Screen down until it's shut, wait a second, then lift it back up to where it was.", joints={"joint_1": E(peak="lower", end=0.0)}),
    # a verb we do not know before an end state; "hover" raises the object; a lower door under a drawer
    R("laptop_10101", "Snap the laptop shut.", joints={"joint_1": E(end="lower")}),
    R("stapler_103099", "Hover the stapler 5 cm over the desk.", base=(0.0, 0.0, 0.05), joints={"joint_0": E(still=True)}),
    R("storage_23472", "Open the lower cabinet door all the way.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    # "(big knob, the one on the left)": a heading in parentheses; "(anticlockwise)"; "180 clockwise" is degrees
    R("safe_101593", "(the knob, the one on the left) -> quarter turn clockwise", joints={"joint_1": E(end=-1.5708), "joint_2": E(still=True)}),
    R("extra/microwave_7128", "top knob 90 clockwise", joints={"joint_3": E(abs_end=1.5708)}),
    # "nothing", "forget the pedal", "unit" after the object's name, "the loo"
    R("extra/suitcase_100550", "Unzip nothing, just lower the front lid all the way.", joints={"joint_0": E(end="upper")}),
    R("trash_can_102181", "Forget the pedal, lift the lid by hand.", joints={"joint_0": E(still=True), "joint_1": E(moves=True)}),
    R("dishwasher_11700", "Turn the dishwasher unit around.", yaw_deg=180.0, joints={"joint_0": E(still=True)}),
    # --- blind dev probe, round 14 (benchmark/probes/dev_round14_prompts.jsonl, scored once before these): classes fixed, rephrased ---
    R("microwave_7304", "open the door ~45 deg, just enough to see inside", joints={"joint_1": E(end=0.7854)}),
    R("refrigerator_11178", "Left fridge door, open it to 45 degrees.", joints={"joint_0": E(end=0.7854), "joint_1": E(still=True)}),
    R("extra/oven_7179", "Upper oven door, bring it all the way down.", joints={"joint_4": E(moves=True), "joint_3": E(still=True)}),
    R("toaster_103477", "Browning dial: 0.8 rad in the clockwise sense.", joints={"joint_0": E(abs_end=0.8)}),
    R("safe_101593", "big dial: 120 degrees counter clockwise, nothing else", joints={"joint_1": E(abs_end=2.0944), "joint_0": E(still=True),
                                                                                        "joint_2": E(still=True)}),
    R("extra/oven_7179", "I need the top-most rack 20 cm out.", joints={"joint_0": E(end=0.2)}),
    R("storage_19179", "On this chest, the lower one should come out 20 cm.", joints={"joint_0": E(end=0.2), "joint_1": E(still=True)}),
    R("toilet_102622", "Lift the lid, then hit the flush.", joints={"joint_0": E(end="upper"), "joint_1": E(moves=True)}, order=(("joint_0", "joint_1"),)),
    R("faucet_148", "Mixer lever to the coldest setting.", joints={"joint_0": E(end="lower")}),
    # "then step off" lets go of the control the step before pressed, not of the part it moved
    R("trash_can_102181", "Step on the pedal to raise the lid, then step off so it falls shut.", joints={"joint_0": E(peak="upper", end="lower"),
                                                                                                       "joint_1": E(end="lower")}),
    # --- blind dev probe, round 15 (benchmark/probes/dev_round15_prompts.jsonl, scored once before these): classes fixed, rephrased ---
    # "measured from fully shut, ...": a clause that only names the zero of the next amount
    R("window_103135", "Measured from fully shut, open the window 20 degrees.", joints={"joint_0": E(end=WINDOW_103135_CLOSED + 0.349066)}),
    # "back in until it's shut", "back up until it's at 30 degrees": the result clause says where the way back ends
    R("window_103135", "open the window all the way, then bring it back in until it's shut", joints={"joint_0": E(end="lower")}),
    R("oven_7138", "drop the oven door flat, then ease it back up until it's at 30 degrees", joints={"joint_0": E(end=0.5236)}),
    # "proud of the front", "perpendicular to the front": a face of the object, not a part named "front"
    R("storage_27044", "Slide the drawer out until it sits 200 mm proud of the front.", joints={"joint_0": E(end=0.2)}),
    R("refrigerator_11178", "Set the right door perpendicular to the front, 90 degrees open.", joints={"joint_1": E(end=1.5708), "joint_0": E(still=True)}),
    R("extra/storage_26525", "half-open the drawer", joints={"joint_0": E(end=0.256)}),
    # "the angle between it and the keyboard": one thing measured, from shut
    R("laptop_10101", "tilt the screen down until the angle between it and the keyboard is 60 degrees", joints={"joint_1": E(end=LAPTOP_10101_CLOSED + 1.0472)}),
    R("suitcase_103762", "Close the suitcase so it's ready to go.", joints={"joint_0": E(end=-1.0472), "joint_1": E(still=True)}),
    R("bucket_102352", "Send the handle's hinge to its far limit.", joints={"joint_0": E(end="upper")}),
    R("extra/toaster_103473", "Push down the lever farthest from me.", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("extra/toaster_103473", "There's a lever at each end. Push down the one nearest to me.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    # "the safe has two dials; grab the bigger one and ...": the dials, not the safe's door; taking hold moves nothing
    R("safe_101593", "The safe has two dials; grab the bigger one and turn it 90 degrees clockwise.",
      joints={"joint_1": E(abs_end=1.5708, sign=-1), "joint_0": E(still=True), "joint_2": E(still=True)}),
    R("oven_7221", "door fully open, a 3-second pause, then back shut", joints={"joint_0": E(peak="upper")}),
    R("box_100671", "lid 60 degrees up from closed", joints={"joint_0": E(end=BOX_100671_CLOSED + 1.0472)}),
    # "that rack" after "the bottom rack": the one said before; "baste" is a word of its own
    R("extra/oven_7179", "I want to baste the turkey on the bottom rack, pull that rack out", joints={"joint_2": E(end="upper")}),
    # --- round 16 (benchmark/probes/dev_round16_prompts.jsonl, scored at the start and after round 15 before these) ---
    # the scene and who acts in it ("montage", "episode", "the character", "the arm") are no parts: no refusal over them
    R("extra/storage_24644", "Quick drawer peek: pull it 20 cm out, then push it home.", joints={"joint_0": E(peak=0.2)}),
    R("washing_machine_103508", "Laundry montage: turn the far-left dial a quarter turn clockwise.", joints={"joint_3": E(end=1.5708)}),
    R("microwave_7119", "Task for the operator: pull the door open to its stop, then end the episode.", joints={"joint_0": E(end="upper")}),
    R("laptop_10101", "Open the screen 90 degrees from closed, then the gripper lets go.", joints={"joint_1": E(end=LAPTOP_10101_CLOSED + 1.5708)}),
    R("extra/suitcase_100550", "For the packing montage, fold the suitcase lid fully open.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    # ... but "the foot comes off" lets go of the pedal it pressed: the pedal and the lid come back
    R("examples/pedal_bin", "Tap the pedal: the lid pops open, then the foot comes off, the pedal springs back and the lid falls shut.",
      joints={"pedal_pivot": E(peak="upper"), "lid_hinge": E(peak="lower")}),
    # a purpose on the part its means already moves says why: "unlock it" is no second turn of the dial
    R("safe_102387", "spin the dial a full turn to unlock it", joints={"joint_1": E(abs_end=2 * PI), "joint_0": E(still=True)}),
    R("extra/safe_102380", "turn the knob a quarter turn to unlock it", joints={"joint_0": E(abs_end=PI / 2)}),
    # --- round 17 (benchmark/probes/dev_round17_prompts.jsonl, scored first at 1a25844.. before these) ---
    R("safe_101593", "Eighth of a turn anticlockwise on the large dial.", joints={"joint_1": E(end=PI / 4), "joint_0": E(still=True)}),
    R("storage_27044", "Draw the drawer out to 2/3 of the full extension.", joints={"joint_0": E(end=0.456)}),
    R("suitcase_103762", "Close the suitcase, then open it again so it ends up exactly like it was.", joints={"joint_0": E(peak=-1.0472)}),
    R("storage_27044", "slide the cabinet 0.4 m to the viewer's left", joints={"joint_0": E(still=True)}, base=(0.0, 0.4, 0.0)),
    # a gerund as the subject is the means; "which lets / makes X ..." is what it causes
    R("trash_can_102181", "Pressing the pedal opens the lid.", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("extra/coffee_machine_102145", "Swinging the lever over to the left makes the top lid pop up.",
      joints={"joint_0": E(end=-0.609469), "joint_1": E(end=0.036), "joint_2": E(still=True)}),
    R("safe_102387", "Spin the dial one complete revolution to unlock it, which lets the door swing all the way open.",
      joints={"joint_1": E(abs_end=2 * PI), "joint_0": E(end="upper")}, order=(("joint_1", "joint_0"),)),
    R("toilet_102622", "give the loo a flush using the button on the cistern", joints={"joint_1": E(peak="lower"), "joint_0": E(still=True)}),
    # --- silent wrongs left in the earlier dev rounds, and round 16's leftovers ---
    # an amount alone after a comma says how far the step before goes: one revolution, not a quarter turn and then one more
    R("trash_can_102155", "Roll the left-hand wheel around once, a full revolution. Bin stays put.", joints={"joint_1": E(abs_end=2 * PI), "joint_2": E(still=True)}),
    # "flat on the box / keyboard" is shut on the body, not the other flat pose; "flat on the table" is still laid open
    R("box_102456", "Bring the toy box's cover down flat on the box.", joints={"joint_0": E(end="lower")}),
    R("laptop_10101", "fold the screen flat on the keyboard", joints={"joint_1": E(end=LAPTOP_10101_CLOSED)}),
    # "one above the other" arranges the knobs named before; "a quarter-turn" is an amount
    R("extra/microwave_7128", "This microwave has two knobs stacked one above the other; turn the top one a quarter-turn to the left.",
      joints={"joint_3": E(abs_end=PI / 2), "joint_2": E(still=True)}),
    # "the lower oven's door": the door on that side of the object
    R("extra/oven_7179", "open the lower oven's door", joints={"joint_3": E(end="upper"), "joint_4": E(still=True)}),
    R("extra/oven_7179", "bring the top compartment's door down to fully open", joints={"joint_4": E(end="upper"), "joint_3": E(still=True)}),
    # "while it's opening (,) tip the handle back": the motion before, told as it goes; the next step runs with it
    R("extra/suitcase_100550", "Lower the front half of the suitcase flat onto the floor, and while it's opening tip the carry handle back.",
      joints={"joint_0": E(end="upper"), "joint_1": E(end=1.221730476)}),
    # --- round 18 (benchmark/probes/dev_round18_prompts.jsonl, scored first before these) ---
    R("storage_27044", "slide the drawer out all the way and back in", joints={"joint_0": E(peak="upper")}),
    R("storage_27044", "Drawer comes out about 20 cm and stays put for 1.5 s.", joints={"joint_0": E(end=0.2)}),
    R("storage_27044", "drawer glides out to three-quarters extension and stops.", joints={"joint_0": E(end=0.513)}),
    R("coffee_machine_103030", "the lid rises a quarter of its travel and stops there", joints={"joint_2": E(end=0.125), "joint_1": E(still=True)}),
    R("trash_can_102181", "a foot presses the pedal and, because of that, the lid rises", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("refrigerator_11178", "open the left door to 90 deg. Left and right as seen from the front.",
      joints={"joint_0": E(end=PI / 2), "joint_1": E(still=True)}),
    R("extra/oven_7179", "open the upper door, then slide out the rack behind it",
      joints={"joint_4": E(end="upper"), "joint_0": E(end="upper"), "joint_1": E(still=True), "joint_2": E(still=True)}),
    R("extra/oven_7179", "Pull the lower door down so you can get at the bottom-most rack, and slide that rack out.",
      joints={"joint_3": E(end="upper"), "joint_2": E(end="upper"), "joint_1": E(still=True)}),
    R("safe_101564", "give a quick tap to the key that sits at the upper right", joints={"joint_2": E(moves=True), "joint_0": E(still=True)}),
    R("bottle_cap_3558", "loosen the cap by turning it 90 degrees", joints={"joint_0": E(end=PI / 2)}),
    R("extra/safe_101623", "Swing the door out as far as the hinge lets it, then put it back.", joints={"joint_1": E(peak="upper")}),
    # "of the three" counts a group, it is no key label: no code '3' typed before the button asked for (was: key 3, then key 1)
    R("safe_101564", "press the top button of the three on the left", refuse=True),
    # "the key above the 5": placed from the key labelled 5 (was: the 5 itself pressed: silent); "next to the 5" has two nearest
    R("safe_101564", "press the key above the 5", joints={"joint_1": E(moves=True), "joint_4": E(still=True)}),
    R("safe_101564", "press the key to the left of the 9", joints={"joint_7": E(moves=True), "joint_8": E(still=True)}),
    R("safe_101564", "Press the key next to the 5 (phone-style keypad).", refuse=True),
    # --- round 19 (benchmark/probes/dev_round19_prompts.jsonl, scored first before these) ---
    # framing words: where the user stands, comparisons, an afterthought bounding the amount (reading/framing.py)
    R("toaster_103477", "rotate the small knob 90 degrees clockwise, as seen when looking at the front", joints={"joint_0": E(end=-PI / 2)}),
    R("dishwasher_12553", "There's a single little button up on the control strip, on the right-hand side when you stand facing the dishwasher. Press it.",
      joints={"joint_1": E(moves=True), "joint_0": E(still=True)}),
    R("toaster_103483", "Press the toaster's lever all the way down, like you're starting a batch of toast.", joints={"joint_0": E(end="upper")}),
    R("storage_20453", "could you slide the desk's drawer out about 20 cm? not all the way", joints={"joint_0": E(end=0.2)}),
    R("extra/storage_25308", "Can you pull out the drawer on the left side by 20 cm? Left as you face the cabinet.", joints={"joint_1": E(end=0.2)}),
    R("safe_102387", "Swing the safe's door fully open, let it sit there for two seconds, then shut it completely.",
      joints={"joint_0": E(end=SAFE_102387_CLOSED)}),
    R("extra/oven_7179", "Please you open first the big lower door, and when it is down, open also the small upper door.",
      joints={"joint_3": E(end="upper"), "joint_4": E(end="upper")}),
    R("storage_19179", "Please make the lower drawer of this cabinet to come out", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("kitchen_pot_100038", "make the lid of the pot go up", joints={"joint_0": E(end="upper")}),
    # "the middle one of the three (knobs)": the middle knob; "either direction is fine" says nothing more
    R("washing_machine_103508", "There are three knobs on the back panel. Rotate the middle one of the three by roughly 90 degrees, either direction is fine.",
      joints={"joint_2": E(abs_end=PI / 2), "joint_1": E(still=True), "joint_3": E(still=True)}),
    R("extra/microwave_7128", "The bottom one of the two microwave dials - rotate it 180 degrees.", joints={"joint_2": E(abs_end=PI), "joint_3": E(still=True)}),
    # the viewer's side: "the door on my right" is a place, not a direction; "the operator's right-hand side"; "swing the lever right"
    R("refrigerator_11178", "Swing the door on my right wide open", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("faucet_991", "rotate the mixer handle fully toward the operator's right-hand side", joints={"joint_0": E(end="lower")}),
    R("extra/faucet_1343", "Swing the faucet lever right as far as it goes, then bring it back to centre.", joints={"joint_0": E(peak="lower")}),
    R("extra/coffee_machine_102145", "flick the small lever across to the left side", joints={"joint_0": E(end="lower")}),  # a flick with a place stays
    # what a description names: "the door has two knobs" (the knobs), "a big wheel ... and a smaller dial higher up", "Two catches ..."
    R("safe_101593", "the safe door has two knobs on it. give the right-hand one half a turn", joints={"joint_2": E(abs_end=PI), "joint_1": E(still=True)}),
    R("extra/safe_101623", "There's a big three-spoke wheel on this safe's door and a smaller round dial sitting higher up. Spin only the higher one, one full revolution.",
      joints={"joint_2": E(moves=True), "joint_0": E(still=True)}),
    R("extra/box_100214", "Two catches on the front of this toolbox. Swing the one on the right up so it lies flat against the box.",
      joints={"joint_2": E(end="upper"), "joint_1": E(still=True)}),
    R("trash_can_102155", "spin its left wheel through one full revolution. The bin itself shouldn't go anywhere - just the wheel turning in place.",
      joints={"joint_1": E(abs_end=2 * PI), "joint_0": E(still=True)}),
    R("extra/oven_7179", "To get at the lowest rack you have to drop the lower door first; do that, then slide the rack out.",
      joints={"joint_3": E(end="upper"), "joint_2": E(end="upper"), "joint_0": E(still=True), "joint_1": E(still=True)}),
    R("dishwasher_12553", "Hit the button on the control panel; that unlatches the door, which then drops down open.",
      joints={"joint_1": E(moves=True), "joint_0": E(end="upper")}),
    # "the lower door" of a cabinet whose one door lies under its drawer: that door; of a one-door oven: still refused
    R("storage_23472", "the lower door swings wide open, and then the drawer sitting over it slides out", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("oven_7138", "I want the lower door opened.", refuse=True),
    # --- round 20 (benchmark/probes/dev_round20_prompts.jsonl, scored first before these) ---
    R("dishwasher_12553", "Press the button and drop the door open at the same time", joints={"joint_1": E(moves=True), "joint_0": E(end="upper")}),
    R("microwave_7119", "I only want the round plate to turn, roughly half a revolution.", joints={"joint_1": E(abs_end=PI), "joint_0": E(still=True)}),
    R("bucket_102352", "The handle swings up from where it hangs until it stands straight up, ready for carrying.", joints={"joint_0": E(end=2.3593)}),
    R("safe_101564", "press the key in the bottom-left corner - just that one, once.", joints={"joint_11": E(moves=True), "joint_10": E(still=True)}),
    R("storage_19179", "the thief yanks the lower of the two drawers wide open", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("toaster_103477", "Press the toaster's lever down until it catches at the bottom", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("safe_101593", "Turn the small round dial a quarter turn clockwise", joints={"joint_2": E(end=-PI / 2), "joint_1": E(still=True)}),
    R("extra/box_100214", "snap the right-hand latch of the box shut. Lid and left latch stay put.",
      joints={"joint_2": E(end="upper"), "joint_0": E(still=True), "joint_1": E(still=True)}),
    R("extra/storage_26525", "I need the nightstand drawer pulled all the way out and left there, fully open, for four seconds.", joints={"joint_0": E(end="upper")}),
    R("faucet_148", "Rotate the mixer handle 45 degrees towards the left, left meaning from the user's side of the sink.", joints={"joint_0": E(end=PI / 4)}),
    R("extra/safe_101623", "The safe door carries a three-spoke wheel and a smaller round dial sitting higher up. Rotate only the higher one, 90 degrees clockwise.",
      joints={"joint_2": E(end=PI / 2), "joint_0": E(still=True)}),
    R("extra/oven_7179", "open the door in front of the middle rack", joints={"joint_3": E(end="upper"), "joint_4": E(still=True)}),
    # "the topmost piece", "the top part": any movable part, placed; "the cap sitting on the jar" is above it, the jar no theme
    R("coffee_machine_103030", "pull off just the topmost piece, the little cap sitting on the jar. The jar itself stays seated on the base.",
      joints={"joint_2": E(end="upper"), "joint_1": E(still=True)}),
    R("microwave_7304", "open the left door", joints={"joint_1": E(end="upper")}),  # inspect shows it on the left
    R("microwave_7304", "open the right door", refuse=True),
    # --- round 21 (benchmark/probes/dev_round21_prompts.jsonl, scored first before these) ---
    R("dishwasher_12553", "there's a small protruding element above the door. Push it in with the end effector.", joints={"joint_1": E(moves=True)}),
    R("microwave_7119", "Open the door, let the turntable make one full revolution, then close the door again.",
      joints={"joint_0": E(peak="upper"), "joint_1": E(abs_end=2 * PI)}),
    R("coffee_machine_103030", "Both at once please: the lid rises all the way up while the knob turns half a turn counter-clockwise. Start them together.",
      joints={"joint_0": E(end=PI), "joint_2": E(end="upper")}),
    R("toaster_103477", "Please turn a little the round knob which is low on the front of toaster, it is for the browning level.", joints={"joint_0": E(moves=True)}),
    R("storage_27044", "Could you pull the drawer out by about 30 cm? Not the whole way.", joints={"joint_0": E(end=0.3)}),
    R("extra/suitcase_100550", "fold the suitcase's carry handle down toward the back, i.e. away from the side where the lid opens",
      joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),
    R("extra/storage_25308", "first the right drawer comes out, and once that one is open the left drawer follows",
      joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}, order=(("joint_0", "joint_1"),)),
    R("refrigerator_11178", "Open the fridge door that's on your left when you stand facing the fridge.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    # a code told key by key after a colon; "Not the drip tray plate." names nothing to keep still
    R("safe_101564", "Punch in a three-key code on the safe keypad: the top-left key, then the middle key of the third row from the top, then the bottom-right key.",
      joints={"joint_0": E(moves=True), "joint_7": E(moves=True), "joint_9": E(moves=True), "joint_13": E(still=True)}),
    R("extra/coffee_machine_102145", "could you pop up the little cover on the very top of the coffee machine? Not the drip tray plate down at the bottom.",
      joints={"joint_1": E(end="upper")}),
    R("coffee_machine_103030", "take off whatever piece is sitting on the very top. Only that piece - the jug stays seated on the base.",
      joints={"joint_2": E(end="upper"), "joint_1": E(still=True)}),
    R("coffee_machine_103030", "Lift the jug off the base. The lid is sitting on the jug, so it just rides up along with it.",
      joints={"joint_1": E(end="upper"), "joint_2": E(still=True)}),
    R("extra/oven_7179", "Drop the upper oven door open so there's room, then slide out the rack that sits in that upper compartment.",
      joints={"joint_4": E(end="upper"), "joint_0": E(end="upper"), "joint_1": E(still=True), "joint_2": E(still=True)}),
    R("laptop_10697", "Push the upper half of the laptop (the lid with the display) backwards as far as its hinge will let it go.", joints={"joint_1": E(end="upper")}),
    # --- round 22 (benchmark/probes/dev_round22_prompts.jsonl: scored first on this code, then these classes fixed) ---
    R("washing_machine_103508", "Close the lid of the washer, then twist the leftmost dial to choose a program.", joints={"joint_3": E(moves=True)}),
    R("microwave_7119", "Open the microwave door wide, then give the glass turntable one complete revolution, and after that close the door again.",
      joints={"joint_0": E(peak="upper"), "joint_1": E(abs_end=2 * PI)}),
    R("dishwasher_12553", "one gripper pushes the button in while, simultaneously, the other arm pulls the door down open.",
      joints={"joint_1": E(moves=True), "joint_0": E(end="upper")}),
    R("box_102456", "cloes teh lid of the box pls, its half open rn", joints={"joint_0": E(end=BOX_102456_CLOSED)}),
    R("refrigerator_11178", "both fridge doors fly open at exactly the same moment, all the way.", joints={"joint_0": E(end="upper"), "joint_1": E(end="upper")}),
    R("extra/oven_7179", "Slide the middle rack out for me - open a door first if you have to.",
      joints={"joint_1": E(end="upper"), "joint_3": E(end="upper"), "joint_4": E(still=True)}),
    R("extra/safe_101612", "Please rotate the round knob which is on the left side of the handle, one complete turn.", joints={"joint_1": E(abs_end=2 * PI)}),
    R("extra/coffee_machine_102145", "Shove the little lever all the way over to the left - my left, standing in front of the machine.",
      joints={"joint_0": E(end="lower")}),
    # --- round 23 (benchmark/probes/dev_round23_prompts.jsonl: scored first on this code, then these classes fixed) ---
    R("microwave_7304", "I'd love the microwave door to stand open about 45 degrees.", joints={"joint_1": E(end=PI / 4)}),
    R("dishwasher_12553", "open the dishwasher, then close it again and after that push the button to start it",
      joints={"joint_0": E(peak="upper"), "joint_1": E(moves=True)}, order=(("joint_0", "joint_1"),)),
    R("extra/microwave_7128", "Hit the start button on the microwave.", joints={"joint_1": E(moves=True), "joint_0": E(still=True)}),
    R("extra/microwave_7128", "press the power button", joints={"joint_1": E(moves=True), "joint_0": E(still=True)}),
    R("extra/microwave_7128", "press the release button", joints={"joint_1": E(moves=True), "joint_0": E(end="upper")}),
    R("safe_101593", "open the door after you spin the handle", joints={"joint_1": E(moves=True), "joint_0": E(end="upper")}, order=(("joint_1", "joint_0"),)),
    R("safe_101593", "This safe only opens after you spin the cross-shaped handle. Spin it, then pull the door open.",
      joints={"joint_1": E(moves=True), "joint_0": E(end="upper")}, order=(("joint_1", "joint_0"),)),
    R("extra/box_100214", "Latch the toolbox shut.", joints={"joint_0": E(end="lower"), "joint_1": E(end="upper"), "joint_2": E(end="upper")},
      order=(("joint_0", "joint_1"),)),
    R("extra/box_100214", "close the toolbox", joints={"joint_0": E(end="lower"), "joint_1": E(still=True), "joint_2": E(still=True)}),
    R("microwave_7236", "I'd like to put a bowl of soup in the microwave to heat it up.", joints={"joint_0": E(end="upper")}),
    R("oven_7138", "The lasagna's done, I need to get it out of the oven.", joints={"joint_0": E(end="upper")}),
    R("extra/oven_7179", "I need to take the rack out of the upper oven compartment.",
      joints={"joint_4": E(end="upper"), "joint_0": E(end="upper"), "joint_1": E(still=True), "joint_3": E(still=True)}, order=(("joint_4", "joint_0"),)),
    R("extra/coffee_machine_102145", "Raise the lid on top of the big round water tank, keep it up for 2 seconds, then lower it again.",
      joints={"joint_1": E(peak="upper"), "joint_2": E(still=True)}),
    R("bucket_102352", "Swing the handle up and over so it hangs down the back of the bucket.", joints={"joint_0": E(end="upper")}),
    # --- round 24 (benchmark/probes/dev_round24_prompts.jsonl: scored first after round 23's fixes, then these classes fixed) ---
    R("toaster_103483", "I want to toast a slice of bread, get the toaster going.", joints={"joint_0": E(moves=True)}),
    R("extra/safe_102380", "Shut the safe door, and once it's closed spin the dial around twice.",
      joints={"joint_2": E(end="lower"), "joint_0": E(abs_end=4 * PI)}, order=(("joint_2", "joint_0"),)),
    R("extra/safe_102380", "spin the dial twice", joints={"joint_0": E(abs_end=4 * PI)}),
    R("extra/microwave_7128", "I'd like the door opened first and then the glass plate inside turned one full circle.",
      joints={"joint_0": E(end="upper"), "joint_4": E(abs_end=2 * PI)}, order=(("joint_0", "joint_4"),)),
    R("oven_7221", "So I'm animating a little kitchen scene, and what I'd love is for the door to swing about halfway open, stay like that for a couple of "
      "seconds, and then shut again.", joints={"joint_0": E(end="lower")}),
    R("laptop_10101", "Tilt the screen back so it's open to about 135 degrees from the keyboard.", joints={"joint_1": E(end=LAPTOP_10101_CLOSED + 3 * PI / 4)}),
    R("storage_23472", "I'd like the cupboard at the bottom opened, and please leave the drawer where it is.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("safe_101564", "On the keypad hit the top-left button, then the one right under it, and after that swing the safe door open.",
      joints={"joint_0": E(moves=True), "joint_5": E(moves=True), "joint_13": E(end="upper")}, order=(("joint_0", "joint_5"), ("joint_5", "joint_13"))),
    R("window_103135", "It's really stuffy in here. Could you let some fresh air in?", joints={"joint_0": E(end="upper")}),
    R("dishwasher_11700", "I've got a stack of dirty plates I need to load into this.", joints={"joint_0": E(end="upper")}),
    R("extra/safe_101623", "This safe has two knobs on its door and I'm interested in the smaller one, the one higher up. Could you give that one half a turn?",
      joints={"joint_2": E(abs_end=PI), "joint_0": E(still=True)}),
    R("extra/safe_101612", "Turn the handle on the safe as far as it goes, hold it there for 3 seconds, then let it go back.",
      joints={"joint_2": E(peak="lower")}),
    R("bucket_102352", "Swing the handle over the top of the bucket until it's pointing at the ceiling.", joints={"joint_0": E(end=2.3593)}),
    R("bucket_102352", "lift the handle up", joints={"joint_0": E(end=2.3593)}),
    # --- round 25 (benchmark/probes/dev_round25_prompts.jsonl: scored first after rounds 23-24's fixes, then these classes fixed) ---
    R("extra/microwave_7128", "Turn the upper of the two dials on the right side of the microwave a quarter turn clockwise.",
      joints={"joint_3": E(abs_end=PI / 2), "joint_2": E(still=True)}),
    R("extra/safe_101623", "There are two dials on the safe door. Rotate the bigger, lower one half a turn clockwise.",
      joints={"joint_0": E(abs_end=PI), "joint_2": E(still=True)}),
    R("microwave_7236", "I want to put my leftovers inside to warm them up.", joints={"joint_0": E(end="upper")}),
    R("extra/microwave_7128", "i need put bowl of soup inside microwave for heating", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("window_103135", "It's stuffy in this room, let some fresh air in please.", joints={"joint_0": E(end="upper")}),
    # --- round 26 (benchmark/probes/dev_round26_prompts.jsonl: first run 77 of 81 before these) ---
    R("microwave_7236", "Pop the microwave door open, I need to put a plate in.", joints={"joint_0": E(end="upper")}),
    R("microwave_7119", "put a plate inside", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),
    R("coffee_machine_103030", "Of the two pieces stacked on top of the base, lift off the upper one.",
      joints={"joint_2": E(end="upper"), "joint_1": E(still=True), "joint_0": E(still=True)}),
    R("box_102456", "opne the box lid all teh way back", joints={"joint_0": E(end="upper")}),
    R("laptop_10101", "tilt the screen all the way back", joints={"joint_1": E(end="upper")}),
    # a key placed relative to another: an intensifier before the relation, "left of", "one" and a row after the landmark
    R("safe_101564", "Tap the key right above the bottom-right one.", joints={"joint_8": E(moves=True), "joint_9": E(still=True)}),
    R("safe_101564", "press the button just left of the top-right button", joints={"joint_1": E(moves=True), "joint_2": E(still=True)}),
    R("safe_101564", "press the key directly under the middle key of the top row", joints={"joint_4": E(moves=True), "joint_1": E(still=True)}),
    R("safe_101564", "press the key immediately below the 5", joints={"joint_7": E(moves=True), "joint_4": E(still=True)}),
    # --- round 27 (benchmark/probes/dev_round27_prompts.jsonl: first run 74 of 81 after round 26's fixes) ---
    R("bucket_100454", "The handle's standing straight up. Let it fall down on the side that's facing me.", joints={"joint_0": E(end="lower")}),
    R("bucket_100454", "The handle is upright. Let it fall toward me.", joints={"joint_0": E(end="lower")}),
    R("bucket_102352", "Swing the handle over the top so it ends up hanging down the far side of the bucket, away from me.",
      joints={"joint_0": E(end="upper")}),
    R("coffee_machine_103030", "Lift off just the piece right at the very top of the coffee maker and leave everything below it alone.",
      joints={"joint_2": E(end="upper"), "joint_1": E(still=True)}),
    R("safe_101564", "Enter a two-key code on the keypad - top-left key first, then the bottom-right one - and after that pull the safe door open.",
      joints={"joint_0": E(moves=True), "joint_9": E(moves=True), "joint_13": E(end="upper"), "joint_1": E(still=True)},
      order=(("joint_0", "joint_9"), ("joint_9", "joint_13"))),
    R("extra/box_100214", "Of the two latches on the front of the box, flip the right-hand one up so it's closed.",
      joints={"joint_2": E(end="upper"), "joint_1": E(still=True)}),
    R("extra/box_100214", "Can you shut the lid first, and once it's down, snap the left latch over it?",
      joints={"joint_0": E(end="lower"), "joint_1": E(end="upper"), "joint_2": E(still=True)}, order=(("joint_0", "joint_1"),)),
    # where a part sits is where it sits with the object shut: the knobs of a safe whose door rests open
    R("extra/safe_101623", "turn the left knob a quarter turn", joints={"joint_0": E(abs_end=PI / 2), "joint_2": E(still=True)}),
    R("extra/safe_101623", "turn the right knob a quarter turn", joints={"joint_2": E(abs_end=PI / 2), "joint_0": E(still=True)}),
    # --- round 28 (benchmark/probes/dev_round28_prompts.jsonl: first run 74 of 81 after rounds 26-27's fixes) ---
    R("laptop_10101", "fold the upper half down until it lies flat on the lower half", joints={"joint_1": E(end="lower")}),
    R("coffee_machine_103030", "The lid stays locked until the dial on the base is turned. Unlock it and lift the lid off.",
      joints={"joint_0": E(moves=True), "joint_2": E(end="upper"), "joint_1": E(still=True)}, order=(("joint_0", "joint_2"),)),
    R("safe_101593", "Turning the spoked handle on this safe pulls back the locking bolts. Get it open.",
      joints={"joint_1": E(moves=True), "joint_0": E(end="upper"), "joint_2": E(still=True)}, order=(("joint_1", "joint_0"),)),
    R("washing_machine_103508", "On the washer's control panel, twist the knob that sits furthest to the left.",
      joints={"joint_3": E(moves=True), "joint_1": E(still=True), "joint_2": E(still=True)}),
    R("storage_23472", "This bedside cabinet was left half open. Push the drawer all the way in first, and once it's shut, close the cabinet door underneath it.",
      joints={"joint_1": E(end="lower"), "joint_0": E(end="lower")}, order=(("joint_1", "joint_0"),)),
    R("safe_101564", "Punch in two keys on the safe - the top-left one, then the middle key of the bottom row - and then swing the door open.",
      joints={"joint_0": E(moves=True), "joint_10": E(moves=True), "joint_13": E(end="upper")}, order=(("joint_0", "joint_10"), ("joint_10", "joint_13"))),
    R("extra/box_100214", "Snap the right-hand clasp on the front of the chest shut, and leave the left one as it is.",
      joints={"joint_2": E(end="upper"), "joint_1": E(still=True)}),
    # --- round 29 (benchmark/probes/dev_round29_prompts.jsonl: first run 77 of 81 after rounds 26-28's fixes) ---
    R("laptop_10248", "For a product shot I need the laptop screen standing at 90 degrees to the keyboard.", joints={"joint_1": E(end=-0.1396)}),
    R("bucket_100454", "Move the bucket straight up by 30 cm.", joints={"joint_0": E(still=True)}, base=(0.0, 0.0, 0.3)),
    R("safe_101564", "Tap the top-left key on the keypad, then the key right next to it in the middle of the top row, and once that's done swing the safe door open.",
      joints={"joint_0": E(moves=True), "joint_1": E(moves=True), "joint_5": E(still=True), "joint_13": E(end="upper")}),
    R("safe_101564", "press the top-left key, then the key next to it", joints={"joint_0": E(moves=True), "joint_1": E(moves=True), "joint_5": E(still=True)}),
    R("storage_20453", "I only need the drawer out about halfway, can you slide it out that much?", joints={"joint_0": E(end=0.288)}),
    # --- round 48 (voice transcripts, a learner, specifications): commas left out, a part said first and taken up by "it", "shall" ---
    R("extra/storage_25308", "Drawer on left open it and then close it again.", joints={"joint_1": E(peak=0.44), "joint_0": E(still=True)}),  # r48e_025
    R("suitcase_103762", "Briefcase close it.", joints={"joint_0": E(end=-1.0472), "joint_1": E(still=True)}),  # r48e_100 (was silent: the handle turned)
    R("refrigerator_11178", "uh the fridge door on the right can you swing it open", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),  # r48f_064
    R("extra/kitchen_pot_100015", "Stockpot drag it toward me 0.5 m please.", base=(-0.5, 0.0, 0.0)),  # r48e_028
    R("toaster_103477", "uh the browning knob give it a quarter turn clockwise", joints={"joint_0": E(end=-1.5708), "joint_1": E(still=True), "joint_2": E(still=True)}),  # r48f_104
    R("safe_102387", "Door swing it shut first; only then spin the dial for half of turn to clockwise.", joints={"joint_0": E(end=SAFE_102387_CLOSED), "joint_1": E(end=-PI)},
      order=(("joint_0", "joint_1"),)),  # r48e_120: "shut first" is the end state, not an ordinal of the door
    R("dishwasher_11700", "uh the dishwasher can you lower its door forty five degrees and that's it no further", joints={"joint_0": E(end=0.7854)}),  # r48f_003
    R("laptop_10101", "The screen shall be tilted back to the maximum angle allowed by the hinge.", joints={"joint_1": E(end="upper")}),  # r48g_054
    R("extra/storage_24644", "An extension of exactly six inches shall be applied to the drawer; it must not be opened beyond that.", joints={"joint_0": E(end=0.1524)}),  # r48g_072
    R("coffee_machine_103030", "Viewed from the front of the machine, the speed dial on the front face of the base shall be turned clockwise by one quarter of a turn.",
      joints={"joint_0": E(end=-1.5708), "joint_1": E(still=True), "joint_2": E(still=True)}),  # r48g_004
    R("extra/storage_25308", "uh first pull out the left drawer and then after it's open do the right drawer as well", joints={"joint_1": E(end=0.44), "joint_0": E(end=0.524)},
      order=(("joint_1", "joint_0"),)),  # r48f_068 (was silent: both at once, right first)
    R("extra/storage_25308", "In this shot, the drawer on the left as seen from the front slides out halfway.", joints={"joint_1": E(end=0.22), "joint_0": E(still=True)}),  # r48h_001
    R("extra/box_100214", "Viewed from the front of the case, where its two clasps sit, the clasp on the right snaps shut.", joints={"joint_2": E(end=0.4363), "joint_1": E(still=True)}),  # r48h_019
    R("window_103135", "um swing the window open as far as it'll go hold it for two seconds and then close it back up", joints={"joint_0": E(end=WINDOW_103135_CLOSED)}),  # r48f_021 ("close it back up" on a window resting ajar: closed)
    R("extra/safe_101623", "Open the safe door so it stand exactly 90 degree open.", joints={"joint_1": E(end=0.3896)}),  # r48e_075: "so it stand(s)"
    R("extra/oven_7179", "Oven have three sliding rack; please pull out the rack of middle.", joints={"joint_1": E(end="upper"), "joint_0": E(still=True), "joint_2": E(still=True)}),  # r48e_074
    R("storage_19179", "The drawer more high of the two must open 40 cm.", joints={"joint_1": E(end=0.4), "joint_0": E(still=True)}),  # r48e_061
    R("extra/storage_25308", "Please pull out the left side drawer until it don't go more.", joints={"joint_1": E(end=0.44), "joint_0": E(still=True)}),  # r48e_108: a side said apart
    R("refrigerator_11178", "The refrigerator door that is on the right, as seen when standing in front of the appliance, is to be opened.",
      joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),  # r48g_069
    R("extra/storage_25308", "move the drawer to the left", refuse=True),  # "left" is where it goes, not which drawer: still asks which
    R("trash_can_102155", "The left-hand wheel is to be rolled around through one full revolution. The bin itself is not to move.",
      joints={"joint_1": E(abs_end=2 * PI)}, base=(0.0, 0.0, 0.0)),  # r48g_115 (was silent: "to move" read as a purpose, a quarter turn)
    R("extra/oven_7179", "The oven has two doors; in this shot the higher of the two drops down to 45°.", joints={"joint_4": E(end=0.7854), "joint_3": E(still=True)}),  # r48h_013
    R("laptop_10101", "In this shot the top half of the laptop closes down onto the bottom half until it rests flat against it.", joints={"joint_1": E(end="lower")}),  # r48h_028
    R("dishwasher_12553", "A finger taps the button on the control panel; only once it has popped back out does the dishwasher door swing all the way down.",
      joints={"joint_1": E(moves=True), "joint_0": E(end=1.5708)}, order=(("joint_1", "joint_0"),)),  # r48h_077 (was silent: the door never moved)
    R("safe_101564", "Key in 0 to unlock it, then swing the door open.", joints={"joint_10": E(peak=0.004), "joint_13": E(end="upper")},
      order=(("joint_10", "joint_13"),)),  # r10_086: a purpose ("to unlock it"), not a part said first and taken up by "it"
    R("washing_machine_103508", "Laundry room cutscene: the char reaches over to the washer's control panel and twists the knob on the far left of the three (left as seen from the front of the machine).",
      joints={"joint_3": E(moves=True), "joint_1": E(still=True), "joint_2": E(still=True)}),  # r46c_099: "of the three" after its noun names no new group
    R("extra/kitchen_pot_100015", "Pull the stockpot to direction of me for half metre.", base=(-0.5, 0.0, 0.0)),  # r48e_027: "to direction of", "for half metre"
    R("storage_27044", "First open drawer lower for half of metre.", joints={"joint_0": E(end=0.5)}),  # r48e_005 (its first clause): "half of metre"
    R("refrigerator_11178", "Fridge shot. Step 1: The right-hand door is to be opened to 60°. Step 2: Only once it has reached that angle is the other door to be swung fully open.",
      joints={"joint_1": E(end=1.0472), "joint_0": E(end=PI)}, order=(("joint_1", "joint_0"),)),  # r48g_029: "only once ... is the other door to be"
    # --- round 49 (blind, on rewritten dev assets): numbered steps, rates over a time, a place where it started, "until it's halfway" ---
    R("extra/oven_7179", "Step 1: The upper door of the oven is to be opened fully. Step 2: Only after Step 1 has been completed is the highest tray to be extended completely.",
      joints={"joint_4": E(end=1.5708), "joint_0": E(end=0.528), "joint_1": E(still=True), "joint_2": E(still=True), "joint_3": E(still=True)},
      order=(("joint_4", "joint_0"),)),  # r48g_059 ("step" was read as a verb, "completed" as a part)
    R("extra/oven_7179", "1. Open the upper door. 2. Pull out the highest tray.", joints={"joint_4": E(end=1.5708), "joint_0": E(end=0.528), "joint_3": E(still=True)},
      order=(("joint_4", "joint_0"),)),  # "2." had repeated the step before it
    R("trash_can_102155", "For the game scene, the wheelie bin as a whole is to be pushed 0.5 m in the direction of its front.", base=(-0.5, 0.0, 0.0)),  # r48g_001
    R("extra/storage_25308", "Slide the left drawer out at 10 cm per second for 2 seconds.", joints={"joint_1": E(end=0.2), "joint_0": E(still=True)}),  # r49b_030 (refused: "per")
    R("extra/microwave_7128", "Open the door at 30 degrees a second for 2 seconds.", joints={"joint_0": E(end=1.0472)}),  # a rate and a time: that far
    R("extra/microwave_7128", "Spin the turntable at half a turn per second for two seconds.", joints={"joint_4": E(abs_end=6.2832), "joint_0": E(still=True)}),  # r49b_029
    R("extra/storage_25308", "Pull the left drawer fully open, then push it back until it's about halfway.", joints={"joint_1": E(end=0.22)}),  # r49b_025 (was silent: back to start)
    R("extra/storage_25308", "Slide the left drawer all the way out, then back to the spot it started from.", joints={"joint_1": E(peak=0.44)}),  # r49b_052
    R("extra/storage_25308", "Pull the left drawer out 20 cm, then give the left drawer a good shove so it slides shut.", joints={"joint_1": E(peak=0.2)}),  # r49b_045 ("good" read as a part)
    R("suitcase_103762", "I'm heading to the airport - get this case shut so nothing falls out.", joints={"joint_0": E(end=-1.0472), "joint_1": E(still=True)}),  # r49a_043
    R("extra/microwave_7128", "Open the door, shut it again, then twist the upper knob a quarter turn to set the timer.",
      joints={"joint_0": E(peak=1.5708), "joint_3": E(end=-1.5708), "joint_2": E(still=True)}),  # r49c_021 (was silent: "the timer" turned the other knob too)
    R("toilet_102622", "I need to use the toilet.", joints={"joint_0": E(end=1.5708), "joint_1": E(still=True)}),  # r49a_044: a use that needs it open
    R("suitcase_103762", "I'm done packing, get it ready to carry.", joints={"joint_0": E(end=-1.0472), "joint_1": E(still=True)}),  # r49c_049
    R("safe_102387", "Lock my jewelry away in the safe.", joints={"joint_0": E(end=SAFE_102387_CLOSED)}),  # r49c_050
    R("extra/oven_7179", "Open both doors fully, then shut just the bottom door and leave the top one the way it is.",
      joints={"joint_3": E(peak=1.5708), "joint_4": E(end=1.5708)}),  # r50e_013 (was silent: "leave ... the way it is" opened it)
    R("bucket_102352", "Flip the handle over to the far side, then bring it back up to vertical.", joints={"joint_0": E(end=2.3593)}),  # r50d_028 (was silent: back to start)
    R("window_103135", "Push the window wide open, then pull it shut.", joints={"joint_0": E(end=WINDOW_103135_CLOSED)}),  # r50d_022 (opened first: the refused-looking "push ... wide open" closed it)
    R("faucet_991", "Swing the lever all the way left, then bring it halfway back toward the centre.", joints={"joint_0": E(end=0.7854)}),  # r50e_028, r49b_024
    R("toaster_103483", "Push the lever down to start toasting; when the toast is done the lever springs back up.", joints={"joint_0": E(peak=0.3)}),  # r49b_043
    R("window_103135", "Pull the upper pane shut against the frame.", joints={"joint_0": E(end=WINDOW_103135_CLOSED)}),  # r50d_013: its one moving pane is the upper one
    R("extra/oven_7179", "I need to check on the cookies in the top oven, get that rack out for me.",
      joints={"joint_4": E(end=1.5708), "joint_0": E(end=0.528), "joint_1": E(still=True), "joint_2": E(still=True)}, order=(("joint_4", "joint_0"),)),  # r50e_041
    R("extra/oven_7179", "The cookies are in the top oven, get that rack out for me.", joints={"joint_4": E(end=1.5708), "joint_0": E(end=0.528), "joint_3": E(still=True)}),
    R("extra/toaster_103473", "I'm making toast for two, start both sides.", joints={"joint_0": E(moves=True), "joint_1": E(moves=True)}),  # r49c_045
    R("microwave_7236", "Animator note: microwave door opens to 60°, short beat, closes again. Nothing else moves.", joints={"joint_0": E(peak=1.0472)}),  # r5_039
    R("extra/bucket_100432", "Flop the handle down to one side, then stand it back up.", joints={"joint_0": E(peak=-1.885)}),  # r41l_023: back where it was, not "vertical"
    R("oven_7221", "Open the lower door of this oven.", refuse=True),  # r4_044: no fixed door to compare with
    # --- session 31: codes told then entered, a part name the agent does not know read by elimination, a non-part phrase ---
    R("safe_101564", "Code is 2, 5, 8 - type it in on the keypad.", joints={"joint_1": E(peak=0.004), "joint_4": E(peak=0.004), "joint_7": E(peak=0.004), "joint_13": E(still=True), "joint_0": E(still=True)},
      order=(("joint_1", "joint_4"), ("joint_4", "joint_7"))),  # r10_044 ("the code" was grounded as all twelve keys)
    R("safe_101564", "um the code is two five eight punch it in on the keypad", joints={"joint_1": E(peak=0.004), "joint_4": E(peak=0.004), "joint_7": E(peak=0.004), "joint_13": E(still=True)}),  # r48f_035
    R("safe_101564", "The code 1-2-3 shall be entered on the keypad, one key at a time; only after the code is complete is the door to be opened to 90 degrees.",
      joints={"joint_0": E(peak=0.004), "joint_1": E(peak=0.004), "joint_2": E(peak=0.004), "joint_13": E(end=1.5708)}, order=(("joint_2", "joint_13"),)),  # r48g_112: the code before a passive verb; "the code is complete"
    R("safe_101564", "Step 1: The keys 1, 2 and 3 on the keypad are to be pressed one after another. Step 2: Once the code has been entered, the door is to be swung open by 90 degrees.",
      joints={"joint_0": E(peak=0.004), "joint_1": E(peak=0.004), "joint_2": E(peak=0.004), "joint_3": E(still=True), "joint_13": E(end=1.5708)}, order=(("joint_2", "joint_13"),)),  # r48g_111
    R("trash_can_102181", "Flip up the shutter.", joints={"joint_0": E(moves=True), "joint_1": E(end=3.1542)}),  # the one hinged closure
    R("microwave_7119", "Open the panel.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),  # the turntable cannot open
    R("trash_can_102181", "The bin is to be opened in a hands-free manner.", joints={"joint_0": E(moves=True), "joint_1": E(end=3.1542)},
      order=(("joint_0", "joint_1"),)),  # r48g_011 ("manner" was refused as a missing part)
    R("refrigerator_11178", "Open the hatch.", refuse=True),  # two doors fit: no guess
    R("extra/microwave_7128", "Turn the thermostat.", refuse=True),  # two knobs fit
    # --- round 51 (blind: everyday names for parts, codes said in sentences) ---
    R("switch_100952", "Flip the paddle and then flip it back.", joints={"joint_0": E(moves=True)}),  # r51h_025
    R("dishwasher_12553", "Press the little push-pad above the door, on the right.", joints={"joint_1": E(moves=True), "joint_0": E(still=True)}),  # r51h_046
    R("toaster_103483", "Press the toast plunger down and let it pop back up.", joints={"joint_0": E(peak="upper")}),  # r51h_027
    R("window_103135", "Push the hinged glass out as far as it goes.", joints={"joint_0": E(end="upper")}),  # r51h_038
    R("extra/box_100214", "Close the top, then flip the left clasp, then the right one.", joints={"joint_0": E(end="lower"), "joint_1": E(moves=True), "joint_2": E(moves=True)},
      order=(("joint_0", "joint_1"), ("joint_1", "joint_2"))),  # r51h_049
    R("washing_machine_103508", "Twist the small knob.", refuse=True),  # r51g_051: two small knobs alike
    R("safe_101564", "My PIN's 1904. Tap it in and pull the safe open.", joints={"joint_0": E(peak=0.004), "joint_8": E(peak=0.004), "joint_10": E(peak=0.004), "joint_5": E(peak=0.004), "joint_13": E(end="upper")}, order=(("joint_5", "joint_13"),)),  # r51g_036
    R("extra/box_100214", "Snap the right-hand catch into place.", joints={"joint_2": E(end="upper"), "joint_1": E(still=True)}),  # r51h_050: "into place" is shut (had not moved, silently)
    R("storage_19179", "Pull the top drawer out, then push it back into place.", joints={"joint_1": E(peak="upper", end="lower")}),
    R("bottle_cap_3558", "Give the top of the bottle a quarter turn to loosen it.", joints={"joint_0": E(end=1.5708)}),  # r51g_001: the amount was lost (a half turn, silently)
    R("microwave_7119", "Swing the front hatch of the microwave open.", joints={"joint_0": E(end="upper"), "joint_1": E(still=True)}),  # r51g_024: a hatch is a door or a lid
    R("safe_101564", "pls hit the three top row keys going left to right", joints={"joint_0": E(moves=True), "joint_1": E(moves=True), "joint_2": E(moves=True), "joint_13": E(still=True)},
      order=(("joint_0", "joint_1"), ("joint_1", "joint_2"))),  # r47d_025: "three" counts the keys, no code (a regression the sweep caught)
    R("extra/kitchen_pot_100015", "To let the steam out, raise the lid a little, and then set it back down.", joints={"joint_0": E(moves=True)}),  # r47c_101: no name is read by elimination in a purpose
    R("safe_101564", "Actuate the third key down in the right-hand column of the keypad.", refuse=True),  # r8_044: a place not read is not a word to drop
    R("box_102456", "Flip the top all the way open.", joints={"joint_0": E(end="upper")}),  # r51g_006: nothing read as a part; the one lid
    R("extra/bucket_100432", "Pull the wire loop up so it stands straight.", joints={"joint_0": E(end=0.4778)}),  # r51h_052
    R("kitchen_pot_100038", "Lift the pot's top off, hold it up for two seconds, then set it back down.", joints={"joint_0": E(peak="upper", end="lower")}),  # r51g_020
    R("stapler_103099", "Spin the whirligig.", refuse=True),  # nothing the verb fits: still refused
    R("storage_23472", "Pull the thing at the top all the way out.", joints={"joint_1": E(end="upper"), "joint_0": E(still=True)}),  # r51g_042: what slides, not the door there
    R("safe_101564", "Unlock it: my PIN is 9512. Then swing the door open.", joints={"joint_8": E(peak=0.004), "joint_4": E(peak=0.004), "joint_0": E(peak=0.004), "joint_1": E(peak=0.004), "joint_13": E(end="upper")}, order=(("joint_1", "joint_13"),)),  # r51h_004
]


def _value(row_asset: str, joint: str, value: float | str) -> float:
    spec = asset(row_asset).joints[joint]
    if value == "upper":
        assert spec.upper is not None
        return spec.upper
    if value == "lower":
        assert spec.lower is not None
        return spec.lower
    return float(value)


def _first_motion(track: np.ndarray) -> int:
    moved = np.flatnonzero(np.abs(track - track[0]) > 1e-4)
    return int(moved[0]) if moved.size else len(track)


def _check_joint(row: Row, joint: str, expect: E, track: np.ndarray) -> None:
    rest = asset(row.asset).joints[joint].rest
    label = f"{row.id} / {joint}"
    if expect.still:
        assert float(np.ptp(track)) < 1e-6, f"{label}: should not move, moves over {np.ptp(track):.4g}"
    if expect.moves:
        assert float(np.ptp(track)) > 1e-3, f"{label}: should move"
    if expect.end is not None:
        wanted = _value(row.asset, joint, expect.end)
        assert track[-1] == pytest.approx(wanted, abs=TOLERANCE), f"{label}: ends at {track[-1]:.4g}, expected {wanted:.4g}"
    if expect.abs_end is not None:
        assert abs(track[-1] - rest) == pytest.approx(expect.abs_end, abs=TOLERANCE), f"{label}: ends {track[-1]:.4g} from rest {rest}"
    if expect.peak is not None:
        wanted = _value(row.asset, joint, expect.peak)
        assert float(np.min(np.abs(track - wanted))) < TOLERANCE, f"{label}: never reaches {wanted:.4g} (range {track.min():.4g}..{track.max():.4g})"
        assert track[-1] == pytest.approx(rest, abs=TOLERANCE), f"{label}: should return to {rest}, ends at {track[-1]:.4g}"
    if expect.sign is not None:
        assert np.sign(track[-1] - rest) == expect.sign, f"{label}: turned {track[-1] - rest:+.4g}, expected sign {expect.sign:+d}"


@pytest.mark.parametrize("row", ROWS, ids=[r.id for r in ROWS])
def test_prompt(row: Row) -> None:
    if row.refuse:
        with pytest.raises(GroundingError) as info:
            animate(row.asset, row.prompt)
        assert "Movable parts" in str(info.value) or "no movable parts" in str(info.value)
        return
    outcome = animate(row.asset, row.prompt)
    trajectory = outcome.trajectory
    for joint, expect in row.joints.items():
        _check_joint(row, joint, expect, trajectory.joint(joint))
    if row.yaw_deg is not None:
        x, y, z, w = trajectory.base_rotation_xyzw[-1]
        yaw = math.degrees(math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)))
        assert yaw == pytest.approx(row.yaw_deg, abs=1.0) or abs(yaw) == pytest.approx(abs(row.yaw_deg), abs=1.0) == 180.0, f"{row.id}: yaw {yaw:.1f}"
    elif row.base is not None:
        assert trajectory.base_translation[-1] == pytest.approx(np.array(row.base), abs=0.01), f"{row.id}: base ends at {trajectory.base_translation[-1]}"
    else:
        assert not trajectory.has_base_motion(), f"{row.id}: the object should not move as a whole"
    for first, second in row.order:
        a, b = _first_motion(trajectory.joint(first)), _first_motion(trajectory.joint(second))
        assert a < b, f"{row.id}: {first} should start (frame {a}) before {second} (frame {b})"


def test_table_is_large_and_varied() -> None:
    assert len(ROWS) >= 80
    assert sum(r.refuse for r in ROWS) >= 6
    assert len({r.asset for r in ROWS}) >= 25


def _duration(asset_name: str, prompt: str) -> float:
    return float(animate(asset_name, prompt).trajectory.duration_s)


@pytest.mark.parametrize(("prompt", "extra"), [
    ("Open the microwave door 90 degrees, wait, then shut it.", 0.5),
    ("open the microwave door 90 degrees, wait two seconds, then shut it", 2.0),
])
def test_wait_holds_between_steps(prompt: str, extra: float) -> None:
    """ "..., wait (N seconds), then ...": the scene holds still between the two steps."""
    plain = _duration("microwave_7304", "Open the microwave door 90 degrees, then shut it.")
    assert _duration("microwave_7304", prompt) >= plain + extra - 1e-6


def _held_at_peak(asset_name: str, prompt: str, joint: str) -> float:
    """Seconds ``joint`` stays at its furthest point from where it started (within 1% of the way)."""
    trajectory = animate(asset_name, prompt).trajectory
    track = trajectory.q[:, trajectory.joint_names.index(joint)]
    away = np.abs(track - track[0])
    return float(np.count_nonzero(away >= away.max() * 0.99) - 1) / trajectory.fps


@pytest.mark.parametrize(("asset_name", "prompt", "joint", "seconds"), [
    ("switch_100952", "um turn it on leave it on for two and a half seconds and then turn it back off", "joint_0", 2.5),
    ("extra/storage_24644", "uh open the drawer keep it like that three seconds and then shut it", "joint_0", 3.0),
    ("dishwasher_11700", "uh the dishwasher door lower it sixty degrees hold it two seconds and then close it", "joint_0", 2.0),
    ("dishwasher_11700", "Please put the dishwasher door down to 70°, hold for 2 sec, after close it back up.", "joint_0", 2.0),
    ("box_100671", "Open the lid to 90° from closed, make pause of 2 seconds, after close it.", "joint_0", 2.0),
])
def test_run_on_hold_or_wait(asset_name: str, prompt: str, joint: str, seconds: float) -> None:
    """A hold or a wait run into the step before it ("turn it on leave it on for 2.5 s", voice transcripts), or said the way a
    learner says it ("make pause of 2 s", "after close it"), keeps the part at its furthest point that long before it goes back
    (round 48: the hold was dropped, or came after the return)."""
    assert _held_at_peak(asset_name, prompt, joint) >= seconds - 0.05


@pytest.mark.parametrize(("asset_name", "prompt", "joint", "presses"), [
    ("safe_101564", "press the 5 key twice", "joint_4", 2),
    ("safe_101564", "tap the top-left key three times, then open the door", "joint_0", 3),
    ("dishwasher_12553", "press the button 2 times", "joint_1", 2),
])
def test_counted_presses(asset_name: str, prompt: str, joint: str, presses: int) -> None:
    """"press the 5 key twice" is two presses, each let go before the next (the count was read and dropped: one press)."""
    trajectory = animate(asset_name, prompt).trajectory
    track = trajectory.q[:, trajectory.joint_names.index(joint)]
    down = np.abs(track - track[0]) > 0.5 * np.abs(track - track[0]).max()
    assert int(np.count_nonzero(down[1:] & ~down[:-1])) == presses


def test_hold_for_a_time_waits() -> None:
    plain = _duration("trash_can_102181", "Step on the pedal, then let go.")
    held = _duration("trash_can_102181", "Step on the pedal, hold the lid open for two seconds, then let go.")
    assert held >= plain + 2.0 - 1e-6


def test_set_back_down_returns_to_start() -> None:
    """ "lift it 10 cm and set it back down": the base goes up, then comes back down."""
    trajectory = animate("examples/pedal_bin", "Lift the pedal bin 10 cm and set it back down.").trajectory
    assert float(trajectory.base_translation[:, 2].max()) == pytest.approx(0.1, abs=0.01)
    assert float(abs(trajectory.base_translation[-1]).max()) == pytest.approx(0.0, abs=0.01)


def test_carried_amount_returns_to_start() -> None:
    """ "0.3 m forward and then 0.3 m back": the base goes out and comes back."""
    trajectory = animate("examples/toy_car", "Push the car 0.3 m forward and then 0.3 m back to where it started.").trajectory
    assert float(trajectory.base_translation[:, 0].max()) == pytest.approx(0.3, abs=0.01)
    assert float(trajectory.base_translation[-1, 0]) == pytest.approx(0.0, abs=0.01)


def test_slowly_takes_longer_than_quickly() -> None:
    """A speed word scales the time of a whole-object motion; it is not a speed in m/s."""
    slow = _duration("examples/toy_car", "push the toy car forward 40 cm slowly")
    plain = _duration("examples/toy_car", "push the toy car forward 40 cm")
    fast = _duration("examples/toy_car", "push the toy car forward 40 cm quickly")
    assert slow > plain >= fast


def test_held_means_holds() -> None:
    """ "press and hold the button for three seconds to reset it": the hold is kept though a purpose follows."""
    assert _duration("dishwasher_12553", "Press and hold the button for three seconds to reset the dishwasher, then let go.") >= 3.0
