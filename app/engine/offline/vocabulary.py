"""Words the offline agent understands: part categories, verbs, qualifiers, quantities.

Everything here is data; ``language`` and ``grounding`` interpret it.
"""

from __future__ import annotations

from typing import Literal

PartCategory = Literal[
    "door", "lid", "drawer", "knob", "handle", "button", "pedal", "screen", "wheel",
    "window", "switch", "lever", "turntable", "tray", "latch", "body", "container", "code",
]

# canonical category -> words (single tokens or space-separated phrases) that name it.
CATEGORY_WORDS: dict[str, tuple[str, ...]] = {
    "door": ("door", "doors", "gate", "rotation door"),
    "lid": ("lid", "lids", "cover", "hatch", "cap", "flap", "top lid", "rotation lid"),
    "drawer": ("drawer", "drawers", "rack", "shelf", "slide out tray"),
    "tray": ("tray", "trays", "baking tray", "oven tray"),
    "turntable": ("turntable", "turn table", "rotation tray", "carousel", "glass plate", "plate"),
    "knob": ("knob", "knobs", "dial", "dials", "rotary knob", "control knob"),
    "handle": ("handle", "handles", "grip", "rotation handle", "door handle", "bail"),
    "lever": ("lever", "levers", "slider", "sliders", "carriage"),
    "latch": ("latch", "latches", "latch knob", "latch handle", "catch", "bolt", "lock"),
    "button": ("button", "buttons", "key", "keys", "keypad", "key pad", "number pad", "push button", "pushbutton", "release button"),
    "pedal": ("pedal", "pedals", "pad", "pads", "foot pad", "footpad", "foot pedal", "foot_pad", "foot lever", "step"),
    "screen": ("screen", "display", "monitor", "panel"),
    "wheel": ("wheel", "wheels", "caster", "casters", "castor", "tire", "tyre", "tires"),
    "window": ("window", "windows", "sash", "pane", "rotation window"),
    "switch": ("switch", "switches", "toggle", "rocker", "toggle button"),
    "container": ("container", "basket", "jug", "carafe", "water tank", "jar", "jars"),
    "body": ("body", "base", "frame", "chassis", "housing", "case", "casing", "stand"),
    # what a code is entered on: a combination dial, else the keypad's buttons (grounding.RELATED)
    "code": ("combination", "combination lock", "code", "passcode", "keycode"),
}

# semantics.txt labels (PartNet) and names that map onto a category
LABEL_CATEGORY: dict[str, str] = {
    "rotation_door": "door", "door": "door", "door_frame": "body",
    "rotation_lid": "lid", "lid": "lid",
    "drawer": "drawer", "slider": "lever", "container": "container",
    "knob": "knob", "handle": "handle", "rotation_handle": "handle",
    "button": "button", "toggle_button": "switch", "switch": "switch",
    "foot_pad": "pedal", "pedal": "pedal",
    "screen": "screen", "wheel": "wheel", "rotation_window": "window", "window": "window",
    "rotation_tray": "turntable", "tray": "tray", "turntable": "turntable",
}

# categories that are controls a user operates to cause an effect
CONTROL_CATEGORIES = frozenset({"button", "pedal", "knob", "handle", "lever", "switch", "latch"})
# how each control behaves once the hand lets go (paper: buttons/pedals self-return, knobs stay)
CONTROL_RETURN: dict[str, str] = {
    "button": "self_return", "pedal": "self_return", "handle": "self_return", "latch": "self_return",
    "lever": "stays", "knob": "stays", "switch": "stays",
}
# controls on a door/lid that must be operated before it opens
UNLATCH_CATEGORIES = frozenset({"handle", "latch", "knob"})
HINGED = ("door", "lid", "screen", "window")
"""Parts that swing open on a hinge (a latch may hold them; a pedal may lift them)."""

# whole-object names: (asset keyword, words a user may call the object)
OBJECT_WORDS: tuple[str, ...] = (
    "object", "thing", "it", "them", "whole", "entire", "unit", "item", "appliance", "furniture",
    "bin", "trash", "trashcan", "can", "dustbin", "garbage", "car", "toy", "cart", "trolley", "vehicle",
    "suitcase", "luggage", "box", "bucket", "pail", "safe", "microwave", "oven", "stove", "fridge",
    "refrigerator", "cabinet", "cupboard", "dresser", "wardrobe", "storage", "toaster", "laptop",
    "computer", "notebook", "stapler", "faucet", "tap", "washer", "dishwasher", "machine", "toilet",
    "kettle", "pot", "bottle", "chest", "crate", "table", "chair", "basket",
    "briefcase", "nightstand", "dresser", "locker", "wheelie", "dumpster", "washer", "fridge", "freezer", "unit",
    "appliance", "device", "cooker", "stove", "kettle", "sink", "luggage", "bag", "trolley", "stroller", "pram",
    "wagon", "buggy", "robot", "vehicle", "truck", "bus", "cabinet", "shelf", "bookcase", "desk", "crib",
)

