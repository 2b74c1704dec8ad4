"""Service settings: the only place that reads the environment (and ``.env``)."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from pydantic import Field, SecretStr, field_validator
from pydantic_settings import BaseSettings, SettingsConfigDict

from app.engine.config import EngineConfig, FallbackPolicy

DEFAULT_DATA_DIR = Path.home() / ".local" / "share" / "artimo"


class Settings(BaseSettings):
    """Environment variables (names in capitals) with documented defaults.

    Embedded default: SQLite and a SQLite-backed Celery broker under ``ARTIMO_DATA_DIR``.
    Production: set ``DATABASE_URL`` (Postgres) and ``REDIS_URL`` (broker).
    """

    model_config = SettingsConfigDict(env_file=".env", env_file_encoding="utf-8", extra="ignore")

    artimo_data_dir: Path = DEFAULT_DATA_DIR
    database_url: str | None = None
    """SQLAlchemy URL; default ``sqlite:///$ARTIMO_DATA_DIR/artimo.db``."""
    redis_url: str | None = None
    """When set, Celery uses Redis as broker; otherwise kombu's SQLAlchemy transport on SQLite."""
    artimo_api_key: SecretStr | None = None
    """An accepted API key (so the embedded service works out of the box)."""
    artimo_storage_dir: Path | None = None
    """Artifacts and uploads; default ``$ARTIMO_DATA_DIR/storage``."""
    artimo_link_secret: SecretStr | None = None
    """Key signing share links and the page's sign-in link; default a random key kept in
    ``$ARTIMO_DATA_DIR/link-secret`` (set it when several API hosts must accept each other's links)."""
    page_login_ttl_s: int = Field(default=7 * 24 * 3600, gt=0)
    """How long the sign-in link ``artimo serve`` prints stays valid."""

    max_upload_bytes: int = Field(default=256 * 1024 * 1024, gt=0)
    max_upload_files: int = Field(default=2000, gt=0)
    max_json_body_bytes: int = Field(default=2 * 1024 * 1024, gt=0)
    """Largest body that is not a multipart upload (``POST /v1/batches``), bytes."""
    body_idle_timeout_s: float = Field(default=30.0, gt=0)
    """A request body with no new bytes for this long is refused (408)."""
    body_timeout_s: float = Field(default=900.0, gt=0)
    """Longest time to receive a whole request body (408 after it)."""
    metrics_token: SecretStr | None = None
    """Bearer token for ``/metrics``; without it ``/metrics`` answers only on loopback."""
    rate_limit_per_minute: int = Field(default=120, gt=0)
    auth_cache_s: float = Field(default=2.0, ge=0)
    auth_failures_per_minute: int = Field(default=60, gt=0)
    """Requests with a missing or wrong key one client address may make per minute before 429s."""
    """How long an authenticated key is remembered in-process (a disabled key stops working within this)."""
    """Requests per API key per minute (health routes are exempt)."""
    job_soft_time_limit_s: int = Field(default=900, gt=0)
    job_hard_time_limit_s: int = Field(default=960, gt=0)
    max_batch_cases: int = Field(default=200, gt=0)
    max_active_jobs_per_client: int = Field(default=200, gt=0)
    """Jobs one API key may have queued or running at once; more are refused (429) until some finish."""
    api_max_in_flight: int = Field(default=8, ge=1)
    """HTTP requests inside one API process at once (others wait in the event loop); must stay <= the
    DB pool's capacity (5+10 SQLite, 10+20 Postgres) or sync routes can deadlock (see app/api/admission.py).
    8 measured best for latency on 2 cores (benchmark/load_service.py)."""
    celery_queue: str = "artimo"
    """Celery queue the API sends jobs to and the workers consume."""
    job_max_attempts: int = Field(default=3, ge=1)
    """Deliveries of one job (worker lost, time limit kill) before it is failed for good."""
    broker_visibility_timeout_s: int | None = Field(default=None, gt=0)
    """Redis: an unacknowledged job is redelivered after this; default hard time limit + 120 s."""
    requeue_queued_after_s: int = Field(default=120, ge=0)
    """On (re)connection a worker re-sends jobs still queued after this long (their message may be lost)."""
    requeue_sweep_s: float = Field(default=30.0, gt=0)
    """How often a worker looks for jobs whose message was lost (also between reconnections)."""
    requeue_stuck_after_s: float = Field(default=30.0, ge=0)
    """A job still queued this long while the broker queue is empty has lost its message: it is re-sent."""
    worker_heartbeat_s: float = Field(default=10.0, gt=0)
    """How often each worker records that it is alive; ``/readyz`` needs one heard from within 3 intervals."""
    job_stage_delay_s: float = Field(default=0.0, ge=0, le=60)
    """Pause after each pipeline stage (tests/demos: makes progress, cancel and kill observable)."""

    log_level: str = "INFO"
    """Level of the service's root logger (API, workers)."""

    openai_api_key: SecretStr | None = None
    openai_base_url: str = "https://api.openai.com/v1"
    gemini_api_key: SecretStr | None = None
    gemini_base_url: str = "https://generativelanguage.googleapis.com/v1beta"
    default_provider: str = "offline"
    artimo_render_images: bool | None = None
    """Render images for the model roles; unset: on whenever a role is a model that looks at images."""
    artimo_connect_timeout_s: float = Field(default=10.0, gt=0)
    artimo_read_timeout_s: float = Field(default=60.0, gt=0)
    artimo_call_timeout_s: float = Field(default=240.0, gt=0)
    """Limit per model call, retries included (keep it well under the job time limits)."""
    artimo_fallback: str = ""
    """Per-role fallback, e.g. ``critic=offline,perceiver=fail`` (default: critic offline, others fail)."""
    artimo_model_profile: str = ""
    """Model-profile overrides ``KEY=VALUE,...`` (e.g. ``token_param=max_completion_tokens,temperature=none``)."""

    def provider_key(self, provider: str) -> SecretStr | None:
        """The server's API key for a model provider (``None``: none configured, or the offline provider)."""
        return {"openai": self.openai_api_key, "gemini": self.gemini_api_key}.get(provider)

    def missing_provider_key(self, provider: str | None) -> str | None:
        """Why a job on ``provider`` (default: the server's) cannot run here, or ``None`` when it can."""
        name = provider or self.default_provider
        if name in ("openai", "gemini") and self.provider_key(name) is None:
            return (f"this server has no API key for provider '{name}' ({name.upper()}_API_KEY is not set); "
                    "use provider 'offline' or ask the operator")
        return None

    @property
    def data_dir(self) -> Path:
        return self.artimo_data_dir.expanduser()

    @property
    def sqlalchemy_url(self) -> str:
        return self.database_url or f"sqlite:///{self.data_dir / 'artimo.db'}"

    @property
    def database_shown(self) -> str:
        """The database URL for messages (password hidden)."""
        from sqlalchemy.engine import make_url

        return make_url(self.sqlalchemy_url).render_as_string(hide_password=True)

    @property
    def broker_url(self) -> str:
        return self.redis_url or f"sqla+sqlite:///{self.data_dir / 'broker.db'}"

    @property
    def worker_stale_after_s(self) -> float:
        return 3 * self.worker_heartbeat_s

    @property
    def visibility_timeout_s(self) -> int:
        return self.broker_visibility_timeout_s or self.job_hard_time_limit_s + 120

    @property
    def storage_dir(self) -> Path:
        return (self.artimo_storage_dir or self.data_dir / "storage").expanduser()

    @field_validator("artimo_fallback")
    @classmethod
    def _fallback(cls, value: str) -> str:
        FallbackPolicy.parse(value)  # a ValueError names the bad item
        return value

    @property
    def model_profile(self) -> tuple[tuple[str, str], ...]:
        pairs = (item.partition("=") for item in self.artimo_model_profile.split(",") if item.strip())
        return tuple((key.strip(), value.strip()) for key, _, value in pairs)

    def engine_config(self) -> EngineConfig:
        """The engine's tunables for one job (API keys never reach the engine this way)."""
        return EngineConfig(asset_cache_dir=self.data_dir / "asset-cache", render_images=self.artimo_render_images,
                            connect_timeout_s=self.artimo_connect_timeout_s, request_timeout_s=self.artimo_read_timeout_s,
                            call_timeout_s=self.artimo_call_timeout_s, fallback=FallbackPolicy.parse(self.artimo_fallback))


@lru_cache(maxsize=1)
def get_settings() -> Settings:
    """Cached settings; tests clear the cache (``get_settings.cache_clear()``) after changing the environment."""
    return Settings()
