"""The far end of a side: "the far-right drawer", "the far left knob" name the part furthest that way (written
"rightmost"); "swing it across to the far right" is a way to go, all the way ("all_the_way to the right")."""

from __future__ import annotations

from app.engine.offline.reading.token import Token


def far_side(out: list[Token], t: Token, before: str, after: str) -> bool:
    """Write the far side at ``t`` into ``out``; False when ``t`` is no far side."""
    if not (t.text in ("far-left", "far-right") or (t.text == "far" and after in ("left", "right") and before in ("the", "its"))):
        return False
    side = t.text.split("-")[-1] if "-" in t.text else after
    if len(out) > 1 and before == "the" and out[-2].text in ("to", "toward", "towards"):
        if not any(w.text in ("all_the_way", "way") for w in out[-8:]):
            out.insert(len(out) - 2, Token("all_the_way", "all_the_way", t.start, t.end))
        out.extend([Token(side, side, t.start, t.end)] if "-" in t.text else [])
        return True  # "far right": the "right" after it comes next
    out.append(Token(f"{side}most", f"{side}most", t.start, t.end))  # "the far-right drawer": the rightmost
    return True