VerbKind = Literal["operate", "open", "close", "press", "release", "pull_out", "push_in", "turn", "raise", "lower", "toggle", "move", "unlatch", "spin"]

VERBS: dict[str, str] = {
    "open": "open", "unfold": "open", "uncover": "open", "unclose": "open", "swing": "open",
    "close": "close", "shut": "close", "fold": "close", "seal": "close",
    "press": "press", "depress": "press", "push": "press", "step": "press", "stomp": "press",
    "tap": "press", "hit": "press", "click": "press", "squeeze": "press", "actuate": "press", "pump": "press",
    "release": "release", "let": "release",
    "pull": "pull_out", "draw": "pull_out", "extend": "pull_out", "slide": "pull_out", "eject": "pull_out",
    "retract": "push_in", "insert": "push_in", "tuck": "push_in",
    "turn": "turn", "rotate": "turn", "twist": "turn", "dial": "turn", "crank": "turn", "wind": "turn", "set": "turn",
    "spin": "spin", "revolve": "spin", "roll": "move", "drive": "move",
    "lift": "raise", "raise": "raise", "flip": "toggle", "pick": "raise", "elevate": "raise", "tilt": "raise",
    "lower": "lower", "drop": "lower", "put": "lower",
    "toggle": "toggle", "switch": "toggle", "flick": "toggle", "rock": "toggle",
    "move": "move", "drag": "move", "shove": "move", "carry": "move", "transport": "move",
    "translate": "move", "shift": "move", "nudge": "move", "wheel": "move",
    "operate": "operate", "use": "operate", "activate": "operate", "engage": "operate", "trigger": "operate",
    "work": "operate", "hold": "press",
    "stamp": "press", "lay": "lower", "take": "pull_out", "remove": "pull_out", "run": "spin", "start": "spin", "type": "press", "enter": "press", "punch": "press", "fall": "lower", "spring": "release", "snap": "release",
    "bounce": "release", "return": "release", "swivel": "turn", "pivot": "turn", "screw": "turn",
    "unscrew": "turn", "loosen": "turn", "tighten": "turn", "reopen": "open", "raise_up": "raise",
    "tip": "lower", "tow": "move", "haul": "move", "unlatch": "unlatch", "unlock": "unlatch", "unhook": "unlatch", "unbolt": "unlatch",
    "free": "unlatch", "lean": "raise", "hoist": "raise", "coast": "move",
}
# verb forms -> lemma (regular -s/-ed/-ing endings are handled by ``lemma``)
IRREGULAR: dict[str, str] = {
    "tipped": "tip", "tipping": "tip", "shut": "shut", "shutting": "shut", "let": "let", "letting": "let", "swung": "swing", "spun": "spin",
    "drew": "draw", "drawn": "draw", "put": "put", "putting": "put", "set": "set", "setting": "set",
    "drove": "drive", "driven": "drive", "lifted": "lift", "stepped": "step", "stepping": "step",
    "dropped": "drop", "dropping": "drop", "tapped": "tap", "tapping": "tap", "slid": "slide",
    "sliding": "slide", "closing": "close", "closed": "close", "opening": "open", "opened": "open",
    "pressing": "press", "pressed": "press", "pushing": "push", "pushed": "push", "pulling": "pull",
    "pulled": "pull", "turning": "turn", "turned": "turn", "rotating": "rotate", "rotated": "rotate",
    "twisting": "twist", "twisted": "twist", "raising": "raise", "raised": "raise", "lowering": "lower",
    "lowered": "lower", "moving": "move", "moved": "move", "rolling": "roll", "rolled": "roll",
    "dragging": "drag", "dragged": "drag", "spinning": "spin", "flipping": "flip", "flipped": "flip",
    "releasing": "release", "released": "release", "lifting": "lift", "toggling": "toggle", "toggled": "toggle",
    "unlatching": "unlatch", "unlocking": "unlock", "unfolding": "unfold", "folding": "fold",
    "extending": "extend", "retracting": "retract", "inserting": "insert", "depressing": "depress",
    "stomping": "stomp", "cranking": "crank", "winding": "wind", "dialing": "dial", "dialling": "dial",
    "switching": "switch", "switched": "switch", "flicking": "flick", "shoving": "shove", "carrying": "carry",
    "carried": "carry", "driving": "drive", "tilting": "tilt", "tilted": "tilt", "picking": "pick",
    "pumping": "pump", "fell": "fall", "falling": "fall", "falls": "fall", "sprang": "spring",
    "springs": "spring", "springing": "spring", "snaps": "snap", "snapped": "snap",
    "took": "take", "taking": "take", "taken": "take", "removing": "remove", "removed": "remove", "ran": "run", "running": "run",
    "stamped": "stamp", "stamping": "stamp", "laid": "lay", "laying": "lay", "typed": "type", "typing": "type", "entered": "enter", "entering": "enter", "returns": "return", "returned": "return",
    "unscrewing": "unscrew", "unscrewed": "unscrew", "swivelling": "swivel", "swiveled": "swivel", "squeezing": "squeeze", "nudging": "nudge", "shifting": "shift",
    "freeing": "free", "leant": "lean", "hoisting": "hoist", "coasting": "coast",
}

