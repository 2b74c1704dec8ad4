"""The embedded broker's transport: messages arrive in order, and no delivered row stays behind."""

from __future__ import annotations

import sqlite3
from pathlib import Path

from kombu import Connection

from workers.broker import SQLITE_TRANSPORT


def _rows(database: Path) -> list[tuple[int, str]]:
    with sqlite3.connect(database) as db:
        return db.execute("SELECT visible, payload FROM kombu_message ORDER BY id").fetchall()


def _connection(database: Path, transport: str = SQLITE_TRANSPORT) -> Connection:
    return Connection(f"sqlite:///{database}", transport=transport, transport_options={"connect_args": {"timeout": 5}})


def _take(queue, count: int) -> list[int]:  # type: ignore[no-untyped-def]
    """Receive and acknowledge ``count`` messages; their job numbers in order."""
    received = []
    for _ in range(count):
        message = queue.get(timeout=5)
        received.append(message.payload["job"])
        message.ack()
    return received


def test_delivered_messages_leave_no_rows(tmp_path: Path) -> None:
    database = tmp_path / "broker.db"
    with _connection(database) as connection:
        queue = connection.SimpleQueue("jobs")
        for number in range(5):
            queue.put({"job": number})
        assert [visible for visible, _ in _rows(database)] == [1] * 5
        assert _take(queue, 5) == [0, 1, 2, 3, 4]
        queue.close()
    assert _rows(database) == []


def test_rows_left_by_the_stock_transport_are_removed(tmp_path: Path) -> None:
    database = tmp_path / "broker.db"
    with _connection(database, "sqlalchemy") as connection:  # kombu's own: keeps delivered rows invisible
        queue = connection.SimpleQueue("jobs")
        for number in range(3):
            queue.put({"job": number})
        queue.get(timeout=5).ack()
        queue.close()
    assert [visible for visible, _ in _rows(database)] == [0, 1, 1]
    with _connection(database) as connection:
        queue = connection.SimpleQueue("jobs")  # opening a channel sweeps the delivered row
        assert [visible for visible, _ in _rows(database)] == [1, 1]
        assert _take(queue, 2) == [1, 2]
        queue.close()
    assert _rows(database) == []


def test_an_unacknowledged_message_is_delivered_again(tmp_path: Path) -> None:
    database = tmp_path / "broker.db"
    with _connection(database) as connection:
        queue = connection.SimpleQueue("jobs")
        queue.put({"job": 7})
        assert queue.get(timeout=5).payload == {"job": 7}  # taken, never acknowledged
        queue.close()  # kombu publishes it again
    with _connection(database) as connection:
        queue = connection.SimpleQueue("jobs")
        message = queue.get(timeout=5)
        assert message.payload == {"job": 7}
        message.ack()
        queue.close()
    assert _rows(database) == []
