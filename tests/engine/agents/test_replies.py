"""Reading a role's JSON object out of real replies (lenient parser, never completing a cut reply)."""

from __future__ import annotations

import pytest

from app.engine.agents.replies import NoJsonObject, drop_reasoning, first_json_object


@pytest.mark.parametrize("text", [
    '{"a": 1}',
    'Here you go:\n```json\n{"a": 1}\n```\nAnything else?',
    '<think>maybe {"a": 2} is better? no.</think>\n{"a": 1}',
    '{"a": 1, // the answer\n}',
    "{'a': 1,}",
    '```\n{"a": 1}\n```\n{"b": 2}',
])
def test_first_complete_object(text: str) -> None:
    assert first_json_object(text) == {"a": 1}


def test_outer_object_with_a_comment_wins_over_clean_inner_objects() -> None:
    assert first_json_object('{"outer": {"inner": 1}, // note\n "b": 2}') == {"outer": {"inner": 1}, "b": 2}


@pytest.mark.parametrize("text,why", [
    ('{"a": {"b": [1, 2', "cut short"),
    ("no object here", "no '{'"),
    ("<think>{\"a\": 1}</think>", "no '{'"),
    ("<think>still thinking {\"a\": 1}", "no '{'"),
])
def test_no_complete_object(text: str, why: str) -> None:
    with pytest.raises(NoJsonObject) as info:
        first_json_object(text)
    assert why in str(info.value)


def test_reasoning_blocks_are_dropped() -> None:
    assert drop_reasoning("<thinking>x</thinking>A<think>y</think>B") == "AB"
