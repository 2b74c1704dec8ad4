"""Prompt -> ordered actions: clauses with verb, part mentions, quantities, means and sequence.

Handles sequences ("first A, then B", "A and then B", "after A-ing, B", "B after A-ing",
"before B, A"), means-end ("press X to open Y", "open Y by pressing X", "use X to open Y",
"press X so the Y opens") and parallel actions ("A while B").
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

from app.engine.offline.quantities import Quantity, parse_quantity
from app.engine.offline.rephrase import normalize
from app.engine.offline.vocabulary import (
    CATEGORY_WORDS,
    COLLECTIVE,
    IRREGULAR,
    ORDINALS,
    PARTICLES,
    SPATIAL,
    VERBS,
)
from app.engine.offline.vocabulary import OBJECT_WORDS as _OBJECT_WORDS

_SEQ_SPLIT = re.compile(
    r"\s*(?:[.;!?:]+(?=\s|$)\s*|,?\s*\band\s+then\b\s*|,?\s*\bthen\b\s*|,?\s*\bafterwards?\b,?\s*|,?\s*\bafter that\b,?\s*"
    r"|,?\s*\bnext\b,?\s*|,?\s*\b(?:and\s+)?(?:after|once) (?:it|that|this)(?: is done)?\b,?\s*|,?\s*\bfinally\b,?\s*|,?\s*\bsubsequently\b,?\s*|,?\s*\bonce (?:that is|it is|it's) done\b,?\s*)"
)
_PARALLEL = re.compile(r"\s*,?\s*\b(?:while|whilst|at the same time as|simultaneously with|and at the same time|as soon as)\b\s*")
_INTRANSITIVE = {
    "drops shut": "close", "falls shut": "close", "slams shut": "close", "swings shut": "close", "snaps shut": "close",
    "drops closed": "close", "falls closed": "close", "drops open": "open", "falls open": "open", "flips all the way back": "open",
    "flips back": "open", "flips up": "open", "swings up": "open", "comes down": "lower",
    "opens": "open", "open": "open", "pops open": "open", "swings open": "open", "flips open": "open",
    "springs open": "open", "lifts": "open", "rises": "open", "comes up": "open", "pops up": "raise",
    "closes": "close", "shuts": "close", "slides out": "pull_out", "comes out": "pull_out",
    "spins": "spin", "turns": "spin", "rotates": "spin", "rolls": "spin", "drops": "lower", "goes down": "lower",
}
_INTRANSITIVE_RE = re.compile(r"\b(" + "|".join(sorted(map(re.escape, _INTRANSITIVE), key=len, reverse=True)) + r")\b")
_FILLER = re.compile(r"^\s*(?:please\s+|first(?:ly)?,?\s+|now,?\s+|just\s+|and\s+|also\s+|to\s+)+")


@dataclass(frozen=True)
class Mention:
    """A reference to a part (or the whole object) inside a clause."""

    category: str
    head: str
    spatial: tuple[str, ...] = ()
    ordinal: int | None = None
    plural: bool = False
    owner: Mention | None = None
    position: int = 0
    instrument: bool = False
    """Named as the means of a whole-object motion ("by its handle", "on its wheels", "lid and all")."""
    row: int | None = None
    column: int | None = None
    """1-based from the top / left; -1 = last (bottom / right); 0 = middle."""
    size: str | None = None
    """``large`` or ``small`` ("the large dial")."""


@dataclass(frozen=True)
class Clause:
    text: str
    verb: str | None
    kind: str | None
    particle: str | None
    mentions: tuple[Mention, ...]
    quantity: Quantity
    unknown_object: str | None = None


@dataclass(frozen=True)
class Action:
    """One step a user asked for: ``clause`` (the goal), optionally achieved through ``means``."""

    clause: Clause
    means: Clause | None = None
    parallel: bool = False
    conjoined: bool = False
    """Joined to the previous action by "and" / a comma ("pick up the bucket and raise it 50 cm")."""


@dataclass(frozen=True)
class ParsedPrompt:
    text: str
    actions: tuple[Action, ...]
    quantity: Quantity = field(default_factory=Quantity)


_NEGATED = re.compile(r"^(?:without|not|never|do not|don't|avoid|but not)\b")
_PROGRESSIVE = re.compile(r"^(?:the|its|it)\b[^,]*\b(?:is|are)\s+(?:still\s+)?[a-z]+ing\b[^,]*$")


def lemma(word: str) -> str:
    """Verb lemma for regular and listed irregular forms."""
    if word in IRREGULAR:
        return IRREGULAR[word]
    if word in VERBS:
        return word
    for suffix, repl in (("ing", ""), ("ing", "e"), ("ed", ""), ("ed", "e"), ("es", ""), ("s", "")):
        if word.endswith(suffix) and word[: -len(suffix)] + repl in VERBS:
            return word[: -len(suffix)] + repl
    return word


OBJECT_WORDS_SET = frozenset(_OBJECT_WORDS)
_PHRASES = sorted(((p, c) for c, words in CATEGORY_WORDS.items() for p in words), key=lambda pc: -len(pc[0]))


def _find_mentions(text: str, exclude_verbs: set[int] | None = None) -> list[tuple[int, int, str, str]]:
    """(start, end, category, phrase) of every part phrase, longest match first, non-overlapping."""
    taken: list[tuple[int, int]] = []
    found = []
    for phrase, category in _PHRASES:
        for match in re.finditer(r"(?<![\w-])" + re.escape(phrase) + r"(?![\w-])", text):
            start, end = match.span()
            if any(start < e and end > s for s, e in taken):
                continue
            if exclude_verbs and start in exclude_verbs:
                continue
            taken.append((start, end))
            found.append((start, end, category, phrase))
    return sorted(found)


_ROW_WORDS = {"top": 1, "first": 1, "upper": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "middle": 0, "center": 0, "centre": 0,
              "bottom": -1, "last": -1, "lower": -1, "left": 1, "leftmost": 1, "right": -1, "rightmost": -1}
_LINE = re.compile(r"\b(top|bottom|middle|center|centre|first|second|third|fourth|fifth|last|upper|lower|left|right|leftmost|rightmost)[\s-]+(row|column)\b")


def _lines(text: str) -> tuple[int | None, int | None, str]:
    """Row and column qualifiers ("second row", "left column"), and the text without them."""
    row = column = None
    for match in _LINE.finditer(text):
        if match.group(2) == "row":
            row = _ROW_WORDS[match.group(1)]
        else:
            column = _ROW_WORDS[match.group(1)]
    return row, column, _LINE.sub(" ", text)


_LARGE = frozenset({"large", "larger", "largest", "big", "bigger", "biggest", "main", "wide", "wider", "widest", "spoked"})
_SMALL = frozenset({"small", "smaller", "smallest", "little", "tiny", "mini", "narrow", "narrower", "narrowest"})


def _size(window: str) -> str | None:
    """Size qualifier of a mention ("the large dial")."""
    words = set(re.findall(r"[a-z]+", window))
    if words & _LARGE:
        return "large"
    if words & _SMALL:
        return "small"
    return None


def _qualifiers(window: str) -> tuple[tuple[str, ...], int | None, bool]:
    words = re.findall(r"[a-z0-9]+", window)
    spatial = tuple(dict.fromkeys(SPATIAL[w] for w in words if w in SPATIAL))
    ordinal = next((ORDINALS[w] for w in words if w in ORDINALS), None)
    collective = any(w in COLLECTIVE for w in words)
    return spatial, ordinal, collective


def _verb(text: str) -> tuple[str | None, str | None, int, int]:
    """First verb of a clause: (lemma, kind, start, end); verbs used as nouns after 'the' are skipped."""
    previous = ""
    for match in re.finditer(r"[a-z]+", text):
        word = match.group(0)
        base = lemma(word)
        hyphenated = text[match.end() : match.end() + 1] == "-" or text[max(0, match.start() - 1) : match.start()] == "-"
        if base in VERBS and not hyphenated and previous not in ("the", "a", "an", "its", "of", "this", "that", "each", "every"):
            if base == "step" and not re.search(r"\bstep\s+on\b", text[match.start():]):
                previous = word
                continue
            kind = VERBS[base]
            if base in ("fold", "flip", "tilt", "lean") and re.match(r"\s*(?:[\w']+\s+){0,5}?(?:back|backwards|backward|open|out|up)\b", text[match.end():]):
                kind = "open"
            if base in ("spring", "snap", "pop", "bounce") and re.match(r"\s*back\b", text[match.end():]):
                kind = "release"
            return base, kind, match.start(), match.end()
        previous = word
    return None, None, -1, -1


def _particle(text: str, verb_end: int) -> str | None:
    after = text[verb_end:].split()
    for word in after[:6]:
        if word in PARTICLES and word not in ("on", "off", "over", "back"):
            return PARTICLES[word]
        if word in (",", "to", "by", "so", "and"):
            break
    for word in ("open", "shut", "closed", "out", "in", "up", "down"):
        if re.search(r"\b" + word + r"\b\s*(?:,|$|\bwith\b|\bby\b|\bfor\b|\bto\b|\d)", text[verb_end:]):
            return PARTICLES[word]
    return None


_INSTRUMENT_BEFORE = re.compile(
    r"\b(?:on|by|with|using|via|holding|gripping|from|out of|off(?: of)?|away from|clear of|below|above|under|beneath|over|beside|behind|near|next to|left of|right of|against)"
    r"\s+(?:its|their|the|his|her|both)?\s*(?:[a-z-]+\s+)?$"
)
_DESCRIPTIVE_AFTER = re.compile(r"^\s*(?:and all|included|attached|on top)\b")


def _object_mention(text: str, after: int, parts: list[tuple[int, int, str, str]]) -> Mention | None:
    """The whole object named in the clause (not as a modifier: "the safe door", "the bucket's handle")."""
    starts = {start for start, _, _, _ in parts}
    for match in re.finditer(r"[a-z]+", text[after:]):
        word = match.group(0)
        if word not in OBJECT_WORDS_SET:
            continue
        end = after + match.end()
        direct = re.match(r"(?:'s)?\s+", text[end:])
        if direct is not None:
            nxt = end + direct.end()
            modifier = re.match(r"[a-z-]+(?:'s)?\s+", text[nxt:])
            if nxt in starts or (modifier is not None and nxt + modifier.end() in starts):
                continue
        if re.match(r"(?:\s+[a-z-]+)?'s\s+(?!own\b)[a-z]", text[end:]):
            return None  # "the laptop's battery": the object owns a part we do not know, it is not the target
        return Mention(category="object", head=word, position=after + match.start())
    return None


_CONTROLS = frozenset({"button"})
"""Categories of parts whose name a part word may modify ("the door release button", "the lid button")."""

_MANNER = frozenset({"fully", "completely", "all", "halfway", "slightly", "gently", "slowly", "quickly", "partly", "partially", "way"})
"""Words after a verb that say how, never what ("rock the switch fully ...")."""


def parse_clause(text: str) -> Clause:
    """Verb, particle, mentions and quantity of one clause."""
    verb, kind, position, verb_end = _verb(text)
    verb_end = max(verb_end, 0)
    row, column, plain = _lines(text)
    found = _find_mentions(plain, exclude_verbs={position} if verb in ("switch", "dial", "step", "wheel", "lever") else None)
    # "the pedal bin", "the drawer unit": a part word naming the object it belongs to
    found = [f for f in found if not ((after := re.match(r"\s+([a-z]+)", plain[f[1]:])) and after.group(1) in OBJECT_WORDS_SET)]
    # "the combination dial": a code word naming the part after it is only its modifier
    found = [f for f in found if not (f[2] == "code" and any(re.fullmatch(r"\s+", plain[f[1]:g[0]]) for g in found))]
    # "the door release button": a part word directly before a control's name only says what the control is for
    found = [f for f in found if not any(g[2] in _CONTROLS and f[2] != g[2] and re.fullmatch(r"\s+", plain[f[1]:g[0]]) for g in found)]
    mentions: list[Mention] = []
    boundary = verb_end
    for start, end, category, phrase in found:
        window = plain[boundary:start] if start >= boundary else plain[max(0, start - 25):start]
        spatial, ordinal, collective = _qualifiers(window)
        trailing = re.match(r"\s+(?:on|at)\s+(?:the\s+)?(left|right|top|bottom|front|back|rear)\b(?:[\s-]+hand)?(?:\s+side)?", plain[end:])
        if trailing and SPATIAL[trailing.group(1)] not in spatial:
            spatial = (*spatial, SPATIAL[trailing.group(1)])  # "the door on the left"
        plural = collective or (phrase.endswith("s") and not phrase.endswith(("ss", "us")))
        earlier_target = bool(mentions) or any(w in OBJECT_WORDS_SET for w in re.findall(r"[a-z]+", plain[verb_end:start]))
        instrument = earlier_target and bool(_INSTRUMENT_BEFORE.search(plain[max(boundary, verb_end):start]) or _DESCRIPTIVE_AFTER.match(plain[end:]))
        size = _size(window)
        mention = Mention(category=category, head=phrase, spatial=spatial, ordinal=ordinal, plural=plural, position=start, instrument=instrument, row=row, column=column, size=size)
        if mentions and re.search(r"\b(?:of|on|in|at|from)\s+(?:the\s+)?$", plain[boundary:start]):
            previous = mentions.pop()
            mention = Mention(category=previous.category, head=previous.head, spatial=previous.spatial, ordinal=previous.ordinal, plural=previous.plural,
                              owner=mention, position=previous.position, instrument=previous.instrument, row=row, column=column)
        elif re.search(r"'s\s*$", plain[boundary:start]) and mentions:
            owner = mentions.pop()
            mention = Mention(category=category, head=phrase, spatial=spatial, ordinal=ordinal, plural=plural, owner=owner, position=start, row=row, column=column)
        mentions.append(mention)
        boundary = end
    whole = _object_mention(plain, verb_end, found)
    if whole is not None and (not mentions or whole.position < min(m.position for m in mentions)):
        mentions.insert(0, whole)
    unknown = None
    if not mentions and verb:
        rest = re.sub(r"^\s*(?:the|a|an|its|this|that)\s+", "", plain[verb_end:]).strip()
        rest = re.sub(r"^(?:[a-z-]+\s+)?[a-z]+'s\s+", "", rest)  # "the laptop's battery": the battery is what is named
        noun = re.match(r"([a-z][a-z\- ]{1,40}?)(?:\s+(?:to|by|and|with|for|so|until|all|fully|halfway|slightly)\b|[,.]|$)", rest)
        if noun and noun.group(1).strip() and noun.group(1).split()[0] not in PARTICLES and noun.group(1).split()[0] not in _MANNER:
            unknown = noun.group(1).strip()
    scope = re.split(r"\b(?:with|while|without)\b", plain[verb_end:], maxsplit=1)[0] if verb else ""
    particle = _particle(plain[:verb_end] + scope, verb_end) if verb else None
    return Clause(text=text.strip(), verb=verb, kind=kind, particle=particle, mentions=tuple(mentions), quantity=parse_quantity(text), unknown_object=unknown)


def _effect_clause(text: str) -> Clause | None:
    """An intransitive effect ("the door pops open") as a clause with the matching kind."""
    match = _INTRANSITIVE_RE.search(text)
    if match is None:
        return None
    found = _find_mentions(text[: match.start()])
    if not found:
        return None
    kind = _INTRANSITIVE[match.group(1)]
    clause = parse_clause(text[: match.start()].strip())
    return Clause(text=text.strip(), verb=kind, kind=kind, particle=None, mentions=clause.mentions, quantity=parse_quantity(text))


def _means_end(text: str) -> Action:
    """Split a clause into goal and means when the text says how the goal is reached."""
    use = re.match(r"^(?:use|using)\s+(.*?)\s+to\s+(.+)$", text)
    if use:
        return Action(clause=parse_clause(use.group(2)), means=parse_clause("operate " + use.group(1)))
    by = re.match(r"^(.*?)\s+by\s+([a-z]+ing\b.*)$", text)
    if by and _verb(by.group(1))[0]:
        return Action(clause=parse_clause(by.group(1)), means=parse_clause(by.group(2)))
    for connector in (r"in order to", r"so as to", r"to"):
        match = re.match(r"^(.*?)\s+" + connector + r"\s+([a-z]+)\b(.*)$", text)
        if match and _verb(match.group(1))[0] and lemma(match.group(2)) in VERBS:
            return Action(clause=parse_clause(match.group(2) + match.group(3)), means=parse_clause(match.group(1)))
    effect = re.match(r"^(.*?)\s*,?\s+(?:so that|so|which makes|which|and|until|causing|making)\s+(?:the\s+|its\s+)?(.+)$", text)
    if effect and _verb(effect.group(1))[0]:
        goal = _effect_clause(effect.group(2))
        if goal is not None and goal.kind == "close" and _verb(effect.group(1))[1] == "release":
            # "release it so the lid shuts": letting go is the action; what it held falls back on its own
            return Action(clause=parse_clause(effect.group(1)))
        if goal is not None:
            return Action(clause=goal, means=parse_clause(effect.group(1)))
    return Action(clause=parse_clause(text))


_STATE = r"(?:while|whilst|as long as)\s+((?:the|its|their)\s+[\w\s'-]+?)\s+(?:is|are|stays|remains)\s+(?:still\s+)?(?:fully\s+)?(open|opened|closed|shut)"


def _precondition(segment: str) -> list[str] | None:
    """ "B while the door is open" / "while the door is open, B": a state to reach first, not a
    parallel action ("open the door", then B); a state the object starts in adds nothing."""
    trailing = re.match(r"^(.+?),?\s+" + _STATE + r"\s*$", segment)  # "B while the door is open"
    leading = re.match(r"^" + _STATE + r"\s*,\s*(.+)$", segment)  # "while the door is open, B"
    if trailing is not None:
        action, subject, state = trailing.groups()
    elif leading is not None:
        subject, state, action = leading.groups()
    else:
        return None
    return [f"open {subject}", action] if state.startswith("open") else [action]


def _ordered(segment: str) -> list[str]:
    """Reorder "after A-ing, B" / "B after A-ing" / "before B, A" into execution order."""
    state = _precondition(segment)
    if state is not None:
        return state
    for pattern, order in (
        (r"^after\s+(.*?),\s*(.+)$", (1, 2)),
        (r"^once\s+(.*?),\s*(.+)$", (1, 2)),
        (r"^when\s+(.*?),\s*(.+)$", (1, 2)),
        (r"^before\s+(.*?),\s*(.+)$", (2, 1)),
        (r"^(.+?)\s+after\s+([a-z]+ing\b.*)$", (2, 1)),
        (r"^(.+?),?\s+before\s+([a-z]+ing\b.*)$", (1, 2)),
    ):
        match = re.match(pattern, segment)
        if match:
            return [match.group(i).strip() for i in order]
    return [segment]


def _split_and(segment: str) -> list[str]:
    """Split "A and B" / "A, B" when B starts with a verb of its own (a second action)."""
    parts = re.split(r"\s*,?\s*\band\b\s+(?=(?:also\s+)?[a-z]+)|\s*,\s+(?=[a-z]+)", segment)
    merged: list[str] = []
    for part in parts:
        first = part.split()[0] if part.split() else ""
        modifier = lemma(first) == "let" and re.match(r"let (?:it|them|the \w+) (?:roll|coast|glide|slide|return|spring back)", part)
        own_verb = lemma(first) in VERBS or (first in ("the", "its", "it") and _verb(part)[0] is not None)
        if merged and (not own_verb or modifier):
            merged[-1] = merged[-1] + " and " + part
        else:
            merged.append(part)
    return merged


_ONE = re.compile(r"\b(" + "|".join(sorted(set(SPATIAL) | set(ORDINALS), key=len, reverse=True)) + r")((?:[\s-]+hand)?\s+)ones?\b")


def _resolve_one(piece: str, actions: list[Action]) -> str:
    """ "open the right door, then the left one": "one" names the previous clause's part."""
    heads = [m.head for action in reversed(actions) for m in action.clause.mentions if m.category != "object"]
    if not heads or not _ONE.search(piece):
        return piece
    return _ONE.sub(lambda m: m.group(1) + m.group(2) + heads[0], piece)


