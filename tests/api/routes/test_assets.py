"""POST /v1/assets and GET /v1/assets/{ref}: upload, dedupe, validation errors, limits."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from app.core.asset_summary import summary_key
from app.core.config import Settings
from app.main import create_app
from tests.support import upload_assets as assets


def _upload(http: TestClient, headers: dict[str, str], *uploads: tuple[str, bytes]):  # type: ignore[no-untyped-def]
    return http.post("/v1/assets", headers=headers, files=[("asset", (name, data)) for name, data in uploads])


def test_zip_upload_is_stored_once_and_reused(http, alice, settings) -> None:
    first = _upload(http, alice.headers, assets.cabinet_zip())
    assert first.status_code == 201, first.text
    body = first.json()
    assert body["created"] is True and body["filename"] == "cabinet.zip" and len(body["sha256"]) == 64
    again = _upload(http, alice.headers, assets.cabinet_zip())
    assert again.status_code == 200
    assert again.json()["id"] == body["id"] and again.json()["created"] is False
    stored = sorted(p.name for p in (settings.storage_dir / "assets").iterdir())
    assert stored == [summary_key(body["sha256"], "mobility.urdf").split("/")[1], f"{body['sha256']}.zip"]
    assert body["urdf"] == "mobility.urdf"


def test_multi_file_upload_is_packed_deterministically(http, alice) -> None:
    first = _upload(http, alice.headers, *assets.mesh_asset_files())
    assert first.status_code == 201, first.text
    assert first.json()["filename"] == "door.zip"
    reordered = _upload(http, alice.headers, *reversed(assets.mesh_asset_files()))
    assert reordered.status_code == 200
    assert reordered.json()["sha256"] == first.json()["sha256"]


def test_asset_is_found_by_id_and_sha256_but_not_by_other_clients(http, alice, bob) -> None:
    body = _upload(http, alice.headers, assets.hinge_zip("-lookup")).json()
    for ref in (body["id"], body["sha256"], body["sha256"].upper()):
        found = http.get(f"/v1/assets/{ref}", headers=alice.headers)
        assert found.status_code == 200 and found.json()["id"] == body["id"]
    assert http.get(f"/v1/assets/{body['id']}", headers=bob.headers).status_code == 404
    assert http.get(f"/v1/assets/{body['sha256']}", headers=bob.headers).status_code == 404
    assert http.get("/v1/assets/not-a-ref", headers=alice.headers).status_code == 404


def test_summary_lists_joints_limits_and_sizes(http, alice, bob, settings) -> None:
    body = _upload(http, alice.headers, assets.hinge_zip("-summary")).json()
    summary = http.get(body["summary_url"], headers=alice.headers)
    assert summary.status_code == 200, summary.text
    data = summary.json()
    (hinge,) = data["joints"]
    assert hinge["joint_name"] == "lid_hinge" and hinge["type"] == "revolute"
    assert (hinge["parent"], hinge["child"]) == ("base", "lid") and hinge["axis"] == [1.0, 0.0, 0.0]
    assert (hinge["limit"]["lower"], hinge["limit"]["upper"]) == (0.0, 1.5)
    assert data["links"] == ["base", "lid"]
    assert data["scale"]["object_bbox_extents_m"] == pytest.approx([1.0, 1.0, 0.6], abs=1e-6)
    assert http.get(f"/v1/assets/{body['sha256']}/summary", headers=bob.headers).status_code == 404
    assert http.get("/v1/assets/not-a-ref/summary", headers=alice.headers).status_code == 404

    assert data["urdf"] == "mobility.urdf" and data["scale"]["asset"] == "hinge-summary"
    lid = next(p for p in data["layout"]["parts"] if p["link"] == "lid")
    assert lid["joint"] == "lid_hinge" and lid["vertical"] == "top"
    (ends,) = data["layout"]["joints"]
    assert ends["joint"] == "lid_hinge" and ends["rest_end"] == "lower"

    # an asset stored before summaries existed gets its summary on first request, then keeps it
    kept = settings.storage_dir / summary_key(body["sha256"], "mobility.urdf")
    kept.unlink()
    again = http.get(f"/v1/assets/{body['id']}/summary", headers=alice.headers)
    assert again.status_code == 200 and again.json() == data and kept.is_file()


def test_same_content_from_another_client_is_a_record_of_its_own(http, alice, bob, settings) -> None:
    """Bob learns nothing of Alice's upload: his own id, name and time; the bytes are stored once."""
    first = _upload(http, alice.headers, ("alice-name.zip", assets.hinge_zip("-shared")[1])).json()
    second = _upload(http, bob.headers, ("bob-name.zip", assets.hinge_zip("-shared")[1]))
    assert second.status_code == 201 and second.json()["created"] is True
    theirs = second.json()
    assert theirs["id"] != first["id"] and theirs["created_at"] != first["created_at"] and theirs["filename"] == "bob-name.zip"
    assert theirs["sha256"] == first["sha256"]
    assert http.get(f"/v1/assets/{first['id']}", headers=bob.headers).status_code == 404
    assert http.get(f"/v1/assets/{theirs['sha256']}", headers=bob.headers).json()["id"] == theirs["id"]
    summary = http.get(f"/v1/assets/{theirs['id']}/summary", headers=bob.headers).json()
    assert summary["scale"]["asset"] == "bob-name"
    assert len(list((settings.storage_dir / "assets").glob("*.zip"))) == 1


