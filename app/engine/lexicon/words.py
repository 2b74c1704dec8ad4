"""Function words and quantity words: spatial qualifiers, ordinals, amounts, speeds, units,
connectives, object nouns. Pure data; the front end's stages read it.
"""

from __future__ import annotations

from collections.abc import Mapping
from enum import StrEnum
from types import MappingProxyType

from app.engine.lexicon.people import ACTOR_NOUNS as ACTOR_NOUNS
from app.engine.lexicon.people import AGENT_NOUNS as AGENT_NOUNS
from app.engine.lexicon.people import CAUSER_NOUNS as CAUSER_NOUNS
from app.engine.lexicon.people import PERSON_NOUNS as PERSON_NOUNS


class Side(StrEnum):
    TOP = "top"
    BOTTOM = "bottom"
    LEFT = "left"
    RIGHT = "right"
    FRONT = "front"
    BACK = "back"
    MIDDLE = "middle"
    INNER = "inner"
    OUTER = "outer"


def _m(**pairs: object) -> Mapping[str, object]:
    return MappingProxyType(dict(pairs))


SPATIAL: Mapping[str, tuple[Side, bool]] = MappingProxyType({
    # word -> (side, extreme: "the single most X one")
    "top": (Side.TOP, False), "upper": (Side.TOP, False), "higher": (Side.TOP, False), "uppermost": (Side.TOP, True),
    "topmost": (Side.TOP, True), "highest": (Side.TOP, True),
    "bottom": (Side.BOTTOM, False), "lower": (Side.BOTTOM, False), "lowest": (Side.BOTTOM, True), "bottommost": (Side.BOTTOM, True),
    "left": (Side.LEFT, False), "leftmost": (Side.LEFT, True), "left-hand": (Side.LEFT, False), "lefthand": (Side.LEFT, False),
    "right": (Side.RIGHT, False), "rightmost": (Side.RIGHT, True), "right-hand": (Side.RIGHT, False), "righthand": (Side.RIGHT, False),
    "front": (Side.FRONT, False), "frontmost": (Side.FRONT, True), "back": (Side.BACK, False), "rear": (Side.BACK, False),
    "backmost": (Side.BACK, True), "rearmost": (Side.BACK, True),
    "middle": (Side.MIDDLE, False), "center": (Side.MIDDLE, False), "centre": (Side.MIDDLE, False), "central": (Side.MIDDLE, False),
    "inner": (Side.INNER, False), "inside": (Side.INNER, False), "internal": (Side.INNER, False), "outer": (Side.OUTER, False),
    "outside": (Side.OUTER, False), "outermost": (Side.OUTER, True), "innermost": (Side.INNER, True),
})
ORDINALS: Mapping[str, int] = MappingProxyType({
    "first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7, "eighth": 8, "ninth": 9, "tenth": 10,
    "1st": 1, "2nd": 2, "3rd": 3, "4th": 4, "5th": 5, "6th": 6, "last": -1, "final": -1,
})
SIZES: Mapping[str, str] = MappingProxyType({
    **dict.fromkeys(("large", "larger", "largest", "big", "bigger", "biggest", "main", "wide", "wider", "widest", "tall", "taller", "tallest",
                     "long", "longer", "longest", "spoked", "huge", "giant"), "large"),
    **dict.fromkeys(("small", "smaller", "smallest", "little", "tiny", "mini", "narrow", "narrower", "narrowest", "short", "shorter", "shortest",
                     "stubby", "slim", "thin", "petite", "wee"), "small"),
})
SHAPE_WORDS = frozenset({"round", "flat", "square", "curved", "wire", "glass", "metal", "plastic", "wooden", "rubber", "clear", "flap-like",
                         "hinged", "sliding", "folding", "swinging", "rotating", "spinning", "pull-out", "pop-up", "push", "spring-loaded"})
"""What a part looks like or how it moves, not what it is: with an unknown name ("the hinged glass") enough to choose by."""
UNJOINTED_NOUNS = frozenset({"pocket", "pouch", "strap", "cord", "cable", "plug", "zipper", "tag", "label", "sticker", "logo", "wheels"})
"""Things objects carry that are never a joint's part ("unzip the front pocket" of a suitcase whose only zip is its lid's):
named and missing, they are refused, never read as the one part the verb fits."""
HINGE_WORDS = frozenset({"hinged", "folding", "swinging", "flap-like"})
SLIDE_WORDS = frozenset({"sliding", "pull-out", "pop-up", "telescopic", "telescoping", "extendable", "retractable", "trolley"})
"""Words before a part noun that say it slides ("the telescopic trolley handle"): a part that only swings is not it."""
COLLECTIVE = frozenset({"both", "all", "every", "each"})
DETERMINERS = frozenset({"the", "a", "an", "some", "its", "their", "this", "that", "these", "those", "my", "your", "his", "her", "our", "one's", "it's"})
PRONOUNS = frozenset({"it", "them", "they", "itself"})
OTHER_WORDS = frozenset({"other", "another", "remaining", "opposite"})
NEGATIONS = frozenset({"not", "never", "don't", "dont", "without", "avoid", "except", "but", "cannot", "can't", "doesn't", "won't", "mustn't",
                       "shouldn't", "shouldnt", "mustnt", "doesnt", "wont", "neither"})

