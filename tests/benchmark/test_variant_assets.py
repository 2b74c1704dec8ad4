"""The variant assets of a dev round are written again from the shared folders and a manifest, alike every time."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from benchmark import variant_assets
from benchmark.variants import make_variant
from tests.conftest import partnet_root


def _manifest(tmp_path: Path, steps: list[list[str]]) -> Path:
    path = tmp_path / "manifest.json"
    path.write_text(json.dumps({"g/faucet_148": {"source": "partnet/faucet_148", "steps": steps}}))
    return path


def test_steps_apply_in_order_and_match_a_direct_variant(tmp_path: Path) -> None:
    out = tmp_path / "out"
    assert variant_assets.main(["--manifest", str(_manifest(tmp_path, [["mirror", "yaw"]])), "--assets", str(partnet_root().parent),
                                "--out", str(out)]) == 0
    make_variant(partnet_root() / "faucet_148", tmp_path / "direct" / "faucet_148", ("mirror", "yaw"))
    assert (out / "g" / "faucet_148" / "mobility.urdf").read_bytes() == (tmp_path / "direct" / "faucet_148" / "mobility.urdf").read_bytes()
    assert (out / "g" / "faucet_148" / "semantics.txt").is_file()


def test_two_steps_compose(tmp_path: Path) -> None:
    variant_assets.write_assets({"g/faucet_148": {"source": "partnet/faucet_148", "steps": [["yaw"], ["yaw"]]}}, partnet_root().parent, tmp_path)
    text = (tmp_path / "g" / "faucet_148" / "mobility.urdf").read_text()
    assert text != (partnet_root() / "faucet_148" / "mobility.urdf").read_text()


@pytest.mark.parametrize(("steps", "message"), [([["spin"]], "unknown transforms"), ([], "no steps")])
def test_a_bad_manifest_is_an_error(tmp_path: Path, steps: list[list[str]], message: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert variant_assets.main(["--manifest", str(_manifest(tmp_path, steps)), "--assets", str(partnet_root().parent), "--out", str(tmp_path / "o")]) == 2
    assert message in capsys.readouterr().err


def test_a_missing_source_is_an_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert variant_assets.main(["--manifest", str(_manifest(tmp_path, [["mirror"]])), "--assets", str(tmp_path), "--out", str(tmp_path / "o")]) == 2
    assert "source asset not found" in capsys.readouterr().err


def test_a_stack_repeats_the_object_with_every_name_unique(tmp_path: Path) -> None:
    """``stack3z``: three copies one above the other, each with its own moving parts, fixed to the first copy's root."""
    from app.engine.asset.loader import load_asset
    from app.engine.asset.summary import world_bounds

    variant_assets.write_assets({"g/storage_19179": {"source": "partnet/storage_19179", "steps": [["stack3z"]]}}, partnet_root().parent, tmp_path)
    source, stacked = load_asset(partnet_root() / "storage_19179"), load_asset(tmp_path / "g" / "storage_19179")
    assert len(stacked.movable_joints) == 3 * len(source.movable_joints)
    assert len(set(stacked.links)) == 3 * len(source.links)
    height = lambda model: float(max(b[1][2] for b in world_bounds(model).values()) - min(b[0][2] for b in world_bounds(model).values()))  # noqa: E731
    assert height(stacked) == pytest.approx(3 * height(source) + 2 * 0.02, rel=1e-6)
    lines = (tmp_path / "g" / "storage_19179" / "semantics.txt").read_text().split("\n")
    assert len([line for line in lines if line]) == 3 * len([line for line in (partnet_root() / "storage_19179" / "semantics.txt").read_text().split("\n") if line])
