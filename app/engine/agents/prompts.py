"""Prompt templates: ``prompts/<role>.yaml`` with ``version``, ``system``, ``user`` (Jinja2, strict)."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

import yaml
from jinja2 import Environment, StrictUndefined, Template, TemplateError

from app.engine.errors import EngineError


class PromptError(EngineError):
    """A prompt template is missing, malformed, or lacks a variable."""


@dataclass(frozen=True)
class RenderedPrompt:
    role: str
    version: str
    sha256: str
    system: str
    user: str


@dataclass(frozen=True)
class _Template:
    version: str
    system: Template
    user: Template
    sha256: str


_ENV = Environment(undefined=StrictUndefined, autoescape=False, keep_trailing_newline=True)


@lru_cache(maxsize=64)
def _compile(source: str) -> Template:
    """A compiled template (shared by every store: compiling costs ~10 ms, rendering far less)."""
    return _ENV.from_string(source)


@lru_cache(maxsize=64)
def _load_template(path: Path) -> _Template:
    """Read, check and compile one template file (once per process: templates are immutable files)."""
    try:
        text = path.read_text(encoding="utf-8")
        data = yaml.safe_load(text)
    except (OSError, yaml.YAMLError) as exc:
        raise PromptError(f"cannot read prompt template {path}: {exc}") from exc
    if not isinstance(data, dict) or not all(isinstance(data.get(k), str) for k in ("version", "system", "user")):
        raise PromptError(f"prompt template {path} needs string keys version, system, user")
    try:
        system, user = _compile(data["system"]), _compile(data["user"])
    except TemplateError as exc:
        raise PromptError(f"prompt template {path}: {exc}") from exc
    return _Template(version=data["version"], system=system, user=user, sha256=hashlib.sha256(text.encode()).hexdigest())


class PromptStore:
    """Loads and renders the role templates under ``root``."""

    def __init__(self, root: Path) -> None:
        self.root = root

    def _load(self, role: str) -> _Template:
        return _load_template(self.root / f"{role}.yaml")

    def render(self, role: str, **variables: Any) -> RenderedPrompt:
        """Render ``role``'s template.

        Raises
        ------
        PromptError
            Missing template or a variable the template uses but was not given.
        """
        template = self._load(role)
        try:
            system = template.system.render(**variables)
            user = template.user.render(**variables)
        except TemplateError as exc:
            raise PromptError(f"prompt template {role}: {exc}") from exc
        return RenderedPrompt(role=role, version=template.version, sha256=template.sha256, system=system, user=user)