NUMBER_WORDS: Mapping[str, float] = MappingProxyType({
    "zero": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9, "ten": 10,
    "eleven": 11, "twelve": 12, "fifteen": 15, "twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60,
    "seventy": 70, "eighty": 80, "ninety": 90, "hundred": 100, "forty-five": 45, "fortyfive": 45, "a hundred": 100,
    "one hundred": 100, "hundred and twenty": 120, "one hundred and twenty": 120, "a hundred and twenty": 120,
    "one hundred and eighty": 180, "a hundred and eighty": 180, "hundred and eighty": 180, "one hundred and thirty-five": 135,
    "twenty-five": 25, "thirty-five": 35, "forty-five degrees": 45, "seventy-five": 75, "eighty-five": 85, "sixty-five": 65,
})
DENOMINATORS: Mapping[str, int] = MappingProxyType({
    "half": 2, "halves": 2, "third": 3, "thirds": 3, "quarter": 4, "quarters": 4, "fourth": 4, "fourths": 4, "fifth": 5, "fifths": 5,
    "sixth": 6, "sixths": 6, "eighth": 8, "eighths": 8, "tenth": 10, "tenths": 10, "twelfth": 12, "twelfths": 12,
})
"""Fraction words: "three-eighths of a turn", "an eighth of a turn", "5 eighths"."""
MULTIPLIERS: Mapping[str, float] = MappingProxyType({"once": 1, "twice": 2, "thrice": 3})

AMOUNTS: Mapping[str, float] = MappingProxyType({
    # fraction of the closed -> open (or rest -> far limit) range
    "fully": 1.0, "completely": 1.0, "all the way": 1.0, "wide": 1.0, "wide open": 1.0, "entirely": 1.0, "totally": 1.0,
    "full": 1.0, "maximum": 1.0, "max": 1.0, "as far as it goes": 1.0, "as far as possible": 1.0, "as far as it will go": 1.0,
    "to the limit": 1.0, "as high as it can go": 1.0, "as high as it will go": 1.0, "to far end of its range": 1.0,
    "to the far end of its range": 1.0, "to the end of its range": 1.0, "to the far end of its travel": 1.0, "to the end of its travel": 1.0, "to the end": 1.0, "as wide as": 1.0, "as high as": 1.0, "all the way open": 1.0,
    "halfway": 0.5, "half way": 0.5, "half-way": 0.5, "half": 0.5, "midway": 0.5, "partway": 0.5, "part way": 0.5, "half open": 0.5,
    "partly": 0.3, "partially": 0.3, "a bit": 0.25, "a little": 0.2, "a little bit": 0.2, "somewhat": 0.3, "ajar": 0.25,
    "slightly": 0.2, "barely": 0.1, "just a crack": 0.1, "a crack": 0.1, "just a sliver": 0.1, "a few": 0.25, "a tad": 0.15,
    "mostly": 0.75, "most of the way": 0.75, "three quarters": 0.75, "three-quarters": 0.75, "a third": 1 / 3, "one third": 1 / 3,
    "two thirds": 2 / 3, "two-thirds": 2 / 3, "a quarter of the way": 0.25, "a quarter": 0.25, "one quarter": 0.25,
    "a third of the way": 1 / 3, "as far as": 1.0, "as high as it goes": 1.0, "as high as possible": 1.0, "as low as it goes": 1.0,
    "as low as possible": 1.0, "as wide as it goes": 1.0, "as far as it will": 1.0, "to the very top": 1.0, "to the top": 1.0,
    "to the very bottom": 1.0, "to the bottom": 1.0, "the rest of the way": 1.0, "as flat as it can go": 1.0, "as far as it can go": 1.0,
    "as flat as possible": 1.0, "as wide as possible": 1.0, "hits its stop": 1.0, "hits the stop": 1.0, "hits its limit": 1.0, "hits the end": 1.0,
    "reaches its stop": 1.0, "reaches its limit": 1.0, "reaches the end": 1.0, "stops moving": 1.0, "can't go any further": 1.0,
    "won't go any further": 1.0, "to the stop": 1.0, "to the max": 1.0, "to the maximum": 1.0, "as wide as it can go": 1.0, "rest of the way": 1.0, "all the way up": 1.0, "all the way down": 1.0, "all the way back": 1.0,
})
LOOSE_AMOUNTS = frozenset({"partly", "partially", "a bit", "a little", "a little bit", "somewhat", "ajar", "slightly", "barely",
                           "just a crack", "a crack", "just a sliver", "a few", "a tad", "mostly", "partway", "part way"})
