"""Prompt text -> a canonical phrasing the clause parser reads.

Lower case, units split from numbers, and rewrites of phrasings that mean a simpler one:
"one and a half" -> 1.5, keypad codes -> one press per key, "both doors, left one first" ->
two clauses, "wait 2 seconds" -> a pause clause, "back to where it started" -> "back",
"let the door drop" -> "drop the door", "give the car a push" -> "push the car", ...
Each rewrite says in a comment what it is for.
"""

from __future__ import annotations

import re
from collections.abc import Callable


def normalize(prompt: str) -> str:
    text = prompt.lower().replace("°", " degrees ").replace("’", "'")
    text = re.sub(r"(\d)([a-z%])", r"\1 \2", text)
    text = re.sub(r"([+-])\s+([xyz])\b", r"\1\2", text)
    text = re.sub(r"[\"()\[\]]", " ", text)
    for fraction, digits in (("a half", "5"), ("a quarter", "25"), ("three quarters", "75")):
        text = re.sub(r"(\d+|one|two|three|four|five) and " + fraction + r"\b", _and_a_fraction(digits), text)
    text = _keypad(text)
    # "open both doors 90 degrees, left one first": one after the other, the named one first
    text = _BOTH_FIRST.sub(_both_first, text)
    # "press the key to pop the door (fully) open": the effect is the opening
    text = re.sub(r"\bto\s+(?:pop|spring|snap|swing)\s+((?:the|its)\s+[\w-]+(?:\s+[\w-]+)?)\s+((?:fully|wide|all the way)\s+)?open\b", r"to open \1 \2", text)
    # "key in the top button" (a verb; "the middle key in the bottom row" names a key)
    text = re.sub(r"(^|[,.;:!?]\s*|\b(?:then|and|first|please|now|to)\s+)key(?:s|ed|ing)?\s+in\b", r"\1press", text)
    # "...; the door then opens": the sequence word leads its clause
    text = re.sub(r"(^|[.;!?:]\s+)((?:the|its|their)\s+(?:[\w-]+\s+){0,2}?[\w-]+)\s+then\s+", r"\1then \2 ", text)
    # "..., wait (2 seconds), then ...": a pause of its own between the steps around it
    text = _WAIT.sub(_pause, text)
    # "back to where it started": a return, not a verb of its own
    text = re.sub(r"\b(?:back\s+)?to (?:where (?:it|they|you|we) (?:started|began|was|were)|(?:its|their|the) (?:starting|original|initial) (?:point|position|place|spot))\b",
                  "back", text)
    # "reopen it to its original angle", "set it back down": a return to where the part rested
    text = re.sub(r"\bto (?:its|their|the) (?:original|initial|starting) (?:angle|height|opening|setting|state|level)\b", "back to rest", text)
    text = re.sub(r"\b(?:set|put|place)s?\s+(it|them)\s+(?:back\s+)?down\b", r"lower \1 back down", text)
    # "raise the lid, hold it there, then ...": staying put is a pause, not a motion
    text = re.sub(r"\b(?:hold|keep|leave)s?\s+(?:it|them)\s+(?:there|in place|in position|steady|still)\b", ". pause. ", text)
    # "the chest of drawers", "a bank of drawers": the drawers name the whole object
    text = re.sub(r"\b(?:chest|cabinet|set|bank|unit|tower|stack)s? of drawers\b", "dresser", text)
    # "take your foot off (the pedal)", "lift your finger": the user lets go of what was pressed
    text = re.sub(
        r"\b(?:take|takes|taking|lift|lifts|lifting|remove|removes|removing|move|pull|raise)\s+(?:your|my|the|his|her|their|one's)\s+"
        r"(?:foot|feet|hand|hands|finger|fingers|thumb|toe)\b(?:\s+(?:off|away|up|back))?(?:\s+(?:of|from)\s+(?:it|them|the\s+[\w-]+))?",
        "release it", text)
    text = re.sub(r"\blet\s+go\b(?!\s+of)", "release it", text)  # "..., then let go"
    text = _LET_MOTION.sub(_let_motion, text)
    # "..., without using the pedal": a part the user says not to use is not an instrument
    text = re.sub(r",?\s*\b(?:without|but not|and not|never)\s+(?:using|pressing|touching|stepping on|moving|opening)?\s*(?:the|its|a|any)\s+[\w-]+", " manually", text)
    text = re.sub(r",?\s*the one (?:with|that|which|having)\b[^,;.]*", "", text)
    # "give the car a push" -> "push the car"
    text = re.sub(
        r"\bgive\s+((?:it|them|the\s+[\w-]+(?:\s+[\w-]+)??|[\w-]+))\s+((?:a|an|half|quarter|one|two|three|full|\d[\w.]*)\s+(?:[\w.]+\s+){0,2}?)"
        r"(push|shove|nudge|spin|turn|twist|pull|tug|press|kick)s?\b",
        _give, text)
    return re.sub(r"\s+", " ", text).strip()


