"""Part kinds: what a kind of part is called, what it does and how it behaves — one entry per kind.

Code never compares category names; it asks the entry (``info(kind).control``,
``info(kind).operates``, ...). Adding a kind of part is one :data:`REGISTRY` entry.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from enum import StrEnum
from types import MappingProxyType
from typing import Literal


class PartKind(StrEnum):
    DOOR = "door"
    LID = "lid"
    SEAT = "seat"
    FLAP = "flap"
    DRAWER = "drawer"
    TRAY = "tray"
    SHELF = "shelf"
    TURNTABLE = "turntable"
    CONTAINER = "container"
    SCREEN = "screen"
    WINDOW = "window"
    CAP = "cap"
    KNOB = "knob"
    HANDLE = "handle"
    LEVER = "lever"
    LATCH = "latch"
    BUTTON = "button"
    PEDAL = "pedal"
    SWITCH = "switch"
    WHEEL = "wheel"
    SPOUT = "spout"
    BODY = "body"
    CODE = "code"
    """Not a part: what a code is entered on (a combination dial, else the keypad's buttons)."""


Return = Literal["self_return", "stays"]
Press = Literal["into_face", "down", "turn", "none"]


@dataclass(frozen=True)
class KindInfo:
    """Everything the agent knows about one kind of part."""

    kind: PartKind
    words: tuple[str, ...]
    """Singular nouns and noun phrases that name it (plurals come from the lemmatiser)."""
    labels: tuple[str, ...] = ()
    """PartNet-Mobility ``semantics.txt`` labels of this kind."""
    related: tuple[PartKind, ...] = ()
    """Kinds a mention may mean when the asset has none of this kind (a "lid" that is a door)."""
    related_one: tuple[PartKind, ...] = ()
    """Kinds one such part, named in the singular, may be when the asset has none ("turn the big wheel" on a safe: its
    wheel handle; "spin the wheels" there is still refused)."""
    control: bool = False
    """A user operates it to cause something else (knobs, buttons, pedals, ...)."""
    returns: Return = "stays"
    """What it does when the hand lets go (paper: buttons and pedals spring back, knobs stay)."""
    returns_only_on_hinged: bool = False
    """It springs back only when mounted on a hinged part (a door handle; a bucket's carry handle stays)."""
    operates: tuple[PartKind, ...] = ()
    """Kinds it moves through its mechanism when operated (a pedal lifts a lid)."""
    operates_needs_name: bool = False
    """It operates those only when its own name says so ("release", "open") or the object is a kind whose
    only door such buttons release (microwaves)."""
    holds_effect: bool = False
    """Its effect lasts only while it is held (a pedal holding a lid up); letting go undoes it."""
    latches_host: bool = False
    """It holds the hinged part it sits on shut: opening that part needs it operated first."""
    hinged: bool = False
    """Swings open about a hinge (doors, lids, screens)."""
    openable: bool = False
    """Has an open and a closed state a user means by open/close."""
    rolls: bool = False
    """Rolls when the whole object moves (wheels)."""
    spins: bool = False
    """Turns freely as its own motion (wheels, turntables)."""
    press: Press = "none"
    """Which way "press" moves it: into the face it sits on, down, or a turn."""
    actuation_s: float | None = None
    """Seconds a user takes to operate it (controls), before speed words."""
    lid_like: bool = False
    """Swings up about a horizontal hinge (a lid, a seat): a side-hinged door is not one."""
    turns_only: bool = False
    """Only ever turns: a sliding part is never this kind."""
    reclines: bool = False
    """Pushed back, it tips further open (a laptop's screen), not shut like a door or a drawer."""
    affordances: tuple[str, ...] = ()
    """What Causal.json's ``semantics.links[].affordance`` lists for it."""
    opened_by: tuple[PartKind, ...] = ()
    """Opening or closing it means opening or closing the part of these kinds that rides on it (a jug's lid)."""


REGISTRY: dict[PartKind, KindInfo] = {
    info.kind: info
    for info in (
        KindInfo(PartKind.DOOR, ("door", "gate", "hatch", "rotation door", "hatch door", "oven door", "front door", "drop-front", "drop front", "fall-front"),
                 labels=("door", "rotation_door"), related=(PartKind.LID, PartKind.FLAP, PartKind.WINDOW, PartKind.SCREEN),
                 hinged=True, openable=True, affordances=("open", "close")),
        KindInfo(PartKind.LID, ("lid", "cover", "top lid", "rotation lid", "top cover"),
                 labels=("lid", "rotation_lid", "pump_lid"), related=(PartKind.DOOR, PartKind.FLAP, PartKind.SEAT, PartKind.SCREEN, PartKind.WINDOW, PartKind.CAP),
                 hinged=True, openable=True, lid_like=True, affordances=("open", "close", "lift")),
        KindInfo(PartKind.SEAT, ("seat", "toilet seat", "ring"), labels=("seat",), related=(PartKind.LID,),
                 hinged=True, openable=True, lid_like=True, affordances=("raise", "lower")),
        KindInfo(PartKind.FLAP, ("flap", "board", "fold-down door", "drop-down door", "tab", "hinged flap", "flip-up flap"), labels=("board",),
                 related=(PartKind.DOOR, PartKind.LID, PartKind.LEVER), hinged=True, openable=True, affordances=("open", "close")),
        KindInfo(PartKind.DRAWER, ("drawer", "draw", "slide out tray"), labels=("drawer",), related=(PartKind.TRAY, PartKind.SHELF, PartKind.CONTAINER),
                 openable=True, affordances=("pull_out", "push_in")),
        KindInfo(PartKind.TRAY, ("tray", "baking tray", "oven tray", "crumb tray"), labels=("tray", "translation_tray"),
                 related=(PartKind.DRAWER, PartKind.SHELF, PartKind.CONTAINER, PartKind.TURNTABLE), openable=True, affordances=("pull_out", "push_in")),
        KindInfo(PartKind.SHELF, ("shelf", "rack", "dish rack", "basket"), labels=("shelf",), related=(PartKind.DRAWER, PartKind.TRAY),
                 openable=True, affordances=("pull_out", "push_in")),
        KindInfo(PartKind.TURNTABLE, ("turntable", "turn table", "rotation tray", "carousel", "glass plate", "plate", "glass tray"),
                 labels=("rotation_tray", "turntable"), related=(PartKind.TRAY,), spins=True, affordances=("spin",)),
        KindInfo(PartKind.CONTAINER, ("container", "jug", "carafe", "water tank", "tank", "reservoir", "water reservoir", "jar", "canister"), labels=("container",),
                 related=(PartKind.DRAWER, PartKind.TRAY), openable=True, affordances=("pull_out", "push_in", "lift"),
                 opened_by=(PartKind.LID, PartKind.CAP)),
        KindInfo(PartKind.SCREEN, ("screen", "display", "monitor", "lcd"), labels=("screen",), related=(PartKind.LID, PartKind.DOOR),
                 hinged=True, openable=True, reclines=True, affordances=("open", "close")),
        KindInfo(PartKind.WINDOW, ("window", "sash", "pane", "rotation window", "casement"), labels=("window", "rotation_window", "translation_window"),
                 related=(PartKind.DOOR, PartKind.LID), hinged=True, openable=True, affordances=("open", "close")),
        KindInfo(PartKind.CAP, ("cap", "bottle cap", "screw cap"), labels=("cap",), related=(PartKind.LID,),
                 openable=True, affordances=("unscrew", "screw")),
        KindInfo(PartKind.KNOB, ("knob", "dial", "rotary knob", "control knob", "timer", "thermostat", "combination wheel", "combination dial",
                                 "combination knob", "browning control", "browning dial", "browning", "browning setting", "browning level",
                                 "selector", "program selector", "programme selector", "cycle selector", "selector knob", "selector dial"), labels=("knob",),
                 related=(PartKind.HANDLE, PartKind.LATCH, PartKind.SWITCH, PartKind.LEVER), control=True, press="turn", turns_only=True,
                 actuation_s=None, affordances=("turn",)),
        KindInfo(PartKind.HANDLE, ("handle", "grip", "grip bar", "rotation handle", "door handle", "bail", "carry handle", "crank", "spoked wheel", "handwheel",
                                   "hand wheel", "wheel handle", "spoke wheel", "handle wheel"),
                 labels=("handle", "rotation_handle"), related=(PartKind.KNOB, PartKind.LEVER, PartKind.LATCH, PartKind.SWITCH), control=True,
                 returns="self_return", returns_only_on_hinged=True, press="down", actuation_s=0.4, affordances=("turn", "press_down", "lift")),
        KindInfo(PartKind.LEVER, ("lever", "slider", "carriage", "flush lever", "toggle lever", "paddle", "mixer arm", "mixer lever", "mixer handle"), labels=("lever", "slider", "rotation_slider"),
                 related=(PartKind.HANDLE, PartKind.SWITCH, PartKind.KNOB), control=True, press="down", actuation_s=0.5,
                 affordances=("press_down", "lift")),
        KindInfo(PartKind.LATCH, ("latch", "lock", "catch", "bolt", "clasp", "latch knob", "latch handle"), labels=("lock", "latch"),
                 related=(PartKind.HANDLE, PartKind.KNOB, PartKind.LEVER), control=True, returns="self_return", latches_host=True,
                 press="turn", actuation_s=0.4, affordances=("unlatch",)),
        KindInfo(PartKind.BUTTON, ("button", "key", "keypad", "key pad", "number pad", "push button", "pushbutton", "release button", "keypad key",
                                   "flush button", "push-bar", "push bar"),
                 labels=("button",), related=(PartKind.SWITCH, PartKind.LEVER), control=True, returns="self_return",
                 operates=(PartKind.DOOR, PartKind.LID, PartKind.SCREEN, PartKind.WINDOW, PartKind.FLAP), operates_needs_name=True,
                 press="into_face", actuation_s=0.3, affordances=("press",)),
        KindInfo(PartKind.PEDAL, ("pedal", "pad", "foot pad", "footpad", "foot pedal", "foot lever", "step", "treadle"), labels=("foot_pad", "pedal"),
                 related=(PartKind.LEVER, PartKind.BUTTON), control=True, returns="self_return", operates=(PartKind.LID,), holds_effect=True,
                 press="down", actuation_s=0.4, affordances=("press",)),
        KindInfo(PartKind.SWITCH, ("switch", "toggle", "rocker", "toggle button", "toggle switch", "light switch"), labels=("switch", "toggle_button"),
                 related=(PartKind.BUTTON, PartKind.LEVER), control=True, press="into_face", actuation_s=0.3, affordances=("toggle",)),
        KindInfo(PartKind.WHEEL, ("wheel", "caster", "castor", "tire", "tyre", "roller"), labels=("wheel",), rolls=True, spins=True,
                 related_one=(PartKind.HANDLE, PartKind.KNOB),
                 affordances=("roll",)),
        KindInfo(PartKind.SPOUT, ("spout", "stem", "nozzle", "neck"), labels=("stem", "spout"), related=(PartKind.LEVER,),
                 affordances=("raise", "lower")),
        KindInfo(PartKind.BODY, ("body", "frame", "chassis", "housing", "casing", "stand", "keyboard", "base"), labels=()),
        KindInfo(PartKind.CODE, ("combination", "combination lock", "code", "passcode", "keycode", "pin code", "pin", "pin number"), related=(PartKind.KNOB, PartKind.BUTTON)),
    )
}


def info(kind: PartKind) -> KindInfo:
    return REGISTRY[kind]


def kind_of_label(label: str) -> PartKind | None:
    """The kind a PartNet ``semantics.txt`` label names (``None`` for bodies and unknown labels)."""
    return _LABELS.get(label.strip().lower())


_LABELS: dict[str, PartKind] = {label: entry.kind for entry in REGISTRY.values() for label in entry.labels}

HINGED_KINDS = frozenset(k for k, v in REGISTRY.items() if v.hinged)
CONTROL_KINDS = frozenset(k for k, v in REGISTRY.items() if v.control)
OPENABLE_ORDER: tuple[PartKind, ...] = (
    PartKind.DOOR, PartKind.LID, PartKind.SCREEN, PartKind.WINDOW, PartKind.FLAP, PartKind.SEAT,
    PartKind.DRAWER, PartKind.TRAY, PartKind.SHELF, PartKind.CONTAINER, PartKind.CAP,
)
"""Which openable kinds "open the <object>" means first: doors and lids, then drawers."""
NAMED_BY_USE: Mapping[str, PartKind] = MappingProxyType({"release": PartKind.BUTTON})
"""Nouns that name a part by what it does ("the door release"): the kind it is when no link of the asset is named so."""
