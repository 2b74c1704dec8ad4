"""API keys: cleaned once, checked, and never shown (every provider message goes through :func:`mask`)."""

from __future__ import annotations

from app.engine.errors import ProviderError

MASK = "[redacted key]"
MIN_MASKED_LENGTH = 4
"""Fragments shorter than this are not masked (they would hide ordinary words)."""


def clean_key(raw: str | None, provider: str) -> str | None:
    """``raw`` without surrounding whitespace (a CRLF .env leaves a ``\\r``); None when empty.

    Raises
    ------
    ProviderError
        The key holds a character an HTTP header cannot carry (non-ASCII, control or inner
        space); the message names its position, never the key.
    """
    if raw is None:
        return None
    key = raw.strip()
    if not key:
        return None
    for position, char in enumerate(key, start=1):
        if not 33 <= ord(char) <= 126:
            kind = "a non-ASCII" if ord(char) > 126 else "a space or control"
            raise ProviderError(f"the {provider} API key has {kind} character at position {position} of {len(key)}; "
                                "copy the key again (the value itself is not shown)")
    return key


def mask(text: str, *secrets: str | None) -> str:
    """``text`` with every occurrence of each secret (and of its unstripped form) replaced by :data:`MASK`."""
    for secret in secrets:
        if not secret:
            continue
        for variant in {secret, secret.strip()}:
            if len(variant) >= MIN_MASKED_LENGTH:
                text = text.replace(variant, MASK)
    return text
