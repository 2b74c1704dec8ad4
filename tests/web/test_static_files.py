"""The page's files and the API docs reference nothing outside this server (no CDN), and a
missing front-end install is reported clearly instead of a blank page."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from app.core.config import Settings
from app.main import create_app
from app.web import mount

REMOTE = re.compile(r"""(?:src|href|from|import|url)\s*[=(]?\s*["']?(?:https?:)?//""", re.IGNORECASE)


@pytest.fixture
def http(tmp_path: Path) -> TestClient:
    settings = Settings(_env_file=None, artimo_data_dir=tmp_path)  # type: ignore[call-arg]
    return TestClient(create_app(settings))


def test_static_files_load_nothing_remote() -> None:
    files = [p for p in mount.STATIC_DIR.rglob("*") if p.suffix in (".html", ".js", ".css")]
    assert len(files) >= 10
    for path in files:
        text = path.read_text(encoding="utf-8")
        assert not REMOTE.search(text), f"{path.name} loads something from another host"


def test_page_and_import_map(http: TestClient) -> None:
    page = http.get("/")
    assert page.status_code == 200 and page.headers["content-type"].startswith("text/html")
    assert '"three": "/vendor/three/build/three.module.js"' in page.text
    for testid in ("api-key",):
        assert f'data-testid="{testid}"' in page.text
    assert http.get("/vendor/three/build/three.module.js").status_code == 200
    assert http.get("/vendor/three/examples/jsm/loaders/GLTFLoader.js").status_code == 200
    assert http.get("/static/js/main.js").headers["content-type"].startswith("text/javascript")


@pytest.mark.parametrize(("path", "assets"), [
    ("/docs", ["/vendor/swagger-ui/swagger-ui-bundle.js", "/vendor/swagger-ui/swagger-ui.css"]),
    ("/redoc", ["/vendor/redoc/redoc.standalone.js"]),
])
def test_docs_use_local_copies(http: TestClient, path: str, assets: list[str]) -> None:
    html = http.get(path).text
    assert "http://" not in html and "https://" not in html, html
    for asset in assets:
        assert asset in html
        response = http.get(asset)
        assert response.status_code == 200 and len(response.content) > 10_000
        assert b"https://cdn." not in response.content


def test_every_stable_test_hook_exists() -> None:
    text = "".join(p.read_text(encoding="utf-8") for p in mount.STATIC_DIR.rglob("*") if p.suffix in (".html", ".js"))
    for testid in ("api-key", "asset-file", "prompt", "submit", "job-status", "viewer-canvas", "play", "scrubber",
                   "joint-panel", "phase-timeline", "explain", "plan-editor", "run-plan", "artifact-links"):
        assert f'testid: "{testid}"' in text or f'data-testid="{testid}"' in text, testid


def test_missing_packages_answer_with_the_install_hint(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(mount, "VENDOR", {"three": tmp_path / "absent"})
    settings = Settings(_env_file=None, artimo_data_dir=tmp_path)  # type: ignore[call-arg]
    response = TestClient(create_app(settings)).get("/vendor/three/build/three.module.js")
    assert response.status_code == 503 and "npm ci --prefix app/web" in response.text
