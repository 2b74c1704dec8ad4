"""Stage 1 — normalise: prompt text -> :class:`Token` list.

Lower case, numbers split from their units ("10cm"), spelled-out numbers to digits
("forty-five", "one and a half"), spelling corrected against the domain lexicon and the
asset's own part names (:mod:`.spelling`), multi-word expressions joined into one token
("at the same time" -> ``at_the_same_time``), and verb / noun lemmas from ``lemminflect``.
Every token keeps its span in the original prompt, so later stages can quote the user.
This is the only stage that reads the raw text.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import replace

from app.engine.lexicon.said_otherwise import SAME_MEANING, WHILE_PHRASES
from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import (
    AMOUNTS,
    DEFINITES,
    DENOMINATORS,
    MULTIWORD,
    NUMBER_WORDS,
    OBJECT_NOUNS,
    SIZES,
)
from app.engine.offline.reading.counted_from import counted_from
from app.engine.offline.reading.counts import counted_unit, tidy_counts
from app.engine.offline.reading.everyday import everyday_words
from app.engine.offline.reading.framing import drop_framing
from app.engine.offline.reading.free_choice import free_choice
from app.engine.offline.reading.needs_doing import needs_doing
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.rewrites import corrections, drop_asides, expand, facing, same_words
from app.engine.offline.reading.token import Token
from app.engine.offline.reading.word_class import lemma_of
from app.engine.offline.reading.word_forms import known_forms

__all__ = ["Token", "tokenize"]

_TOKEN = re.compile(
    r"(?P<ord>\d+(?:st|nd|rd|th))(?![a-z])"
    r"|(?P<axis>[+-][xyz])(?![a-z])"
    r"|(?P<pi>(?<![\w.])-?(?:\d+(?:\.\d+)?\s*\*?\s*)?(?:pi|π)(?:\s*/\s*\d+(?:\.\d+)?)?)(?![a-z])"
    r"|(?P<arrow>->|=>|→)"
    r"|(?P<ident>[a-z]+(?:_[a-z0-9]+)*_\d+)(?![a-z0-9_])"
    r"|(?P<num>(?<![\w.])-?(?:\d+(?:\.\d+)?(?:/\d+)?|\.\d+))"
    r"|(?P<rate>rad/s|m/s|cm/s|deg/s|rad/sec)"
    r"|(?P<word>[a-z]+(?:['’][a-z]+)?(?:-[a-z]+)*)"
    r"|(?P<deg>°)"
    r"|(?P<inch>(?<=\d)[\"”″]|(?<=\d )[\"”″])"
    r"|(?P<pct>%)"
    r"|(?P<punct>[.,;:!?])"
    r"|(?P<dash>[—–]|(?<=\s)--?(?=\s))"
    r"|(?P<slash>(?<=\s)/(?=\s))"
    r"|(?P<paren>[()])"
)
_ARROW_STEP_WORDS = frozenset({"up", "down", "open", "shut", "closed", "out", "back", "off", "first"})
"""Words that make a verbless segment before "->" a step ("lid up to 90 deg -> ..."), not a heading."""
_LETTERS = frozenset("abcdefgh")
"""Letters that number steps: "a) close the lid b) ..."."""
_ABBREVIATIONS = re.compile(r"\b(?:i\.e|e\.g)\.?(?![a-z])")
""""e.g.": same length, read as a comma; "i.e.": "ie", a restatement dropped by :mod:`.framing` (offsets stay put)."""
_QUOTED_CRY = re.compile(r"(?<![a-z])['\"“‘]([^'\"“”‘’]{1,40}?)[?!]+(['\"”’])")
"""A question or cry quoted as a name ("the classic 'anyone in here?' move"): its mark ends no sentence (same length)."""
_SHORT_ABOUT = re.compile(r"\b(approx|appr|ca)\.(?=\s+[a-z0-9])")
""""open approx. half": the point of an abbreviation of "about" ends no sentence (same length)."""
_BULLET = re.compile(r"(?m)^([ \t]*)[-*•](?=[ \t])")
"""A list item's bullet at the start of a line ("- top drawer out 40 cm"): the end of the item before (same length)."""
_QUOTED_NUMBER = re.compile(r"[\"“”](\d+(?:\.\d+)?)[\"“”]")
_UNITS_AFTER_DIGITS = re.compile(r"(\d)(?!(?:st|nd|rd|th)(?![a-z]))([a-z°%])")




