"""Engine error hierarchy.

Every error the engine raises on purpose derives from :class:`EngineError` and
carries structured context as fields, so callers (CLI, workers, API) can report
it without parsing the message.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from app.engine.report import RunReport


class EngineError(Exception):
    """Root of every deliberate engine failure.

    ``calls`` holds the model role calls made before the failure (``RoleCall`` records),
    so the report still lists them.
    """

    calls: tuple[object, ...] = ()

    def __init__(self, message: str, **context: object) -> None:
        super().__init__(message)
        self.message = message
        self.context = context
        self.report: RunReport | None = None
        """The report of the run that failed, when ``run_pipeline`` raised this (report.json's content)."""

    def __str__(self) -> str:
        return self.message


class AssetError(EngineError):
    """An asset (URDF + meshes) is unusable; ``file`` and ``element`` name the culprit."""

    def __init__(self, message: str, *, file: str | None = None, element: str | None = None) -> None:
        where = ", ".join(p for p in (file and f"file {file}", element and f"element {element}") if p)
        super().__init__(f"{message} ({where})" if where else message, file=file, element=element)
        self.reason = message
        """The message without the file/element suffix (to re-raise naming another file)."""
        self.file = file
        self.element = element


class PlanValidationError(EngineError):
    """A Causal.json or Plan.json document is invalid; ``issues`` lists every problem."""

    def __init__(self, message: str, *, issues: list[str] | None = None) -> None:
        self.issues = list(issues or [])
        text = message if not self.issues else message + ":\n" + "\n".join(f"  - {i}" for i in self.issues)
        super().__init__(text, issues=self.issues)


class ExpressionError(PlanValidationError):
    """A ``q_target_expr`` could not be parsed or evaluated."""


class ExecutionError(EngineError):
    """The executor could not turn a valid plan into a trajectory."""


class ExportError(EngineError):
    """Writing an output file (trajectory, GLB) failed."""


class RenderError(EngineError):
    """Offscreen rendering failed (no EGL, bad geometry, ...)."""


class ProviderError(EngineError):
    """A model provider call failed.

    ``transport`` (when set) lists the HTTP attempts made (``TransportAttempt`` records)
    and ``calls`` the role calls recorded before the failure, so the report keeps them.
    """

    transport: tuple[object, ...] = ()
    usage: object | None = None
    """Tokens of a reply that came back but could not be used (truncated, blocked)."""


class ProviderRateLimited(ProviderError):
    """The provider answered with a rate-limit response (``retry_after_s`` when it said)."""

    def __init__(self, message: str, *, retry_after_s: float | None = None) -> None:
        super().__init__(message, retry_after_s=retry_after_s)


class ProviderTimeout(ProviderError):
    """The provider did not answer in time."""


class ProviderQuotaExceeded(ProviderError):
    """The account's quota or credit is used up (e.g. OpenAI ``insufficient_quota``): retrying cannot help."""


class ProviderResponseError(ProviderError):
    """The provider answered with an error or an unreadable body (``retriable`` for 5xx / network)."""

    def __init__(self, message: str, *, retriable: bool = False, status: int | None = None, param: str | None = None) -> None:
        super().__init__(message, retriable=retriable, status=status, param=param)
        self.status = status
        self.param = param


class ProviderBlocked(ProviderResponseError):
    """The provider refused to answer (content filter, safety block, refusal); ``reason`` says why."""

    def __init__(self, message: str, *, reason: str) -> None:
        super().__init__(message)
        self.context["reason"] = reason
        self.reason = reason


class ReplyTruncated(ProviderResponseError):
    """The reply stopped at the output-token limit (``finish_reason: length`` / ``MAX_TOKENS``)."""

    def __init__(self, message: str, *, limit: int, partial: str = "") -> None:
        super().__init__(message)
        self.context["limit"] = limit
        self.limit = limit
        self.partial = partial


class RoleOutputError(EngineError):
    """A role (perceiver, planner, critic) produced no valid output within its attempts (``calls``: each attempt)."""


class GroundingError(EngineError):
    """The prompt could not be grounded to parts of the asset."""

    def __init__(self, message: str, *, movable_parts: list[str] | None = None, candidates: list[str] | None = None) -> None:
        self.movable_parts = list(movable_parts or [])
        self.candidates = list(candidates or [])
        """When the prompt is ambiguous: how to name each part it could mean."""
        super().__init__(message, movable_parts=self.movable_parts, candidates=self.candidates)


class MetricError(EngineError):
    """A benchmark case or prediction could not be scored."""


class CancelledError(EngineError):
    """The caller asked the pipeline to stop."""
