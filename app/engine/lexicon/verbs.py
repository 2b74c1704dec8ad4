"""Verb senses: what a verb does to a part or to the whole object — one entry per verb lemma.

Verbs are grouped VerbNet-style by how they behave: the sense they carry on a part, how a
particle changes it ("pull out", "push in", "swing shut"), what they mean when the whole
object is the theme ("turn it around" is a yaw, "push the cart" moves it), what a bare use
implies ("flush" works a flush lever), and which kind of motion they name (a hinge or a slide).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from types import MappingProxyType
from typing import Literal

from app.engine.lexicon.kinds import PartKind


class VerbSense(StrEnum):
    OPEN = "open"
    CLOSE = "close"
    PRESS = "press"
    RELEASE = "release"
    PULL_OUT = "pull_out"
    PUSH_IN = "push_in"
    TURN = "turn"
    SPIN = "spin"
    RAISE = "raise"
    LOWER = "lower"
    TOGGLE = "toggle"
    MOVE = "move"
    YAW = "yaw"
    UNLATCH = "unlatch"
    LOCK = "lock"
    OPERATE = "operate"
    HOLD = "hold"
    WAIT = "wait"
    RECLINE = "recline"
    SWITCH_ON = "switch_on"
    SWITCH_OFF = "switch_off"
    RETURN = "return"
    GRASP = "grasp"
    """Take hold of a part: no motion of its own (what follows moves it)."""


Motion = Literal["any", "hinge", "slide", "twist"]
_NONE: Mapping[str, VerbSense] = MappingProxyType({})


@dataclass(frozen=True)
class VerbInfo:
    lemma: str
    sense: VerbSense
    particles: Mapping[str, VerbSense] = field(default_factory=lambda: _NONE)
    """A particle that changes the sense: "pull ... out" -> PULL_OUT, "swing ... shut" -> CLOSE."""
    object_sense: VerbSense | None = None
    """Sense when the whole object is the theme (``None``: the verb does not move whole objects)."""
    displaces: bool = False
    """A press-type verb that also carries a free object away ("push the box", "kick the bin")."""
    motion: Motion = "any"
    """The kind of motion the verb names: a hinge ("fold", "swing"), a straight slide ("slide") or a twist about the part's
    own axis ("twist", "rotate", "screw"), which a part that only slides cannot make."""
    implies: tuple[PartKind, ...] = ()
    """Kinds a bare use works ("flush the toilet" -> its lever or button)."""
    stative: bool = False
    """Describes a state to keep ("hold", "keep", "leave"), not a motion."""
    rocker_sense: VerbSense | None = None
    """Sense on a rocker or button (a part pressed into its face) when no particle says the way: the verb names a hinge
    motion but no way of its own ("tilt the wall switch" rocks it over, it does not raise it)."""


def _p(**pairs: VerbSense) -> Mapping[str, VerbSense]:
    return MappingProxyType(dict(pairs))


S = VerbSense
_OPENING = _p(open=S.OPEN, shut=S.CLOSE, closed=S.CLOSE, out=S.PULL_OUT, up=S.RAISE, down=S.LOWER, back=S.RETURN, off=S.OPEN)
_PUSHING = _p(open=S.OPEN, shut=S.CLOSE, closed=S.CLOSE, **{"in": S.PUSH_IN}, down=S.PRESS, back=S.RETURN, up=S.RAISE, out=S.PULL_OUT)
_PULLING = _p(open=S.OPEN, shut=S.CLOSE, closed=S.CLOSE, out=S.PULL_OUT, down=S.LOWER, up=S.RAISE, back=S.RETURN, **{"in": S.PUSH_IN}, off=S.OPEN)
_FOLDING = _p(open=S.OPEN, out=S.OPEN, up=S.RAISE, back=S.RECLINE, down=S.LOWER, shut=S.CLOSE, closed=S.CLOSE, over=S.TOGGLE)
_TURNING = _p(on=S.SWITCH_ON, off=S.SWITCH_OFF, back=S.RETURN, open=S.OPEN, shut=S.CLOSE, around=S.YAW, round=S.YAW)
_RAISING = _p(open=S.OPEN, up=S.RAISE, off=S.OPEN, back=S.RETURN, out=S.PULL_OUT)
_LOWERING = _p(down=S.LOWER, shut=S.CLOSE, closed=S.CLOSE, back=S.RETURN, open=S.OPEN)

_VERBS: tuple[VerbInfo, ...] = (
    # open / close
    VerbInfo("open", S.OPEN, _p(up=S.OPEN, back=S.RETURN, out=S.OPEN)),
    VerbInfo("reopen", S.OPEN),
    VerbInfo("unfold", S.OPEN, motion="hinge"),
    VerbInfo("uncover", S.OPEN),
    VerbInfo("close", S.CLOSE, _p(up=S.CLOSE, back=S.RETURN)),
    VerbInfo("seat", S.LOWER, _p(back=S.LOWER, down=S.LOWER)),  # "seat the lid back on the pot"
    VerbInfo("shut", S.CLOSE),
    VerbInfo("seal", S.CLOSE),
    VerbInfo("slam", S.CLOSE, _p(shut=S.CLOSE, down=S.PRESS, closed=S.CLOSE)),
    VerbInfo("bang", S.CLOSE, _p(shut=S.CLOSE, closed=S.CLOSE, open=S.OPEN, down=S.LOWER)),  # "the lid bangs shut again"
    VerbInfo("fold", S.CLOSE, _FOLDING, motion="hinge"),
    VerbInfo("swing", S.OPEN, _p(open=S.OPEN, shut=S.CLOSE, closed=S.CLOSE, out=S.OPEN, up=S.RAISE, down=S.LOWER, back=S.RETURN, over=S.TOGGLE),
             motion="hinge"),
    VerbInfo("flip", S.TOGGLE, _p(open=S.OPEN, up=S.OPEN, back=S.OPEN, down=S.CLOSE, shut=S.CLOSE, closed=S.CLOSE, on=S.SWITCH_ON, off=S.SWITCH_OFF,
                              round=S.YAW, around=S.YAW), motion="hinge"),
    VerbInfo("tilt", S.RAISE, _p(back=S.RECLINE, open=S.OPEN, up=S.RAISE, down=S.LOWER, forward=S.CLOSE), motion="hinge", rocker_sense=S.TOGGLE),
    VerbInfo("recline", S.RECLINE, motion="hinge"),
    VerbInfo("lean", S.RECLINE, _p(back=S.RECLINE, forward=S.CLOSE), motion="hinge"),
    VerbInfo("crack", S.OPEN, _p(open=S.OPEN)),
    VerbInfo("fling", S.OPEN, _p(open=S.OPEN, back=S.OPEN, up=S.RAISE, shut=S.CLOSE, closed=S.CLOSE, down=S.LOWER), motion="hinge"),
    VerbInfo("throw", S.OPEN, _p(open=S.OPEN, back=S.OPEN, up=S.RAISE, shut=S.CLOSE), motion="hinge"),
    VerbInfo("chuck", S.OPEN, _p(open=S.OPEN, back=S.OPEN, up=S.RAISE, shut=S.CLOSE), motion="hinge"),  # "chuck the bag in"
    VerbInfo("prop", S.OPEN, _p(open=S.OPEN, up=S.RAISE)),
    VerbInfo("flop", S.LOWER, _p(down=S.LOWER, open=S.OPEN, back=S.OPEN, over=S.LOWER), motion="hinge"),
    VerbInfo("pop", S.OPEN, _p(open=S.OPEN, out=S.PULL_OUT, up=S.RAISE, back=S.RELEASE, on=S.CLOSE, into=S.PUSH_IN, shut=S.CLOSE, closed=S.CLOSE,
                               **{"in": S.PUSH_IN})),
    # press / release
    VerbInfo("press", S.PRESS, _p(down=S.PRESS, **{"in": S.PRESS}, open=S.OPEN), displaces=False),
    VerbInfo("depress", S.PRESS),
    VerbInfo("push", S.PRESS, _PUSHING, object_sense=S.MOVE, displaces=True),
    VerbInfo("step", S.PRESS, _p(on=S.PRESS, down=S.PRESS, off=S.RELEASE)),
    VerbInfo("stomp", S.PRESS, _p(on=S.PRESS)),
    VerbInfo("stamp", S.PRESS, _p(on=S.PRESS)),
    VerbInfo("tread", S.PRESS, _p(on=S.PRESS, down=S.PRESS)),
    VerbInfo("tap", S.PRESS),
    VerbInfo("jab", S.PRESS),  # "jab the release with my knuckle"
    VerbInfo("prod", S.PRESS),
    VerbInfo("hit", S.PRESS, displaces=True, object_sense=S.MOVE),
    VerbInfo("punch", S.PRESS, _p(**{"in": S.PRESS}), displaces=True, object_sense=S.MOVE),
    VerbInfo("click", S.PRESS, _p(shut=S.CLOSE, closed=S.CLOSE, open=S.OPEN, down=S.PRESS, back=S.RETURN, into_place=S.CLOSE)),  # "the latch clicks closed"
    VerbInfo("squeeze", S.PRESS),
    VerbInfo("pump", S.PRESS),
    VerbInfo("type", S.PRESS, _p(**{"in": S.PRESS})),
    VerbInfo("enter", S.PRESS, _p(**{"in": S.PRESS})),
    VerbInfo("key", S.PRESS, _p(**{"in": S.PRESS})),
    VerbInfo("dial", S.TURN, _p(**{"in": S.TURN}), implies=(PartKind.KNOB,)),
    VerbInfo("release", S.RELEASE),
    VerbInfo("come", S.MOVE, _p(off=S.RELEASE, away=S.RELEASE, out=S.PULL_OUT, open=S.OPEN, down=S.LOWER, up=S.RAISE, back=S.RETURN,
                                  loose=S.OPEN, undone=S.OPEN, round=S.SPIN, around=S.SPIN)),
    VerbInfo("let", S.RELEASE, _p(go=S.RELEASE, down=S.LOWER, up=S.RAISE, open=S.OPEN, shut=S.CLOSE, closed=S.CLOSE, out=S.PULL_OUT, on=S.SWITCH_ON,
                                  back=S.RETURN)),
    VerbInfo("spring", S.RELEASE, _p(back=S.RELEASE, open=S.OPEN, up=S.RAISE)),
    VerbInfo("snap", S.RELEASE, _p(back=S.RELEASE, open=S.OPEN, shut=S.CLOSE, over=S.TOGGLE)),
    VerbInfo("bounce", S.RELEASE, _p(back=S.RELEASE)),
    # slide in / out
    VerbInfo("pull", S.PULL_OUT, _PULLING, object_sense=S.MOVE),
    VerbInfo("draw", S.PULL_OUT, _PULLING),
    VerbInfo("extend", S.PULL_OUT),
    VerbInfo("slide", S.PULL_OUT, _PULLING, object_sense=S.MOVE, motion="slide"),
    VerbInfo("withdraw", S.PULL_OUT, _PULLING),  # "withdraw the lowest rack from behind it"
    VerbInfo("glide", S.PULL_OUT, _PULLING, object_sense=S.MOVE, motion="slide"),
    VerbInfo("eject", S.PULL_OUT),
    VerbInfo("take", S.PULL_OUT, _p(out=S.PULL_OUT, off=S.OPEN)),
    VerbInfo("remove", S.PULL_OUT),
    VerbInfo("retract", S.PUSH_IN),
    VerbInfo("insert", S.PUSH_IN),
    VerbInfo("tuck", S.PUSH_IN, _p(**{"in": S.PUSH_IN})),
    VerbInfo("tidy", S.CLOSE, _p(away=S.PUSH_IN, up=S.CLOSE)),  # "tidy the drawer away"
    VerbInfo("zip", S.CLOSE, _p(up=S.CLOSE, shut=S.CLOSE, closed=S.CLOSE, open=S.OPEN)),  # "zip the suitcase back up"
    VerbInfo("unzip", S.OPEN, _p(open=S.OPEN)),
    VerbInfo("yank", S.PULL_OUT, _PULLING, object_sense=S.MOVE),
    VerbInfo("tug", S.PULL_OUT, _PULLING, object_sense=S.MOVE),
    # turn / spin
    VerbInfo("turn", S.TURN, _TURNING, object_sense=S.YAW),
    VerbInfo("rotate", S.TURN, _TURNING, object_sense=S.YAW, motion="twist"),
    VerbInfo("twist", S.TURN, _TURNING, motion="twist"),
    VerbInfo("crank", S.TURN),
    VerbInfo("wind", S.TURN, _p(up=S.TURN)),
    VerbInfo("set", S.TURN, _p(down=S.LOWER, back=S.RETURN)),
    VerbInfo("swivel", S.TURN, _TURNING, object_sense=S.YAW, motion="twist"),
    VerbInfo("pivot", S.TURN, _TURNING, object_sense=S.YAW),
    VerbInfo("yaw", S.YAW, object_sense=S.YAW),  # about the vertical axis: the whole object
    VerbInfo("angle", S.TURN, _TURNING, object_sense=S.YAW),
    VerbInfo("spin", S.SPIN, _p(around=S.SPIN, round=S.SPIN), object_sense=S.YAW),
    VerbInfo("revolve", S.SPIN),
    VerbInfo("screw", S.TURN, _p(on=S.CLOSE, off=S.OPEN, down=S.CLOSE, shut=S.CLOSE), motion="twist"),
    VerbInfo("unscrew", S.OPEN, motion="twist"),
    VerbInfo("loosen", S.OPEN),
    VerbInfo("tighten", S.CLOSE),
    VerbInfo("run", S.SPIN),
    VerbInfo("heat", S.SPIN, _p(up=S.SPIN, through=S.SPIN)),  # "heat up my leftovers in the microwave": set it going, as "run" does
    VerbInfo("warm", S.SPIN, _p(up=S.SPIN, through=S.SPIN)),
    VerbInfo("reheat", S.SPIN, _p(up=S.SPIN, through=S.SPIN)),
    VerbInfo("defrost", S.SPIN, _p(up=S.SPIN, through=S.SPIN)),
    VerbInfo("nuke", S.SPIN),
    VerbInfo("zap", S.SPIN),
    VerbInfo("start", S.SPIN, implies=(PartKind.LEVER,)),
    # raise / lower
    VerbInfo("lift", S.RAISE, _RAISING, object_sense=S.MOVE),
    VerbInfo("raise", S.RAISE, _RAISING, object_sense=S.MOVE),
    VerbInfo("hoist", S.RAISE, _RAISING, object_sense=S.MOVE),
    VerbInfo("levitate", S.RAISE, _RAISING, object_sense=S.MOVE),
    VerbInfo("hover", S.RAISE, _RAISING, object_sense=S.MOVE),
    VerbInfo("elevate", S.RAISE, _RAISING, object_sense=S.MOVE),
    VerbInfo("elevate", S.RAISE, _RAISING, object_sense=S.MOVE),
    VerbInfo("pick", S.GRASP, _RAISING, object_sense=S.MOVE),  # "pick the bottom one and turn it": which; "pick it up": raise
    VerbInfo("lower", S.LOWER, _LOWERING, object_sense=S.MOVE),
    VerbInfo("drop", S.LOWER, _LOWERING, object_sense=S.MOVE),
    VerbInfo("sink", S.LOWER, _LOWERING, object_sense=S.MOVE),
    VerbInfo("descend", S.LOWER, _LOWERING),
    VerbInfo("rise", S.RAISE, _RAISING),
    VerbInfo("ascend", S.RAISE, _RAISING),
    VerbInfo("put", S.LOWER, _p(down=S.LOWER, back=S.RETURN, away=S.PUSH_IN, on=S.CLOSE), object_sense=S.MOVE),
    VerbInfo("lay", S.LOWER, _p(down=S.LOWER, shut=S.CLOSE, closed=S.CLOSE, back=S.RECLINE, open=S.OPEN, flat=S.OPEN), object_sense=S.MOVE),
    VerbInfo("place", S.LOWER, _LOWERING, object_sense=S.MOVE),
    VerbInfo("fall", S.LOWER, _p(shut=S.CLOSE, closed=S.CLOSE, open=S.OPEN, back=S.RETURN)),
    VerbInfo("tip", S.LOWER, _p(over=S.TOGGLE, back=S.RECLINE, up=S.RAISE)),
    # switches
    VerbInfo("toggle", S.TOGGLE, _p(on=S.SWITCH_ON, off=S.SWITCH_OFF)),
    VerbInfo("switch", S.TOGGLE, _p(on=S.SWITCH_ON, off=S.SWITCH_OFF)),
    VerbInfo("flick", S.TOGGLE, _p(on=S.SWITCH_ON, off=S.SWITCH_OFF, up=S.RAISE, down=S.LOWER)),
    VerbInfo("rock", S.TOGGLE, object_sense=S.MOVE),
    VerbInfo("flush", S.PRESS, implies=(PartKind.LEVER, PartKind.BUTTON, PartKind.HANDLE)),
    VerbInfo("toast", S.LOWER, implies=(PartKind.LEVER,)),
    # whole-object motion
    VerbInfo("move", S.MOVE, _p(back=S.RETURN), object_sense=S.MOVE),
    VerbInfo("go", S.MOVE, _p(out=S.PULL_OUT, **{"in": S.PUSH_IN}, up=S.RAISE, down=S.LOWER, back=S.RETURN, open=S.OPEN, shut=S.CLOSE,
                              closed=S.CLOSE, over=S.TOGGLE, round=S.SPIN, around=S.SPIN), object_sense=S.MOVE),
    VerbInfo("follow", S.MOVE, _p(down=S.LOWER, up=S.RAISE, out=S.PULL_OUT, open=S.OPEN, back=S.RETURN)),
    VerbInfo("drag", S.MOVE, object_sense=S.MOVE),
    VerbInfo("shove", S.MOVE, object_sense=S.MOVE, displaces=True),
    VerbInfo("blow", S.OPEN, _p(open=S.OPEN, shut=S.CLOSE, closed=S.CLOSE, back=S.RETURN)),  # "a gust blows the door shut"
    VerbInfo("nudge", S.MOVE, object_sense=S.MOVE, displaces=True),
    VerbInfo("ease", S.MOVE, _PULLING, object_sense=S.MOVE),
    VerbInfo("heave", S.RAISE, _RAISING, object_sense=S.MOVE),  # "heave the whole pot straight up half a metre"  # "ease the oven back toward the wall", "ease the drawer out"
    VerbInfo("kick", S.MOVE, object_sense=S.MOVE, displaces=True),
    VerbInfo("carry", S.MOVE, object_sense=S.MOVE),
    VerbInfo("transport", S.MOVE, object_sense=S.MOVE),
    VerbInfo("translate", S.MOVE, object_sense=S.MOVE),
    VerbInfo("shift", S.MOVE, object_sense=S.MOVE),
    VerbInfo("displace", S.MOVE, object_sense=S.MOVE),
    VerbInfo("budge", S.MOVE, object_sense=S.MOVE),
    VerbInfo("sweep", S.MOVE),  # "sweep the lever across to the right"
    VerbInfo("roll", S.MOVE, object_sense=S.MOVE),
    VerbInfo("wheel", S.MOVE, object_sense=S.MOVE),
    VerbInfo("drive", S.MOVE, object_sense=S.MOVE),
    VerbInfo("tow", S.MOVE, object_sense=S.MOVE),
    VerbInfo("haul", S.MOVE, object_sense=S.MOVE),
    VerbInfo("coast", S.MOVE, object_sense=S.MOVE),
    VerbInfo("scoot", S.MOVE, object_sense=S.MOVE),
    VerbInfo("relocate", S.MOVE, object_sense=S.MOVE),
    VerbInfo("reposition", S.MOVE, object_sense=S.MOVE),
    # latches
    VerbInfo("unlatch", S.UNLATCH),
    VerbInfo("unlock", S.UNLATCH, implies=(PartKind.LATCH, PartKind.HANDLE, PartKind.KNOB)),
    VerbInfo("unhook", S.UNLATCH),
    VerbInfo("unbolt", S.UNLATCH),
    VerbInfo("unclip", S.UNLATCH),
    VerbInfo("unclasp", S.UNLATCH),
    VerbInfo("free", S.UNLATCH),
    VerbInfo("lock", S.LOCK, _p(up=S.LOCK)),
    VerbInfo("latch", S.LOCK, _p(up=S.LOCK, shut=S.LOCK, closed=S.LOCK)),  # "latch it up": fastened, not lifted
    # generic operation
    VerbInfo("operate", S.OPERATE),
    VerbInfo("use", S.OPERATE),
    VerbInfo("activate", S.OPERATE),
    VerbInfo("engage", S.OPERATE),
    VerbInfo("trigger", S.OPERATE),
    VerbInfo("work", S.OPERATE),
    VerbInfo("actuate", S.OPERATE),
    VerbInfo("grab", S.GRASP, stative=True),
    VerbInfo("grasp", S.GRASP, stative=True),
    VerbInfo("grip", S.GRASP, stative=True),
    VerbInfo("choose", S.GRASP, stative=True),
    VerbInfo("select", S.GRASP, stative=True),
    VerbInfo("get_at", S.GRASP, stative=True),  # "to get at the second rack, ...": reach it (what follows moves it)
    VerbInfo("bring", S.MOVE, _p(up=S.RAISE, down=S.LOWER, back=S.RETURN, out=S.PULL_OUT, **{"in": S.PUSH_IN}, around=S.YAW, round=S.YAW),
             object_sense=S.MOVE),
    VerbInfo("stand", S.RAISE, _p(up=S.RAISE, on=S.PRESS)),
    VerbInfo("clip", S.LOCK, _p(shut=S.LOCK, closed=S.LOCK, on=S.LOCK, open=S.UNLATCH)),
    VerbInfo("snap_shut", S.CLOSE),
    VerbInfo("fasten", S.LOCK),
    VerbInfo("buckle", S.LOCK),
    VerbInfo("secure", S.LOCK),
    # states, time, returns
    VerbInfo("hold", S.HOLD, _p(down=S.PRESS, open=S.HOLD, up=S.HOLD), stative=True),
    VerbInfo("keep", S.HOLD, stative=True),
    VerbInfo("rest", S.HOLD, stative=True),
    VerbInfo("maintain", S.HOLD, stative=True),  # "maintain that position for three seconds"
    VerbInfo("leave", S.HOLD, stative=True),
    VerbInfo("wait", S.WAIT, stative=True),
    VerbInfo("pause", S.WAIT, stative=True),
    VerbInfo("return", S.RETURN),
    VerbInfo("undo", S.RETURN),
    VerbInfo("revert", S.RETURN),
    VerbInfo("centre", S.RETURN),
    VerbInfo("center", S.RETURN),
    VerbInfo("recentre", S.RETURN),
    VerbInfo("recenter", S.RETURN),
    VerbInfo("settle", S.RETURN, _p(back=S.RETURN, down=S.LOWER, shut=S.CLOSE, closed=S.CLOSE)),
    VerbInfo("restore", S.RETURN),
    VerbInfo("reset", S.RETURN),
)

VERBS: Mapping[str, VerbInfo] = MappingProxyType({v.lemma: v for v in _VERBS})

GENERIC = VerbInfo("generic", S.MOVE, _p(open=S.OPEN, shut=S.CLOSE, closed=S.CLOSE, out=S.PULL_OUT, up=S.RAISE, down=S.LOWER, back=S.OPEN,
                                       **{"in": S.PUSH_IN}, on=S.SWITCH_ON, off=S.SWITCH_OFF, over=S.TOGGLE, into_place=S.CLOSE))
"""What an imperative verb we do not know does ("jiggle the lid open"), read from its particle; the
explanation warns that the verb was guessed."""

PARTICLES = frozenset({"out", "in", "open", "shut", "closed", "up", "down", "back", "away", "off", "on", "over", "around", "round", "go", "forward", "into_place"})
"""Words that may follow a verb and change its sense (``VerbInfo.particles``)."""


def verb(lemma: str) -> VerbInfo | None:
    return VERBS.get(lemma)


VERBLESS_SENSES: Mapping[str, VerbSense] = MappingProxyType({
    "up": VerbSense.RAISE, "down": VerbSense.LOWER, "out": VerbSense.PULL_OUT, "open": VerbSense.OPEN, "shut": VerbSense.CLOSE,
    "closed": VerbSense.CLOSE,
})
"""What a clause with no verb asks by its particle ("lid up to 90 deg", "screen down until it's shut")."""
WISHED_SENSES: Mapping[str, VerbSense] = MappingProxyType({**VERBLESS_SENSES, "opened": VerbSense.OPEN, "in": VerbSense.PUSH_IN,
                                                          "covered": VerbSense.CLOSE, "uncovered": VerbSense.OPEN})
"""What a wish with no verb asks by the state it names ("I need the rack out", "the lid has to be shut")."""
STATE_PARTICLES = frozenset({"open", "shut", "closed", "up", "down", "in", "out", "into_place"})
"""Particles that name where a part ends ("shove it back in", "swing it shut")."""


def ends_after_back(info: VerbInfo | None, word: str) -> bool:
    """After "back", ``word`` says where the part ends: "shove it back in" (a verb with no "back" of its own), "pop it
    back on" (a verb whose "back" is springing back, and which has ``word`` as a particle); not "spring back up"."""
    if info is None or "back" not in info.particles:
        return word in STATE_PARTICLES
    return info.particles["back"] is VerbSense.RELEASE and word in ("on", "in", "into") and word in info.particles


CHOOSING_VERBS = frozenset({"take", "pick", "choose", "use", "select", "grab"})
"""Verbs that, with one of several like units as their only object and a step after them, only say which unit the
steps are on ("Take the left one and swing its lever"): no step of their own."""
