"""Pick the roles for a provider name: offline rules, or a chat model per role."""

from __future__ import annotations

from dataclasses import dataclass

from app.engine.agents.roles import Roles
from app.engine.config import EngineConfig
from app.engine.errors import ProviderError

OFFLINE = "offline"
OPENAI = "openai"
GEMINI = "gemini"
GEOMETRIC = "geometric"
"""Critic model name that selects the offline geometric critic with a model provider."""
DEFAULT_MODELS: dict[str, dict[str, str]] = {
    OPENAI: {"perceiver": "gpt-4.1", "planner": "gpt-4.1", "critic": "gpt-4.1"},
    GEMINI: {"perceiver": "gemini-2.5-pro", "planner": "gemini-2.5-pro", "critic": "gemini-2.5-pro"},
}
DEFAULT_BASE_URLS = {OPENAI: "https://api.openai.com/v1", GEMINI: "https://generativelanguage.googleapis.com/v1beta"}


@dataclass(frozen=True)
class ProviderConfig:
    """Where a model provider lives; secrets reach the engine only through this object."""

    api_key: str | None = None
    base_url: str | None = None
    models: tuple[tuple[str, str], ...] = ()
    """(role, model name) overrides."""


def available_providers() -> tuple[str, ...]:
    return (OFFLINE, OPENAI, GEMINI)


def _chat(provider: str, model: str, settings: ProviderConfig, config: EngineConfig):  # type: ignore[no-untyped-def]
    base_url = settings.base_url or DEFAULT_BASE_URLS[provider]
    if provider == OPENAI:
        from app.engine.providers.openai_compat import OpenAICompatibleModel

        return OpenAICompatibleModel(model, api_key=settings.api_key, base_url=base_url, timeout_s=config.request_timeout_s)
    from app.engine.providers.gemini import GeminiModel

    return GeminiModel(model, api_key=settings.api_key, base_url=base_url, timeout_s=config.request_timeout_s)


def make_roles(provider: str = OFFLINE, settings: ProviderConfig | None = None, config: EngineConfig | None = None) -> Roles:
    """Roles for ``provider``.

    Raises
    ------
    ProviderError
        Unknown provider, or a remote provider without an API key or base URL.
    """
    from app.engine.offline.roles import GeometricCritic, offline_roles

    if provider == OFFLINE:
        return offline_roles()
    if provider not in (OPENAI, GEMINI):
        raise ProviderError(f"unknown provider '{provider}' (available: {', '.join(available_providers())})")
    settings = settings or ProviderConfig()
    config = config or EngineConfig()
    if not settings.api_key and not settings.base_url:
        raise ProviderError(f"provider '{provider}' needs an API key (or a base URL of a local server); the offline provider needs none")
    from app.engine.agents.model_roles import ModelCritic, ModelPerceiver, ModelPlanner
    from app.engine.agents.prompts import PromptStore

    models = {**DEFAULT_MODELS[provider], **dict(settings.models)}
    prompts = PromptStore(config.prompts_dir)
    chats = {name: _chat(provider, name, settings, config) for name in sorted(set(models.values()) - {GEOMETRIC})}
    critic = GeometricCritic() if models["critic"] == GEOMETRIC else ModelCritic(chats[models["critic"]], prompts, keyframes=_keyframes())
    return Roles(provider=provider, perceiver=ModelPerceiver(chats[models["perceiver"]], prompts),
                 planner=ModelPlanner(chats[models["planner"]], prompts), critic=critic, closers=tuple(chats.values()))


def _keyframes():  # type: ignore[no-untyped-def]
    from app.engine.agents.keyframes import critic_keyframes

    return critic_keyframes
