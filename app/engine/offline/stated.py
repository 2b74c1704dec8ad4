"""A mechanism the prompt states instead of asking for a step: "Turning the spoked handle pulls back the locking
bolts. Get it open." (the handle releases what the bolts hold), "The lid stays locked until the dial on the base is
turned. Unlock it and lift the lid off." (the dial releases the lid). The control is recorded as what holds its host
shut (:func:`.mechanisms.latches_of` then works it before the host opens), and the statement adds no step itself."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import PartKind
from app.engine.lexicon.verbs import VerbSense
from app.engine.offline.reading.acts import Act
from app.engine.offline.tracker import ANY_HOST

if TYPE_CHECKING:
    from app.engine.offline.builder import Builder
    from app.engine.offline.grounding import Part
    from app.engine.offline.reading.mention import Mention

_WORKING = frozenset({"turning", "twisting", "rotating", "pressing", "pushing", "pulling", "sliding", "flipping", "lifting", "spinning"})
"""A gerund subject: "Turning the handle pulls back the bolts" says what working the handle does."""
_FREEING = frozenset({VerbSense.RETURN, VerbSense.RELEASE, VerbSense.UNLATCH, VerbSense.OPEN, VerbSense.PULL_OUT})
_HELD = frozenset({"locked", "latched", "shut", "closed"})
_WORKED = frozenset({VerbSense.TURN, VerbSense.PRESS, VerbSense.OPERATE, VerbSense.PULL_OUT, VerbSense.RAISE, VerbSense.TOGGLE, VerbSense.YAW})


def _released_by(act: Act) -> tuple[Mention, Mention | None] | None:
    """(the control, the part it releases or None) when ``act`` states a release, else None."""
    goal = act.goal
    words = goal.text.split()
    if words and words[0] in _WORKING and goal.themes and len(act.results) == 1:  # not "..., so the door swings open": a request
        result = act.results[0]
        if result.sense in _FREEING and result.themes and all(m.kind is PartKind.LATCH for m in result.themes):
            return goal.themes[0], None  # "Turning the handle pulls back the locking bolts"
    if _HELD & set(words) and {"stays", "stay", "remains", "remain", "is", "are"} & set(words) and goal.themes and act.results:
        result = act.results[0]
        if result.themes and result.sense in _WORKED:
            return result.themes[0], goal.themes[0]  # "The lid stays locked until the dial is turned"
    return None


def record_release(builder: Builder, act: Act) -> bool:
    """Record the release ``act`` states (True), or leave it to be read as a step (False)."""
    stated = _released_by(act)
    if stated is None:
        return False
    control_words, host_words = stated
    try:
        controls, _ = builder.refs.resolve(control_words)
        hosts = builder.refs.resolve(host_words)[0] if host_words is not None else []
    except GroundingError:
        return False
    if len(controls) != 1 or len(hosts) > 1:
        return False
    host = hosts[0].joint if hosts else ANY_HOST
    builder.tracker.releases[host] = controls[0]
    builder.notes.append(f"read '{act.goal.text}' as how {builder.asset.name} works: the {control_words.head} ({controls[0].joint}) "
                         f"releases {'the ' + host_words.head if host_words is not None else 'what holds it shut'}")
    return True


_STUCK = frozenset({"latched", "locked", "stuck", "jammed"})


def stated_latched(builder: Builder, act: Act) -> bool:
    """"The microwave door is latched and won't pull open. Get it open.": the part is held shut, so opening it works the
    one control that releases it (recorded, with a note; True). False when the clause says no such thing or the part has
    no such control."""
    words = act.goal.text.split()
    said = next((k for k, w in enumerate(words) if w in _STUCK), None)
    if said is None or said == 0 or words[said - 1] not in ("is", "are", "'s", "seems", "feels") or len(act.goal.themes) != 1:
        return False
    try:
        parts, _ = builder.refs.resolve(act.goal.themes[0])
    except GroundingError:
        return False
    if len(parts) != 1 or parts[0].joint in builder.tracker.releases:
        return False
    release = _released_by_control(builder, parts[0])
    if release is None:
        return False
    builder.notes.append(f"read '{act.goal.text}' as {parts[0].link} held shut: {release.link} ({release.joint}) releases it")
    return True


def _released_by_control(builder: Builder, host: Part) -> Part | None:
    """The one control that releases ``host``, recorded as what opens it (``host`` becomes "it"); None when it has none."""
    from app.engine.offline import mechanisms as mech

    release = mech.controls_for(host, builder.parts, builder.tracker, builder.excluded, popped=True)
    if not release:
        return None
    builder.tracker.releases[host.joint] = release[0]
    builder.refs.remember([host], [])
    return release[0]


_LACKS = (("has", "no"), ("have", "no"), ("hasn't", "got"), ("doesn't", "have"), ("there's", "no"), ("there", "is", "no"))


def stated_no_handle(builder: Builder, act: Act) -> bool:
    """"This microwave door has no handle. Get it open.": a part said to lack a way to pull it opens by the one control
    that releases it (recorded, with a note; True); the clause names nothing to move. False when it says no such thing."""
    words = act.goal.text.split()
    lacks = next((k for k in range(len(words)) for lead in _LACKS if tuple(words[k:k + len(lead)]) == lead), None)
    if lacks is None or not act.goal.themes:
        return False
    named = [m for m in act.goal.themes if m.start < lacks and (m.kind is not None or m.is_object)]
    hosts = [p for p in builder.parts if p.kind is PartKind.DOOR] if not named or named[0].is_object else None
    if hosts is None:
        try:
            hosts, _ = builder.refs.resolve(named[0])
        except GroundingError:
            return False
    if len(hosts) != 1:
        return False
    release = _released_by_control(builder, hosts[0])
    if release is None:
        builder.refs.remember(hosts, [])
        builder.notes.append(f"ignored '{act.goal.text}': how {hosts[0].link} is, no step")
        return True
    builder.notes.append(f"read '{act.goal.text}' as how {hosts[0].link} opens: by {release.link} ({release.joint}), its release")
    return True
