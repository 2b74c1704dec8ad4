"""What a model name may look like (one definition for the API, the worker and the providers)."""

from __future__ import annotations

import re

MODEL_NAME_PATTERN = r"^[A-Za-z0-9][A-Za-z0-9._:@+-]*(?:/[A-Za-z0-9][A-Za-z0-9._:@+-]*)*$"
"""A model name: letters, digits and ``. _ : @ + -``, in ``/``-separated segments that start with a
letter or digit (``gpt-4.1``, ``gemini-2.5-pro``, ``meta-llama/Llama-3.1-8B``). No ``..`` segment,
no ``?``, ``#``, ``%`` or spaces: a name never changes the provider URL it may be placed in."""


def valid_model_name(name: str) -> bool:
    return re.fullmatch(MODEL_NAME_PATTERN, name) is not None
