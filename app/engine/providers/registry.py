"""Pick the roles for a provider name."""

from __future__ import annotations

from app.engine.agents.roles import Roles
from app.engine.errors import ProviderError

OFFLINE = "offline"


def available_providers() -> tuple[str, ...]:
    return (OFFLINE,)


def make_roles(provider: str = OFFLINE) -> Roles:
    """Roles for ``provider``.

    Raises
    ------
    ProviderError
        Unknown provider name.
    """
    if provider == OFFLINE:
        from app.engine.offline.roles import offline_roles

        return offline_roles()
    raise ProviderError(f"unknown provider '{provider}' (available: {', '.join(available_providers())})")
