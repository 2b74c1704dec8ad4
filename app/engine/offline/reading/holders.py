"""Things that are no part, put into or taken out of the object, or worked on inside it ("put a bowl of soup in the
microwave", "grab the jewellery box out of the safe", "load the dishes", "check on the roast in the bottom oven"): the
request is to open what holds them."""

from __future__ import annotations

from app.engine.lexicon.words import OBJECT_NOUNS, PERSON_NOUNS, PLACES, SPATIAL, Side
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

COMPARTMENTS = frozenset({"compartment", "cavity", "section", "oven", "chamber"})
SIDE_OF = frozenset({"upper", "lower", "top", "bottom", "left", "right", "left-hand", "right-hand", "front", "back", "rear"})
_PUTTING = frozenset({"put", "place", "pop", "stick", "set", "load", "insert", "slide", "shove", "stash", "store", "stow", "drop", "pack", "toss",
                      "pour", "dump", "chuck", "throw"})
_FETCHING = frozenset({"get", "take", "fetch", "grab", "remove", "pull", "bring", "lift", "retrieve"})
_INTO = frozenset({"in", "into", "inside"})
_OUT_OF = frozenset({"out_of", "from", "out", "off"})
_BROUGHT = frozenset({"a", "an", "some", "my", "our", "this", "these"})
"""Before what is put in or taken out: a thing of the user's, not a part of the object ("the tray" may be a part)."""


def names_kind(word: str) -> bool:
    """A word naming a kind of part, plurals too ("both racks")."""
    return kind_of_word(word) is not None or (word.endswith("s") and kind_of_word(word[:-1]) is not None)


_THING_MODIFIERS = frozenset({"dirty", "clean", "washed", "wet", "dry", "used", "my", "our", "your", "some", "of", "these", "those", "few"})
"""Before a part word, what makes it a thing brought along ("the dirty plates", "a stack of plates", "my plates")."""


def names_part(words: list[str], k: int) -> bool:
    """``words[k]`` names a kind of part, and is not said as a thing of the user's ("load the dirty plates")."""
    return names_kind(words[k]) and not (k > 0 and words[k - 1] in _THING_MODIFIERS)


_THINGS_OWNED = frozenset({"the", "my", "our", "that", "this", "his", "her"})


def inside_end(tokens: list[Token], i: int) -> int:
    """The index after "check on the roast in there" / "look at what's inside" at ``i`` (a thing that is no part, inside the
    object, and nothing else said in the sentence), else 0."""
    end = next((k for k in range(i, len(tokens)) if tokens[k].is_sentence_end), len(tokens))
    if (clause := next((k for k in range(i, end) if tokens[k].is_punct), end)) < end and any(t.lemma in ("close", "shut") for t in tokens[clause:end]):
        end = clause  # "peek at the roast in the oven, then close it up again": the look, then the shutting
    words = [t.text for t in tokens[i + 1:end]]
    inside = words[-1:] in (["inside"], ["in_there"]) or words[-2:] in (["in", "there"], ["in", "here"]) or (
        words[-3:-1] == ["in", "the"] and words[-1] in OBJECT_NOUNS) or (  # "peek at the roast in the oven"
        2 <= len(words) <= 4 and words[0] in ("on", "at") and words[1] in _THINGS_OWNED and words[-1] not in OBJECT_NOUNS) or (
        words in (["on", "it"], ["on", "them"]))  # "check on the roast"; "Pizza's in the top oven, I'd like to check on it"
    if not inside or any(names_kind(w) for w in words):
        return 0
    return end


def looked_into(tokens: list[Token], i: int) -> int:
    """At "peek"/"look" of "peek inside the microwave", "look in the cupboard at the bottom" (the object, or a part that
    holds things, and nothing else in the clause): the index after it, else 0."""
    end = next((k for k in range(i + 1, len(tokens)) if tokens[k].is_punct or tokens[k].text in ("and", "then", "and_then", "to", "for", "so")), len(tokens))
    words = [t.text for t in tokens[i + 2:end]]
    if not 2 <= len(words) <= 6 or words[0] not in ("the", "that", "this", "its"):
        return 0
    named = [w for w in words[1:] if w in OBJECT_NOUNS or names_kind(w)]
    return end if named and (named[0] in OBJECT_NOUNS or named[0] in COMPARTMENTS) else 0


_DOING = frozenset({"doing", "done", "cooked", "ready", "coming", "getting", "boiling", "cooking", "simmering", "baking", "burning", "set"})


