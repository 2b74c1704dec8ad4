"""``artimo serve``'s key line says which database and data folder the key belongs to, in each of its three cases."""

from __future__ import annotations

from pathlib import Path

from pydantic import SecretStr

from app.cli.serve_cmd import _api_key
from app.core.config import Settings
from app.db.migrate import upgrade


def _settings(data_dir: Path, key: str | None = None) -> Settings:
    settings = Settings(artimo_data_dir=data_dir, database_url=None, artimo_api_key=SecretStr(key) if key else None)
    settings.data_dir.mkdir(parents=True, exist_ok=True)
    upgrade(settings.sqlalchemy_url)
    return settings


def test_every_key_line_names_the_database_and_the_data_folder(tmp_path: Path) -> None:
    data_dir = tmp_path / "data"
    database = f"database sqlite:///{data_dir / 'artimo.db'}"
    generated, _ = _api_key(_settings(data_dir))
    assert generated.startswith("API key (shown once, stored hashed): artimo_")
    assert f"(valid for the {database}; data folder {data_dir})" in generated
    again, _ = _api_key(_settings(data_dir))
    assert f"printed when this {database} was first served" in again and f"ARTIMO_DATA_DIR={data_dir}" in again
    from_environment, _ = _api_key(_settings(data_dir, "artimo_test_key_0123456789abcdef"))
    assert from_environment.startswith("API key: the value of $ARTIMO_API_KEY (")
    assert f"registered in the {database} (data folder {data_dir})" in from_environment  # before: "for any database ...", no folder
