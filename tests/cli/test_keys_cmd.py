"""``artimo keys create/list/disable`` on an embedded (SQLite) database."""

from __future__ import annotations

from pathlib import Path

import pytest

from app.cli.main import main
from app.core.config import get_settings
from app.crud.clients import client_by_key
from app.db.session import session_factory


@pytest.fixture
def embedded(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):  # type: ignore[no-untyped-def]
    monkeypatch.setenv("ARTIMO_DATA_DIR", str(tmp_path))
    monkeypatch.delenv("DATABASE_URL", raising=False)
    get_settings.cache_clear()
    yield get_settings()
    get_settings.cache_clear()


def test_create_list_disable(embedded, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["keys", "create", "--name", "alice", "--rate-limit", "30"]) == 0
    key = capsys.readouterr().out.strip()
    assert key.startswith("artimo_") and len(key) > 30
    with session_factory(embedded.sqlalchemy_url)() as session:
        client = client_by_key(session, key=key)
        assert client is not None and client.name == "alice" and client.rate_limit_per_minute == 30
    assert main(["keys", "list"]) == 0
    listing = capsys.readouterr().out
    assert "alice" in listing and key[:12] in listing and key not in listing
    assert main(["keys", "disable", key[:12]]) == 0
    with session_factory(embedded.sqlalchemy_url)() as session:
        assert client_by_key(session, key=key) is None


def test_bad_rate_limit_is_refused(embedded) -> None:
    assert main(["keys", "create", "--name", "x", "--rate-limit", "0"]) == 2


def test_submit_without_key_fails_cleanly(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.delenv("ARTIMO_API_KEY", raising=False)
    assert main(["submit", str(tmp_path), "--prompt", "x", "--server", "http://127.0.0.1:1"]) == 2


def test_submit_to_an_unreachable_server_fails_cleanly(monkeypatch: pytest.MonkeyPatch, tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "mobility.urdf").write_text("<robot/>")
    assert main(["submit", str(tmp_path), "--prompt", "x", "--server", "http://127.0.0.1:1", "--key", "k"]) == 1
    assert "cannot reach the server" in capsys.readouterr().err


def test_create_says_which_database_the_key_belongs_to(embedded, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["keys", "create", "--name", "bob"]) == 0
    said = capsys.readouterr().err
    assert f"sqlite:///{embedded.data_dir / 'artimo.db'}" in said and f"ARTIMO_DATA_DIR={embedded.data_dir}" in said


def test_a_postgres_password_is_never_printed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from app.core.config import Settings

    settings = Settings(_env_file=None, database_url="postgresql+psycopg://artimo:s3cret@db.example/artimo")  # type: ignore[call-arg]
    assert "s3cret" not in settings.database_shown and "db.example/artimo" in settings.database_shown
