"""``artimo jobs list|show|download|cancel``, ``submit --model/--urdf``, ``validate-glb`` and ``--version``
as a user runs them (in process, against a real uvicorn serving the app)."""

from __future__ import annotations

import json
import socket
import threading
import time
import uuid
from collections.abc import Iterator
from pathlib import Path

import pytest
import uvicorn

from app.cli.main import main
from app.core.config import Settings
from app.main import create_app


@pytest.fixture
def server(settings: Settings, sent: list[uuid.UUID]) -> Iterator[str]:
    from app.api.deps import get_enqueuer

    application = create_app(settings)
    application.dependency_overrides[get_enqueuer] = lambda: sent.append
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    instance = uvicorn.Server(uvicorn.Config(application, host="127.0.0.1", port=port, log_config=None))
    thread = threading.Thread(target=instance.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 20
    while not instance.started:
        assert time.monotonic() < deadline, "uvicorn did not start"
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}"
    instance.should_exit = True
    thread.join(10)


def test_version(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as done:
        main(["--version"])
    assert done.value.code == 0 and capsys.readouterr().out.startswith("artimo 0.")


def test_jobs_commands_against_a_server(server, alice, settings, sent, capsys, tmp_path: Path, examples_dir: Path) -> None:  # type: ignore[no-untyped-def]
    from workers.tasks import execute_job

    common = ["--server", server, "--key", alice.key]
    assert main(["submit", str(examples_dir / "pedal_bin"), "--prompt", "press the pedal to open the bin", *common,
                 "--model", "critic=geometric", "--fps", "24"]) == 0
    job_id = capsys.readouterr().out.strip()
    assert main(["jobs", "show", job_id, *common]) == 0
    shown = json.loads(capsys.readouterr().out)
    assert shown["status"] == "queued" and shown["options"] == {"critic_model": "geometric", "fps": 24}
    execute_job(str(sent[-1]), settings=settings, worker="inline")
    assert main(["jobs", "list", *common]) == 0
    listing = capsys.readouterr().out
    assert job_id in listing and "succeeded" in listing and "1 of 1 jobs" in listing
    assert main(["jobs", "download", job_id, "--out", str(tmp_path / "out"), *common]) == 0
    assert (tmp_path / "out" / "animation.glb").is_file() and (tmp_path / "out" / "report.json").is_file()
    assert main(["validate-glb", str(tmp_path / "out" / "animation.glb")]) == 0
    assert "0 errors, 0 warnings" in capsys.readouterr().out
    assert main(["jobs", "cancel", job_id, *common]) == 1  # already finished
    assert "already succeeded" in capsys.readouterr().err


def test_jobs_cancel_and_bad_ids(server, alice, capsys, examples_dir: Path) -> None:  # type: ignore[no-untyped-def]
    common = ["--server", server, "--key", alice.key]
    assert main(["submit", str(examples_dir / "oven"), "--prompt", "open the oven", *common]) == 0
    job_id = capsys.readouterr().out.strip()
    assert main(["jobs", "cancel", job_id, *common]) == 0
    assert "cancelled" in capsys.readouterr().out
    assert main(["jobs", "show", "not-a-job", *common]) == 1
    assert "job_id must be a UUID" in capsys.readouterr().err


def test_submit_with_a_urdf_choice_and_bad_model_option(server, alice, capsys, tmp_path: Path, examples_dir: Path) -> None:  # type: ignore[no-untyped-def]
    import shutil

    both = tmp_path / "both"
    shutil.copytree(examples_dir / "oven", both / "oven")
    shutil.copytree(examples_dir / "pedal_bin", both / "pedal_bin")
    common = ["--server", server, "--key", alice.key]
    assert main(["submit", str(both), "--prompt", "open the oven", *common]) == 1
    assert "oven/oven.urdf, pedal_bin/pedal_bin.urdf" in capsys.readouterr().err
    assert main(["submit", str(both), "--urdf", "oven.urdf", "--prompt", "open the oven", *common]) == 0
    capsys.readouterr()
    assert main(["submit", str(both), "--model", "judge=x", "--prompt", "p", *common]) == 2
    assert "ROLE=NAME" in capsys.readouterr().err


def test_unreachable_server_and_missing_key_are_clear(capsys, monkeypatch: pytest.MonkeyPatch) -> None:  # type: ignore[no-untyped-def]
    monkeypatch.delenv("ARTIMO_API_KEY", raising=False)
    assert main(["jobs", "list", "--server", "http://127.0.0.1:9"]) == 2
    assert "no API key" in capsys.readouterr().err
    assert main(["jobs", "list", "--server", "http://127.0.0.1:9", "--key", "k"]) == 1
    assert "cannot reach the server at http://127.0.0.1:9" in capsys.readouterr().err


def test_validate_glb_reports_problems_and_a_missing_file(capsys, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    bad = tmp_path / "bad.glb"
    bad.write_bytes(b"glTF not really")
    assert main(["validate-glb", str(bad)]) == 1
    assert "bad.glb" in capsys.readouterr().out
    assert main(["validate-glb", str(tmp_path / "none.glb")]) == 2
    assert "no such file" in capsys.readouterr().err