def asked_after(tokens: list[Token], i: int) -> int:
    """At "see"/"check" of "see how the soup is doing", "check if the cake is done" (a thing that is no part, its state
    asked after, and nothing else in the sentence): the index after it, else 0."""
    end = next((k for k in range(i, len(tokens)) if tokens[k].is_sentence_end), len(tokens))
    words = [t.text for t in tokens[i + 2:end]]
    if not words or not _DOING & set(words) or any(names_kind(w) for w in words) or any(w in ("and", "then", "and_then") for w in words):
        return 0
    return end


def stowed(tokens: list[Token], i: int) -> int:
    """At a verb of putting in or taking out: the index after the preposition in "put a bowl of soup in | the microwave",
    "get it out of | the oven", "put my leftovers inside |" when what is moved is no part (a pronoun only when no part
    was named before), else 0. The holder follows that index; when none does, the object itself holds it."""
    verb = tokens[i].text
    into = _INTO if verb in _PUTTING else _OUT_OF if verb in _FETCHING else None
    if into is None or (i and tokens[i - 1].text in ("the", "a", "its")) or (i and tokens[i - 1].text in ("i", "we", "i've", "we've") and any(
            t.text == "already" for t in tokens[i:i + 12])):
        return 0  # "I put my leftover soup in the microwave already": done, told
    k = i + 1
    while k < len(tokens) and k < i + 8 and tokens[k].text not in into and not tokens[k].is_punct:
        k += 1
    thing = tokens[i + 1:k]
    if not thing and k == i + 1 and k + 1 < len(tokens) and tokens[k].text in _INTO and tokens[k + 1].text in ("this", "it"):
        return k + 2  # "the plates I need to load into this": open it
    if not thing and k == i + 1 and k + 2 < len(tokens) and tokens[k].text in _INTO and tokens[k + 1].text in ("the", "my", "that") and (
            tokens[k + 2].text in OBJECT_NOUNS):
        return k + 1  # "a stack of dirty plates to load into the dishwasher": open it
    brought = bool(thing) and thing[0].text in _BROUGHT  # "put a plate in": a thing brought to it, even when a part is called so
    held_in = {t.text for t in tokens[k + 1:k + 5]} & set(OBJECT_NOUNS) - PLACES  # "the jewellery box out of the safe": kept in it
    said = [t.text for t in thing]
    if not thing or k >= len(tokens) or tokens[k].text not in into or any(
            (names_part(said, n) and not brought) or (t.text in OBJECT_NOUNS and not held_in - {t.text}) for n, t in enumerate(thing)):
        return 0
    if all(t.text in ("it", "them", "everything") for t in thing) and any(kind_of_word(t.text) is not None for t in tokens[:i]):
        return 0  # "... the tray. Get it out of the oven": it is the tray
    there = k + 1 < len(tokens) and tokens[k + 1].text in ("there", "here")  # "put a bowl of soup in there": in the object
    if tokens[k].text in ("inside", "in") and verb != "drop" and (k + 1 == len(tokens) or tokens[k + 1].is_punct or tokens[k + 1].text in (
            "to", "for", "and", "so") or there):  # "drop the bread in": a toaster's lever, not a holder opened
        return k + 1 + there if not {t.text for t in thing} & {"it", "them", "back", "one", "all"} else 0  # "put my leftovers inside": open it; "slide it back in": no
    k += k + 1 < len(tokens) and tokens[k].text == "out" and tokens[k + 1].text in ("of", "from")
    if k + 1 >= len(tokens) or tokens[k + 1].is_punct:
        return 0  # "drop the bread in — lever down": no holder named
    holder = [t.text for t in tokens[k + 1:k + 7]]  # "off the very bottom rack", "in the left side of the fridge"
    holder = holder[:next((n for n, w in enumerate(holder) if w in ("until", "till", "so", "and", "then", "while", "to", "it's")), len(holder))]
    if holder and holder[0] not in ("the", "this", "that", "its", "my"):
        holder = ["the", *holder]  # "inside microwave"
    if len(holder) < 2 or not any((w in OBJECT_NOUNS and w not in PLACES and tokens[k].text != "off") or kind_of_word(w) is not None
                                  for w in holder[1:]):
        return 0  # "lift the box off the table": where it stands, no holder; "off the bottom rack": the part it sits on
    return k + 1


_ACCESSING = frozenset({"load", "unload", "empty", "clean", "wipe", "stock", "restock", "fill", "refill", "check", "baste", "stir", "season",
                        "taste", "glaze"})
"""What a person does inside an object ("load the dishes", "clean the inside of the oven"): its door or lid opened."""


