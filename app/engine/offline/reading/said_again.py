"""A clause that ends on "the same": the step before, done again to what it names ("give the other one the same")."""

from __future__ import annotations

from app.engine.offline.reading.token import Token


def ends_the_same(tokens: list[Token]) -> bool:
    """"give the other one the same (again)": the clause ends on "the same" (not "the same door")."""
    said = [t.text for t in tokens if t.text not in (".", "!", "again", "too", "as_well", "please")]
    return said[-2:] == ["the", "same"]