_OPPOSITE = {"left": "right", "right": "left", "top": "bottom", "bottom": "top", "upper": "lower", "lower": "upper", "front": "back", "back": "front"}
_BOTH_FIRST = re.compile(
    r"\b([a-z]+)\s+(?:both|the two|the 2)\s+((?:[\w-]+\s+)?)([\w-]+?)s\b([^,.;]*?),?\s+(?:the\s+)?(left|right|top|bottom|upper|lower|front|back)(?:[\s-]+hand)?\s+one\s+first\b"
)


def _both_first(match: re.Match[str]) -> str:
    """ "open both doors 90 degrees, left one first" -> "open the left door 90 degrees, then open the right door 90 degrees"."""
    verb, modifier, noun, rest, side = match.groups()
    rest = rest.rstrip()
    return f"{verb} the {side} {modifier}{noun}{rest}, then {verb} the {_OPPOSITE[side]} {modifier}{noun}{rest}"


_WAIT = re.compile(
    r",?\s*\b(?:and\s+)?(?:then\s+)?(?:wait|pause)(?:\s+for)?(?:\s+(?:about|roughly|around))?"
    r"(?:\s+(\d+(?:\.\d+)?|an?|one|two|three|four|five|ten)\s*(?:s|secs?|seconds?)\b)?(?:\s+(?:for\s+)?an?\s+(?:moment|bit|while|beat))?\s*,?"
)


def _pause(match: re.Match[str]) -> str:
    """ "wait 2 seconds" -> a sentence of its own: "pause for 2 seconds"."""
    amount = match.group(1)
    if amount is None:
        return ". pause. "
    return f". pause for {'1' if amount in ('a', 'an') else amount} seconds. "


_HALF = {"one": "1", "two": "2", "three": "3", "four": "4", "five": "5"}
_KEYPAD = re.compile(
    r"\b(?:type|enter|punch|key|input)\s+(?:in\s+)?(?:the\s+)?(?:code|combination|pin|sequence|digits)?\s*:?\s*(.+?)\s+"
    r"(?:on|into|using|at)\s+(?:the\s+)?(?:keypad|key pad|keys|buttons|number pad|keyboard)\b"
)


def _keypad(text: str) -> str:
    """ "type the code top-left, bottom-middle on the keypad" -> one key press per item, in order."""
    match = _KEYPAD.search(text)
    if match is None:
        return text
    items = [i.strip() for i in re.split(r"\s*(?:,|\bthen\b|\band\b)\s*", match.group(1)) if i.strip()]
    presses = ", then ".join(f"press the {item} key" for item in items)
    return text[: match.start()] + presses + text[match.end():]


def _and_a_fraction(digits: str) -> Callable[[re.Match[str]], str]:
    """Replacement for "one and a half" -> "1.5" (``digits`` = the decimals)."""

    def replace_match(match: re.Match[str]) -> str:
        return f"{_HALF.get(match.group(1), match.group(1))}.{digits}"

    return replace_match


def _give(match: re.Match[str]) -> str:
    """ "give the car a push" -> "push the car"; "give the dial half a turn" -> "turn the dial half a turn"."""
    target, amount, verb = match.group(1), match.group(2), match.group(3)
    measured = re.search(r"\b(?:half|quarter|full|one|two|three|\d)", amount)
    return f"{verb} {target} {amount}{verb}" if measured else f"{verb} {target}"


_LET_MOTION = re.compile(
    r"\blet\s+(it|them|(?:the|its|their)\s+(?:[\w'-]+\s+){0,3}?[\w'-]+)\s+(drop|fall|swing|lean|tip|down|come down|coast|glide)\b"
)


def _let_motion(match: re.Match[str]) -> str:
    """ "let the door drop / swing open / down", "let the car coast": the motion verb that follows is the action."""
    subject, verb = match.group(1), match.group(2)
    if verb in ("coast", "glide") and subject in ("it", "them"):
        return match.group(0)  # "push the car and let it coast": how the push ends, not a motion of its own
    return f"{'lower' if verb in ('down', 'come down') else verb} {subject}"
