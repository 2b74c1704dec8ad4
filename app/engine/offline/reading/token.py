"""The token: one word, number or punctuation mark of the prompt, with its span in the original text."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Token:
    """One word, number or punctuation mark of the prompt."""

    text: str
    """Normalised form (lower case, spelling corrected, multi-word expressions joined with ``_``)."""
    lemma: str
    """Verb lemma for verb forms ("pressed" -> "press"), singular for plural nouns, else ``text``."""
    start: int
    end: int
    """Span in the original prompt."""
    number: float | None = None
    plural: bool = False
    corrected_from: str | None = None
    """The word as typed, when spelling correction changed it."""
    ident: bool = False
    """A name as written in the URDF ("joint_1", "link_0"): never corrected, read as a part name."""

    @property
    def is_punct(self) -> bool:
        return self.text in ".,;:!?"

    @property
    def is_sentence_end(self) -> bool:
        return self.text in ".;!?"