"""Amounts that are a reading of a vague word (the explanation warns about them)."""
SPEEDS: Mapping[str, float] = MappingProxyType({
    # duration multiplier
    "slowly": 2.0, "slow": 2.0, "gently": 1.5, "carefully": 1.5, "gradually": 2.0, "leisurely": 2.0, "softly": 1.5,
    "quickly": 0.5, "fast": 0.5, "rapidly": 0.5, "swiftly": 0.5, "briskly": 0.6, "suddenly": 0.4, "quick": 0.5, "real_quick": 0.5, "real_fast": 0.5, "real_slow": 2.0,
    "abruptly": 0.4, "vigorously": 0.5, "hard": 0.7, "firmly": 0.9, "smoothly": 1.2, "sharply": 0.5,
})
ROTATION_SENSE: Mapping[str, str] = MappingProxyType({
    "clockwise": "cw", "cw": "cw", "anticlockwise": "ccw", "counterclockwise": "ccw", "counter-clockwise": "ccw",
    "anti-clockwise": "ccw", "ccw": "ccw", "widdershins": "ccw",
})
SCREWING_SENSES: Mapping[str, str] = MappingProxyType({
    "unscrewing": "counterclockwise", "loosening": "counterclockwise", "screwing": "clockwise", "tightening": "clockwise",
})
"""The way a screw turns as it is undone or done up ("in the unscrewing direction"), as a word of ``ROTATION_SENSE``."""
DIRECTIONS: Mapping[str, str] = MappingProxyType({
    "forward": "forward", "forwards": "forward", "ahead": "forward", "frontward": "forward", "frontwards": "forward",
    "backward": "backward", "backwards": "backward", "rearward": "backward", "rearwards": "backward",
    "leftward": "left", "leftwards": "left", "rightward": "right", "rightwards": "right", "sideways": "sideways",
    "upward": "up", "upwards": "up", "downward": "down", "downwards": "down", "aside": "sideways",
})
LENGTH_UNITS: Mapping[str, float] = MappingProxyType({
    "mm": 1e-3, "millimeter": 1e-3, "millimetre": 1e-3, "cm": 1e-2, "centimeter": 1e-2, "centimetre": 1e-2,
    "dm": 0.1, "decimeter": 0.1, "decimetre": 0.1, "m": 1.0, "meter": 1.0, "metre": 1.0, "in": 0.0254, "inch": 0.0254, "ft": 0.3048, "foot": 0.3048, "feet": 0.3048,
})
ANGLE_UNITS: Mapping[str, float] = MappingProxyType({"degree": 0.017453292519943295, "deg": 0.017453292519943295, "°": 0.017453292519943295,
                                                      "radian": 1.0, "rad": 1.0})
TURN_UNITS: Mapping[str, float] = MappingProxyType({"turn": 1.0, "revolution": 1.0, "rotation": 1.0, "spin": 1.0, "twist": 1.0, "circle": 1.0, "lap": 1.0})
TIME_UNITS: Mapping[str, float] = MappingProxyType({"s": 1.0, "sec": 1.0, "second": 1.0, "ms": 1e-3, "millisecond": 1e-3, "minute": 60.0, "min": 60.0})
RATE_UNITS: Mapping[str, tuple[str, float]] = MappingProxyType({
    # unit phrase -> (quantity, factor to SI)
    "rad/s": ("omega", 1.0), "rad per second": ("omega", 1.0), "radians per second": ("omega", 1.0), "radps": ("omega", 1.0),
    "rpm": ("omega", 0.10471975511965977), "revolutions per minute": ("omega", 0.10471975511965977),
    "deg/s": ("omega", 0.017453292519943295), "degrees per second": ("omega", 0.017453292519943295),
    "m/s": ("speed", 1.0), "meters per second": ("speed", 1.0), "metres per second": ("speed", 1.0), "cm/s": ("speed", 0.01),
})
PAUSE_NOUNS = frozenset({"pause", "wait", "beat", "break", "delay", "rest", "breather"})
"""Nouns of a wait ("2 s pause", "a 4-second beat")."""
GENERIC_PART_NOUNS = frozenset({"piece", "part", "section", "component", "panel", "portion", "segment", "element", "bit", "half", "thing", "slab"})
"""Nouns that name no kind of part: with a place or a size ("the topmost piece", "the left-hand section") any movable part there."""
FACE_RELATIONS = frozenset({"perpendicular", "parallel", "square", "level", "flush", "proud", "normal", "relative", "line"})
"""Words that set a part against a face of the object ("proud of the front", "perpendicular to the front", "in line with
the top"): the side named after them is that face, neither a part nor a way to go."""
STATES: Mapping[str, str] = MappingProxyType({
    # adjectives / particles naming an end state
    "open": "open", "opened": "open", "shut": "closed", "closed": "closed", "up": "up", "down": "down",
    "vertical": "vertical", "vertically": "vertical", "upright": "vertical", "perpendicular": "vertical", "straight up": "vertical",
    "straight": "vertical",
    "flat": "flat", "horizontal": "flat", "horizontally": "flat", "level": "flat",
    "on": "on", "off": "off", "pressed": "pressed", "down position": "down", "in": "in", "out": "out", "flush": "closed",
    "locked": "closed", "latched": "closed",
})

# clause connectives (single words; multi-word ones are joined by the normaliser first)
SEQUENCE = frozenset({"then", "afterwards", "afterward", "next", "finally", "later", "subsequently", "thereafter", "after_that",
                      "and_then", "once_done", "when_done", "after_which", "followed_by", "and_after_that", "and_finally", "lastly",
                      "after_it", "after_this", "once_it_is_done", "once_that_is_done", "when_that_is_done"})
PARALLEL = frozenset({"while", "whilst", "as", "simultaneously", "at_the_same_time", "meanwhile", "together_with", "along_with",
                      "at_once"})
SIMULTANEOUS = frozenset({"simultaneously", "at_the_same_time", "together", "at_once", "in_parallel", "in_unison", "both_at_once"})
BEFORE = frozenset({"before"})
AFTER = frozenset({"after", "once", "when"})
PURPOSE = frozenset({"to", "in_order_to", "so_as_to"})
RESULT = frozenset({"so", "so_that", "which", "making", "causing", "until"})
MEANS = frozenset({"by"})
INSTRUMENT = frozenset({"with", "using", "via", "through", "that_has", "which_has", "that_have", "which_have"})
HOLD_WORDS = frozenset({"keep", "hold", "leave", "stay", "remain"})