def test_a_zip_of_two_assets_needs_a_urdf_choice(http, alice) -> None:
    two = ("two.zip", assets.zip_bytes({"cap/mobility.urdf": assets.hinge_urdf(name="cap"),
                                        "bin/mobility.urdf": assets.hinge_urdf(name="bin")}))
    refused = _upload(http, alice.headers, two)
    assert refused.status_code == 422 and refused.json()["kind"] == "AssetError"
    assert "bin/mobility.urdf, cap/mobility.urdf" in refused.json()["detail"] and "'urdf' field" in refused.json()["detail"]
    chosen = http.post("/v1/assets", headers=alice.headers, files=[("asset", two)], data={"urdf": "cap/mobility.urdf"})
    assert chosen.status_code == 201 and chosen.json()["urdf"] == "cap/mobility.urdf"
    other = http.post("/v1/assets", headers=alice.headers, files=[("asset", two)], data={"urdf": "bin/mobility.urdf"})
    assert other.status_code == 201 and other.json()["id"] != chosen.json()["id"]
    assert other.json()["sha256"] == chosen.json()["sha256"]
    ambiguous = http.get(f"/v1/assets/{chosen.json()['sha256']}", headers=alice.headers)
    assert ambiguous.status_code == 409 and chosen.json()["id"] in ambiguous.json()["detail"]
    wrong = http.post("/v1/assets", headers=alice.headers, files=[("asset", two)], data={"urdf": "lid.urdf"})
    assert wrong.status_code == 422 and "matches none" in wrong.json()["detail"]


