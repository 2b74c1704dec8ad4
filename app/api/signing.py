"""Signed, expiring tokens: artifact share links (``?token=``) and the page's sign-in link.

A token is ``<payload>.<signature>``: the payload is base64url JSON (``k`` kind, ``e``
expiry in Unix seconds, plus the kind's fields), the signature base64url HMAC-SHA256 of
the payload text under the server's link secret. Altering any character breaks the
signature; an expired token is refused even when its signature is right.

The secret is ``ARTIMO_LINK_SECRET`` when set (set it when several API hosts must accept
each other's links), else a random key kept in ``$ARTIMO_DATA_DIR/link-secret`` (mode
0600), made on first use, so links stay valid across restarts of one installation.
"""

from __future__ import annotations

import base64
import binascii
import contextlib
import hashlib
import hmac
import json
import math
import os
import secrets
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from app.api.errors import ApiError
from app.core.config import Settings

SECRET_FILE = "link-secret"
SECRET_BYTES = 32
PAGE_TOKEN_PREFIX = "artimo-page."
"""Page sign-in tokens are sent as ``Authorization: Bearer artimo-page.<token>``."""
MAX_TOKEN_CHARS = 2000
_lock = threading.Lock()
_cache: dict[Path, bytes] = {}


class Forbidden(ApiError):
    status_code = 403


@dataclass(frozen=True)
class TokenClaims:
    kind: str
    expires_at: int
    fields: dict[str, Any]


def _b64(data: bytes) -> str:
    return base64.urlsafe_b64encode(data).rstrip(b"=").decode("ascii")


def _unb64(text: str) -> bytes:
    return base64.urlsafe_b64decode(text + "=" * (-len(text) % 4))


def _secret_file(path: Path) -> bytes:
    with _lock:
        if path in _cache:
            return _cache[path]
        path.parent.mkdir(parents=True, exist_ok=True)
        if not path.exists():
            temporary = path.with_name(f".{path.name}.{os.getpid()}")
            descriptor = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
            with os.fdopen(descriptor, "wb") as handle:
                handle.write(secrets.token_bytes(SECRET_BYTES))
            try:
                with contextlib.suppress(FileExistsError):
                    os.link(temporary, path)  # first writer wins; another process's secret is kept
            finally:
                temporary.unlink()
        secret = path.read_bytes()
        _cache[path] = secret
        return secret


def link_secret(settings: Settings) -> bytes:
    """The signing key of this installation (see the module docstring)."""
    configured = settings.artimo_link_secret
    if configured is not None:
        return configured.get_secret_value().encode("utf-8")
    return _secret_file(settings.data_dir / SECRET_FILE)


def expiry(ttl_s: int) -> int:
    """The whole second a token made now for ``ttl_s`` seconds expires at (rounded up: never shorter than asked)."""
    return math.ceil(time.time() + ttl_s)


def sign(secret: bytes, kind: str, ttl_s: int, **fields: Any) -> str:
    """A token of ``kind`` valid for at least ``ttl_s`` seconds carrying ``fields``."""
    payload = _b64(json.dumps({"k": kind, "e": expiry(ttl_s), **fields}, separators=(",", ":")).encode())
    signature = _b64(hmac.new(secret, payload.encode("ascii"), hashlib.sha256).digest())
    return f"{payload}.{signature}"


def verify(secret: bytes, token: str, kind: str) -> TokenClaims:
    """The claims of a valid, unexpired token of ``kind``.

    Raises
    ------
    Forbidden
        Malformed, altered (bad signature), of another kind, or expired.
    """
    payload, _, signature = token.partition(".")
    if not payload or not signature or len(token) > MAX_TOKEN_CHARS:
        raise Forbidden("malformed token")
    expected = _b64(hmac.new(secret, payload.encode("ascii", "replace"), hashlib.sha256).digest())
    if not hmac.compare_digest(expected.encode("ascii"), signature.encode("utf-8", "replace")):  # str compare refuses non-ASCII
        raise Forbidden("invalid token: the signature does not match (altered or from another server)")
    try:
        claims = json.loads(_unb64(payload))
    except (ValueError, binascii.Error) as exc:
        raise Forbidden("malformed token") from exc
    if not isinstance(claims, dict) or claims.get("k") != kind or not isinstance(claims.get("e"), int):
        raise Forbidden(f"not a {kind} token")
    if claims["e"] < time.time():
        raise Forbidden("the link has expired", expired_at=claims["e"])
    fields = {key: value for key, value in claims.items() if key not in ("k", "e")}
    return TokenClaims(kind=kind, expires_at=claims["e"], fields=fields)


def page_token(settings: Settings, client_id: str, ttl_s: int) -> str:
    """A bearer credential for the page, standing for ``client_id`` until it expires."""
    return PAGE_TOKEN_PREFIX + sign(link_secret(settings), "page", ttl_s, c=client_id)


def page_token_client(settings: Settings, credential: str) -> str | None:
    """The client id a page token stands for, or ``None`` if it is not a valid page token."""
    if not credential.startswith(PAGE_TOKEN_PREFIX):
        return None
    try:
        claims = verify(link_secret(settings), credential[len(PAGE_TOKEN_PREFIX):], "page")
    except Forbidden:
        return None
    client = claims.fields.get("c")
    return client if isinstance(client, str) else None
