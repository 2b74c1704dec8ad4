"""``ArtimoClient``: a small synchronous client of the ArtiMo HTTP API (httpx).

>>> client = ArtimoClient("http://127.0.0.1:8000", key)
>>> job = client.submit("examples/pedal_bin", "press the pedal to open the bin")
>>> job = client.wait(job["id"], timeout=300)
>>> client.download(job["id"], Path("out"))

A folder is zipped on the fly (deterministic order, in memory up to the server's limit);
every error answer raises :class:`ClientError` carrying the server's message.
"""

from __future__ import annotations

import io
import logging
import time
import zipfile
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import httpx

logger = logging.getLogger(__name__)

DEFAULT_TIMEOUT_S = 60.0
DEFAULT_RETRY_WAIT_S = 120.0
"""Longest total wait per request for a busy server (429 / 503 with ``Retry-After``)."""
MAX_RETRIES = 20
RETRY_STATUSES = frozenset({429, 503})
DEFAULT_POLL_S = 1.0
TERMINAL_STATUSES = frozenset({"succeeded", "failed", "cancelled"})
ZIP_EPOCH = (1980, 1, 1, 0, 0, 0)

JobDict = dict[str, Any]


class ClientError(Exception):
    """The server refused a request (or could not be reached: ``status`` 0)."""

    def __init__(self, status: int, message: str, body: Any = None) -> None:
        super().__init__(f"HTTP {status}: {message}" if status else message)
        self.status = status
        self.message = message
        self.body = body