MULTIWORD: tuple[str, ...] = (
    # joined into one token ("at_the_same_time"), longest first
    "at the same time as", "at the same time", "in order to", "after it", "after this", "once it is done", "once that is done",
    "when that is done", "so as to", "so that", "let it lie", "let them lie", "let it sit", "which means that", "which means", "that means that", "that means", "this means that",
    "this means", "gust of wind", "puff of wind", "blast of wind", "gust of air", "rush of air", "the whole time", "the entire time", "all the while", "all the time", "for as long as", "the whole while", "after that", "and then", "and after that",
    "and finally", "once done", "when done", "after which", "followed by", "all the way", "as far as it will go", "as far as it goes",
    "as far as possible", "most of the way", "a little bit", "a little", "a bit", "a tad", "just a crack", "a crack", "just a sliver", "half way",
    "part way", "three quarters", "a quarter of the way", "a third of the way", "a quarter", "a third", "one third", "two thirds",
    "one quarter", "counter clockwise", "anti clockwise", "rad per second", "radians per second", "revolutions per minute",
    "degrees per second", "meters per second", "metres per second", "straight up", "to the left", "to the right", "to the limit",
    "to the end", "together with", "along with", "in parallel", "in unison", "at once", "both at once", "next to", "in front of", "get at",
    "on top of", "real quick", "real fast", "real slow", "straight away", "right away", "in and straight back out", "in and back out", "in and out",
    "down and straight back up", "down and back up", "into place", "in place", "on the spot", "where it stands", "left hand", "right hand", "chest of drawers", "bank of drawers", "set of drawers", "out of",
    "back and forth", "all the way open", "wide open", "half open", "a few", "one by one", "one after the other", "one after another", "one at a time", "every other", "apart from", "except for", "aside from", "other than",
    "in turn", "in sequence", "after another", "by hand", "with one hand", "and all", "as far as",
    "where it started", "where it was", "where it began", "where they started", "where they were", "where you started",
    "a couple of seconds", "a couple of", "a few seconds", "a full second", "a whole second", "a full minute", "a whole minute", "a second and a half", "half a second", "do the same", "the same amount",
    "the same way", "as much", "the same distance", "the same angle", "one by one", "left to right", "right to left", "top to bottom",
    "bottom to top", "in order", "hands-free", "hands free", "last of all", "a tiny bit", "a wee bit", "a teeny bit", "'s been", "'s got", "has got", "have got", "'ve got", "i need", "i want", "i only want", "i just want", "i really want", "i only need", "i just need", "i really need", "i'd like", "we need", "i would like", "i'd love", "i would love", "i'd prefer", "i would prefer",
    "we'd like", "we want", "we would like",
    "as high as it goes", "as high as possible", "as low as it goes", "as low as possible", "as wide as it goes", "as far as it will",
    "toward the middle", "toward the centre", "toward the center", "towards the middle", "towards the centre", "towards the center",
    "like that", "like this", "as wide as", "as high as", "back to the middle", "back to the centre", "back to the center",
    "back to centre", "back to center", "back to neutral", "to the middle", "to the centre", "to the center", "as a result", "because of that", "because of this", "as a consequence", "hits its stop", "hits the stop", "hits its limit", "hits the end", "reaches its stop", "reaches its limit",
    "reaches the end", "stops moving", "can't go any further", "won't go any further", "to the very top", "to the top", "to the very bottom", "to the bottom", "as well", "in total", "stays where it is", "stay where it is", "stays as it is", "stay as it is", "stays put", "stay put", "as flat as it can go", "as far as it can go", "as far as it goes", "as high as it can go", "as high as it will go", "as high as it goes",
    "to far end of its range", "to the far end of its range", "to the end of its range", "to the far end of its travel", "to the end of its travel", "as flat as possible", "as far as possible",
    "as wide as possible", "as wide as it can go", "the rest of the way", "the way it was before", "the way it was", "how it was before", "how it was", "how they were", "like it was before", "like it was", "like they were", "as it was before", "as it was", "as before",
    "that has", "which has", "that have", "which have", "in the reverse order", "in reverse order", "in that order", "in this order", "to the stop", "to the max", "to the maximum", "in the same direction", "right angle", "rest of the way",
)

