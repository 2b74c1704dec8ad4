"""kombu's SQLAlchemy transport for the embedded SQLite broker: short polls, no left-over rows.

The stock transport polls its table once a second, which caps a worker at about one job per
second (a job of the offline agent takes ~0.3 s) and adds up to a second to every pick-up.
kombu reads ``polling_interval`` from the transport options, but this transport hands every
option to ``create_engine``, which rejects it, so the interval is set here instead.

kombu's queue model declares its ``messages`` relationship ``lazy="noload"``, which
SQLAlchemy 2.1 deprecates (a warning on every process's first broker use); the model is
declared here with a plain lazy relationship instead (the transport never reads it).

The stock transport also keeps every delivered message as a row marked invisible, so the
broker file grows by one row per job forever. A delivered row is never read again (kombu
holds unacknowledged messages in memory and re-publishes them if the channel closes
unacknowledged), so here a delivered message's row is deleted in the same transaction that
takes it, and rows left invisible by the stock transport are removed when a channel opens.
"""

from __future__ import annotations

import json
from queue import Empty
from typing import Any

from kombu.transport.sqlalchemy import Channel as SQLAlchemyChannel
from kombu.transport.sqlalchemy import Transport as SQLAlchemyTransport
from kombu.transport.sqlalchemy.models import Queue as QueueBase
from kombu.utils import cached_property
from kombu.utils.encoding import bytes_to_str
from sqlalchemy import text
from sqlalchemy.exc import OperationalError
from sqlalchemy.orm import declared_attr, relationship

POLL_INTERVAL_S = 0.1
"""Seconds between polls of the broker table when it is empty (one indexed SELECT each)."""


def _messages(_cls: Any) -> Any:
    return relationship("Message", backref="queue", lazy="select")


class Channel(SQLAlchemyChannel):
    @cached_property
    def queue_cls(self) -> Any:
        """kombu's queue model, its ``messages`` relationship not ``noload`` (deprecated in SQLAlchemy 2.1)."""
        namespace = {"__tablename__": self.queue_tablename, "messages": declared_attr(_messages)}
        return self._declarative_cls("Queue", QueueBase, namespace)

    def __init__(self, connection: Any, **kwargs: Any) -> None:
        super().__init__(connection, **kwargs)
        self._purge_delivered()

    def _purge_delivered(self) -> None:
        """Remove rows the stock transport left behind as delivered (``visible`` false).

        Best effort: a busy database (another process inside a write) leaves them for the next
        channel instead of failing this one.
        """
        message = self.message_cls
        try:
            self.session.query(message).filter(message.visible == False).delete(synchronize_session=False)  # noqa: E712
            self.session.commit()
        except OperationalError:
            self.session.rollback()

    def _get(self, queue: str, timeout: Any = None) -> Any:  # noqa: ARG002 (kombu passes it; the poll interval governs waiting)
        """The oldest visible message of ``queue``, deleted as it is taken."""
        owner = self._get_or_create(queue)
        message = self.message_cls
        if self.session.bind.name == "sqlite":
            self.session.execute(text("BEGIN IMMEDIATE TRANSACTION"))
        try:
            row = (
                self.session.query(message)
                .with_for_update()
                .filter(message.queue_id == owner.id)
                .filter(message.visible != False)  # noqa: E712
                .order_by(message.sent_at)
                .order_by(message.id)
                .limit(1)
                .first()
            )
            if row is None:
                raise Empty()
            payload = row.payload
            self.session.delete(row)
            return json.loads(bytes_to_str(payload))
        finally:
            self.session.commit()


class Transport(SQLAlchemyTransport):
    Channel = Channel
    polling_interval = POLL_INTERVAL_S
