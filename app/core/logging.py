"""``configure_logging(settings)``: handlers for the service processes, called only by entry points.

The API's lifespan, the Celery ``setup_logging`` signal and ``artimo serve`` call it; modules
only create loggers. Records carry the process role and, inside a job, the job id.
"""

from __future__ import annotations

import logging
import re
import sys
from contextvars import ContextVar

from app.core.config import Settings

LOG_FORMAT = "%(asctime)s %(levelname)s [%(process)d] %(name)s%(job)s: %(message)s"
NOISY_LOGGERS = ("sqlalchemy.engine", "httpx", "multipart")

CREDENTIAL_PARAMETERS = frozenset({"api_key", "apikey", "key", "token", "access_token", "auth", "authorization"})
"""Query parameters that look like credentials: refused by the API, redacted in every log line."""
_CREDENTIAL_IN_QUERY = re.compile(r"([?&](?:" + "|".join(sorted(CREDENTIAL_PARAMETERS)) + r")=)[^&\s\"]*", re.IGNORECASE)

current_job: ContextVar[str | None] = ContextVar("current_job", default=None)
"""The job id the current code runs for (set by the worker), added to every record."""


class _JobFilter(logging.Filter):
    def filter(self, record: logging.LogRecord) -> bool:
        job = current_job.get()
        record.job = f" [job {job}]" if job else ""
        return True


def redact_credentials(text: str) -> str:
    """``text`` with the values of credential-like query parameters replaced."""
    return _CREDENTIAL_IN_QUERY.sub(r"\1[redacted]", text)


class _RedactFilter(logging.Filter):
    """Access-log lines (uvicorn) show the requested URL: a key sent as ``?api_key=`` must not be written."""

    def filter(self, record: logging.LogRecord) -> bool:
        message = record.getMessage()
        redacted = redact_credentials(message)
        if redacted != message:
            record.msg, record.args = redacted, ()
        return True


def configure_logging(settings: Settings) -> None:
    """One stderr handler on the root logger at ``settings.log_level`` (idempotent)."""
    root = logging.getLogger()
    level = logging.getLevelName(settings.log_level.upper())
    root.setLevel(level if isinstance(level, int) else logging.INFO)
    for handler in list(root.handlers):
        if getattr(handler, "_artimo", False):
            root.removeHandler(handler)
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(logging.Formatter(LOG_FORMAT))
    handler.addFilter(_JobFilter())
    handler.addFilter(_RedactFilter())
    handler._artimo = True  # type: ignore[attr-defined]
    root.addHandler(handler)
    for name in NOISY_LOGGERS:
        logging.getLogger(name).setLevel(max(logging.WARNING, root.level))