OBJECT_NOUNS: tuple[str, ...] = (
    # what a user may call the whole object
    "object", "thing", "whole", "entire", "unit", "item", "appliance", "furniture", "model", "asset", "module", "assembly",
    "bin", "trash", "trashcan", "can", "dustbin", "garbage", "car", "toy", "cart", "trolley", "vehicle",
    "suitcase", "luggage", "box", "bucket", "pail", "safe", "vault", "microwave", "nuker", "oven", "stove", "fridge", "refrigerator", "freezer",
    "cabinet", "cupboard", "dresser", "wardrobe", "storage", "toaster", "laptop", "computer", "notebook", "macbook", "stapler",
    "faucet", "tap", "washer", "dishwasher", "machine", "toilet", "kettle", "pot", "saucepan", "bottle", "chest", "crate", "table",
    "chair", "briefcase", "nightstand", "bedside", "locker", "wheelie", "dumpster", "device", "cooker", "sink", "bag", "handbag",
    "purse", "stroller", "pram", "wagon", "buggy", "robot", "truck", "bus", "bookcase", "desk", "crib", "bureau",
    "sideboard", "credenza", "armoire", "tallboy", "commode", "strongbox", "lockbox", "tote", "blender", "chest_of_drawers", "toolbox",
    "cooler", "trunk", "footlocker", "coffer", "breadbox", "lunchbox", "cashbox", "tin", "suitcase", "saucepan", "casserole", "kettle",
    "vanity", "hutch", "cubby", "wardrobe", "closet", "pantry", "oven", "range", "toaster", "tap", "faucet", "mixer", "basin",
    "bank_of_drawers", "set_of_drawers", "pan", "light", "lamp", "espresso", "blender", "jug",
    "mixer", "juicer", "grill", "range", "hamper", "tub", "carton", "package", "case", "pc", "basin",
    "workbench", "nightstand", "endtable", "drawers", "pail", "spigot", "chiller", "top-loader", "front-loader", "loo", "lavatory", "wc",
)
PERSONS = frozenset({"i", "i'm", "i'll", "i've", "i'd", "you", "you're", "you'll", "we", "we're", "we'll", "me", "my", "someone", "somebody", "nobody"})
"""The user and other people: a clause about them is not about the asset ("so I can reach in")."""
MODALS = frozenset({"can", "could", "will", "would", "may", "might", "should", "must", "won't", "can't"})
_PROGRESS = tuple((when, who, state) for when in ("when", "once", "after") for who in ("i'm", "you're", "we're", "i've", "you've", "we've")
                  for state in ("done", "finished", "ready", "through"))
ASIDE_PHRASES: tuple[tuple[str, ...], ...] = (*_PROGRESS, ("once", "that", "is", "done"), ("when", "that", "is", "done"),
                                              ("after", "that", "is", "done"), ("once", "that's", "done"), ("when", "that's", "done"),
                                              ("once", "done"))
"""The user's own progress ("when I'm done"): read as "then"."""
REQUEST_PHRASES: tuple[tuple[str, ...], ...] = (
    ("no", "more", "than", "that"), ("no", "further", "than", "that"), ("not", "more", "than", "that"), ("no", "more", "than", "this"),
    ("if", "you", "can"), ("if", "you", "could"), ("if", "possible"), ("if", "you", "don't", "mind"), ("if", "you", "would"),
    ("let's",), ("no", "more"), ("stop", "right", "there"), ("stop", "there"), ("stop", "at", "that", "point"), ("stop", "at", "that"), ("animate",), ("task", ":"), ("goal", ":"), ("note", ":"), ("task", "spec", ":"), ("robot", "spec", ":"), ("spec", ":"),
    ("task", "list", ":"), ("shot", "list", ":"), ("to", "do", ":"), ("todo", ":"),
    ("as", "you", "look", "at", "it"), ("as", "you", "face", "it"), ("as", "you", "see", "it"), ("when", "you", "look", "at", "it"),
    ("would", "you", "mind"), ("could", "i", "just"), ("could", "i"), ("can", "i", "just"), ("can", "i"), ("may", "i"), ("could", "you", "please"), ("can", "you", "please"), ("could", "you"), ("can", "you"), ("will", "you"),
    ("would", "you"), ("i'd", "like", "you", "to"), ("i", "want", "you", "to"), ("i", "need", "you", "to"), ("go", "ahead", "and"), ("let", "me"),
    ("can", "someone"), ("could", "someone"), ("can", "somebody"), ("could", "somebody"), ("will", "someone"), ("would", "someone"),
    ("be", "so", "kind", "as", "to"), ("be", "kind", "enough", "to"), ("good", "morning"), ("good", "afternoon"), ("good", "evening"))
"""A request's frame ("could you open ...?"): dropped, the verb after it is the action."""
CORRECTIONS: tuple[tuple[str, ...], ...] = (
    ("no", "wait"), ("actually", "no"), ("no", "actually"), ("no", "sorry"), ("sorry",), ("nvm",), ("never", "mind"), ("i", "mean"),
    ("or", "rather"), ("scratch", "that"), ("correction",), ("actually",), ("no",))
"""Words that take back the amount just said ("open it 60 degrees... no wait, make it 45"): the amount after them replaces it."""
CORRECTION_LEADS: tuple[tuple[str, ...], ...] = (("make", "it"), ("make", "that"), ("change", "it", "to"), ("change", "that", "to"), ("go", "for"),
                                                   ("i", "meant"), ("i", "mean"))
"""What may come between a correction and its new amount (or its other part: "no wait, I meant the other one")."""
PLACE_SIDES: Mapping[str, Side] = MappingProxyType({
    "floor": Side.BOTTOM, "ground": Side.BOTTOM, "counter": Side.BOTTOM, "countertop": Side.BOTTOM, "worktop": Side.BOTTOM,
    "table": Side.BOTTOM, "ceiling": Side.TOP, "wall": Side.BACK})
"""Places a part is nearest to ("the rack nearest the floor", "the dial closest to the counter"): the object's side they face."""
OPPOSITE_SIDES: Mapping[Side, Side] = MappingProxyType({Side.BOTTOM: Side.TOP, Side.TOP: Side.BOTTOM, Side.BACK: Side.FRONT,
                                                         Side.FRONT: Side.BACK, Side.LEFT: Side.RIGHT, Side.RIGHT: Side.LEFT})