def test_a_deleted_or_truncated_stored_asset_is_restored_by_uploading_it_again(http, alice, settings) -> None:
    body = _upload(http, alice.headers, assets.hinge_zip("-restore")).json()
    stored = settings.storage_dir / "assets" / f"{body['sha256']}.zip"
    original = stored.read_bytes()
    stored.write_bytes(original[: len(original) // 2])
    kept = settings.storage_dir / summary_key(body["sha256"], "mobility.urdf")
    kept.unlink()  # the summary must now be computed from the damaged zip: a server error, not the user's AssetError
    damaged = http.get(f"/v1/assets/{body['id']}/summary", headers=alice.headers)
    assert damaged.status_code == 500 and damaged.json()["kind"] == "StorageError", damaged.text
    assert "upload the same file again" in damaged.json()["detail"]
    again = _upload(http, alice.headers, assets.hinge_zip("-restore"))
    assert again.status_code == 200 and stored.read_bytes() == original
    assert http.get(f"/v1/assets/{body['id']}/summary", headers=alice.headers).status_code == 200
    stored.unlink()
    assert _upload(http, alice.headers, assets.hinge_zip("-restore")).status_code == 200 and stored.read_bytes() == original


@pytest.mark.parametrize(
    ("builder", "words"),
    [
        (assets.zip_slip, ["unsafe zip member", "../evil.txt", "slip.zip"]),
        (assets.zip_bomb, ["zip bomb", "padding.bin", "bomb.zip"]),
        (assets.xml_bomb, ["forbidden XML construct", "mobility.urdf"]),
        (assets.missing_mesh, ["meshes/missing.obj", "does not exist", "link lid"]),
        (assets.no_urdf, ["no .urdf file", "empty.zip"]),
        (assets.not_a_zip, ["not a readable zip", "broken.zip"]),
    ],
    ids=lambda value: getattr(value, "__name__", None),
)
def test_every_asset_error_is_a_422_naming_the_problem(http, alice, settings, builder, words) -> None:
    response = _upload(http, alice.headers, builder())
    assert response.status_code == 422, response.text
    body = response.json()
    assert body["kind"] == "AssetError"
    for word in words:
        assert word in body["detail"]
    assert not (settings.storage_dir / "assets").exists() or not any((settings.storage_dir / "assets").iterdir())


@pytest.mark.parametrize("name", ["../escape.urdf", "/abs/mobility.urdf", "C:/x/mobility.urdf", "a/../../b.obj", "folder/"])
def test_unsafe_file_names_in_multi_file_uploads_are_rejected(http, alice, name) -> None:
    files = [("asset", ("ok/mobility.urdf", assets.hinge_urdf().encode())), ("asset", (name, b"data"))]
    response = http.post("/v1/assets", headers=alice.headers, files=files)
    assert response.status_code == 422, response.text


def test_duplicate_names_are_rejected(http, alice) -> None:
    urdf = assets.hinge_urdf().encode()
    response = _upload(http, alice.headers, ("a/mobility.urdf", urdf), ("a\\mobility.urdf", urdf))
    assert response.status_code == 422 and "twice" in response.json()["detail"]


def test_no_asset_is_a_422(http, alice) -> None:
    response = http.post("/v1/assets", headers=alice.headers, files=[("other", ("x.txt", b"x"))])
    assert response.status_code == 422 and "no asset" in response.json()["detail"]


def _limited_app(settings: Settings, **limits: int) -> TestClient:
    return TestClient(create_app(settings.model_copy(update=limits)))


def test_upload_larger_than_the_limit_is_a_413(settings, alice) -> None:
    with _limited_app(settings, max_upload_bytes=64 * 1024) as http:
        big = ("big.zip", b"PK\x03\x04" + b"\0" * (200 * 1024))
        response = _upload(http, alice.headers, big)
        assert response.status_code == 413 and "limit" in response.json()["detail"]
        small = _upload(http, alice.headers, assets.hinge_zip("-small"))
        assert small.status_code == 201, small.text


def test_declared_huge_body_is_refused_before_reading(http, alice) -> None:
    headers = {**alice.headers, "Content-Type": "multipart/form-data; boundary=xyz", "Content-Length": str(2 * 1024**3)}
    response = http.post("/v1/assets", headers=headers, content=b"--xyz--\r\n")
    assert response.status_code == 413


def test_too_many_files_is_a_413(settings, alice) -> None:
    with _limited_app(settings, max_upload_files=3) as http:
        files = [(f"a/file{i}.obj", b"v 0 0 0\n") for i in range(4)]
        response = _upload(http, alice.headers, *files)
        assert response.status_code == 413 and "more than 3 files" in response.json()["detail"]


def test_wrong_content_type_is_a_415(http, alice) -> None:
    assert http.post("/v1/assets", headers=alice.headers, json={"asset": "x"}).status_code == 415
    assert http.post("/v1/assets", headers=alice.headers, content=b"raw").status_code == 415


@pytest.mark.parametrize(
    "body",
    [b"garbage without boundary", b"--xyz\r\nContent-Type: text/plain\r\n\r\nno disposition\r\n--xyz--\r\n"],
)
def test_malformed_multipart_is_a_400(http, alice, body) -> None:
    headers = {**alice.headers, "Content-Type": "multipart/form-data; boundary=xyz"}
    response = http.post("/v1/assets", headers=headers, content=body)
    assert 400 <= response.status_code < 500, response.text


def test_multipart_without_boundary_is_a_400(http, alice) -> None:
    headers = {**alice.headers, "Content-Type": "multipart/form-data"}
    assert http.post("/v1/assets", headers=headers, content=b"x").status_code == 400


_BAD_JOINT = ('<joint name="lid_hinge" type="revolute"><parent link="base"/><child link="lid"/>{}'
              '<limit lower="0" upper="1.5" effort="1" velocity="1"/></joint>')


@pytest.mark.parametrize(
    ("old", "new", "says"),
    [
        # was a 500 on upload
        ('<axis xyz="1.0 0.0 0.0"/>', '<axis xyz="0 1"/>', "axis needs 3 numbers"),
        # were accepted (201), then the summary answered 500 and jobs failed with internal errors
        ('<box size="1.0 1.0 0.5"/>', '<box size="nan 1 1"/>', "box size holds a NaN"),
        ('<origin xyz="0.0 -0.5 0.5" rpy="0.0 0.0 0.0"/>', '<origin xyz="1e308 0 0"/>', "larger than 10000"),
        ('<origin xyz="0.0 0.0 0.25" rpy="0.0 0.0 0.0"/>', '<origin xyz="nan 0 0.25"/>', "not a finite transform"),
    ],
    ids=["axis-2-numbers", "nan-box", "huge-origin", "nan-visual-origin"],
)
def test_bad_numbers_are_a_422_on_upload_not_a_later_500(http, alice, old, new, says) -> None:
    urdf = assets.hinge_urdf(name="numbers")
    assert old in urdf
    response = _upload(http, alice.headers, ("numbers.zip", assets.zip_bytes({"n/mobility.urdf": urdf.replace(old, new, 1)})))
    assert response.status_code == 422, response.text
    assert response.json()["kind"] == "AssetError" and says in response.json()["detail"]


@pytest.mark.filterwarnings("ignore::PIL.Image.DecompressionBombWarning")
def test_a_small_zip_with_a_huge_texture_is_refused_without_decoding_it(http, alice) -> None:
    """~13000 x 13000 pixels (hundreds of MB decoded) in a few kB: a 422, before any decoding."""
    from tests.engine.asset.test_asset_rejections import _png_header

    files = {"t/mobility.urdf": assets.hinge_urdf(name="texture"), "t/textures/huge.png": _png_header(13000, 13000)}
    response = _upload(http, alice.headers, ("texture.zip", assets.zip_bytes(files)))
    assert response.status_code == 422, response.text
    assert "13000 x 13000 pixels" in response.json()["detail"] and "textures/huge.png" in response.json()["detail"]
