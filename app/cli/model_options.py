"""Command-line options shared by the commands that run model roles (animate, bench run, bench critic).

The CLI is an entry point: it reads API keys, endpoints and timeout defaults from the
environment here and hands them to the engine as arguments (the engine never reads it).
"""

from __future__ import annotations

import argparse
import os
from typing import Any

from app.engine.errors import ProviderError

ROLE_NAMES = ("perceiver", "planner", "critic", "coverage")
TIMEOUT_ENV = {"connect_timeout_s": "ARTIMO_CONNECT_TIMEOUT_S", "request_timeout_s": "ARTIMO_READ_TIMEOUT_S", "call_timeout_s": "ARTIMO_CALL_TIMEOUT_S"}


def add_model_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--provider", default="offline", help="offline (default, no API key), openai (any OpenAI-compatible server) or gemini")
    parser.add_argument("--model", action="append", default=[], metavar="ROLE=NAME",
                        help="model per role (perceiver, planner, critic, coverage), e.g. --model critic=geometric (repeatable)")
    parser.add_argument("--base-url", default=None, help="provider endpoint (default: $OPENAI_BASE_URL / $GEMINI_BASE_URL or the public API)")
    parser.add_argument("--fallback", action="append", default=[], metavar="offline|fail|ROLE=offline|fail",
                        help="when a model role gives no usable answer: use the offline role, or fail "
                             "(default: critic=offline, perceiver=fail, planner=fail; repeatable)")
    parser.add_argument("--profile", action="append", default=[], metavar="KEY=VALUE",
                        help="model profile override, e.g. token_param=max_completion_tokens, temperature=none, output_mode=json_object")
    parser.add_argument("--timeout", dest="request_timeout_s", type=float, default=None,
                        help="read timeout per model request, seconds (default 60; $ARTIMO_READ_TIMEOUT_S)")
    parser.add_argument("--connect-timeout", dest="connect_timeout_s", type=float, default=None,
                        help="connect timeout, seconds (default 10; $ARTIMO_CONNECT_TIMEOUT_S)")
    parser.add_argument("--call-timeout", dest="call_timeout_s", type=float, default=None,
                        help="limit per model call with its retries, seconds (default 240; $ARTIMO_CALL_TIMEOUT_S)")
    render = parser.add_mutually_exclusive_group()
    render.add_argument("--render", dest="render", action="store_const", const=True, default=None,
                        help="render images even for the offline agent (into OUT/images)")
    render.add_argument("--no-render", dest="render", action="store_const", const=False,
                        help="do not render images for model roles (they then see none; the report warns)")


def _pairs(items: list[str], what: str) -> list[tuple[str, str]]:
    pairs = []
    for item in items:
        key, sep, value = item.partition("=")
        if not sep or not key or not value:
            raise ProviderError(f"{what} expects KEY=VALUE, got {item!r}")
        pairs.append((key.strip(), value.strip()))
    return pairs


def engine_overrides(args: argparse.Namespace) -> dict[str, Any]:
    """EngineConfig fields from the options (and the timeout environment variables)."""
    from app.engine.config import FallbackPolicy

    values: dict[str, Any] = {"render_images": args.render}
    for field, variable in TIMEOUT_ENV.items():
        given = getattr(args, field)
        if given is None and os.environ.get(variable):
            try:
                given = float(os.environ[variable])
            except ValueError as exc:
                raise ProviderError(f"${variable} must be a number of seconds, got {os.environ[variable]!r}") from exc
        if given is not None:
            if given <= 0:
                raise ProviderError(f"{variable.lower()} must be positive, got {given}")
            values[field] = given
    if args.fallback:
        try:
            values["fallback"] = FallbackPolicy.parse(",".join(args.fallback))
        except ValueError as exc:
            raise ProviderError(f"--fallback: {exc}") from exc
    return values


def provider_config(args: argparse.Namespace) -> Any:
    """API key and endpoint from the environment, models and profile overrides from the options."""
    from app.engine.providers.registry import ProviderConfig

    models = _pairs(args.model, "--model")
    unknown = [role for role, _ in models if role not in ROLE_NAMES]
    if unknown:
        raise ProviderError(f"--model expects ROLE=NAME with ROLE one of {', '.join(ROLE_NAMES)}, got {', '.join(unknown)}")
    profile = tuple(_pairs(args.profile, "--profile"))
    prefix = {"openai": "OPENAI", "gemini": "GEMINI"}.get(args.provider)
    if prefix is None:
        return ProviderConfig(models=tuple(models), profile=profile)
    return ProviderConfig(api_key=os.environ.get(f"{prefix}_API_KEY"), base_url=args.base_url or os.environ.get(f"{prefix}_BASE_URL"),
                          models=tuple(models), profile=profile)