DEFINITES = frozenset({"the", "this", "that", "its"})
"""Determiners of one known thing: "the 5 key" is the key labelled 5 (not five keys), "the dore" is a part misspelt."""
WHOLE_WORDS = frozenset({"whole", "entire", "asset", "model", "body"})
"""Words that name the whole object, never the part a verb works on it ("rotate the whole tap asset": not its handle)."""
ASPECT_VERBS = frozenset({"starts", "start", "started", "begins", "begin", "began", "continues", "continue"})
"""Verbs of starting or going on: the verb after them is the motion ("the plate starts turning / begins to turn")."""
WISHES = frozenset({"i_need", "i_want", "i'd_like", "we_need", "i_would_like", "i'd_love", "i_would_love", "i'd_prefer", "i_would_prefer",
                    "we'd_like", "we_want", "we_would_like"})
"""What opens a wish ("I need the rack out", "..., I want the lid up"): a clause of its own."""
VIEWER_POSSESSIVES = frozenset({"my", "your", "our", "the_viewer's", "viewer's"})
""""to my left", "on your right": the viewer's side, which is the object's left / right as seen facing its front."""
ASIDE_WORDS = frozenset({"please", "kindly", "pls", "plz", "thanks", "thank", "cheers", "yo", "hey", "hi", "hello", "hmm", "hm", "um", "umm", "uh", "oh", "ah", "lol",
                         "obviously", "naturally", "clearly", "evidently", "basically", "ok", "okay", "alright", "pleas", "love", "mate", "hun", "darling",
                         "dear", "sweetie", "buddy", "pal", "matey",
                         "haha", "hehe", "hahaha", "whoosh", "wow", "yay", "oops", "voila", "ta-da", "tada"})
"""Words dropped wherever they stand: politeness says nothing about the motion."""
FILLERS = frozenset({"please", "now", "just", "also", "kindly", "first", "firstly", "simply", "lastly", "finally", "and", "then", "next",
                     "only"})
"""Words that may open a clause before its verb."""
RELEASE_NAME_WORDS = frozenset({"release", "open", "opener", "door", "eject", "unlock", "lid", "pop"})
"""Words in a button's own name that say it releases a door or lid."""
FUNCTION_NAME_WORDS = frozenset({"start", "power", "on", "off", "stop", "cancel", "timer", "clock", "cook", "defrost", "popcorn", "reheat",
                                 "mode", "program", "programme", "temperature", "wash", "rinse", "number", "digit", "pin"})
"""Words in what the user calls a control that give it another job than releasing a door ("the start button")."""
CLOSED_AGAINST = frozenset({"keyboard", "base", "body", "frame", "deck", "wall", "jamb", "cabinet", "carcass", "housing", "case"})
"""What a hinged part closes against: "135 degrees from the keyboard" is 135 degrees from closed."""
FUNCTION_VERBS = frozenset({"start", "begin", "activate", "run", "cook", "heat", "warm", "reheat", "defrost", "brew", "boil", "wash", "toast"})
"""What an appliance does when worked: "press the button to start it" asks for the press only, not a motion of "it"."""
BUTTON_RELEASED_OBJECTS = frozenset({"microwave", "kettle", "cooker", "rice"})
"""Kinds of object whose only door or lid a (any) button releases."""
OPERATED_OBJECTS = frozenset({"tap", "faucet", "valve", "mixer", "switch", "spigot"})
"""Objects that are themselves controls: "turn the tap" works its handle, it does not yaw the object."""
CAUSATIVES = frozenset({"let", "make", "have", "get", "allow", "watch", "see"})
"""Verbs whose object does the inner verb on its own ("let the lid drop", "make the tray rotate")."""
TOLD_CAUSATIVES = frozenset({"let", "make", "allow"})
"""Causatives by lemma, in the third person too ("..., which lets the door swing open", "... makes the lid pop up")."""
LIGHT_VERBS = frozenset({"give"})
"""Verbs whose deverbal object is the real action ("give the car a push")."""
WISH_WORDS = frozenset({"need", "want", "like", "needs", "wants", "would_like", "i'd_like"})
""""I need the rack out": a wish names the end state wanted."""
COUPLING_WORDS = frozenset({"linked", "connected", "coupled", "hooked", "attached", "tied", "geared", "joined", "wired", "chained", "ganged"})
"""Participles that describe how parts are tied together ("the two carriages are linked"): a description, not an action."""
STATIVE_VERBS = frozenset({"is", "are", "was", "were", "be", "being", "been", "lie", "lies", "lying", "stands", "standing",
                           "sit", "sits", "sitting", "point", "points", "pointing", "face", "faces", "facing", "stay", "stays", "remain",
                           "remains", "sticking", "sticks", "stick", "hang", "hangs", "hanging", "rest", "rests", "resting", "look", "looks",
                           "starts", "begins", "started", "has", "had", "features", "contains", "live", "lives", "belong", "belongs", *COUPLING_WORDS})
"""Verbs of state: a clause built on one describes where a part is, it does not move it."""
PLACES = frozenset({"stove", "table", "floor", "ground", "counter", "countertop", "bench", "workbench", "desk", "wall", "hook", "shelf",
                    "cooktop", "hob", "burner", "worktop", "surface", "carpet", "mat", "tray_table"})
