"""kombu's SQLAlchemy transport with a short poll interval, for the embedded SQLite broker.

The stock transport polls its table once a second, which caps a worker at about one job per
second (a job of the offline agent takes ~0.3 s) and adds up to a second to every pick-up.
kombu reads ``polling_interval`` from the transport options, but this transport hands every
option to ``create_engine``, which rejects it, so the interval is set here instead.
"""

from __future__ import annotations

from kombu.transport.sqlalchemy import Transport as SQLAlchemyTransport

POLL_INTERVAL_S = 0.1
"""Seconds between polls of the broker table when it is empty (one indexed SELECT each)."""


class Transport(SQLAlchemyTransport):
    polling_interval = POLL_INTERVAL_S