def accessed(tokens: list[Token], i: int, out: list[Token]) -> tuple[int, list[Token]] | None:
    """At a verb of working inside the object, the whole request "load the dishes" / "wipe out the inside of the
    microwave" / "check on the roast in the bottom oven": (the index after it, what opens: the compartment named, or
    nothing for the object). None when the words name a part or say more."""
    if tokens[i].text not in _ACCESSING or (out and out[-1].text in ("the", "a", "its", "to_be")):
        return None
    end = next((k for k in range(i + 1, len(tokens)) if tokens[k].is_punct or tokens[k].text in ("so", "and", "then", "because")), len(tokens))
    words = [t.text for t in tokens[i + 1:end]]
    on = next((k for k in range(1, len(words) - 1) if words[k] in ("on", "in", "inside") and words[k + 1] == "the"), None)
    if on is not None and words[0] in _THINGS_OWNED and not any(names_part(words, k) for k in range(on)) and any(names_part(words, k) for k in range(on + 1, len(words))) and not any(
            t.number is not None for t in tokens[i + 1:end]):
        return end, list(tokens[i + 2 + on:end])  # "baste the chicken on the rack in the top oven": that rack
    if not words or any(names_part(words, k) for k in range(len(words))) or any(t.number is not None for t in tokens[i + 1:end]):
        return None  # "clean the lid", "fill it 3 cm": a part, or an amount
    place = next((k for k in range(len(words) - 2) if words[k] in ("in", "inside", "of") and words[k + 1] == "the" and words[k + 2] in SIDE_OF), None)
    if place is not None and words[-1] in COMPARTMENTS:
        return end, list(tokens[i + 1 + place + 1:end])  # "check on the roast in the bottom oven": that compartment
    inside = "inside" in words or "in_there" in words or words[-2:] == ["in", "there"]
    objects = [w for w in words if w in OBJECT_NOUNS]
    things = words[0] in ("the", "my", "some", "our", "this", "those", "these", "all") or words[0] in ("on", "out", "up")
    placed = next((k for k, w in enumerate(words) if w in OBJECT_NOUNS and k and (words[k - 1] in SPATIAL or words[k - 1].split("-")[0] in SPATIAL)), None)
    if placed is not None and words[0] == "the":  # "load the upper dishwasher": that one of the units
        return end, list(tokens[i + 1:i + 2 + placed])
    return (end, []) if (inside or objects or (things and tokens[i].text in ("load", "unload", "empty"))) else None


_HEATING = frozenset({"heat", "warm", "reheat", "defrost", "nuke", "zap", "microwave"})


def heated(tokens: list[Token], i: int) -> tuple[int, int] | None:
    """At a verb of heating in "heat up my leftovers in the microwave": (where the holder phrase starts, where it ends) when
    what is heated is no part and the holder is the object or a part; else None. The request is to put the thing in,
    then set the object going."""
    if tokens[i].text not in _HEATING or (i and tokens[i - 1].text in ("the", "a", "its", "to")):
        return None
    k = i + 1 + (i + 1 < len(tokens) and tokens[i + 1].text in ("up", "through"))
    start = k
    while k < len(tokens) and k < start + 6 and tokens[k].text not in _INTO and not tokens[k].is_punct:
        k += 1
    thing = [t.text for t in tokens[start:k]]
    if not thing or k + 2 >= len(tokens) or tokens[k].text not in _INTO or any(names_part(thing, n) for n in range(len(thing))):
        return None
    end = k + 1
    while end < len(tokens) and not tokens[end].is_punct and tokens[end].text not in ("for", "and", "then", "so", "to", "until"):
        end += 1
    holder = [t.text for t in tokens[k + 1:end]]
    if not any(w in OBJECT_NOUNS or names_kind(w) for w in holder):
        return None
    return k + 1, end


_GOING = frozenset({"go", "goes", "belong", "belongs", "fit", "fits"})


def going_in(tokens: list[Token], i: int, out: list[Token]) -> int | None:
    """At "go" of "the dirty plates need to go in the dishwasher" / "my laptop has to go in ...": where the request's
    words start in ``out`` when what goes in is no part and the holder after "in" is the object or a part; else None."""
    if tokens[i].text not in _GOING or i + 2 >= len(tokens) or tokens[i + 1].text not in ("in", "into", "inside"):
        return None
    holder = [t.text for t in tokens[i + 2:i + 6]]
    if not any((w in OBJECT_NOUNS and w not in PLACES) or names_kind(w) for w in holder):
        return None
    start = clause_start(out)
    said = [t.text for t in out[start:]]
    if not said or any(names_part(said, n) or w in OBJECT_NOUNS for n, w in enumerate(said)):
        return None  # "the tray needs to go in the oven", "the laptop has to go in my bag": a part or the object itself
    return start


