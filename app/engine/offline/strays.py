"""Stray words: an unknown bare word read as a noun beside a part that is named ("slide it home", "raise it clear
of the base", "full cold", "60 degrees total") is not a second, missing part. It is dropped with a note
instead of refusing the whole prompt; a phrase that looks like a part ("the spout", "a drip-tray grate",
"the second drawer") is still refused when the asset lacks it."""

from __future__ import annotations

from app.engine.errors import GroundingError
from app.engine.lexicon.kinds import PartKind
from app.engine.offline.reading.mentions import Mention


def stray(mention: Mention, error: GroundingError, mentions: tuple[Mention, ...], text: str = "") -> bool:
    """Whether ``mention`` (which did not ground, raising ``error``) is a stray word among ``mentions``: no kind the
    lexicon knows, nothing qualifying it as a part, not the clause's first word (its verb), and another phrase of the
    clause names what moves. A single word must be a noun or an adjective ("home", "clear", "total"). A landmark right after a
    part ("the lid on top of | the big round water tank") is a stray whatever its words: a portion of the body that does not move."""
    if error.candidates or mention.is_object or mention.pronoun or mention.anaphor or mention.start == 0:
        return False
    if _landmark(mention, mentions):
        return True
    if mention.kind is PartKind.BODY and _adjunct(mention, mentions, text):
        return True  # "lift the pitcher off its motor base": the body, where it sits, never a part that moves
    if mention.kind is not None:
        return False
    if _adjunct(mention, mentions, text):
        return True
    words = (mention.words or mention.head).split()
    if len(words) == 1 and not _describes(words[0]):
        return False
    qualified = bool(mention.sides or mention.ordinal or mention.size or mention.relation)
    return not qualified and any(other is not mention and not other.is_object for other in mentions)


_RELATIONS = frozenset({"of", "on", "on_top_of", "above", "over", "under", "below", "behind", "beside", "next_to", "near", "by", "atop"})


def _landmark(mention: Mention, mentions: tuple[Mention, ...]) -> bool:
    """``mention`` only places the part named just before it ("the lid on top of | the big round water tank"): a portion
    of the body that does not move, which the part's own words already pick."""
    before = [m for m in mentions if m is not mention and m.end <= mention.start and mention.start - m.end <= 3]
    return bool(before) and before[-1].kind is not None and not before[-1].is_object and (before[-1].words.split() or [""])[-1] in _RELATIONS


def _describes(word: str) -> bool:
    """A noun or adjective, not a verb form or an adverb ("dim the lights", "starts brewing", "already")."""
    from lemminflect import getAllLemmas

    lemmas = getAllLemmas(word)
    return ("NOUN" in lemmas or "ADJ" in lemmas) and not word.endswith(("ing", "ly"))


_JOINING = frozenset({"and", "or", "&", "plus", ",", "then", "also", "as_well_as"})


def _adjunct(mention: Mention, mentions: tuple[Mention, ...], text: str) -> bool:
    """A name we do not know said after what the clause moves, and not joined to it ("open the bin in a hands-free manner",
    "move the whole thing 25 cm in depth"): how or where, not a second part. "the door and the hatch" is joined: a part."""
    before = [m for m in mentions if m is not mention and m.end <= mention.start and not m.pronoun]
    if not before or not mention.words or mention.pronoun or mention.anaphor or mention.plural or mention.collective or (
            mention.sides or mention.ordinal is not None or mention.size or mention.relation is not None):
        return False  # "the third key down in the left-hand column": a place we could not read, not a word to drop
    said, last = f" {text} ", before[-1].words
    at, start = said.find(f" {last} "), said.find(f" {mention.words} ")
    if not last or at < 0 or start < at:
        return False
    between = said[at + len(last) + 1:start].replace(",", " , ").split()
    return bool(between) and not set(between) & _JOINING