_SAID_IN_PARENS = re.compile(r"^(\s*)\(([^()]*)\)|\((\s*(?:anti-?clockwise|counter-?clockwise|clockwise|ccw|cw|left|right|up|down)\s*)\)")
"""Parentheses whose words are kept: a heading in parentheses that opens the prompt ("(big knob, the one on the left)
-> ..."), a bare sense or side ("half a turn (anticlockwise)"). Other parentheses are asides and dropped."""


_VAGUE_THEN_SAID = re.compile(r"\b(?:a few|a couple(?: of)?|several|some|a bit|a little|a tad|a touch)\s+(?:[a-z]+\s*)?\((\s*(?:about |around |roughly |like |~)?\d[^()]*)\)")
"""A loose amount with the number said in parentheses after it ("lift it a few inches (10 cm or so)"): the number."""


def _unbracket(text: str) -> str:
    """``text`` with the parentheses of :data:`_SAID_IN_PARENS` turned into commas, and a loose amount followed by its number
    in parentheses turned into that number (same length: offsets stay put)."""
    text = _VAGUE_THEN_SAID.sub(lambda m: " " * (m.start(1) - m.start(0)) + m.group(1) + " ", text)
    return _SAID_IN_PARENS.sub(lambda m: m.group(0).replace("(", " ").replace(")", ","), text)


