"""Pick the roles for a provider name: offline rules, or a chat model per role (with fallbacks)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from app.engine.agents.roles import Critic, Perceiver, Planner, Roles
from app.engine.config import EngineConfig
from app.engine.errors import ProviderError
from app.engine.providers.http import Timeouts
from app.engine.providers.keys import clean_key
from app.engine.providers.profiles import parse_overrides, profile_for

OFFLINE = "offline"
OPENAI = "openai"
GEMINI = "gemini"
GEOMETRIC = "geometric"
"""Critic (or coverage) model name that selects the offline geometric one with a model provider."""
ROLES = ("perceiver", "planner", "critic", "coverage")
DEFAULT_MODELS: dict[str, dict[str, str]] = {
    OPENAI: {"perceiver": "gpt-4.1", "planner": "gpt-4.1", "critic": "gpt-4.1"},
    GEMINI: {"perceiver": "gemini-2.5-pro", "planner": "gemini-2.5-pro", "critic": "gemini-2.5-pro"},
}
DEFAULT_BASE_URLS = {OPENAI: "https://api.openai.com/v1", GEMINI: "https://generativelanguage.googleapis.com/v1beta"}


@dataclass(frozen=True)
class ProviderConfig:
    """Where a model provider lives; secrets reach the engine only through this object (never printed)."""

    api_key: str | None = field(default=None, repr=False)
    base_url: str | None = None
    models: tuple[tuple[str, str], ...] = ()
    """(role, model name) overrides; roles: perceiver, planner, critic, coverage (default: the critic's)."""
    profile: tuple[tuple[str, str], ...] = ()
    """Model-profile overrides (field, value) for every model of the run (see ``profiles.ModelProfile``)."""


def available_providers() -> tuple[str, ...]:
    return (OFFLINE, OPENAI, GEMINI)


def _chat(provider: str, model: str, key: str | None, settings: ProviderConfig, config: EngineConfig) -> Any:
    base_url = settings.base_url or DEFAULT_BASE_URLS[provider]
    profile = profile_for(provider, model, dict(settings.profile))
    timeouts = Timeouts(connect_s=config.connect_timeout_s, read_s=config.request_timeout_s, call_s=config.call_timeout_s)
    if provider == OPENAI:
        from app.engine.providers.openai_compat import OpenAICompatibleModel

        return OpenAICompatibleModel(model, api_key=key, base_url=base_url, profile=profile, timeouts=timeouts)
    from app.engine.providers.gemini import GeminiModel

    return GeminiModel(model, api_key=key, base_url=base_url, profile=profile, timeouts=timeouts)


def make_roles(provider: str = OFFLINE, settings: ProviderConfig | None = None, config: EngineConfig | None = None) -> Roles:
    """Roles for ``provider``, each model role wrapped in its fallback policy (``config.fallback``).

    Raises
    ------
    ProviderError
        Unknown provider or role, a remote provider without an API key or base URL, a key
        that cannot be sent (non-ASCII, inner whitespace), or a bad model-profile override.
    """
    from app.engine.offline.roles import GeometricCritic, OfflinePerceiver, OfflinePlanner, offline_roles

    if provider == OFFLINE:
        return offline_roles()
    if provider not in (OPENAI, GEMINI):
        raise ProviderError(f"unknown provider '{provider}' (available: {', '.join(available_providers())})")
    settings = settings or ProviderConfig()
    config = config or EngineConfig()
    key = clean_key(settings.api_key, provider)
    if not key and not settings.base_url:
        raise ProviderError(f"provider '{provider}' needs an API key (or a base URL of a local server); the offline provider needs none")
    unknown = [role for role, _ in settings.models if role not in ROLES]
    if unknown:
        raise ProviderError(f"unknown role(s) {', '.join(unknown)} in --model (roles: {', '.join(ROLES)})")
    parse_overrides(dict(settings.profile))
    from app.engine.agents.fallback import FallbackCritic, FallbackPerceiver, FallbackPlanner
    from app.engine.agents.model_critic import ModelCritic
    from app.engine.agents.model_roles import ModelPerceiver, ModelPlanner
    from app.engine.agents.prompts import PromptStore

    models = {**DEFAULT_MODELS[provider], **dict(settings.models)}
    models.setdefault("coverage", models["critic"])
    prompts = PromptStore(config.prompts_dir)
    chats = {name: _chat(provider, name, key, settings, config) for name in sorted(set(models.values()) - {GEOMETRIC})}
    policy = config.fallback
    perceiver: Perceiver = ModelPerceiver(chats[models["perceiver"]], prompts)
    if policy.perceiver == "offline":
        perceiver = FallbackPerceiver(perceiver, OfflinePerceiver())
    planner: Planner = ModelPlanner(chats[models["planner"]], prompts)
    if policy.planner == "offline":
        planner = FallbackPlanner(planner, OfflinePlanner())
    critic: Critic = GeometricCritic()
    vision = ["perceiver"]
    if models["critic"] != GEOMETRIC:
        coverage = None if models["coverage"] == GEOMETRIC else chats[models["coverage"]]
        critic = ModelCritic(chats[models["critic"]], prompts, coverage=coverage)
        vision.append("critic")
        if policy.critic == "offline":
            critic = FallbackCritic(critic, GeometricCritic())
    return Roles(provider=provider, perceiver=perceiver, planner=planner, critic=critic, closers=tuple(chats.values()), vision=tuple(vision))
