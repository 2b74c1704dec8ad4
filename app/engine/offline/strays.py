"""Stray words: an unknown bare word read as a noun beside a part that is named ("slide it home", "raise it clear
of the base", "full cold", "60 degrees total") is not a second, missing part. It is dropped with a note
instead of refusing the whole prompt; a phrase that looks like a part ("the spout", "a drip-tray grate",
"the second drawer") is still refused when the asset lacks it."""

from __future__ import annotations

from app.engine.errors import GroundingError
from app.engine.offline.reading.mentions import Mention


def stray(mention: Mention, error: GroundingError, mentions: tuple[Mention, ...]) -> bool:
    """Whether ``mention`` (which did not ground, raising ``error``) is a stray word among ``mentions``: no kind the
    lexicon knows, nothing qualifying it as a part, not the clause's first word (its verb), and another phrase of the
    clause names what moves. A single word must be a noun or an adjective ("home", "clear", "total")."""
    if error.candidates or mention.kind is not None or mention.is_object or mention.pronoun or mention.anaphor or mention.start == 0:
        return False
    words = (mention.words or mention.head).split()
    if len(words) == 1 and not _describes(words[0]):
        return False
    qualified = bool(mention.sides or mention.ordinal or mention.size or mention.relation)
    return not qualified and any(other is not mention and not other.is_object for other in mentions)


def _describes(word: str) -> bool:
    """A noun or adjective, not a verb form or an adverb ("dim the lights", "starts brewing", "already")."""
    from lemminflect import getAllLemmas

    lemmas = getAllLemmas(word)
    return ("NOUN" in lemmas or "ADJ" in lemmas) and not word.endswith(("ing", "ly"))
