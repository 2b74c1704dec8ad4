"""``artimo submit`` over real HTTP against the API in embedded mode (SQLite, migrated at start-up).

uvicorn serves ``create_app(settings)`` on a free loopback port in a thread; the enqueuer
runs the worker's task function in another thread, so ``--wait --out`` sees a finished job.
"""

from __future__ import annotations

import threading
import time
import uuid
from collections.abc import Iterator
from pathlib import Path

import pytest
import uvicorn

from app.api.deps import get_enqueuer
from app.cli.main import main
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
