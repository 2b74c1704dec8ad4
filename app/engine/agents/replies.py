"""Read a role's JSON object out of a real model's reply.

Real replies wrap the object: a Markdown fence, a sentence before or after it, a
``<think>`` block first, comments or trailing commas inside. The first complete JSON
object in the text (after dropping reasoning blocks) is taken: each ``{`` in turn is read
with the standard JSON decoder, else with the ``json5`` parser (comments, trailing commas,
single quotes), so an outer object with a comment wins over the clean objects inside it. A reply cut short has no complete object and is refused, never
completed by guessing. The object is then validated against the role's schema.
"""

from __future__ import annotations

import json
from typing import Any, TypeVar

import json5
from pydantic import BaseModel

M = TypeVar("M", bound=BaseModel)
THINK_TAGS = (("<think>", "</think>"), ("<thinking>", "</thinking>"), ("<reasoning>", "</reasoning>"))
_DECODER = json.JSONDecoder()


class NoJsonObject(ValueError):
    """The reply holds no complete JSON object."""


def drop_reasoning(text: str) -> str:
    """``text`` without ``<think>...</think>`` (and similar) blocks; an unclosed block runs to the end."""
    for opening, closing in THINK_TAGS:
        while True:
            start = text.find(opening)
            if start < 0:
                break
            end = text.find(closing, start + len(opening))
            text = text[:start] + ("" if end < 0 else text[end + len(closing) :])
    return text


def _candidates(text: str) -> list[int]:
    positions = []
    index = text.find("{")
    while index >= 0:
        positions.append(index)
        index = text.find("{", index + 1)
    return positions


def first_json_object(text: str) -> dict[str, Any]:
    """The first complete JSON object in ``text``.

    Raises
    ------
    NoJsonObject
        There is none (no ``{``, or every candidate is cut short or malformed).
    """
    body = drop_reasoning(text)
    positions = _candidates(body)
    for start in positions:
        try:
            value, _ = _DECODER.raw_decode(body, start)
        except json.JSONDecodeError:
            value, error, _ = json5.parse(body, start=start, consume_trailing=False)
            if error:
                continue
        if isinstance(value, dict):
            return value
    if not positions:
        raise NoJsonObject("the reply holds no JSON object (no '{' outside reasoning blocks)")
    raise NoJsonObject("the reply holds no complete JSON object (malformed or cut short)")


def parse_reply(text: str, schema: type[M]) -> M:
    """Validate the first JSON object of ``text`` against ``schema``.

    Raises
    ------
    NoJsonObject
        No complete object.
    pydantic.ValidationError
        The object does not fit ``schema``.
    """
    return schema.model_validate(first_json_object(text))