def _raw_tokens(prompt: str) -> list[Token]:
    lowered = _ABBREVIATIONS.sub(lambda m: ("ie" if m.group(0).startswith("i") else ",").ljust(len(m.group(0))), prompt.lower().replace("’", "'").replace("‘", "'"))
    lowered = _SHORT_ABOUT.sub(lambda m: m.group(1) + " ", _unbracket(lowered))
    lowered = _QUOTED_CRY.sub(lambda m: " " + m.group(1) + " " * (len(m.group(0)) - len(m.group(1)) - 1), lowered)
    lowered = _BULLET.sub(lambda m: m.group(1) + ".", lowered)
    lowered = _QUOTED_NUMBER.sub(lambda m: f" {m.group(1)} ", lowered)  # 'set it to "3"': a number, not 3 inches
    text = _UNITS_AFTER_DIGITS.sub(r"\1 \2", lowered)
    # the substitution above only inserts spaces: map offsets back to the original prompt
    offsets = _offset_map(lowered, text)
    tokens: list[Token] = []
    depth = 0
    for match in _TOKEN.finditer(text):
        kind = match.lastgroup
        word = match.group(0)
        start, end = offsets[match.start()], offsets[max(match.end() - 1, match.start())] + 1
        numbered = tokens and tokens[-1].number is not None and float(tokens[-1].number).is_integer() and 0 < tokens[-1].number < 30
        if kind == "paren" and word == ")" and not depth and tokens and (tokens[-1].number is not None or tokens[-1].text in _LETTERS) and (
                len(tokens) == 1 or tokens[-2].is_sentence_end or tokens[-2].text in (",", ":") or numbered):
            later = len(tokens) > 1 and tokens[-1].number is not None and tokens[-1].number > 1  # "2) turntable 90 deg 3) door closed": a step of its own
            tokens[-1:] = [Token(".", ".", tokens[-1].start, end), *([Token("then", "then", end, end)] if later else [])]  # "1) lower the lid 2) ..."
            continue
        if kind == "paren":
            depth = max(0, depth + (1 if word == "(" else -1))
            continue
        if kind == "arrow":  # "drawer: half open -> pause -> closed": then; "door -> open it": a heading
            segment = list(itertools.takewhile(lambda t: not (t.is_sentence_end or t.text in (":", "then")), reversed(tokens)))
            compound = len(segment) >= 2 and (kind_of_word(segment[-1].text) is not None or segment[-1].text in OBJECT_NOUNS) and (
                kind_of_word(segment[-2].text) is not None)  # "tap handle ->": a part's name, not "tap" the verb
            verbless = bool(segment) and not any(t.text in VERBS and not (compound and t is segment[-1]) and (
                t is segment[-1] or kind_of_word(t.text) is None) for t in segment) and not any(
                t.number is not None or t.text in _ARROW_STEP_WORDS for t in segment)  # "combination dial ->", not "lid up to 90 deg ->"
            tokens.append(Token(":" if verbless else "then", ":" if verbless else "then", start, end))
            continue
        if depth:
            continue  # "(standard phone layout)": an aside, not part of the request
        if kind == "dash":  # "open both doors — the left to 120 degrees, ...": a pause, like a comma
            spelled = any(t.text in _SPELLED_OUT for t in tokens[-6:]) and not any(t.text in (":", ",", ".") for t in tokens)
            tokens.append(Token(":" if spelled else ",", ":" if spelled else ",", start, end))  # "enter a code on the keypad - 7 first, ...": the keys follow
        elif kind == "slash":  # "drawer out 40cm / hold 3s / back in": one step after another
            tokens.append(Token(";", "/", start, end))  # its lemma keeps the slash (verse_lines may read it as a comma)
        elif kind == "ident":
            tokens.append(Token(word, word, start, end, ident=True))
        elif kind == "pi":  # "pi/2", "3*pi/4", "-pi/4": radians
            value = _pi_value(word)
            tokens.append(Token(f"{value:g}", f"{value:g}", start, end, number=value))
            if not re.match(r"\s*rad", text[match.end():]):
                tokens.append(Token("rad", "rad", start, end))
        elif kind == "num":
            if "/" in word:
                top, bottom = word.split("/")
                value = float(top) / float(bottom) if float(bottom) else float(top)
            else:
                value = float(word)
            tokens.append(Token(word, word, start, end, number=value))
        elif kind == "deg":
            tokens.append(Token("degree", "degree", start, end))
        elif kind == "inch":  # 4" (a double prime after a number)
            tokens.append(Token("inch", "inch", start, end))
        elif kind == "pct":
            tokens.append(Token("percent", "percent", start, end))
        elif kind == "axis":
            tokens.append(Token(word, word, start, end))
        elif word.endswith("'s") and word[:-2] not in _NOT_POSSESSIVE:
            # "the stapler's magazine": the owner, then a possessive marker
            tokens.append(Token(word[:-2], word[:-2], start, end - 2))
            tokens.append(Token("'s", "'s", end - 2, end))
        else:
            tokens.append(Token(word, word, start, end))
    return tokens


def _pi_value(text: str) -> float:
    sign = -1.0 if text.startswith("-") else 1.0
    head, _, tail = text.lstrip("-").replace("π", "pi").partition("pi")
    factor = float(head.replace("*", "").strip() or 1.0)
    divisor = float(tail.replace("/", "").strip() or 1.0)
    return sign * factor * 3.141592653589793 / divisor


_NOT_POSSESSIVE = frozenset({"it", "let", "that", "what", "there", "here", "he", "she", "who", "where", "how"})


def _offset_map(original: str, spaced: str) -> list[int]:
    """Index in ``spaced`` -> index in ``original`` (``spaced`` only has extra spaces)."""
    out, i = [], 0
    for char in spaced:
        if i < len(original) and original[i] == char:
            out.append(i)
            i += 1
        else:
            out.append(max(i - 1, 0))
    out.append(len(original))
    return out


_UNITS = {"zero": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9, "ten": 10,
          "eleven": 11, "twelve": 12, "thirteen": 13, "fourteen": 14, "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18,
          "nineteen": 19}
_TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90}
_JOINED_TAIL = {"a_quarter": 0.25, "a_third": 1 / 3, "three_quarters": 0.75, "one_quarter": 0.25, "one_third": 1 / 3, "two_thirds": 2 / 3}
_FRACTION_TAIL = {("a", "half"): 0.5, ("a", "quarter"): 0.25, ("three", "quarters"): 0.75, ("a", "third"): 1 / 3}