"""Where an object stands: "lift the pot off the stove" names a place, not a part."""
OBJECT_SUFFIXES = ("box", "bin", "case", "can", "chest", "pot", "pan", "safe", "cabinet", "oven", "basket", "bag", "machine")
"""Compound object names end in an object word ("toolbox", "breadbin", "briefcase")."""

PHRASE_BREAKS = frozenset({"and", "or", ",", "then", "to", "by", "with", "using", "so", "until", "while", "for", "into", "onto", "toward",
                   "towards", "than", "is", "are", "was", "be", "as", "if", "but", "not", "without", "about", "over", "through",
                   "along", "across", "around", "back", "up", "down", "out", "off", "open", "shut", "closed", "more", "further",
                   "again", "fully", "halfway", "slightly", "way", "there", "here", "away", "together", "apart",
                   "of", "on", "in", "at", "from", "inside", "behind", "near", "under", "below", "above", "beside", "next_to",
                   "in_front_of", "on_top_of", "out_of", "against", "beneath", "underneath", "where", "when", "once",
                   "after", "before", "during", "because", "which", "that's", "it's", "so_that", "in_order_to", "don't", "do", "does", "only", "even", "just", "very",
                   "hands-free", "hands_free", "straight", "upright", "vertical", "flat", "horizontal",
                   "cannot", "can't", "can", "will", "would", "should", "must", "no",
                   "still", "really", "right_away", "exactly", "too", "far", "measured", "makes", "forms", "needs", "need", "needed", "furthest", "farthest", "farther", "now", "almost", "nearly", "properly", "completely", "gets", "get", "got", "getting", "becomes", "nearest", "closest", "nearer", "closer", "tight", "tightly", "snugly", "securely", "loose", "loosely", "has", "have", "had", "immediately", "gently", "firmly", "briefly", "quickly", "slowly", "carefully"})
"""Words that end a noun phrase (prepositions, conjunctions, adverbs, auxiliaries)."""
_ONLY_BODY = frozenset({"knee", "shin", "toe", "elbow", "hip", "ankle", "forehead", "thigh"})
"""A person's body, hurt on the object ("I keep bumping my knee on it"): never a part (unlike "head", "arm", "foot")."""
NOT_PART_NOUNS = frozenset({"way", "possible", "something", "anything", "nothing", "clear", "side", "hand", "time", "times", "position", "state", "place", "spot", "point", "end", "limit",
                        "degree", "second", "minute", "turn", "percent", "amount", "bit", "little", "tad", "moment", "while",
                        "beat", "angle", "height", "distance", "speed", "rate", "direction", "axis", "x", "y", "z", "table", "floor", "ground", "wall", "counter", "room", "kitchen",
                        "front", "back", "top", "bottom", "left", "right", "middle", "centre", "center", "edge", "corner",
                        "setting", "mark", "notch", "stop", "rest", "original", "start", "level", "pin", "travel", "hinge", "range",
                        "motion", "air", "path", "track", "slot", "opening", "stroke", "sound", "click", "gap", "same", "extension", "pose", "target", "shot", "take", "scene", "clip", "anim", "loop", "keyframe", "frame",
                        "enough", "sense", "dev", "developer", "game", "render", "rig", "tutorial", "cutscene", "storyboard", "narrator", "demo", "like_that", "like_this", "animating", "animation", "moving", "movement",
                        # the scene and the people (or robot) in it: they act on the object, they are no part of it
                        "montage", "sequence", "episode", "gag", "peek", "routine", "spec", "prop", "camera", "viewer", "audience",
                        "character", "actor", "person", "user", "operator", "gripper", "thumb", "finger", "fingers",
                        "hands", "seal", "rotation", "clean"}) | _ONLY_BODY
"""Nouns that never name a part of the asset (units, places, measures)."""
CENTRE_WORDS = frozenset({"back_to_the_middle", "back_to_the_centre", "back_to_the_center", "back_to_centre", "back_to_center", "back_to_neutral",
                          "to_the_middle", "to_the_centre", "to_the_center", "toward_the_middle", "toward_the_centre", "toward_the_center",
                          "towards_the_middle", "towards_the_centre", "towards_the_center"})
"""A part resting midway ("the tap lever") goes back to rest: "then back to the middle"."""
BRIEF_VERBS = frozenset({"tap", "click", "pulse", "poke", "jab", "flick", "dab"})
BRIEF_WORDS = frozenset({"briefly", "momentarily", "quick", "brief", "instantly", "in_and_straight_back_out", "in_and_back_out", "in_and_out",
                         "down_and_straight_back_up", "down_and_back_up"})
"""A brief press ("tap the button", "press it briefly"): a control that would hold is let go at once."""
POSTURES = frozenset({"sitting", "standing", "hanging", "resting", "lying", "sticking", "poking", "propped", "left"})
"""How a part is said to rest ("the door is sitting slightly open"): the clause says how things are, not a step."""
SAME_WAY = frozenset({"in_the_same_direction", "the_same_way"})
""""another 45 degrees the same way": the direction and sense of turning of the clause before."""
TO_THE_END = frozenset({"as_far_as_it_will_go", "as_far_as_it_goes", "as_far_as_possible", "all_the_way", "fully", "to_the_limit", "to_the_stop",
                        "to_the_max", "to_its_limit"})