_SUBJECTLESS = re.compile(r"(?:" + "|".join(sorted((re.escape(w) for w in _INTRANSITIVE if w.split()[0].endswith("s")), key=len, reverse=True)) + r")\b")
"""A clause starting with a third-person intransitive verb ("opens 45 degrees") and no subject of its own."""


def _measured(quantity: Quantity) -> bool:
    """A clause that is only an amount ("then 0.3 m back", "then 90 degrees more")."""
    return quantity.distance_m is not None or quantity.angle_rad is not None or quantity.fraction is not None


def parse_prompt(prompt: str) -> ParsedPrompt:
    """Structured reading of a whole prompt, actions in execution order."""
    text = normalize(prompt)
    actions: list[Action] = []
    for segment in (s for s in _SEQ_SPLIT.split(text) if s and s.strip(" ,")):
        segment = _FILLER.sub("", segment.strip(" ,"))
        steps = _ordered(segment)
        if len(steps) == 2 and not actions and re.match(r"^releasing\s+(?:the|its)\b", steps[0]) and steps[1] in segment[: segment.find(steps[0])]:
            # "open the door after releasing the latch": nothing was pressed before, so releasing the latch means working it
            steps[0] = re.sub(r"^releasing\b", "operating", steps[0])
        for ordered in steps:
            # "while the door is moving" describes an ongoing motion, not a new one
            split = [p for p in _PARALLEL.split(ordered) if p.strip(" ,")]
            parallel_parts = [p for p in split if len(split) == 1 or not _PROGRESSIVE.match(p.strip(" ,"))]
            if len(parallel_parts) == 1 and _PARALLEL.search(ordered) and actions:
                parallel_parts = ["", *parallel_parts]
            for index, part in enumerate(parallel_parts):
                if not part:
                    continue
                for piece_index, piece in enumerate(_split_and(_FILLER.sub("", part.strip(" ,")))):
                    if _NEGATED.match(piece.strip(" ,")):
                        continue  # "without using the pedal", "don't touch the door"
                    action = _means_end(_resolve_one(piece.strip(" ,"), actions))
                    parallel = index > 0 and piece_index == 0
                    clause = action.clause
                    parts = [m for m in clause.mentions if m.category != "object"]
                    if clause.kind is None and action.means is None and parts and actions:
                        # "open the left door, then the right door": the verb carries over
                        previous = actions[-1].clause
                        clause = replace(clause, verb=previous.verb, kind=previous.kind, particle=previous.particle)
                    elif clause.kind is None and action.means is None and not parts and actions and _measured(clause.quantity):
                        # "push the car 0.3 m forward and then 0.3 m back": the verb and its object carry over
                        previous = actions[-1].clause
                        clause = replace(clause, verb=previous.verb, kind=previous.kind, particle=None,
                                         mentions=clause.mentions or previous.mentions, unknown_object=None)
                    elif piece_index > 0 and action.means is None and not clause.mentions and _SUBJECTLESS.match(piece.strip(" ,")):
                        # "the door unlocks and opens 45 degrees": the second verb shares the subject
                        clause = replace(clause, mentions=(Mention(category="object", head="it", position=len(clause.text)),))
                    previous_action = actions[-1] if actions else None
                    if (previous_action is not None and piece_index > 0 and action.means is None and previous_action.means is not None
                            and previous_action.clause.kind == "release" and not _measured(previous_action.clause.quantity)
                            and _measured(clause.quantity) and [m.head for m in clause.mentions] == ["it"]
                            and any(m.category != "object" for m in previous_action.clause.mentions)):
                        # "press the button to release the door, and lower it 40 degrees": the amount is the released part's
                        actions[-1] = replace(previous_action, clause=replace(clause, mentions=previous_action.clause.mentions))
                        continue
                    actions.append(Action(clause=clause, means=action.means, parallel=parallel, conjoined=piece_index > 0))
    return ParsedPrompt(text=text, actions=tuple(actions), quantity=parse_quantity(text))