def _number_word(word: str) -> float | None:
    if word in _UNITS:
        return float(_UNITS[word])
    if word in _TENS:
        return float(_TENS[word])
    if "-" in word and word.partition("-")[2] in DENOMINATORS:
        count = _number_word(word.partition("-")[0]) if word.partition("-")[0] not in ("a", "an", "one") else 1.0
        return None if count is None else count / DENOMINATORS[word.partition("-")[2]]  # "three-eighths"
    if "-" in word:
        tens, _, unit = word.partition("-")
        if tens in _TENS and unit in _UNITS and _UNITS[unit] < 10:
            return float(_TENS[tens] + _UNITS[unit])
    return float(NUMBER_WORDS[word]) if word in NUMBER_WORDS and " " not in word else None


_COUNTED = frozenset({"and", "hundred", "full", "complete", "whole", "more", "quarter", "third", "half", "fifth", "second", "seconds",
                      "sec", "s", "minute", "degree", "degrees", "deg", "turn", "turns", "revolution", "revolutions", "rotation",
                      "rotations", "cm", "mm", "m", "meter", "meters", "metre", "metres", "inch", "inches", "foot", "feet", "ft", "radian",
                      "radians", "rad", "centimeter", "centimeters", "centimetre", "centimetres", "millimeter", "millimeters", "time",
                      "times", "twist", "spin", "notch", "notches", "click", "clicks", "step", "steps", "°", "percent", "%", "-"})


_QUALIFIERS = frozenset({"the", "this", "that", "other", "another", "left", "right", "top", "bottom", "front", "back", "upper", "lower",
                         "middle", "first", "second", "third", "last", "same", "rear", "inner", "outer", *SIZES})


_TURN_WORDS = frozenset({"turn", "turns", "revolution", "revolutions", "rotation", "rotations"})


def _turns_after(tokens: list[Token], i: int) -> bool:
    """"right one full turn": "one" counts the turn after it, though a side word comes before it."""
    j = i + (i < len(tokens) and tokens[i].text in ("full", "complete", "whole"))
    return j < len(tokens) and tokens[j].text in _TURN_WORDS


def _counts(tokens: list[Token], i: int) -> bool:
    """A number word followed by what it counts ("one full turn", "one and a half", "one second")."""
    return i < len(tokens) and (tokens[i].text in _COUNTED or tokens[i].number is not None)


def _join_numbers(tokens: list[Token]) -> list[Token]:
    """Spelled-out numbers to one numeric token: "a hundred and twenty", "forty five", "one and a half", "a full radian"
    (:mod:`.counts`)."""
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        counted = counted_unit(tokens, i)
        if counted is not None:  # "a couple of inches", "an inch and a half": the count, then its unit
            out += counted[0]
            i += counted[1]
            continue
        value = _number_word(tokens[i].text) if tokens[i].number is None and tokens[i].text not in AMOUNTS else None  # "three-quarters": an amount
        after_qualifier = i > 0 and tokens[i - 1].text in _QUALIFIERS
        if tokens[i].text == "one" and (not _counts(tokens, i + 1) or (after_qualifier and not _turns_after(tokens, i + 1))):
            value = None  # "the left one", "one of the doors", "the bottom one half a turn": a pronoun, not a number
        hundreds = tokens[i].text == "hundred" and out and out[-1].text in ("a", "one")
        if hundreds:
            start = out.pop().start
            value, j = 100.0, i + 1
        elif value is not None:
            start, j = tokens[i].start, i + 1
        else:
            out.append(tokens[i])
            i += 1
            continue
        if j < len(tokens) and tokens[j].text == "hundred":
            value, j = value * 100.0, j + 1
        if value >= 100 and j + 1 < len(tokens) and tokens[j].text == "and" and _number_word(tokens[j + 1].text) is not None:
            value, j = value + float(_number_word(tokens[j + 1].text) or 0.0), j + 2
        if value % 10 == 0 and 20 <= value % 100 <= 90 and j < len(tokens):
            unit = _UNITS.get(tokens[j].text)
            if unit is not None and 0 < unit < 10:
                value, j = value + unit, j + 1
        if j + 2 < len(tokens) and tokens[j].text == "and" and (tokens[j + 1].text, tokens[j + 2].text) in _FRACTION_TAIL:
            value, j = value + _FRACTION_TAIL[(tokens[j + 1].text, tokens[j + 2].text)], j + 3
        elif j + 1 < len(tokens) and tokens[j].text == "and" and tokens[j + 1].text in _JOINED_TAIL:
            value, j = value + _JOINED_TAIL[tokens[j + 1].text], j + 2  # "one and a quarter" ("a quarter" is one token)
        text = f"{value:g}"
        out.append(Token(text, text, start, tokens[j - 1].end, number=value))
        i = j
    return tidy_counts(out)


