"""One token scan shared by the rewrite stages that put a span of words another way: find where a span ends at each
index, and write what it reads as in its place."""

from __future__ import annotations

from collections.abc import Callable

from app.engine.offline.reading.token import Token


def replace_spans(tokens: list[Token], end_at: Callable[[list[Token], int], int | None],
                  written: Callable[[list[Token], int, int], list[Token]]) -> list[Token]:
    """``tokens`` with each span ``[k, end_at(tokens, k))`` replaced by ``written(tokens, k, end)``; scanning goes on
    after the span."""
    out: list[Token] = []
    k = 0
    while k < len(tokens):
        end = end_at(tokens, k)
        if end is None:
            out.append(tokens[k])
            k += 1
            continue
        out.extend(written(tokens, k, end))
        k = end
    return out


def drop_spans(tokens: list[Token], end_at: Callable[[list[Token], int], int | None]) -> list[Token]:
    """``tokens`` without each span ``[k, end_at(tokens, k))``."""
    return replace_spans(tokens, end_at, lambda _tokens, _start, _end: [])
