"""Every GLB the export tests write passes the Khronos glTF-Validator with 0 errors and
0 warnings (the harness fails, never skips, when node or the npm package is missing)."""

from __future__ import annotations

import io
import json
import struct
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from app import gltf_validation as gltf_validator
from app.engine.asset.model import Material, MeshPart
from app.engine.execute.trajectory import Trajectory
from app.engine.export.glb import export_glb, glb_bytes
from app.engine.export.gltf_builder import clean_png
from tests.support.glb_cases import ExportCase, build_tiny_asset, build_tiny_trajectory, tiny_png
from tests.support.gltf_validator import ValidatorUnavailable, assert_valid, validate_glb


def _icc_png() -> bytes:
    """A PIL PNG carrying colour-space chunks (iCCP, gAMA, pHYs) and text."""
    image = Image.new("RGB", (3, 2), (200, 30, 90))
    buffer = io.BytesIO()
    from PIL import ImageCms, PngImagePlugin

    profile = ImageCms.ImageCmsProfile(ImageCms.createProfile("sRGB")).tobytes()
    info = PngImagePlugin.PngInfo()
    info.add_text("Comment", "made by a test")
    image.save(buffer, format="PNG", icc_profile=profile, dpi=(72, 96), pnginfo=info)
    data = buffer.getvalue()
    assert b"iCCP" in data and b"pHYs" in data
    return data


def test_every_written_glb_is_valid(export_cases: dict[str, ExportCase], tmp_path: Path) -> None:
    asset, trajectory = build_tiny_asset(), build_tiny_trajectory()
    extra = [export_glb(asset, trajectory, tmp_path / "tiny.glb")]
    single = Trajectory(
        fps=30,
        times=np.zeros(1),
        joint_names=("hinge",),
        q=np.zeros((1, 1)),
        base_translation=np.zeros((1, 3)),
        base_rotation_xyzw=np.array([[0.0, 0.0, 0.0, 1.0]]),
    )
    extra.append(export_glb(asset, single, tmp_path / "single_frame.glb"))
    still = Trajectory(
        fps=10,
        times=np.arange(3) / 10.0,
        joint_names=("hinge",),
        q=np.full((3, 1), 0.4),
        base_translation=np.zeros((3, 3)),
        base_rotation_xyzw=np.tile([0.0, 0.0, 0.0, 1.0], (3, 1)),
    )
    extra.append(export_glb(asset, still, tmp_path / "still.glb"))
    reports = assert_valid([case.path for case in export_cases.values()] + extra)
    assert len(reports) == len(export_cases) + len(extra)
    assert all(r.validator_version == "2.0.0-dev.3.10" for r in reports)


def test_textures_with_colour_profiles_are_cleaned(tmp_path: Path) -> None:
    asset = build_tiny_asset()
    arm = asset.links["arm"]
    part = arm.parts[0]
    recoloured = MeshPart(
        part.vertices, part.faces, part.normals, part.uv, Material(name="icc", image_png=_icc_png()), part.source
    )
    object.__setattr__(arm, "parts", (recoloured, arm.parts[1]))
    path = export_glb(asset, build_tiny_trajectory(), tmp_path / "icc.glb")
    assert_valid([path])
    cleaned = clean_png(_icc_png())
    assert b"iCCP" not in cleaned and b"pHYs" not in cleaned and b"tEXt" not in cleaned
    same = np.asarray(Image.open(io.BytesIO(cleaned)).convert("RGB"))
    assert np.array_equal(same, np.asarray(Image.open(io.BytesIO(_icc_png())).convert("RGB")))
    assert clean_png(tiny_png()) == tiny_png()


def test_the_harness_reports_a_broken_file(tmp_path: Path) -> None:
    data = bytearray(glb_bytes(build_tiny_asset(), build_tiny_trajectory()))
    (length,) = struct.unpack("<I", data[12:16])
    document = json.loads(bytes(data[20 : 20 + length]))
    position = document["meshes"][0]["primitives"][0]["attributes"]["POSITION"]
    document["accessors"][position]["min"][0] -= 1.0
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    broken = (
        struct.pack("<4sII", b"glTF", 2, 0)
        + struct.pack("<II", len(text), 0x4E4F534A)
        + text
        + bytes(data[20 + length :])
    )
    broken = broken[:8] + struct.pack("<I", len(broken)) + broken[12:]
    path = tmp_path / "broken.glb"
    path.write_bytes(broken)
    (report,) = validate_glb([path])
    assert report.num_errors >= 1 and not report.clean
    assert any(m["code"] == "ACCESSOR_MIN_MISMATCH" for m in report.messages)
    with pytest.raises(AssertionError, match="ACCESSOR_MIN_MISMATCH"):
        assert_valid([path])


def test_a_missing_validator_fails_with_the_install_command(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setattr(gltf_validator, "PACKAGE", tmp_path / "missing" / "package.json")
    with pytest.raises(ValidatorUnavailable, match="npm install --prefix tests/tools/gltf_validator"):
        validate_glb([tmp_path / "any.glb"])
    monkeypatch.setattr(gltf_validator.shutil, "which", lambda _name: None)
    with pytest.raises(ValidatorUnavailable, match="node is not installed"):
        validate_glb([tmp_path / "any.glb"])
