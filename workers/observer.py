"""The pipeline observer of a job: stage/progress/messages go to the DB, cancellation comes from it.

The engine calls :meth:`JobObserver.on_stage` before each stage and :meth:`should_stop`
between stages; each call is one short transaction, so the API sees progress while the
job runs and a ``cancel_requested`` flag stops it at the next stage.
"""

from __future__ import annotations

import logging
import time
import uuid
from collections.abc import Callable
from contextlib import AbstractContextManager, nullcontext

from sqlalchemy import select
from sqlalchemy.orm import Session, sessionmaker

from app.crud import jobs as crud_jobs
from app.db.models import Job

logger = logging.getLogger(__name__)

MAX_MESSAGE_CHARS = 4000


class JobObserver:
    """Implements the engine's ``PipelineObserver`` protocol for one job, plus ``should_stop``.

    Parameters
    ----------
    sessions
        Session factory of the job database.
    job_id
        The job being run.
    stage_delay_s
        Pause after each stage, seconds (``Settings.job_stage_delay_s``; 0 in production).
    """

    def __init__(self, sessions: sessionmaker[Session], job_id: uuid.UUID, *, stage_delay_s: float = 0.0) -> None:
        self.sessions = sessions
        self.job_id = job_id
        self.stage_delay_s = stage_delay_s
        self.stages_seen: list[str] = []
        self.shield: Callable[[], AbstractContextManager[None]] = nullcontext
        """Wraps each database write (a cancel watch keeps interruptions out of them)."""

    def on_stage(self, stage: str, progress: int) -> None:
        with self.shield(), self.sessions() as session:
            job = session.get(Job, self.job_id)
            if job is None:
                logger.warning("job %s vanished while running", self.job_id)
                return
            crud_jobs.set_progress(session, job=job, stage=stage, progress=progress)
        self.stages_seen.append(stage)
        logger.info("job %s: stage %s (%d%%)", self.job_id, stage, progress)
        if self.stage_delay_s > 0:
            time.sleep(self.stage_delay_s)

    def on_message(self, message: str) -> None:
        with self.shield(), self.sessions() as session:
            crud_jobs.record_event(session, job_id=self.job_id, kind="message", message=message[:MAX_MESSAGE_CHARS])

    def should_stop(self) -> bool:
        """The engine's check between stages (in the job's thread)."""
        with self.shield():
            return self.cancel_requested()

    def cancel_requested(self) -> bool:
        """Whether the job was cancelled (or deleted); safe from any thread (one short session)."""
        with self.sessions() as session:
            requested = session.execute(select(Job.cancel_requested).where(Job.id == self.job_id)).scalar_one_or_none()
        return bool(requested) if requested is not None else True
