"""``artimo submit`` over real HTTP against the API in embedded mode (SQLite, migrated at start-up).

uvicorn serves ``create_app(settings)`` on a free loopback port in a thread; the enqueuer
runs the worker's task function in another thread, so ``--wait --out`` sees a finished job.
"""

from __future__ import annotations

import threading
import time
import uuid
import zipfile
from collections.abc import Iterator
from pathlib import Path

import httpx
import pytest
import uvicorn

import app.client
from app.api.deps import get_enqueuer
from app.cli.main import main
from app.client import ArtimoClient, ClientError
from app.core.config import Settings
from app.main import create_app
from benchmark.service_stack import free_port
from tests.support.upload_assets import hinge_urdf

tasks = pytest.importorskip("workers.tasks", reason="the worker package is built by the workers helper")
KEY = "submit-test-key"
START_TIMEOUT_S = 20


@pytest.fixture
def server(tmp_path: Path) -> Iterator[str]:
    settings = Settings(_env_file=None, artimo_data_dir=tmp_path / "data", database_url=None, redis_url=None,  # type: ignore[call-arg]
                        artimo_api_key=KEY)  # type: ignore[arg-type]
    app = create_app(settings)

    def run_inline(job_id: uuid.UUID) -> None:
        threading.Thread(target=tasks.execute_job, args=(str(job_id),), kwargs={"settings": settings, "worker": "t"}).start()

    app.dependency_overrides[get_enqueuer] = lambda: run_inline
    port = free_port()
    uv = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_config=None, lifespan="on"))
    thread = threading.Thread(target=uv.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + START_TIMEOUT_S
    while not uv.started and time.monotonic() < deadline:
        time.sleep(0.05)
    assert uv.started, "uvicorn did not start"
    yield f"http://127.0.0.1:{port}"
    uv.should_exit = True
    thread.join(timeout=10)


def test_submit_folder_wait_and_download(server: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    folder = tmp_path / "box_lid"
    folder.mkdir()
    (folder / "mobility.urdf").write_text(hinge_urdf(name="box_lid"))
    out = tmp_path / "out"
    code = main(["submit", str(folder), "--prompt", "open the lid", "--server", server, "--key", KEY, "--out", str(out), "--timeout", "60"])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    assert '"status": "succeeded"' in captured.out
    assert (out / "animation.glb").read_bytes()[:4] == b"glTF"
    assert (out / "trajectory.jsonl").is_file() and (out / "report.json").is_file()


def test_submit_reports_the_servers_message(server: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    folder = tmp_path / "broken"
    folder.mkdir()
    (folder / "mobility.urdf").write_text(hinge_urdf(mesh_file="meshes/missing.obj"))
    assert main(["submit", str(folder), "--prompt", "open", "--server", server, "--key", KEY]) == 1
    error = capsys.readouterr().err
    assert "HTTP 422" in error and "missing.obj" in error
    assert main(["submit", str(folder), "--prompt", "open", "--server", server, "--key", "wrong"]) == 1
    assert "HTTP 401" in capsys.readouterr().err


def _two_assets(tmp_path: Path) -> Path:
    folder = tmp_path / "many"
    for name in ("bin", "box"):
        (folder / name).mkdir(parents=True)
        (folder / name / "mobility.urdf").write_text(hinge_urdf(name=name))
    return folder


def test_submit_refuses_several_urdfs_before_uploading(server: str, tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    """Before: the whole folder was zipped and uploaded, then the server's refusal printed its list three times."""
    folder = _two_assets(tmp_path)
    with zipfile.ZipFile(tmp_path / "many.zip", "w") as archive:
        for path in sorted(folder.rglob("*.urdf")):
            archive.write(path, path.relative_to(folder).as_posix())
    zipped = []
    monkeypatch.setattr(app.client, "zip_folder", lambda path: zipped.append(path) or b"")
    for asset in (folder, tmp_path / "many.zip"):
        assert main(["submit", str(asset), "--prompt", "open the lid", "--server", server, "--key", KEY]) == 1
        error = capsys.readouterr().err
        assert "holds 2 URDF files (bin/mobility.urdf, box/mobility.urdf); choose one with --urdf NAME" in error
        assert error.count("box/mobility.urdf") == 1 and "HTTP" not in error, error
    assert zipped == []
    assert main(["submit", str(folder), "--urdf", "box/nothing.urdf", "--prompt", "open", "--server", server, "--key", KEY]) == 1
    assert "the requested URDF 'box/nothing.urdf' matches none" in capsys.readouterr().err and zipped == []
    assert httpx.get(f"{server}/v1/assets", headers={"Authorization": f"Bearer {KEY}"}).json()["data"] == []  # nothing reached the server


def test_the_servers_several_urdf_refusal_lists_them_once(server: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Through the API (another client, no local check): one list, naming the upload, not the temporary file."""
    with ArtimoClient(server, KEY) as client, pytest.raises(ClientError) as refused:
        client.submit(_two_assets(tmp_path), "open the lid")
    message = str(refused.value)
    assert refused.value.status == 422 and "holds 2 URDF files (bin/mobility.urdf, box/mobility.urdf)" in message
    assert message.count("box/mobility.urdf") == 1 and "(file many.zip, element *.urdf)" in message, message


def test_submit_with_urdf_chooses_one_of_several(server: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["submit", str(_two_assets(tmp_path)), "--urdf", "box/mobility.urdf", "--prompt", "open the lid", "--server", server,
                 "--key", KEY, "--wait", "--timeout", "60"])
    assert code == 0, capsys.readouterr().err
