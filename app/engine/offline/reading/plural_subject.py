"""A verb after a plural subject that acts in a scene ("the android's fingers turn the dial", "his hands lift the lid") and
an inverted order after "only after that" ("only after that does it lift the little lid"): written in the form the verb
finder reads ("fingers turns", "lift the little lid"). Before this stage neither clause had a verb."""

from __future__ import annotations

from dataclasses import replace

from app.engine.lexicon.verbs import VERBS
from app.engine.lexicon.words import AGENT_NOUNS
from app.engine.offline.reading.token import Token

_SUBJECTS = frozenset({"it", "they", "he", "she", "we", "i", "you"})


def plural_subject(tokens: list[Token]) -> list[Token]:
    out: list[Token] = []
    dropped = -1
    for k, t in enumerate(tokens):
        before = tokens[k - 1].text if k else ""
        after = tokens[k + 1] if k + 1 < len(tokens) else None
        if t.text in ("does", "did") and after is not None and after.text in _SUBJECTS and k + 2 < len(tokens) and tokens[k + 2].text in VERBS:
            dropped = k + 1
            continue  # "only after that does it lift the lid": lift the lid (who lifts it is the scene's)
        if k == dropped:
            continue
        if before in AGENT_NOUNS and before.endswith("s") and t.text in VERBS and t.text == t.lemma and not t.text.endswith("s"):
            t = replace(t, text=f"{t.text}s")  # "the fingers turn the dial": the verb, as the finder knows it
        out.append(t)
    return out
