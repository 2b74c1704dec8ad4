"""What users call each kind of object, by the asset's own category (the stem of its name).

"open the trunk" on a microwave names some other object: the agent refuses rather than open the
microwave's door. A noun in no family ("the thing", "the unit", "the machine") fits any object, and
an asset whose category is not listed here is never second-guessed.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType

from app.engine.lexicon.kinds import PartKind

_CONTAINERS = frozenset({"box", "case", "chest", "crate", "container", "tin", "carton", "package", "coffer", "cashbox", "lockbox",
                         "strongbox", "toolbox", "lunchbox", "breadbox", "trunk", "footlocker", "cooler", "casket", "storage"})
_FURNITURE = frozenset({"cabinet", "cupboard", "dresser", "wardrobe", "storage", "nightstand", "bedside", "locker", "bookcase", "desk",
                        "bureau", "sideboard", "credenza", "armoire", "tallboy", "commode", "chest", "chest_of_drawers", "vanity", "hutch",
                        "cubby", "closet", "pantry", "bank_of_drawers", "set_of_drawers", "table", "furniture", "drawers", "workbench",
                        "endtable"})
_BINS = frozenset({"bin", "trash", "trashcan", "can", "dustbin", "garbage", "wheelie", "dumpster", "hamper", "basket"})
_COOKERS = frozenset({"oven", "stove", "cooker", "range", "grill"})
_TAPS = frozenset({"faucet", "tap", "mixer", "spigot", "basin", "sink", "valve"})
_BAGS = frozenset({"bag", "handbag", "purse", "tote", "case", "luggage", "suitcase", "briefcase"})
_POTS = frozenset({"pot", "saucepan", "casserole", "pan", "kettle"})
_VEHICLES = frozenset({"car", "toy", "cart", "trolley", "vehicle", "truck", "bus", "wagon", "stroller", "pram", "buggy"})

OBJECT_FAMILIES: Mapping[str, frozenset[str]] = MappingProxyType({
    "storage": _FURNITURE | _CONTAINERS,
    "cabinet": _FURNITURE | _CONTAINERS,
    "box": _CONTAINERS | _FURNITURE | {"suitcase", "briefcase"},
    "safe": frozenset({"safe", "vault", "strongbox", "lockbox", "box", "cabinet", "locker", "chest", "coffer", "cashbox"}),
    "trash": _BINS | {"container"},
    "pedal": _BINS | {"container"},
    "bucket": frozenset({"bucket", "pail", "tub", "basket", "can", "container"}),
    "microwave": frozenset({"microwave", "oven", "cooker", "nuker"}),
    "oven": _COOKERS | {"microwave"},
    "refrigerator": frozenset({"fridge", "refrigerator", "freezer", "cooler", "cabinet"}),
    "dishwasher": frozenset({"dishwasher", "washer", "cabinet"}),
    "washing": frozenset({"washer", "washing", "dryer", "laundry", "top-loader", "front-loader", "washing-machine"}),
    "toaster": frozenset({"toaster"}),
    "coffee": frozenset({"coffee", "espresso", "brewer", "maker", "coffeemaker", "blender", "jug", "mixer", "juicer"}),
    "faucet": _TAPS,
    "laptop": frozenset({"laptop", "computer", "notebook", "macbook", "pc", "screen"}),
    "suitcase": _BAGS | {"trunk", "box"},
    "bag": _BAGS,
    "kitchen": _POTS,
    "kettle": _POTS,
    "stapler": frozenset({"stapler"}),
    "switch": frozenset({"switch", "light", "lamp", "toggle", "rocker"}),
    "toilet": frozenset({"toilet", "loo", "lavatory", "commode"}),
    "toy": _VEHICLES,
    "car": _VEHICLES,
    "cart": _VEHICLES,
})
"""Asset category -> the object nouns that can name it."""

NAMED_OBJECTS = frozenset().union(*OBJECT_FAMILIES.values())
"""Nouns that name some particular kind of object (a noun outside every family fits any object)."""


def names_other_object(noun: str, category: str | None, words: str = "") -> bool:
    """``noun`` names a kind of object this asset (of ``category``) is not; ``words``, the whole phrase, may name it
    still ("the dishwasher unit" is a dishwasher)."""
    family = OBJECT_FAMILIES.get(category or "")
    return family is not None and noun in NAMED_OBJECTS and noun not in family and not family & set(words.split())


CARRIED: Mapping[str, tuple[frozenset[str], tuple[PartKind, ...]]] = MappingProxyType({
    "toaster": (frozenset({"bread", "toast", "slice", "bagel", "waffle", "crumpet", "muffin", "pop-tart"}), (PartKind.LEVER,)),
    "faucet": (frozenset({"water"}), (PartKind.HANDLE, PartKind.LEVER, PartKind.SWITCH, PartKind.KNOB)),
    "microwave": (frozenset({"mug", "cup", "bowl", "dish", "food", "soup", "coffee", "tea", "meal", "leftovers"}), (PartKind.TURNTABLE,)),
})
"""Asset category -> what users put in it or get from it, and the kinds of part that carry or let it ("sink the bread down
into the slots": the toaster's carriage lever; "turn on the water": the tap's handle, whichever kind it has; "turn the mug
around": the microwave's turntable)."""


def carrier_of(noun: str, category: str | None, has: Callable[[PartKind], bool] | None = None) -> PartKind | None:
    """The kind of part that carries ``noun`` in an object of ``category`` (the first of them it ``has``; None when it
    carries nothing by that name)."""
    carried = CARRIED.get(category or "")
    if carried is None or noun not in carried[0]:
        return None
    return next((kind for kind in carried[1] if has is None or has(kind)), carried[1][0])


SPOUTED = frozenset({"faucet"})
"""Asset categories whose fixed body reaches out over its foot toward the user (a tap's spout): with no door, drawer or
lid to show where the object faces, the reach does."""
