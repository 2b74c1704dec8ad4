"""Streaming ``multipart/form-data`` reader with limits checked while the body arrives.

Files go straight to numbered files in a temporary folder (never to memory, never to a
path built from the client's file name); the request is abandoned with 413 as soon as
the files' bytes, the body's bytes or the number of files pass their limits, so a 2 GB
upload costs at most ``max_bytes`` of disk and no memory.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from pathlib import Path
from typing import BinaryIO

from python_multipart.exceptions import FormParserError
from python_multipart.multipart import MultipartParser, parse_options_header
from starlette.requests import ClientDisconnect, Request

from app.api.errors import BadRequest, PayloadTooLarge, UnsupportedMediaType

logger = logging.getLogger(__name__)

MULTIPART = "multipart/form-data"
BODY_OVERHEAD_BYTES = 1024 * 1024
"""Allowance for part headers and text fields on top of the files' bytes."""
MAX_FIELDS = 64
MAX_FIELD_BYTES = 64 * 1024


@dataclass(frozen=True)
class UploadLimits:
    max_bytes: int
    """Largest total size of the uploaded files, bytes."""
    max_files: int


@dataclass(frozen=True)
class UploadedFile:
    field: str
    filename: str
    """As sent by the client (may hold sub-folders; validate before use)."""
    path: Path
    size: int


@dataclass
class MultipartForm:
    fields: dict[str, list[str]] = field(default_factory=dict)
    files: list[UploadedFile] = field(default_factory=list)

    def value(self, name: str) -> str | None:
        values = self.fields.get(name)
        return values[0] if values else None

    def files_of(self, name: str) -> list[UploadedFile]:
        return [f for f in self.files if f.field == name]


class _Part:
    def __init__(self) -> None:
        self.header_name = b""
        self.header_value = b""
        self.disposition = b""
        self.name = ""
        self.filename: str | None = None
        self.data = bytearray()
        self.handle: BinaryIO | None = None
        self.path: Path | None = None
        self.size = 0


class _Collector:
    """python-multipart callbacks building a :class:`MultipartForm` under ``folder``."""

    def __init__(self, folder: Path, limits: UploadLimits) -> None:
        self.folder = folder
        self.limits = limits
        self.form = MultipartForm()
        self.part = _Part()
        self.file_bytes = 0
        self.file_count = 0
        self.field_count = 0

    def on_part_begin(self) -> None:
        self.part = _Part()

    def on_header_field(self, data: bytes, start: int, end: int) -> None:
        self.part.header_name += data[start:end]

    def on_header_value(self, data: bytes, start: int, end: int) -> None:
        self.part.header_value += data[start:end]

    def on_header_end(self) -> None:
        if self.part.header_name.strip().lower() == b"content-disposition":
            self.part.disposition = self.part.header_value
        self.part.header_name, self.part.header_value = b"", b""

    def on_headers_finished(self) -> None:
        kind, options = parse_options_header(self.part.disposition)
        if kind != b"form-data" or b"name" not in options:
            raise BadRequest("every multipart part needs 'Content-Disposition: form-data; name=...'")
        self.part.name = options[b"name"].decode("utf-8", errors="replace")
        if b"filename" not in options:
            self.field_count += 1
            if self.field_count > MAX_FIELDS:
                raise PayloadTooLarge(f"more than {MAX_FIELDS} form fields")
            return
        self.part.filename = options[b"filename"].decode("utf-8", errors="replace")
        self.file_count += 1
        if self.file_count > self.limits.max_files:
            raise PayloadTooLarge(f"more than {self.limits.max_files} files in one upload", limit=self.limits.max_files)
        self.part.path = self.folder / f"part-{self.file_count:06d}"
        self.part.handle = open(self.part.path, "wb")  # closed in on_part_end / close()

    def on_part_data(self, data: bytes, start: int, end: int) -> None:
        chunk = data[start:end]
        if self.part.handle is None:
            if len(self.part.data) + len(chunk) > MAX_FIELD_BYTES:
                raise PayloadTooLarge(f"form field '{self.part.name}' is longer than {MAX_FIELD_BYTES} bytes")
            self.part.data.extend(chunk)
            return
        self.file_bytes += len(chunk)
        self.part.size += len(chunk)
        if self.file_bytes > self.limits.max_bytes:
            raise PayloadTooLarge(f"upload larger than the limit of {self.limits.max_bytes} bytes", limit=self.limits.max_bytes)
        self.part.handle.write(chunk)

    def on_part_end(self) -> None:
        part = self.part
        if part.handle is None:
            self.form.fields.setdefault(part.name, []).append(part.data.decode("utf-8", errors="replace"))
            return
        part.handle.close()
        part.handle = None
        assert part.path is not None and part.filename is not None
        if part.filename == "" and part.size == 0:  # an empty file input of an HTML form
            return
        self.form.files.append(UploadedFile(field=part.name, filename=part.filename, path=part.path, size=part.size))

    def close(self) -> None:
        if self.part.handle is not None:
            self.part.handle.close()


def _boundary(request: Request) -> bytes:
    kind, options = parse_options_header(request.headers.get("content-type"))
    if kind != MULTIPART.encode():
        raise UnsupportedMediaType(f"expected a {MULTIPART} body, got {kind.decode('latin-1') or 'none'}")
    boundary = options.get(b"boundary")
    if not boundary:
        raise BadRequest("multipart body without a boundary")
    return boundary


def _check_declared_length(request: Request, limits: UploadLimits) -> None:
    declared = request.headers.get("content-length")
    if declared is not None and declared.isdigit() and int(declared) > limits.max_bytes + BODY_OVERHEAD_BYTES:
        raise PayloadTooLarge(f"upload of {declared} bytes is larger than the limit of {limits.max_bytes} bytes", limit=limits.max_bytes)


async def read_multipart(request: Request, limits: UploadLimits, folder: Path) -> MultipartForm:
    """Parse the request body into text fields and files written under ``folder``.

    Raises
    ------
    UnsupportedMediaType
        The body is not ``multipart/form-data``.
    PayloadTooLarge
        Too many bytes, files or fields (checked while reading).
    BadRequest
        A malformed body.
    """
    boundary = _boundary(request)
    _check_declared_length(request, limits)
    collector = _Collector(folder, limits)
    callbacks = {name: getattr(collector, name) for name in (
        "on_part_begin", "on_part_data", "on_part_end", "on_header_field", "on_header_value",
        "on_header_end", "on_headers_finished",
    )}
    parser = MultipartParser(boundary, callbacks)  # type: ignore[arg-type]
    body_bytes = 0
    try:
        async for chunk in request.stream():
            body_bytes += len(chunk)
            if body_bytes > limits.max_bytes + BODY_OVERHEAD_BYTES:
                raise PayloadTooLarge(f"upload larger than the limit of {limits.max_bytes} bytes", limit=limits.max_bytes)
            parser.write(chunk)
        parser.finalize()
    except FormParserError as exc:
        raise BadRequest(f"malformed multipart body: {exc}") from exc
    except ClientDisconnect as exc:
        raise BadRequest("the client disconnected during the upload") from exc
    finally:
        collector.close()
    return collector.form
