"""Model profiles: what each model family accepts (token-limit name, temperature, thinking, output mode).

A profile is chosen from the model's name (longest matching family prefix) and can be
overridden field by field (``ProviderConfig.profile``, CLI ``--profile KEY=VALUE``,
setting ``ARTIMO_MODEL_PROFILE``). Prices are list prices in USD per million tokens, used
only for the report's cost estimate; unknown models have none.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace
from typing import Any, Literal

from app.engine.errors import ProviderError

OutputMode = Literal["json_schema", "json_object", "text"]
TokenParam = Literal["max_tokens", "max_completion_tokens"]
OUTPUT_MODES: tuple[OutputMode, ...] = ("json_schema", "json_object", "text")
"""Strict first; each later mode is the fallback of the one before when an endpoint rejects it."""


@dataclass(frozen=True)
class ModelProfile:
    """How to talk to one model.

    Attributes
    ----------
    token_param : name of the output-limit field (OpenAI reasoning models want ``max_completion_tokens``)
    temperature : sent when not None (reasoning models accept only their default: None)
    max_output_tokens : first output limit; a reply cut at the limit is asked again with twice the room ...
    max_output_tokens_cap : ... up to this
    thinking_budget : Gemini ``thinkingConfig.thinkingBudget`` (tokens), not sent when None
    output_mode : structured output asked for first (``json_schema``: the reply's JSON Schema)
    price_in_per_mtok, price_out_per_mtok : USD per million input / output tokens
    """

    token_param: TokenParam = "max_tokens"
    temperature: float | None = 0.0
    max_output_tokens: int = 8192
    max_output_tokens_cap: int = 32768
    thinking_budget: int | None = None
    output_mode: OutputMode = "json_schema"
    price_in_per_mtok: float | None = None
    price_out_per_mtok: float | None = None

    def cost(self, input_tokens: int, output_tokens: int) -> float | None:
        if self.price_in_per_mtok is None or self.price_out_per_mtok is None:
            return None
        return round((input_tokens * self.price_in_per_mtok + output_tokens * self.price_out_per_mtok) / 1e6, 6)


_REASONING = {"token_param": "max_completion_tokens", "temperature": None, "max_output_tokens": 16384}
FAMILIES: dict[str, dict[str, dict[str, Any]]] = {
    "openai": {
        "gpt-5": {**_REASONING, "price_in_per_mtok": 1.25, "price_out_per_mtok": 10.0},
        "gpt-5-mini": {**_REASONING, "price_in_per_mtok": 0.25, "price_out_per_mtok": 2.0},
        "gpt-5-nano": {**_REASONING, "price_in_per_mtok": 0.05, "price_out_per_mtok": 0.4},
        "o1": {**_REASONING, "price_in_per_mtok": 15.0, "price_out_per_mtok": 60.0},
        "o3": {**_REASONING, "price_in_per_mtok": 2.0, "price_out_per_mtok": 8.0},
        "o3-mini": {**_REASONING, "price_in_per_mtok": 1.1, "price_out_per_mtok": 4.4},
        "o4-mini": {**_REASONING, "price_in_per_mtok": 1.1, "price_out_per_mtok": 4.4},
        "gpt-4.1": {"price_in_per_mtok": 2.0, "price_out_per_mtok": 8.0},
        "gpt-4.1-mini": {"price_in_per_mtok": 0.4, "price_out_per_mtok": 1.6},
        "gpt-4.1-nano": {"price_in_per_mtok": 0.1, "price_out_per_mtok": 0.4},
        "gpt-4o": {"price_in_per_mtok": 2.5, "price_out_per_mtok": 10.0},
        "gpt-4o-mini": {"price_in_per_mtok": 0.15, "price_out_per_mtok": 0.6},
    },
    "gemini": {
        "gemini-2.5-pro": {"thinking_budget": 2048, "max_output_tokens": 16384, "max_output_tokens_cap": 65536,
                           "price_in_per_mtok": 1.25, "price_out_per_mtok": 10.0},
        "gemini-2.5-flash": {"thinking_budget": 1024, "max_output_tokens": 16384, "max_output_tokens_cap": 65536,
                             "price_in_per_mtok": 0.3, "price_out_per_mtok": 2.5},
        "gemini-2.5-flash-lite": {"thinking_budget": 0, "max_output_tokens": 8192, "price_in_per_mtok": 0.1, "price_out_per_mtok": 0.4},
        "gemini-2.0-flash": {"price_in_per_mtok": 0.1, "price_out_per_mtok": 0.4},
    },
}


def _family(provider: str, model: str) -> dict[str, Any]:
    """Settings of the longest family name that ``model`` starts with (after any ``org/`` prefix)."""
    name = model.rsplit("/", 1)[-1].lower()
    known = FAMILIES.get(provider, {})
    matches = [family for family in known if name == family or name.startswith(family + "-")]
    return dict(known[max(matches, key=len)]) if matches else {}


def parse_overrides(items: dict[str, Any]) -> dict[str, Any]:
    """Profile overrides from strings or values (``{"temperature": "none", "max_output_tokens": "4096"}``).

    Raises
    ------
    ProviderError
        An unknown field or a value of the wrong kind.
    """
    known = {f.name: f for f in fields(ModelProfile)}
    out: dict[str, Any] = {}
    for key, value in items.items():
        if key not in known:
            raise ProviderError(f"unknown model profile field '{key}' (known: {', '.join(known)})")
        if isinstance(value, str):
            text = value.strip()
            if text.lower() in ("none", "null", ""):
                value = None
            elif key in ("max_output_tokens", "max_output_tokens_cap", "thinking_budget"):
                value = _number(key, text, int)
            elif key in ("temperature", "price_in_per_mtok", "price_out_per_mtok"):
                value = _number(key, text, float)
            else:
                value = text
        if key == "output_mode" and value not in OUTPUT_MODES:
            raise ProviderError(f"model profile output_mode must be one of {', '.join(OUTPUT_MODES)}, got {value!r}")
        if key == "token_param" and value not in ("max_tokens", "max_completion_tokens"):
            raise ProviderError(f"model profile token_param must be max_tokens or max_completion_tokens, got {value!r}")
        out[key] = value
    return out


def _number(key: str, text: str, kind: type) -> Any:
    try:
        return kind(text)
    except ValueError as exc:
        raise ProviderError(f"model profile field '{key}' needs a number, got {text!r}") from exc


def profile_for(provider: str, model: str, overrides: dict[str, Any] | None = None) -> ModelProfile:
    """The profile of ``model`` at ``provider``, with ``overrides`` applied last."""
    return replace(ModelProfile(), **{**_family(provider, model), **parse_overrides(overrides or {})})
