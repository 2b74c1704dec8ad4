"""No silent successes in the benchmark commands: failed cases and wrong roots make them fail loudly."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from app.cli.main import main
from app.engine.errors import MetricError
from benchmark import paths
from benchmark.paths import check_assets_root, partnet_root

REPO = Path(__file__).resolve().parents[2]


def test_the_partnet_root_comes_from_the_environment_or_beside_the_repository(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    assert partnet_root({"ARTIMO_PARTNET_ROOT": str(tmp_path)}) == tmp_path
    with pytest.raises(MetricError, match=r"\$ARTIMO_PARTNET_ROOT is .* not a folder"):
        partnet_root({"ARTIMO_PARTNET_ROOT": str(tmp_path / "nothing")})
    monkeypatch.setattr(paths, "BESIDE_REPOSITORY", tmp_path / "missing")
    with pytest.raises(MetricError, match=r"set \$ARTIMO_PARTNET_ROOT .* or put them at .*missing"):
        partnet_root({})
    beside = tmp_path / "shared"
    beside.mkdir()
    monkeypatch.setattr(paths, "BESIDE_REPOSITORY", beside)
    monkeypatch.chdir(tmp_path / "..")  # not relative to the working directory
    assert partnet_root({}) == beside
    assert paths.BESIDE_REPOSITORY.is_absolute()


def test_a_root_holding_none_of_the_assets_is_an_error_naming_it(tmp_path: Path) -> None:
    with pytest.raises(MetricError, match=f"assets root {tmp_path} holds none of the 2 assets"):
        check_assets_root(tmp_path, ["safe_101593", "oven_7138"], "dev.jsonl")
    (tmp_path / "oven_7138").mkdir()
    assert check_assets_root(tmp_path, ["safe_101593", "oven_7138"], "dev.jsonl") == ["safe_101593"]


def test_bench_run_with_a_wrong_root_fails_and_names_it(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Before: 0 of 58 scored, exit 0."""
    cases = REPO / "benchmark" / "cases" / "dev.jsonl"
    code = main(["--no-cache", "bench", "run", "--cases", str(cases), "--assets", str(tmp_path), "--out", str(tmp_path / "out"), "--jobs", "1"])
    assert code == 1
    assert f"assets root {tmp_path} holds none of the" in capsys.readouterr().err
    assert not (tmp_path / "out" / "evaluation.json").exists()


def test_a_failed_case_makes_bench_run_exit_1_unless_tolerated(tmp_path: Path, examples_dir: Path, capsys: pytest.CaptureFixture[str]) -> None:
    source = REPO / "benchmark" / "cases" / "dev_examples.jsonl"
    case = json.loads(next(line for line in source.read_text().splitlines() if '"asset": "pedal_bin"' in line))
    refused = {**case, "case_id": "refused", "prompt": "fly the bin to the moon"}
    cases = tmp_path / "cases.jsonl"
    cases.write_text(json.dumps(case) + "\n" + json.dumps(refused) + "\n")
    common = ["--no-cache", "bench", "run", "--cases", str(cases), "--assets", str(examples_dir), "--jobs", "1", "--no-report"]
    assert main([*common, "--out", str(tmp_path / "a")]) == 1
    assert "1 of 2 cases failed" in capsys.readouterr().err
    assert main([*common, "--out", str(tmp_path / "b"), "--allow-failures"]) == 0


def test_bench_evaluate_exits_1_when_cases_are_not_scored(bench: dict[str, Path], tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    common = ["bench", "evaluate", "--cases", str(bench["cases"]), "--assets", str(bench["assets"]), "--pred", str(bench["pred"]),
              "--jobs", "1", "--no-report"]
    assert main([*common, "--out", str(tmp_path / "a.json")]) == 1  # one missing, one unreadable prediction, one broken case
    assert "3 of 6 cases were not scored" in capsys.readouterr().err
    assert main([*common, "--out", str(tmp_path / "b.json"), "--allow-failures"]) == 0


def test_bench_evaluate_uses_the_asset_cache(bench: dict[str, Path], tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Before: every asset loaded afresh (98% of the evaluation's time)."""
    import app.engine.asset.loader
    from benchmark import runner

    cache = tmp_path / "cache"
    runner._ASSETS.clear()  # nothing in memory from earlier tests: the first run fills the disk cache
    runner.evaluate(bench["cases"], bench["assets"], bench["pred"], tmp_path / "first.json", cache_dir=cache)
    runner._ASSETS.clear()
    monkeypatch.setattr(app.engine.asset.loader, "load_asset", lambda *_a, **_k: pytest.fail("loaded an asset despite the cache"))
    runner.evaluate(bench["cases"], bench["assets"], bench["pred"], tmp_path / "second.json", cache_dir=cache)
    first, second = (json.loads((tmp_path / name).read_text()) for name in ("first.json", "second.json"))
    assert first == second


def _script(module: str, *args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    environment = {**os.environ, **(env or {})}
    return subprocess.run([sys.executable, "-m", module, *args], cwd=REPO, env=environment, capture_output=True, text=True, timeout=300)


def test_speed_engine_with_a_wrong_root_is_a_clear_error(tmp_path: Path) -> None:
    """Before: a traceback."""
    done = _script("benchmark.speed_engine", "--assets", str(tmp_path), "--repeats", "1")
    assert done.returncode == 2 and f"{tmp_path} has no safe_101593/mobility.urdf" in done.stderr
    unset = _script("benchmark.speed_engine", env={"ARTIMO_PARTNET_ROOT": str(tmp_path / "nowhere")})
    assert unset.returncode == 2 and "ARTIMO_PARTNET_ROOT" in unset.stderr


def test_speed_agent_does_not_time_failed_runs(tmp_path: Path, examples_dir: Path) -> None:
    """Before: medians of failed runs, exit 0."""
    source = REPO / "benchmark" / "cases" / "dev_examples.jsonl"
    case = json.loads(next(line for line in source.read_text().splitlines() if '"asset": "pedal_bin"' in line))
    cases = tmp_path / "cases.jsonl"
    cases.write_text(json.dumps({**case, "prompt": "fly the bin to the moon"}) + "\n")
    done = _script("benchmark.speed_agent", "--cases", str(cases), "--assets", str(examples_dir))
    assert done.returncode == 1, done.stdout + done.stderr
    assert "no successful run" in done.stdout and "failed:" in done.stderr and "GroundingError" in done.stderr


@pytest.mark.parametrize("module", ["benchmark.speed_models", "benchmark.speed_exports"])
def test_speed_scripts_take_the_root_from_the_shared_resolver_and_name_a_wrong_one(module: str, tmp_path: Path) -> None:
    """Before: speed_models defaulted to a machine path and skipped every case; speed_exports ignored
    $ARTIMO_PARTNET_ROOT (set to a missing folder it ran on ../shared/assets/partnet and exited 0)."""
    nowhere = tmp_path / "nowhere"
    unset = _script(module, env={"ARTIMO_PARTNET_ROOT": str(nowhere)})
    assert unset.returncode == 2, unset.stdout + unset.stderr
    assert f"$ARTIMO_PARTNET_ROOT is {str(nowhere)!r}, which is not a folder" in unset.stderr
    wrong = _script(module, "--assets", str(tmp_path))
    assert wrong.returncode == 2, wrong.stdout + wrong.stderr
    assert str(tmp_path) in wrong.stderr and "wrong --assets?" in wrong.stderr
