"""docker-compose.yml and Dockerfile, checked without Docker (not installed here): YAML structure,
healthchecks, scalable workers, secrets without defaults, and commands that name real modules."""

from __future__ import annotations

import importlib
import re
from pathlib import Path
from typing import Any

import pytest
import yaml

from app.core.config import Settings

REPO = Path(__file__).resolve().parents[2]
COMPOSE = REPO / "docker-compose.yml"
DOCKERFILE = REPO / "Dockerfile"
SECRETS = ("POSTGRES_PASSWORD", "REDIS_PASSWORD", "ARTIMO_API_KEY", "FLOWER_BASIC_AUTH")
VARIABLE = re.compile(r"\$\{([A-Z0-9_]+)(?:(:?[-?])([^}]*))?\}")
HEALTHCHECKED = ("api", "worker", "redis", "postgres", "flower")


def interpolate(text: str, env: dict[str, str]) -> str:
    """Compose-style ``${VAR}``, ``${VAR:-default}``, ``${VAR:?message}`` (``$$`` is a literal ``$``)."""

    def replace(match: re.Match[str]) -> str:
        name, operator, argument = match.group(1), match.group(2), match.group(3)
        value = env.get(name, "")
        if operator in (":?", "?") and not value:
            raise KeyError(f"{name}: {argument}")
        if operator in (":-", "-") and not value:
            return argument or ""
        return value

    return VARIABLE.sub(replace, text.replace("$$", "\0")).replace("\0", "$")


def _compose(env: dict[str, str]) -> dict[str, Any]:
    return yaml.safe_load(interpolate(COMPOSE.read_text(), env))  # type: ignore[no-any-return]


@pytest.fixture(scope="module")
def compose() -> dict[str, Any]:
    return _compose({name: f"secret-{name.lower()}" for name in SECRETS} | {"FLOWER_BASIC_AUTH": "admin:pw"})


def test_every_secret_is_required_and_has_no_default() -> None:
    text = COMPOSE.read_text()
    for name in SECRETS:
        uses = [m for m in VARIABLE.finditer(text) if m.group(1) == name]
        assert uses and all(m.group(2) == ":?" for m in uses), name
        with pytest.raises(KeyError, match=name):
            _compose({other: "x" for other in SECRETS if other != name})


def test_services_and_healthchecks(compose: dict[str, Any]) -> None:
    services = compose["services"]
    assert set(HEALTHCHECKED) | {"migrate"} <= set(services)
    for name in HEALTHCHECKED:
        check = services[name]["healthcheck"]
        assert check["test"][0] in ("CMD", "CMD-SHELL") and len(check["test"]) > 1, name
        assert check["interval"] and check["retries"] >= 3, name


def test_worker_scales_and_waits_for_its_dependencies(compose: dict[str, Any]) -> None:
    worker = compose["services"]["worker"]
    assert int(worker["deploy"]["replicas"]) >= 2
    assert "container_name" not in worker and "ports" not in worker  # --scale would collide
    assert worker["depends_on"]["redis"]["condition"] == "service_healthy"
    assert worker["depends_on"]["migrate"]["condition"] == "service_completed_successfully"
    assert compose["services"]["migrate"]["depends_on"]["postgres"]["condition"] == "service_healthy"
    assert compose["services"]["api"]["depends_on"]["migrate"]["condition"] == "service_completed_successfully"


def test_commands_name_real_modules(compose: dict[str, Any]) -> None:
    services = compose["services"]
    assert services["worker"]["command"][:4] == ["celery", "-A", "workers.celery_app", "worker"]
    assert "app.main:create_app" in services["api"]["command"] and "--factory" in services["api"]["command"]
    assert services["migrate"]["command"] == ["python", "-m", "app.db.migrate"]
    for module in ("workers.celery_app", "app.main", "app.db.migrate"):
        importlib.import_module(module)


def test_environment_names_are_settings_fields(compose: dict[str, Any]) -> None:
    fields = {name.upper() for name in Settings.model_fields}
    for name in ("api", "worker", "migrate"):
        environment = compose["services"][name]["environment"]
        assert set(environment) <= fields, set(environment) - fields
        assert environment["DATABASE_URL"].startswith("postgresql+psycopg://artimo:secret-postgres_password@postgres:5432/")
        assert environment["REDIS_URL"] == "redis://:secret-redis_password@redis:6379/0"


def test_redis_persists_and_all_services_share_one_image(compose: dict[str, Any]) -> None:
    services = compose["services"]
    assert "--appendonly" in services["redis"]["command"]
    assert {services[n]["image"] for n in ("api", "worker", "migrate")} == {"artimo:latest"}


def test_dockerfile_two_layer_install_and_prompts() -> None:
    text = DOCKERFILE.read_text()
    first_copy = text.index("COPY pyproject.toml")
    assert first_copy < text.index("pip install -r") < text.index("COPY app ./app") < text.index("pip install --no-deps")
    for folder in ("prompts", "migrations", "workers", "app"):
        assert f"COPY {folder} ./{folder}" in text
    assert re.search(r'^CMD \["uvicorn", "app.main:create_app", "--factory"', text, re.MULTILINE)
    assert re.search(r"^USER artimo$", text, re.MULTILINE)
