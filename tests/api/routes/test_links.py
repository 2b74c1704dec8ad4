"""Signed share links (``?token=``): download without a header; expired, altered or misused tokens are 403."""

from __future__ import annotations

import time
import uuid

import pytest

from app.api import signing
from tests.api.routes.test_animations import submit
from tests.support import upload_assets as assets

tasks = pytest.importorskip("workers.tasks")


@pytest.fixture
def finished(http, alice, settings, sent) -> str:  # type: ignore[no-untyped-def]
    url = submit(http, alice.headers, prompt="open the lid", upload=assets.hinge_zip("-links")).json()["url"]
    assert tasks.execute_job(str(sent[0]), settings=settings, worker="inline-test").value == "succeeded"
    return url


def _links(http, headers, url, **body):  # type: ignore[no-untyped-def]
    return http.post(f"{url}/links", headers=headers, json=body)



def test_a_signed_link_downloads_without_a_header(http, alice, finished) -> None:
    response = _links(http, alice.headers, finished, names=["animation.glb", "report.json"], expires_in_s=600)
    assert response.status_code == 200, response.text
    links = {link["name"]: link["url"] for link in response.json()["links"]}
    assert "?token=" in links["animation.glb"]
    glb = http.get("/" + links["animation.glb"].split("/", 3)[3])
    assert glb.status_code == 200 and glb.content[:4] == b"glTF" and glb.headers["content-type"] == "model/gltf-binary"
    assert http.get("/" + links["report.json"].split("/", 3)[3]).json()["provider"] == "offline"
    every = _links(http, alice.headers, finished).json()["links"]
    assert {link["name"] for link in every} >= {"animation.glb", "trajectory.jsonl", "plan.json", "report.json", "causal.json"}


def test_altered_token_is_403(http, alice, finished) -> None:
    link = _links(http, alice.headers, finished, names=["animation.glb"]).json()["links"][0]["url"]
    path = "/" + link.split("/", 3)[3]
    payload, signature = path.split("token=")[1].split(".")
    flipped = signature[:-2] + ("A" if signature[-2] != "A" else "B") + signature[-1]
    assert http.get(path.replace(signature, flipped)).status_code == 403
    other_payload = signing._b64(signing._unb64(payload).replace(b'"n":"animation.glb"', b'"n":"report.json"'))
    response = http.get(path.replace("animation.glb?", "report.json?").replace(payload, other_payload))
    assert response.status_code == 403 and "signature" in response.json()["detail"]
    assert http.get(path.replace("animation.glb?", "report.json?")).status_code == 403  # token of another file
    assert http.get(path.split("?")[0]).status_code == 422  # no token at all


def test_a_signature_with_non_ascii_characters_is_403_not_500() -> None:
    """Found by schemathesis: ``?token=0.\x80`` was a TypeError in hmac.compare_digest (a 500)."""
    for token in ("0.\x80", "e30.sig\u00e9", "\u00e9.\u00e9"):
        with pytest.raises(signing.Forbidden, match="signature does not match"):
            signing.verify(b"secret", token, "file")


def test_expired_token_is_403(http, alice, settings, finished, monkeypatch) -> None:
    link = _links(http, alice.headers, finished, names=["animation.glb"], expires_in_s=30).json()["links"][0]["url"]
    path = "/" + link.split("/", 3)[3]
    assert http.get(path).status_code == 200
    later = time.time() + 32
    monkeypatch.setattr(signing.time, "time", lambda: later)
    response = http.get(path)
    assert response.status_code == 403 and "expired" in response.json()["detail"]


def test_links_need_the_owner_and_real_outputs(http, alice, bob, finished) -> None:
    assert _links(http, bob.headers, finished).status_code == 404
    assert _links(http, {}, finished).status_code == 401
    response = _links(http, alice.headers, finished, names=["nope.bin"])
    assert response.status_code == 422 and "nope.bin" in response.json()["detail"]
    assert _links(http, alice.headers, finished, expires_in_s=0).status_code == 422
    assert _links(http, alice.headers, finished, expires_in_s=10**9).status_code == 422


def test_a_token_from_another_secret_is_403(http, alice, finished) -> None:
    job_id = finished.rsplit("/", 1)[1]
    forged = signing.sign(b"not the server's secret", "file", 600, j=job_id, n="animation.glb", c=str(alice.client.id))
    assert http.get(f"/v1/shared/{job_id}/animation.glb", params={"token": forged}).status_code == 403
    unknown = str(uuid.uuid4())
    assert http.get(f"/v1/shared/{unknown}/animation.glb", params={"token": forged}).status_code == 403


def test_the_link_secret_is_kept_private_and_reused(settings) -> None:
    first = signing.link_secret(settings)
    path = settings.data_dir / signing.SECRET_FILE
    assert len(first) == signing.SECRET_BYTES and (path.stat().st_mode & 0o777) == 0o600
    signing._cache.clear()
    assert signing.link_secret(settings) == first


def test_page_token_signs_in_as_its_client(http, alice, settings) -> None:
    token = signing.page_token(settings, str(alice.client.id), 60)
    response = http.get("/v1/animations", headers={"Authorization": f"Bearer {token}"})
    assert response.status_code == 200
    expired = signing.PAGE_TOKEN_PREFIX + signing.sign(signing.link_secret(settings), "page", -1, c=str(alice.client.id))
    assert http.get("/v1/animations", headers={"Authorization": f"Bearer {expired}"}).status_code == 401
    tampered = token[:-3] + ("x" if token[-3] != "x" else "y") + token[-2:]
    assert http.get("/v1/animations", headers={"Authorization": f"Bearer {tampered}"}).status_code == 401
    file_token = signing.PAGE_TOKEN_PREFIX + signing.sign(signing.link_secret(settings), "file", 60, c=str(alice.client.id))
    assert http.get("/v1/animations", headers={"Authorization": f"Bearer {file_token}"}).status_code == 401


def test_a_token_lives_at_least_its_ttl_whatever_the_fraction_of_second(monkeypatch) -> None:
    clock = [1000.99]
    monkeypatch.setattr(signing.time, "time", lambda: clock[0])
    token = signing.sign(b"k" * 32, "file", 1, n="a")
    clock[0] = 1001.9  # 0.91 s later: still inside the second asked for
    assert signing.verify(b"k" * 32, token, "file").fields == {"n": "a"}
    clock[0] = 1002.5
    with pytest.raises(signing.Forbidden, match="expired"):
        signing.verify(b"k" * 32, token, "file")
