"""Stray words: an unknown bare word read as a noun beside a part that is named ("slide it home", "raise it clear
of the base", "full cold", "60 degrees total") is not a second, missing part. It is dropped with a note
instead of refusing the whole prompt; a phrase that looks like a part ("the spout", "a drip-tray grate",
"the second drawer") is still refused when the asset lacks it."""

from __future__ import annotations

from app.engine.errors import GroundingError
from app.engine.lexicon.words import DETERMINERS
from app.engine.offline.reading.mentions import Mention


def stray(mention: Mention, error: GroundingError, mentions: tuple[Mention, ...]) -> bool:
    """Whether ``mention`` (which did not ground, raising ``error``) is a stray word among ``mentions``."""
    if error.candidates or mention.kind is not None or mention.is_object or mention.pronoun or mention.anaphor:
        return False
    words = (mention.words or mention.head).split()
    bare = len(words) == 1 and words[0] not in DETERMINERS and not mention.possessive and mention.whose is None and mention.owner is None
    qualified = bool(mention.sides or mention.ordinal or mention.size or mention.relation or mention.modifiers)
    return bare and not qualified and mention.start > 0 and _describes(words[0]) and any(other is not mention for other in mentions)


def _describes(word: str) -> bool:
    """A noun or adjective, not a verb form or an adverb ("dim the lights", "starts brewing", "already")."""
    from lemminflect import getAllLemmas

    lemmas = getAllLemmas(word)
    return ("NOUN" in lemmas or "ADJ" in lemmas) and not word.endswith(("ing", "ly"))
