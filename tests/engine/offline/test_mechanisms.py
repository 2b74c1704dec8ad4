"""``mechanisms.named_for_another_job``: what the user calls a control may give it a job other than releasing a door."""

from __future__ import annotations

import pytest

from app.engine.offline.mechanisms import named_for_another_job


@pytest.mark.parametrize(("words", "job"), [
    ("the start button", True),
    ("the start button on the microwave", True),
    ("the power button", True),
    ("the cook button", True),
    ("the button on the microwave", False),  # "on" after the noun is a place, not the "on" button
    ("the release button", False),
    ("the door open button", False),
    ("the button", False),
    ("", False),
])
def test_named_for_another_job(words: str, job: bool) -> None:
    assert named_for_another_job(words) is job
