"""Cancellation honoured inside long stages, not only between them.

The engine checks ``should_stop`` between stages; a stage can run for minutes (a large
asset, a slow model). While the engine runs, a watcher thread polls the job's
``cancel_requested`` flag; when it is set, the watcher signals the job's thread
(``SIGUSR2``), whose handler raises :class:`JobCancelled` there, the same way Celery
delivers its soft time limit. The observer's own database writes are shielded: a request
arriving during one is raised as soon as it ends, so no transaction is cut in half.

Only the main thread can receive signals: elsewhere (a test calling the task from another
thread) the watch is a no-op and cancellation happens between stages, as before.
"""

from __future__ import annotations

import logging
import signal
import threading
import uuid
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import FrameType

from app.engine.errors import CancelledError

logger = logging.getLogger(__name__)

CANCEL_SIGNAL = signal.SIGUSR2
POLL_S = 1.0


class JobCancelled(CancelledError):
    """Raised inside a running stage when the job's cancellation was requested."""

    def __init__(self, message: str = "cancelled while running") -> None:
        super().__init__(message)


class CancelWatch:
    """Raise :class:`JobCancelled` in the calling thread once ``requested()`` turns true (while armed)."""

    def __init__(self, job_id: uuid.UUID, requested: Callable[[], bool], poll_s: float = POLL_S) -> None:
        self.job_id = job_id
        self.requested = requested
        self.poll_s = poll_s
        self.armed = False
        self.pending = False
        self._shielded = 0
        self._stop = threading.Event()
        self._target: int | None = None

    def _handle(self, _signum: int, _frame: FrameType | None) -> None:
        if not self.armed:
            return
        if self._shielded:
            self.pending = True
            return
        self.armed = False
        raise JobCancelled()

    @contextmanager
    def shield(self) -> Iterator[None]:
        """No cancellation inside (a database write); a request that came meanwhile is raised right after."""
        self._shielded += 1
        try:
            yield
        finally:
            self._shielded -= 1
        if not self._shielded and self.pending and self.armed:
            self.pending = False
            self.armed = False
            raise JobCancelled()

    def _watch(self) -> None:
        while not self._stop.wait(self.poll_s):
            try:
                wanted = self.requested()
            except Exception as exc:  # the watcher must not die on a database hiccup; the next poll retries
                logger.warning("job %s: cancel check failed: %s", self.job_id, exc)
                continue
            if wanted and self.armed and self._target is not None:
                logger.info("job %s: cancellation requested while a stage runs; interrupting it", self.job_id)
                signal.pthread_kill(self._target, CANCEL_SIGNAL)
                return

    @contextmanager
    def running(self) -> Iterator[None]:
        """Arm the watch for the ``with`` block (the engine run)."""
        if threading.current_thread() is not threading.main_thread():
            yield
            return
        previous = signal.signal(CANCEL_SIGNAL, self._handle)
        self._target = threading.get_ident()
        self.armed = True
        watcher = threading.Thread(target=self._watch, name=f"cancel-watch-{self.job_id}", daemon=True)
        watcher.start()
        try:
            yield
        finally:
            self.armed = False
            self._stop.set()
            watcher.join()
            signal.signal(CANCEL_SIGNAL, previous if previous is not None else signal.SIG_DFL)