_SPELLED_OUT = frozenset({"code", "combination", "sequence", "pin", "passcode", "keys", "buttons", "digits", "numbers"})
"""Before a first dash: what the steps after it spell out ("enter the code - 7, then 3 - and open the door")."""
_PHRASES = sorted((tuple(p.split()) for p in MULTIWORD), key=len, reverse=True)
_CLAUSE_OPENERS = frozenset({"the", "a", "its", "it", "it's", "they", "their"})  # a part's motion; not "the whole time I'm waggling ..."


def _join_phrases(tokens: list[Token]) -> list[Token]:
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        for phrase in _PHRASES:
            n = len(phrase)
            if tuple(t.text for t in tokens[i:i + n]) == phrase:
                joined = SAME_MEANING.get("_".join(phrase), "_".join(phrase))  # "apart from": except
                said = [t.corrected_from or t.text for t in tokens[i:i + n]]  # "all teh way", not just "teh"
                typed = " ".join(w for k, w in enumerate(said) if k == 0 or not (w == said[k - 1] and tokens[i + k].corrected_from))  # "it'll"
                out.append(Token(joined, joined, tokens[i].start, tokens[i + n - 1].end,
                                 corrected_from=typed if any(t.corrected_from for t in tokens[i:i + n]) else None))
                i += n
                break
        else:
            out.append(tokens[i])
            i += 1
    return [replace(t, text="while", lemma="while") if t.text in WHILE_PHRASES and k + 1 < len(out) and out[k + 1].text in _CLAUSE_OPENERS else t
            for k, t in enumerate(out)]  # "... open the whole time the plate is going round": while it goes round




def _halved(tokens: list[Token], known: frozenset[str]) -> list[Token]:
    """"half-open the drawer", "half-oepn it": the verb, then "halfway" (the verb spelt as the other words are); "a
    quarter-turn": two words."""
    from app.engine.offline.reading.spelling import correct

    out: list[Token] = []
    for token in tokens:
        head, dash, verb = token.text.partition("-")
        if dash and head in ("quarter", "half", "full", "third", "eighth") and verb in ("turn", "turns", "revolution", "rotation"):
            out += [Token(head, head, token.start, token.end), Token(verb, verb, token.start, token.end)]  # "a quarter-turn"
            continue
        spelt = correct(replace(token, text=verb, lemma=verb), known) if head == "half" and dash and verb.isalpha() else None
        if spelt is None or spelt.text not in VERBS:
            out.append(token)
            continue
        out += [replace(spelt, corrected_from=token.text if spelt.corrected_from else None), Token("halfway", "halfway", token.start, token.end)]
    return out


def _compounds(tokens: list[Token], known: frozenset[str]) -> list[Token]:
    """"the toiletlid", "pushdown": two words run together (a domain word and a part, a verb and its particle): split."""
    from app.engine.lexicon.verbs import PARTICLES
    from app.engine.offline.reading.part_words import kind_of_word
    from app.engine.offline.reading.spelling import _is_english, domain_words

    out: list[Token] = []
    for n, t in enumerate(tokens):
        word = t.text
        commanded = n + 1 < len(tokens) and tokens[n + 1].text in ("the", "it", "my", "that", "this", "both", "all")  # "pullout the drawer": a verb
        split = next((k for k in range(3, len(word) - 1) if ((word[:k] in domain_words() or word[:k] in known) and kind_of_word(word[k:]) is not None) or (
            word[:k] in VERBS and word[k:] in PARTICLES)), None) if (  # "toiletlid", "pushdown"
            len(word) >= 7 and word.isalpha() and word not in known and word not in domain_words() and (not _is_english(word) or commanded)
            and not word.startswith("keyfram")) else None
        out += [Token(word[:split], word[:split], t.start, t.end, corrected_from=word), Token(word[split:], word[split:], t.start, t.end, corrected_from=word)] if split else [t]
    return out