# directional particles after a verb change its meaning ("pull out", "push in", "press down")
PARTICLES: dict[str, str] = {
    "out": "out", "open": "open", "in": "in", "inside": "in", "down": "down", "up": "up", "back": "back",
    "away": "away", "shut": "shut", "closed": "shut", "forward": "forward", "forwards": "forward",
    "backward": "backward", "backwards": "backward", "over": "over", "off": "off", "on": "on",
}

SPATIAL: dict[str, str] = {
    "top": "top", "upper": "top", "uppermost": "topmost", "topmost": "topmost", "higher": "top", "highest": "topmost",
    "bottom": "bottom", "lower": "bottom", "lowest": "bottommost", "bottommost": "bottommost",
    "left": "left", "leftmost": "leftmost", "right": "right", "rightmost": "rightmost",
    "front": "front", "back": "back", "rear": "back", "middle": "middle", "center": "middle", "centre": "middle",
    "inner": "inner", "inside": "inner", "internal": "inner", "outer": "outer",
}
ORDINALS: dict[str, int] = {
    "first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7, "eighth": 8,
    "ninth": 9, "tenth": 10, "last": -1, "1st": 1, "2nd": 2, "3rd": 3, "4th": 4, "5th": 5,
}
NUMBER_WORDS: dict[str, float] = {
    "zero": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
    "nine": 9, "ten": 10, "twelve": 12, "fifteen": 15, "twenty": 20, "thirty": 30, "forty": 40, "forty-five": 45,
    "fortyfive": 45, "sixty": 60, "ninety": 90, "hundred": 100, "a": 1, "an": 1, "half": 0.5, "quarter": 0.25,
}
COLLECTIVE = frozenset({"both", "all", "every", "each"})

# fraction of the joint range for qualitative amounts
AMOUNTS: dict[str, float] = {
    "fully": 1.0, "completely": 1.0, "all the way": 1.0, "wide": 1.0, "entirely": 1.0, "totally": 1.0,
    "full": 1.0, "maximum": 1.0, "max": 1.0, "as far as": 1.0,
    "halfway": 0.5, "half way": 0.5, "half": 0.5, "midway": 0.5, "partway": 0.5,
    "partly": 0.3, "partially": 0.3, "a bit": 0.25, "a little": 0.2, "somewhat": 0.3, "ajar": 0.25,
    "slightly": 0.2, "barely": 0.1, "just a crack": 0.1, "a crack": 0.1, "a few": 0.25,
    "mostly": 0.75, "three quarters": 0.75, "three-quarters": 0.75, "a third": 1 / 3, "one third": 1 / 3,
    "two thirds": 2 / 3, "a quarter of the way": 0.25, "a quarter": 0.25, "one quarter": 0.25,
}
SPEEDS: dict[str, float] = {
    "slowly": 2.0, "slow": 2.0, "gently": 1.5, "carefully": 1.5, "gradually": 2.0, "leisurely": 2.0,
    "quickly": 0.5, "fast": 0.5, "rapidly": 0.5, "swiftly": 0.5, "briskly": 0.6, "suddenly": 0.4,
    "abruptly": 0.4, "vigorously": 0.5, "hard": 0.7, "firmly": 0.9,
}
SEQUENCE_WORDS = frozenset({"then", "afterwards", "afterward", "next", "finally", "later", "subsequently", "thereafter"})
ROTATION_SENSE: dict[str, str] = {
    "clockwise": "cw", "cw": "cw", "anticlockwise": "ccw", "counterclockwise": "ccw",
    "counter-clockwise": "ccw", "anti-clockwise": "ccw", "ccw": "ccw",
}
STOP_WORDS = frozenset({"the", "a", "an", "its", "it's", "of", "on", "this", "that", "my", "your", "please", "gently"})