_CARRIERS = frozenset({"bag", "backpack", "rucksack", "case", "sleeve", "briefcase", "car", "boot", "trunk", "locker"})
"""Where a person stows the whole object ("the laptop has to go in my bag"): it is folded shut for it."""


def packed(tokens: list[Token], i: int, out: list[Token]) -> tuple[int, str, int] | None:
    """At "go"/"put"/"pack" of "the laptop has to go in my bag" / "put the laptop in my backpack", when the object itself is
    stowed: (where the request starts in ``out``, the object's name, the index after the carrier); else None."""
    verb = tokens[i].text
    if verb in _GOING:
        k, start = i + 1, clause_start(out)
        named = [t.text for t in out[start:]]
    elif verb in ("put", "pack", "slip", "stow", "stick", "shove"):
        k = next((n for n in range(i + 1, min(len(tokens), i + 6)) if tokens[n].text in _INTO), len(tokens))
        start, named = -1, [t.text for t in tokens[i + 1:k]]
    else:
        return None
    name = next((w for w in named if w in OBJECT_NOUNS and w not in PLACES), None)
    if k >= len(tokens) or tokens[k].text not in _INTO or name is None:
        return None
    carrier = [t.text for t in tokens[k + 1:k + 3]]
    if carrier[:1] != [] and carrier[0] in ("my", "a", "the", "his", "her", "our", "your", "its") and carrier[1:2] and carrier[1] in _CARRIERS:
        return (len(out) if start < 0 else start), name, k + 3
    return None


def put_in_only(words: list[str], verb: str | None, unknown_things: bool) -> bool:
    """"drop the banana peel in", "toss the wrapper inside" after the bin was opened: a thing put in, no part named."""
    return verb in _PUTTING and unknown_things and bool(words) and words[-1] in ("in", "inside", "there", "in_there", "here")


_INSIDE_NOUNS = frozenset({"stir", "look", "peek", "peep", "glance", "gander", "check", "clean", "wipe", "taste", "baste", "sniff"})
_QUICK = frozenset({"quick", "good", "little", "small", "brief", "proper", "final", "last", "gentle"})


def looked_inside(tokens: list[Token], i: int) -> int | None:
    """At "give"/"take"/"have" of "give the soup a stir", "take a quick look (inside)", "have a peek in there": the index after
    the request (an act inside the object: what holds it is opened), when the words name no part; else None."""
    if tokens[i].text not in ("give", "take", "have", "grab", "sneak") or (i and tokens[i - 1].text in ("the", "a", "to_be")):
        return None
    k = next((n for n in range(i + 1, min(len(tokens), i + 7)) if tokens[n].text in ("a", "an")), None)
    if k is None or any(names_kind(t.text) or t.text in PERSON_NOUNS for t in tokens[i + 1:k]) or (k > i + 1 and tokens[i].text != "give"):
        return None  # "give the knob a turn": a part; "take the tray a ..." no; "give the kids a look": for them, not inside
    k += 1 + (k + 1 < len(tokens) and tokens[k + 1].text in _QUICK)
    if k >= len(tokens) or tokens[k].text not in _INSIDE_NOUNS:
        return None
    end = k + 1
    if end < len(tokens) and tokens[end].text in ("at", "on"):  # "take a look at the roast"
        end += 1
        while end < len(tokens) and not tokens[end].is_punct and tokens[end].text not in ("and", "then", "and_then", "so", "before", "to", "in", "inside"):
            if names_kind(tokens[end].text):
                return None  # "take a look at the knob": a part
            end += 1
    while end < len(tokens) and tokens[end].text in ("inside", "in_there", "in", "there", "here"):
        end += 1
    return end


_SIDE_NOUNS = frozenset({"side", "half", "part", "end", "bit"})


def side_of_object(words: list[str]) -> tuple[Side, bool] | None:
    """"the left side of the fridge", "the bottom half of the oven": the one side named before "side/half ... of"."""
    sides = [SPATIAL[w] for w, noun, of in zip(words, words[1:], words[2:], strict=False) if w in SPATIAL and noun in _SIDE_NOUNS and of == "of"]
    return sides[0] if len(sides) == 1 else None


def clause_start(out: list[Token]) -> int:
    """Where the clause being written into ``out`` starts: after its last punctuation or joining word."""
    start = len(out)
    while start > 0 and not out[start - 1].is_punct and out[start - 1].text not in ("and", "so", "then", "but"):
        start -= 1
    return start