"""Amounts that take a part to the end of its travel ("push the screen back as far as it'll go")."""
COMPARATIVES = frozenset({"higher", "lower", "wider", "deeper"})
"""After an amount, it is counted from where the part is ("20 degrees higher")."""
OBJECT_TILTS = frozenset({"tilt", "tip", "lean", "rock"})
"""Verbs that would tilt the whole object ("tilt the bin back and wheel it"): not animated; a step of its own is noted and left."""
MISHAP_VERBS = frozenset({"bump", "trip", "stumble", "stub", "snag", "whack", "smack", "graze", "bang", "knock", "hit", "catch", "hurt"})
"""What happens to a person who runs into a part ("I keep bumping my knee on it", "the kids trip over it"): with a body
part said ("hit my head"), or one of the first five alone, a complaint about where the part is, never a motion."""
BODY_WORDS = _ONLY_BODY | {f"{w}s" for w in _ONLY_BODY} | frozenset({"head", "leg", "legs", "foot", "feet", "hand", "hands", "finger",
                                                                      "fingers", "arm", "arms"})
BELONGING_KEYS = frozenset({"keys", "keyring", "key-ring"})
"""Keys a person owns ("my keys", "the car keys"): things kept somewhere, never the keys of a keypad."""
COMPLAINED_STATES: Mapping[str, str] = MappingProxyType({
    "open": "close", "opened": "close", "ajar": "close", "wide_open": "close", "out": "close", "sticking_out": "close", "hanging_open": "close",
    "up": "lower", "raised": "lower", "down": "raise", "lowered": "raise", "on": "switch_off", "running": "switch_off",
    "closed": "open", "shut": "open"})
"""A part's state told with no action ("the lower drawer is sticking out and I keep bumping my knee on it", "the toilet
seat is up again"): the sense of the verb that puts it the other way, when nothing else in the prompt asks for a step."""
_STUFFY = ("open", ("window", "door"), "")
_DRAUGHTY = ("close", ("window", "door"), "")
_GETTING_IN = ("close", ("lid", "door", "window"), "")
_SMELLY = ("close", ("lid",), "")
_DARK = ("switch_on", ("switch",), "")
_BRIGHT = ("switch_off", ("switch",), "")
_WASHING = ("switch_on", ("handle", "lever", "switch", "knob"), "faucet")
"""On a tap only ("my hands are all soapy"): its one handle, lever or switch turned on."""
ROOM_COMPLAINTS: Mapping[str, tuple[str, tuple[str, ...], str]] = MappingProxyType({
    "dark": _DARK, "dim": _DARK, "gloomy": _DARK, "pitch-black": _DARK, "bright": _BRIGHT, "glaring": _BRIGHT,
    "stuffy": _STUFFY, "muggy": _STUFFY, "stifling": _STUFFY, "airless": _STUFFY, "stale": _STUFFY,
    "draft": _DRAUGHTY, "draught": _DRAUGHTY, "drafty": _DRAUGHTY, "draughty": _DRAUGHTY, "chilly": _DRAUGHTY, "freezing": _DRAUGHTY,
    "dust": _GETTING_IN, "bugs": _GETTING_IN, "flies": _GETTING_IN, "mosquitoes": _GETTING_IN, "rain": _GETTING_IN,
    "soapy": _WASHING, "sticky": _WASHING, "greasy": _WASHING, "thirsty": _WASHING, "rinse": _WASHING,
    "cat": _GETTING_IN, "dog": _GETTING_IN, "mice": _GETTING_IN, "mouse": _GETTING_IN,
    "stinkin": _SMELLY, "stinking": _SMELLY, "stinks": _SMELLY, "smelly": _SMELLY, "reeks": _SMELLY, "stench": _SMELLY})
"""How the room is, told with no action ("it's way too dark in here", "it's stuffy in here", "there's a cold draft coming
through the doorway", "I don't want dust getting into this box"): the sense to work the part in, the kinds of part
that answer it (the first the object has one of), and the one category of object it is said of ("" for any)."""
POPPING_VERBS = frozenset({"pop", "spring"})
"""Verbs that say a shut part is let go by its release ("pop the microwave open"): its one release control is worked."""
WHEEL_SHAPED = frozenset({"wheel", "spoked", "spoke", "spokes", "star", "capstan"})
"""Words that describe a handle as a big spoked wheel ("the wheel handle", "the spoked handle"): among several turning
controls, the clearly largest one."""
HEDGE_ADVERBS = frozenset({"roughly", "approximately", "approx", "nearly", "almost", "exactly", "precisely", "circa", "somewhere", "maybe",
                           "perhaps", "about", "around", "currently", "presently"})
"""", roughly half a revolution": how sure the amount is, never a part."""
EVERYDAY_WORDS = frozenset({"someone", "somebody", "clothes", "laundry", "dishes", "plates", "load", "loaded", "unload", "washing",
                            "again", "please", "leftovers", "groceries", "food", "stuff", "things", "inside", "something", "anything",
                            "nothing", "everything", "building", "until", "should", "the", "because", "else",
                            "sorry", "photo", "photos", "picture", "pictures", "video", "request"})
"""Everyday words of requests that are no part and no motion ("someone left ...", "load some clothes in"): typos are
corrected to them, and never from them to a lexicon word ("clothse" is "clothes", not "close")."""