def tokenize(prompt: str, known: frozenset[str] = frozenset()) -> list[Token]:
    """Normalised tokens of ``prompt``; ``known`` adds words (the asset's part names) that are never
    corrected and that misspellings may be corrected to."""
    from app.engine.offline.reading.casual_pieces import casual_pieces
    from app.engine.offline.reading.count_lines import count_lines
    from app.engine.offline.reading.do_that_after import do_that_after
    from app.engine.offline.reading.flanked import flanked, of_that_group
    from app.engine.offline.reading.from_state import from_state, where_in_state
    from app.engine.offline.reading.fronted import fronted
    from app.engine.offline.reading.hand_side import hand_side
    from app.engine.offline.reading.inverted import inverted
    from app.engine.offline.reading.kept_steady import kept_steady
    from app.engine.offline.reading.learner import learner
    from app.engine.offline.reading.left_out import left_out
    from app.engine.offline.reading.left_short import left_short
    from app.engine.offline.reading.not_that_one import not_that_one
    from app.engine.offline.reading.object_her import object_her
    from app.engine.offline.reading.object_wants import object_wants
    from app.engine.offline.reading.padded_units import padded_units
    from app.engine.offline.reading.paused_after import paused_after
    from app.engine.offline.reading.plural_subject import plural_subject
    from app.engine.offline.reading.row_apposed import row_apposed
    from app.engine.offline.reading.said_aside import said_aside
    from app.engine.offline.reading.similes import similes
    from app.engine.offline.reading.spelling import correct, correct_noun
    from app.engine.offline.reading.start_place import start_place
    from app.engine.offline.reading.start_with import start_with
    from app.engine.offline.reading.starts_as import starts_as
    from app.engine.offline.reading.step_labels import step_labels
    from app.engine.offline.reading.telegraphic_not import telegraphic_not
    from app.engine.offline.reading.told_order import told_order
    from app.engine.offline.reading.told_relatives import told_relatives
    from app.engine.offline.reading.told_states import told_states
    from app.engine.offline.reading.too_far import too_far
    from app.engine.offline.reading.verse_lines import verse_lines
    from app.engine.offline.reading.waits_out import waits_out
    from app.engine.offline.reading.which_of import which_of
    from app.engine.offline.reading.whose_side import row_first, whose_side

    tokens = [correct(t, known) if t.number is None and t.text.isalpha() else t for t in _compounds(_halved(expand(_raw_tokens(prompt), known), known), known)]
    tokens = [correct_noun(t, known) if k and tokens[k - 1].text in DEFINITES and t.text.isalpha() else t
              for k, t in enumerate(tokens)]  # "the dore": a part is expected
    for rewrite in (which_of, same_words, everyday_words, _join_phrases, _join_numbers, object_her, inverted, said_aside, row_apposed, verse_lines, padded_units, casual_pieces, starts_as, told_relatives, count_lines, do_that_after, paused_after, where_in_state, left_short, from_state, object_wants, start_with, plural_subject, flanked, of_that_group, hand_side, step_labels, start_place, counted_from, free_choice, needs_doing, waits_out, told_states, known_forms, drop_framing, corrections, drop_asides, similes, not_that_one, telegraphic_not, kept_steady,
                    facing, too_far, told_order, fronted, whose_side, row_first):  # each stage reads what the one before wrote
        tokens = rewrite(tokens)
    out = []
    for token in tokens:
        if token.number is None and "_" not in token.text and token.text.replace("-", "").isalpha():
            lemma, plural = lemma_of(token.text)
            token = replace(token, lemma=lemma, plural=plural)
        out.append(token)
    return left_out(learner(out))