def zip_folder(folder: Path) -> bytes:
    """The folder as a zip (members under ``<folder name>/``, sorted, fixed timestamps)."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for path in sorted(p for p in folder.rglob("*") if p.is_file()):
            info = zipfile.ZipInfo(f"{folder.name}/{path.relative_to(folder).as_posix()}", date_time=ZIP_EPOCH)
            info.external_attr = 0o644 << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            archive.writestr(info, path.read_bytes())
    return buffer.getvalue()


def _asset_part(asset: Path) -> tuple[str, bytes, str]:
    if asset.is_dir():
        return f"{asset.name}.zip", zip_folder(asset), "application/zip"
    if not asset.is_file():
        raise ClientError(0, f"asset {asset} does not exist")
    kind = "application/zip" if asset.suffix.lower() == ".zip" else "application/octet-stream"
    return asset.name, asset.read_bytes(), kind


def _message(response: httpx.Response) -> tuple[str, Any]:
    try:
        body = response.json()
    except ValueError:
        return response.text[:500] or response.reason_phrase, None
    detail = body.get("detail") if isinstance(body, dict) else None
    if isinstance(detail, list):  # FastAPI validation errors
        detail = "; ".join(f"{'.'.join(str(p) for p in e.get('loc', []))}: {e.get('msg')}" for e in detail if isinstance(e, dict))
    return str(detail or body), body


def _retry_after(response: httpx.Response) -> float | None:
    """Seconds the server asks us to wait before sending the same request again, if it does."""
    if response.status_code not in RETRY_STATUSES:
        return None
    try:
        return max(0.0, float(response.headers.get("Retry-After", "")))
    except ValueError:
        return None  # absent, or an HTTP date: not a busy signal we act on


class ArtimoClient:
    """Client of one ArtiMo server.

    Parameters
    ----------
    server
        Base URL, e.g. ``http://127.0.0.1:8000``.
    key
        API key (sent as ``Authorization: Bearer``).
    timeout_s
        Per-request timeout, seconds.
    retry_wait_s
        A busy server (429 rate limit, 503 at capacity) says when to come back (``Retry-After``);
        the request is sent again then, for up to this many seconds in all (0: never).
    transport
        Optional httpx transport (tests pass one that calls the app in-process).
    """

    def __init__(self, server: str, key: str, *, timeout_s: float = DEFAULT_TIMEOUT_S,
                 retry_wait_s: float = DEFAULT_RETRY_WAIT_S, transport: httpx.BaseTransport | None = None) -> None:
        self.retry_wait_s = retry_wait_s
        self.server = server.rstrip("/")
        self._http = httpx.Client(base_url=self.server, headers={"Authorization": f"Bearer {key}"},
                                  timeout=timeout_s, transport=transport, follow_redirects=True)

    def close(self) -> None:
        self._http.close()

    def __enter__(self) -> ArtimoClient:
        return self

    def __exit__(self, *_: object) -> None:
        self.close()

    def _request(self, method: str, url: str, **kwargs: Any) -> httpx.Response:
        waited = 0.0
        for _ in range(MAX_RETRIES + 1):
            try:
                response = self._http.request(method, url, **kwargs)
            except httpx.HTTPError as exc:
                raise ClientError(0, f"cannot reach the server at {self.server} ({type(exc).__name__}: {exc}); "
                                     "is it running (artimo serve), and is --server / $ARTIMO_SERVER right?") from exc
            delay = _retry_after(response)
            if delay is None or waited >= self.retry_wait_s:
                break
            delay = min(delay, self.retry_wait_s - waited)
            logger.info("server busy (%d %s); sending %s %s again in %.1f s",
                        response.status_code, response.reason_phrase, method, url, delay)
            time.sleep(delay)
            waited += delay
        if response.status_code >= 400:
            message, body = _message(response)
            raise ClientError(response.status_code, message, body)
        return response

    def upload_asset(self, asset: Path, *, urdf: str | None = None) -> JobDict:
        """Upload an asset (folder, .zip or single file); returns its id and sha256 (reused if known).

        ``urdf``: which URDF to use when the asset holds several.
        """
        data = {"urdf": urdf} if urdf else None
        response = self._request("POST", "/v1/assets", data=data, files=[("asset", _asset_part(Path(asset)))])
        return dict(response.json())

    def asset_summary(self, ref: str) -> JobDict:
        """An uploaded asset's joints (type, links, axis, limits), link labels and sizes."""
        return dict(self._request("GET", f"/v1/assets/{ref}/summary").json())

    def submit(self, asset: Path | str, prompt: str, **options: Any) -> JobDict:
        """Submit a job; ``asset`` is a folder, a .zip, or an uploaded asset's id/sha256.

        ``options``: ``provider``, ``perceiver_model``, ``planner_model``, ``critic_model``,
        ``fps``, ``max_critic_rounds``, ``preview``, ``exports`` (e.g. ``"usd,mjcf"`` or a list), ``urdf``.
        Returns ``{id, url, status}``.
        """
        data = {"prompt": prompt, **{k: ",".join(v) if isinstance(v, list | tuple) else str(v) for k, v in options.items() if v is not None}}
        path = Path(asset)
        if isinstance(asset, str) and not path.exists():
            fields = [(k, (None, v)) for k, v in {**data, "asset_ref": asset}.items()]  # multipart without a file
            response = self._request("POST", "/v1/animations", files=fields)
        else:
            response = self._request("POST", "/v1/animations", data=data, files=[("asset", _asset_part(path))])
        return dict(response.json())

    def get(self, job_id: str) -> JobDict:
        return dict(self._request("GET", f"/v1/animations/{job_id}").json())

    def list_jobs(self, *, limit: int = 50, offset: int = 0, status: str | None = None) -> JobDict:
        params: dict[str, Any] = {"limit": limit, "offset": offset}
        if status:
            params["status"] = status
        return dict(self._request("GET", "/v1/animations", params=params).json())

    def cancel(self, job_id: str) -> JobDict:
        return dict(self._request("DELETE", f"/v1/animations/{job_id}").json())

    def wait(self, job_id: str, timeout: float = 600.0, poll: float = DEFAULT_POLL_S) -> JobDict:
        """Poll until the job has finished; returns its last state.

        Raises
        ------
        ClientError
            The job did not finish within ``timeout`` seconds (status 0), or a request failed.
        """
        deadline = time.monotonic() + timeout
        while True:
            job = self.get(job_id)
            if job["status"] in TERMINAL_STATUSES:
                return job
            if time.monotonic() >= deadline:
                raise ClientError(0, f"job {job_id} still {job['status']} after {timeout:.0f} s", job)
            time.sleep(poll)

    def download(self, job_id: str, out_dir: Path, names: Sequence[str] | None = None) -> list[Path]:
        """Write the job's output files (all, or ``names``) under ``out_dir``; returns their paths."""
        job = self.get(job_id)
        out_dir = Path(out_dir)
        written = []
        for artifact in job.get("artifacts", []):
            if names is not None and artifact["name"] not in names:
                continue
            target = (out_dir / artifact["name"]).resolve()
            if not target.is_relative_to(out_dir.resolve()):
                raise ClientError(0, f"refusing to write {artifact['name']!r} outside {out_dir}")
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(self._request("GET", artifact["url"]).content)
            written.append(target)
        return written

    def submit_batch(self, cases: Sequence[Mapping[str, Any]], *, name: str | None = None,
                     options: Mapping[str, Any] | None = None) -> JobDict:
        """Submit cases ``{"asset": id|sha256|path, "prompt": ..., "case_id": ...}``; paths are uploaded first."""
        body_cases = []
        for case in cases:
            ref = str(case["asset"])
            if Path(ref).exists():
                ref = self.upload_asset(Path(ref))["id"]
            body_cases.append({**dict(case), "asset": ref})
        body: dict[str, Any] = {"cases": body_cases, "name": name, "options": dict(options or {})}
        return dict(self._request("POST", "/v1/batches", json=body).json())

    def get_batch(self, batch_id: str) -> JobDict:
        return dict(self._request("GET", f"/v1/batches/{batch_id}").json())
